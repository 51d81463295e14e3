#pragma once
// The synthetic set the tests of the diagnosis's rules run on (eccentric mass hidden, seed 21),
// its search cut to a few points and its step four times the set's: rules and promises that hold
// whatever the fits come out at can be checked in seconds, and under the sanitizers (the model
// refuses a step beyond the damped scheme's stability limit; docs/model.md).

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {

// Writes the set into `directory` with `search_settings` in place of its [diagnosis] starts and
// evaluations; false if specimen.toml no longer has the keys this replaces.
inline bool write_small_search_set(const std::filesystem::path& directory,
                                   const std::string& search_settings = "starts = 1\nevaluations = 10\nexploration = 16") {
  SyntheticSpec spec;
  spec.hidden = {Mechanism::eccentric_mass};
  spec.seed = 21;
  write_synthetic_measured_set(directory, spec);
  const std::filesystem::path specimen = directory / "specimen.toml";
  const std::string text = testing::file_text(specimen);
  const std::regex search("starts = [0-9]+\\nevaluations = [0-9]+"), step("safety_factor = [0-9.]+");
  if (!std::regex_search(text, search) || !std::regex_search(text, step)) return false;
  std::ofstream(specimen) << std::regex_replace(std::regex_replace(text, search, search_settings), step,
                                                "safety_factor = 0.2");
  return true;
}

}  // namespace caskdem::diagnosis
