#pragma once
// A full diagnosis of a synthetic measured set (src/diagnosis/synthesize.h) at the shipped search
// settings, for the tests that check its answer (test_hidden_effects.cpp, test_every_mechanism.cpp).

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "diagnosis/diagnose.h"
#include "diagnosis/report.h"
#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {

// With `report`, diagnosis.json and report.md are written there too (no plots).
inline Diagnosis diagnose_synthetic(const std::vector<Mechanism>& hidden, std::uint64_t seed, bool second_effect,
                                    const std::string& stated_rule = "gyration",
                                    const std::filesystem::path& report = {},
                                    NormalLaw data_law = NormalLaw::linear, bool compare_normal_laws = false) {
  const testing::TestDirectory directory;
  SyntheticSpec spec;
  spec.hidden = hidden;
  spec.seed = seed;
  spec.normal_law = data_law;
  write_synthetic_measured_set(directory.path(), spec);
  if (stated_rule != "gyration") {  // the data's own rule; the specimen file states another
    const std::filesystem::path file = directory.path() / "specimen.toml";
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "half_width = \"gyration\"";
    text.replace(text.find(from), from.size(), "half_width = \"" + stated_rule + "\"");
    std::ofstream(file) << text;
  }
  const MeasuredSet set = read_measured_set(directory.path());
  DiagnosisOptions options;
  options.threads = 2;
  options.look_for_second_effect = second_effect;
  options.compare_normal_laws = compare_normal_laws;
  Diagnosis d = diagnose(set, options);
  if (!report.empty()) write_diagnosis(report, set, d, options.isa, false);
  return d;
}

inline const CandidateScore& score_of(const Diagnosis& d, Mechanism m) {
  for (const CandidateScore& c : d.ranking) {
    if (c.mechanism == m) return c;
  }
  throw std::logic_error("not ranked");
}

}  // namespace caskdem::diagnosis
