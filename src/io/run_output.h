#pragma once
// What `caskdem run` writes: the time history (CSV and HDF5), the summary (printed, JSON
// and HDF5 attributes) and the plot. The HDF5 layout is documented in docs/output.md
// and read by src/plots/plot_run.py.

#include <filesystem>
#include <ostream>
#include <string>

#include "casefile/case_file.h"
#include "io/hdf5_file.h"
#include "model/build.h"
#include "sim/simulate.h"

namespace caskdem {

struct RunReport {
  const Case* source = nullptr;
  Model model;
  ModelFacts facts;
  RunResult result;
  double wall_seconds = 0.0;
};

void print_summary(std::ostream& out, const RunReport& report);
void write_history_csv(const std::filesystem::path& file, const RunReport& report);
void write_summary_json(const std::filesystem::path& file, const RunReport& report);
void write_run_hdf5(const std::filesystem::path& file, const RunReport& report);

// A run file's root attributes, planar or 3D alike: the version, the case file, its text and
// title (when there is a case), and the wall time.
void write_run_attributes(hdf5::Group& root, const Case* source, double wall_seconds);

// Runs a plotting script from src/plots with Debian's python3 (matplotlib and h5py);
// throws std::runtime_error with the script's output when it fails.
void run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace caskdem
