#pragma once
// What `caskdem run` writes for a 3D case: the summary (printed, JSON and HDF5 attributes),
// the time histories (CSV and HDF5) and the plot's input. Layout in docs/output.md ("A 3D
// run"), read by src/plots/plot_run3d.py.

#include <filesystem>
#include <ostream>

#include "io/run_output.h"
#include "sim/case_run3d.h"

namespace caskdem {

void print_summary3d(std::ostream& out, const RunReport3D& report);
void write_summary_json3d(const std::filesystem::path& file, const RunReport3D& report);
std::string summary_json_text3d(const RunReport3D& report);               // summary.json's text
std::vector<HistoryColumn> history_columns3d(const RunReport3D& report);  // history.csv's columns
void write_history_csv3d(const std::filesystem::path& file, const RunReport3D& report);
void write_run_hdf5_3d(const std::filesystem::path& file, const RunReport3D& report);

}  // namespace caskdem
