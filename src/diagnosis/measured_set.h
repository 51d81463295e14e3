#pragma once
// A measured-data directory: `specimen.toml` (the cask, floor and contact as in a case file,
// with the values the experimenter knows, and an optional [diagnosis] table) and one CSV per
// test (src/diagnosis/measured_test.h). docs/measured-data.md has an example.
//
//   [diagnosis]
//   heldout = ["test5", "test6"]   tests kept out of every fit and used to score (default:
//                                  every third test, starting with the second)
//   starts = 8                     parallel local searches per fit (SIMD lanes of a population)
//   evaluations = 60               objective evaluations per search
//   exploration = 192              points of each fit's first, exploring population
//   seed = 1
//   input_realisations = 1         table inputs each test is simulated with: the measured
//                                  channel, then the channel plus fresh noise at its own level
//                                  (src/diagnosis/measures.h, marginal_loss)

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casefile/case_file.h"
#include "diagnosis/measured_test.h"

namespace caskdem::diagnosis {

// The shaking table's limits (specimen.toml [table]), which the tests `caskdem plan-test`
// proposes respect (plan_test.h).
//   [table]
//   peak_acceleration = "1.0 g"
//   peak_velocity = "0.6 m/s"
//   stroke = "10 cm"              displacement amplitude (half the travel)
//   frequencies = ["0.5 Hz", "20 Hz"]
struct TableLimits {
  double peak_acceleration = 0.0;                   // m/s^2
  double peak_velocity = 0.0;                       // m/s
  double stroke = 0.0;                              // m
  double min_frequency = 0.0, max_frequency = 0.0;  // Hz
};

struct DiagnosisSettings {
  std::vector<std::string> heldout;
  int starts = 8;
  int evaluations = 60;
  int exploration = 192;
  std::uint64_t seed = 1;
  int input_realisations = 1;
  std::optional<TableLimits> table;  // absent: not stated
};

struct MeasuredSet {
  std::filesystem::path directory;
  Case specimen;
  DiagnosisSettings settings;
  std::vector<MeasuredTest> tests;    // sorted by name
  std::vector<int> training, heldout;  // indices into tests
  bool vertical_measured = false;      // every test has a vertical channel

  bool is_heldout(std::size_t test) const {
    return std::find(heldout.begin(), heldout.end(), static_cast<int>(test)) != heldout.end();
  }
};

// Reads specimen.toml and every *.csv in the directory; InputError naming the file and key or
// line when something cannot be used.
MeasuredSet read_measured_set(const std::filesystem::path& directory);

// The specimen file alone (and its [diagnosis] settings).
Case read_specimen(const std::filesystem::path& file, DiagnosisSettings* settings);

// The same from the file's text, read as if it were the file `named_as`.
Case read_specimen_text(std::string_view text, const std::filesystem::path& named_as, DiagnosisSettings* settings);

}  // namespace caskdem::diagnosis
