#pragma once
// What `caskdem run` writes: the time history (CSV and HDF5), the summary (printed, JSON
// and HDF5 attributes) and the plot. The HDF5 layout is documented in docs/output.md
// and read by src/plots/plot_run.py.

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

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

// A history column as the CSV names it (its unit in its name: "rotation_rad"), its unit, and
// its samples.
struct HistoryColumn {
  std::string name;
  std::string unit;
  std::vector<double> values;
};

void print_summary(std::ostream& out, const RunReport& report);
// What summary.json holds, as text (JSON), for the file and for the Python module alike.
std::string summary_json_text(const RunReport& report);
// The columns of history.csv, in its order.
std::vector<HistoryColumn> history_columns(const RunReport& report);
// A CSV file of the columns: a header of their names, one row per sample, no comment line.
void write_columns_csv(const std::filesystem::path& file, const std::vector<HistoryColumn>& columns);
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
