// What a user reads in Python: the files the commands write open with the libraries' defaults
// (Debian's python3-pandas, -numpy and -h5py under /usr/bin/python3, as the plots run), and
// every numeric HDF5 dataset states its unit.
//
//   - a run's history.csv (planar and 3D), an ensemble's fragility CSV: pandas.read_csv and
//     numpy.genfromtxt(names=True) take the first line for the header, its names as written;
//   - a run's HDF5, an ensemble's result file with its /risk group: every numeric dataset has a
//     `units` attribute (text datasets, the motions' names, none).

#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;
using testing::run_caskdem;
using testing::run_shell;

class OutputFormats : public testing::TemporaryFiles {
 protected:
  // The shipped 3D case for one second, its records found from here.
  std::filesystem::path short_3d_case() const {
    std::string text = testing::file_text(std::string(CASKDEM_SOURCE_DIR) + "/cases/model-1-3-kobe-3d.toml");
    for (std::size_t at = text.find("../../shared"); at != std::string::npos; at = text.find("../../shared"))
      text.replace(at, 12, CASKDEM_SHARED_DIR);
    return write("kobe.toml", text + "\n[integration]\nduration = \"1 s\"\n");
  }
  // Runs a Python snippet (argv[1] the file) under the interpreter the plots use; its output.
  testing::Outcome python(const std::string& code, const std::filesystem::path& file) const {
    const auto script = write("check.py", code);
    return run_shell("/usr/bin/python3 " + script.string() + " " + file.string());
  }
};

constexpr const char* kReadTable = R"(import sys
import numpy as np
import pandas as pd
frame = pd.read_csv(sys.argv[1])
array = np.genfromtxt(sys.argv[1], delimiter=",", names=True, dtype=None, encoding=None)
print("pandas", frame.columns[0], len(frame))
print("numpy", array.dtype.names[0], len(array))
print("same names", list(frame.columns) == list(array.dtype.names))
)";

constexpr const char* kUnits = R"(import sys
import h5py
missing = []
def visit(name, item):
    if isinstance(item, h5py.Dataset) and item.dtype.kind in "fiub" and "units" not in item.attrs:
        missing.append(name)
with h5py.File(sys.argv[1], "r") as f:
    f.visititems(visit)
print("without units:", missing)
)";

TEST_F(OutputFormats, HistoriesAndFragilityTablesOpenWithPandasAndNumpyDefaults) {
  const std::string source = CASKDEM_SOURCE_DIR;
  const auto planar = dir_ / "planar", spatial = dir_ / "spatial";
  ASSERT_EQ(run_caskdem("run " + source + "/cases/default-pulse.toml --out " + planar.string() + " --no-plot").status, 0);
  const testing::Outcome run3d = run_caskdem("run " + short_3d_case().string() + " --out " + spatial.string() + " --no-plot");
  ASSERT_EQ(run3d.status, 0) << run3d.output;
  for (const auto& history : {planar / "history.csv", spatial / "history.csv"}) {
    const testing::Outcome read = python(kReadTable, history);
    ASSERT_EQ(read.status, 0) << read.output;
    EXPECT_THAT(read.output, HasSubstr("pandas time_s")) << history;
    EXPECT_THAT(read.output, HasSubstr("numpy time_s")) << history;
    EXPECT_THAT(read.output, HasSubstr("same names True")) << history;
  }
  const auto ensemble = variant_of(source + "/tests/ensemble/data/mixed-outcomes.toml", "small.toml",
                                   "realisations = 64", "realisations = 8");
  const auto result = dir_ / "small.h5";
  ASSERT_EQ(run_caskdem("ensemble " + ensemble.string() + " --out " + result.string() + " --quiet --no-plot").status, 0);
  const testing::Outcome table = python(kReadTable, dir_ / "small-fragility.csv");
  ASSERT_EQ(table.status, 0) << table.output;
  EXPECT_THAT(table.output, HasSubstr("pandas limit_state"));
  EXPECT_THAT(table.output, HasSubstr("same names True"));
}

TEST_F(OutputFormats, EveryNumericHdf5DatasetStatesItsUnit) {
  const std::string source = CASKDEM_SOURCE_DIR;
  const auto planar = dir_ / "planar", spatial = dir_ / "spatial";
  ASSERT_EQ(run_caskdem("run " + source + "/cases/default-pulse.toml --out " + planar.string() + " --no-plot").status, 0);
  ASSERT_EQ(run_caskdem("run " + short_3d_case().string() + " --out " + spatial.string() + " --no-plot").status, 0);
  // The main job's ensemble, small, with its risk written into it.
  const auto ensemble = variant_of(source + "/ensembles/model-1-3-builtin.toml", "small.toml", "realisations = 80",
                                   "realisations = 8");
  const auto result = dir_ / "small.h5";
  ASSERT_EQ(run_caskdem("ensemble " + ensemble.string() + " --out " + result.string() + " --quiet --no-plot").status, 0);
  const testing::Outcome risk =
      run_caskdem("risk " + result.string() + " --hazard " + source + "/hazard/example-site-pgv.csv --no-plot");
  ASSERT_EQ(risk.status, 0) << risk.output;
  for (const auto& file : {planar / "run.h5", spatial / "run.h5", result}) {
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const testing::Outcome units = python(kUnits, file);
    ASSERT_EQ(units.status, 0) << units.output;
    EXPECT_THAT(units.output, HasSubstr("without units: []")) << file;
  }
}

// The recipe of docs/output.md ("Reading them in Python") runs as written, in a directory whose
// results/ holds what the main job and the El Centro case write there.
TEST_F(OutputFormats, TheDocsPythonRecipeRuns) {
  const std::string source = CASKDEM_SOURCE_DIR;
  const std::string docs = testing::file_text(source + "/docs/output.md");
  const auto start = docs.find("```python", docs.find("## Reading them in Python"));
  ASSERT_NE(start, std::string::npos) << "no recipe in docs/output.md";
  const auto body = docs.find('\n', start) + 1;
  const std::string recipe = docs.substr(body, docs.find("```", body) - body);
  const auto results = dir_ / "results";
  ASSERT_EQ(run_caskdem("run " + source + "/cases/model-1-3-elcentro-400gal.toml --no-plot --out " +
                        (results / "model-1-3-elcentro-400gal").string())
                .status,
            0);
  const auto ensemble = variant_of(source + "/ensembles/model-1-3-builtin.toml", "model-1-3-builtin.toml",
                                   "realisations = 80", "realisations = 16");
  ASSERT_EQ(run_caskdem("ensemble " + ensemble.string() + " --quiet --no-plot --out " +
                        (results / "model-1-3-builtin.h5").string())
                .status,
            0);
  const auto script = write("recipe.py", recipe);
  const testing::Outcome ran = run_shell("cd " + dir_.string() + " && /usr/bin/python3 " + script.string());
  EXPECT_EQ(ran.status, 0) << recipe << "\n" << ran.output;
}

}  // namespace
}  // namespace caskdem
