#pragma once
// A measured-data directory made with the independent cylinder model: specimen.toml with the
// nominal values an experimenter knows, test1.csv ... test6.csv with sensor noise, and
// truth.json with what the diagnosis should find.
//
// A test a diagnosis proposed can be added afterwards from its drive file (add_drive_test).
//
// The test programme (1/3 model scale, 200 Hz, each followed by 2.5 s of free response):
//   test1  sine 3.6 Hz, 10 mm (0.52 g)   test4  sine 5.0 Hz, 10 mm (1.01 g)
//   test2  sine 4.2 Hz, 10 mm (0.71 g)   test5  Kobe 1995 KJMA 000, time / sqrt(3), 0.65 g
//   test3  El Centro 1940 180, / sqrt(3), 0.70 g   test6  Loma Prieta 1989 Corralitos 000, / sqrt(3), 0.70 g
// Uplift needs g tan(alpha) = 0.47 g, so the sines are above 3.4 Hz at 10 mm. The held-out
// tests of the [diagnosis] table (test2, test5) each have training tests of their kind.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hidden_effects.h"

namespace independent {

struct MeasuredSetOptions {
  // The footprint rule specimen.toml states: "distributed" (the cask these data come from: a
  // circular base on distributed contact), or a two-corner rule, "gyration" or "radius" (an
  // analyst's guess, deliberately wrong here).
  std::string footprint = "distributed";
  std::filesystem::path motions;        // folder with three-component/*.AT2 (default: the shared motions)
  std::vector<int> tests;               // 1-based tests to write; empty = all six
  double free_time = 2.5;               // s of recording after the motion
  double rotation_noise = 2e-4;         // rad
  double slide_noise = 1e-4;            // m
  double table_noise = 0.003;           // m/s^2, on both table channels
};

struct TestSummary {
  std::string name;
  double peak_rotation = 0.0;  // rad, noise-free
  double peak_slide = 0.0;     // m
  double final_slide = 0.0;    // m
  bool tipped_over = false;
  long evaluations = 0;
};

struct MeasuredSetResult {
  Truth truth;
  std::vector<TestSummary> tests;
};

// Writes the directory (created). Throws std::invalid_argument on an unknown effect or
// footprint rule, std::runtime_error on a missing record.
MeasuredSetResult write_independent_measured_set(const std::filesystem::path& directory, const std::string& effect,
                                                 std::uint64_t seed, const MeasuredSetOptions& options = {});

// Adds test NUMBER to a set written with the same effect and seed: the cask of that truth driven
// by a table drive file (caskdem plan-test's drive-K.csv: "t,table_acc", uniform samples, the
// table still vertically), recorded for the drive's length with the set's noise levels (truth.json)
// and stream 100 + NUMBER, and its entry appended to truth.json. Throws std::runtime_error naming
// the file and line on a bad drive, std::invalid_argument on another effect or seed or a test
// that exists.
TestSummary add_drive_test(const std::filesystem::path& directory, const std::string& effect, std::uint64_t seed,
                           const std::filesystem::path& drive_file, int number, const MeasuredSetOptions& options = {});

}  // namespace independent
