#pragma once
// The results of an ensemble, one row per realisation, and the HDF5 file that holds them.
//
// The file is written whole to a temporary name and renamed over the previous one, so the
// file on disk is always a complete, valid HDF5 file: a run killed at any moment leaves the
// last checkpoint, with its mask of completed realisations, and `--resume` continues from it.
// The file is built in memory and written sealed (hdf5::write_sealed: a CRC-32 of its bytes in its user
// block), and `--resume` and `plot` check the seal before HDF5 reads anything.
// Layout (docs/output.md):
//   /                   attributes: caskdem_version, ensemble_file, ensemble_toml, title,
//                       wall_time_s, completed, realisations, time_step_s, intensity_measure, ...
//   /realisations/      one dataset per field below, length = realisations; `completed` (0/1)
//   /motions/           name, pga, pgv, duration
//   /stripes/level
//   /calibration/       damping_ratio, restitution (when restitution is uncertain)
//   /limit_states/NAME/ stripe statistics, fitted curve and bootstrap band (complete runs)

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ensemble/plan.h"
#include "ensemble/runner.h"

namespace caskdem {

struct EnsembleResults {
  std::int64_t size = 0;
  bool three_d = false;  // a 3D ensemble also keeps incidence and spin
  std::string level_unit = "1";  // the SI unit of the ensemble's intensity measure
  std::vector<std::uint8_t> completed;
  // inputs, filled for every realisation from the plan
  std::vector<std::int64_t> stripe, motion;
  std::vector<double> level, scale_factor, friction_static, friction_kinetic, friction_decay_speed, restitution,
      damping_ratio, mass, centre_height, incidence;
  // outcomes, valid where completed
  std::vector<std::int64_t> status, impacts;
  std::vector<double> max_abs_rotation, max_rotation_ratio, max_abs_slide, residual_slide, max_uplift, end_time,
      tip_over_time, instability_time, spin, max_slip, residual_slip;

  EnsembleResults() = default;
  explicit EnsembleResults(const EnsemblePlan& plan);
  // Every per-realisation column as the file names it, with its SI unit ("1": none): a double
  // column or an integer one (stripe, motion, status, impacts).
  struct Column {
    std::string name, unit;
    const std::vector<double>* real = nullptr;
    const std::vector<std::int64_t>* integer = nullptr;
  };
  std::vector<Column> columns() const;
  void record(std::int64_t index, const RealisationOutcome& outcome, double stability_angle);
  std::int64_t completed_count() const;
  std::vector<std::int64_t> pending() const;
};

struct LimitStateSummary;  // ensemble/analysis.h

struct RunInformation {
  double wall_seconds = 0.0;       // this run's, added to the checkpoint's on resume
  std::string device = "cpu";      // "cpu", or the GPU's name
  std::string instruction_set;     // the CPU engine's, or "cuda"
  int threads = 0;                 // OpenMP threads, or the GPU's lanes (one realisation per thread)
};

// Writes the whole file atomically (temporary file, then rename).
void write_ensemble_file(const std::filesystem::path& file, const EnsemblePlan& plan, const EnsembleResults& results,
                         const RunInformation& run, const std::vector<LimitStateSummary>* limit_states);

// Reads the results of a checkpoint for `plan`; throws InputError when the file does not
// belong to this ensemble (another ensemble file, another size), cannot be read, or when its
// seal fails (a file cut short, flipped bits; hdf5::check_seal).
EnsembleResults read_ensemble_results(const std::filesystem::path& file, const EnsemblePlan& plan, double* wall_seconds);

// For `--resume`, before the plan is made (motions read, spectra computed): an InputError
// unless the file's seal holds, so that a damaged file is refused at once.
void check_result_file_seal(const std::filesystem::path& file);

// For `plot`: an InputError unless the file's seal holds and its realisations are whole.
void verify_ensemble_file(const std::filesystem::path& file);

}  // namespace caskdem
