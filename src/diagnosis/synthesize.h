#pragma once
// Synthetic measured data for testing the diagnosis: a laboratory specimen (the source
// paper's 1/3 model cask) in eight shaking-table tests, simulated with a hidden "truth" (its
// own friction, damping and stiffness, and zero or more mechanisms switched on with values
// drawn from the seed), written as a measured-data directory with realistic sensor noise.
// The diagnosis sees only what an experimenter would: specimen.toml with nominal values and
// the CSV files. The truth is written to truth.json beside them for checking.
//
// Tests (model scale; sampled at 200 Hz, f_s = 0.05 for speed), in pairs of a kind so that
// the default held-out tests (test2, test5) have training tests like them:
//   test1  sine 1.5 Hz, 0.30 g        rocking            test5  sine 1.2 Hz, 0.28 g
//   test2  sine 2.5 Hz, 0.45 g        rocking, sliding   test4  sine 2.0 Hz, 0.50 g
//   test3  synthetic earthquake, 0.40 g                  test6  another, 0.45 g
//   test7  sine 3.0 Hz, 0.40 g        sliding            test8  sine 2.0 Hz, 0.35 g (near slip)
// Every test has a vertical table channel: the sensor's noise alone (the table does not move
// vertically), or, when vertical_excitation is hidden, a second synthetic earthquake at 0.5
// to 0.7 times the horizontal peak, which acts on the cask.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

struct SyntheticSpec {
  std::vector<Mechanism> hidden;
  std::uint64_t seed = 1;
  double rotation_noise = 2e-4;  // rad, standard deviation
  double slide_noise = 1e-4;     // m
  double table_noise = 0.003;    // m/s^2 (0.3 mg: a shaking-table accelerometer's noise floor)
  // The contact's normal law the data are made with; specimen.toml states the linear one
  // whatever this is (a wrong model form, as a footprint rule can be).
  NormalLaw normal_law = NormalLaw::linear;
};

struct SyntheticTruth {
  std::vector<std::string> hidden;                        // mechanism names
  std::vector<std::pair<std::string, double>> parameters;  // every parameter of the true model
};

// The specimen.toml the generator writes, without its [diagnosis] table: the 1/3 model cask
// with nominal friction, damping and contact stiffness.
std::string synthetic_specimen_text();

// Writes specimen.toml, test1.csv ... test8.csv and truth.json into `directory` (created).
SyntheticTruth write_synthetic_measured_set(const std::filesystem::path& directory, const SyntheticSpec& spec);

// Adds test NUMBER to a set this generator wrote with the same spec (seed, hidden mechanisms,
// normal law; the noise levels are the set's, from truth.json): the true model driven by a
// table drive file (a plan's drive-1.csv), the table still vertically, with the noise of
// stream (seed, NUMBER - 1), as the laboratory would run a proposed test. Throws InputError
// naming the file on a bad drive, another spec or a test that exists. truth.json lists the
// added tests ("added_tests"), and writing the set again removes them.
void add_synthetic_drive_test(const std::filesystem::path& directory, const SyntheticSpec& spec,
                              const std::filesystem::path& drive_file, int number);

}  // namespace caskdem::diagnosis
