// The README's tour runs as written (label tour, in the full gate: it takes a few minutes): with
// `caskdem` on the PATH as scripts/main.sh leaves it and the main job's result in results/, every
// command line of the tour's code block, in order, from the repository, exits with status 0.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

namespace fs = std::filesystem;

// The command lines of the README's tour, comments stripped.
std::vector<std::string> tour_lines() {
  std::ifstream in(fs::path(CASKDEM_SOURCE_DIR) / "README.md");
  std::vector<std::string> lines;
  bool in_tour = false, in_block = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## A tour of the commands", 0) == 0) in_tour = true;
    if (!in_tour) continue;
    if (line.rfind("```", 0) == 0) {
      if (in_block) break;
      in_block = true;
      continue;
    }
    if (!in_block) continue;
    const auto comment = line.find("  #");
    if (comment != std::string::npos) line.erase(comment);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

TEST(Tour, EveryCommandRunsAsWritten) {
  const std::vector<std::string> lines = tour_lines();
  ASSERT_GE(lines.size(), 15u) << "the tour's code block was not found in README.md";
  // caskdem on the PATH, as scripts/main.sh puts it there; the main job's result in results/.
  testing::TestDirectory bin("bin");
  fs::create_symlink(CASKDEM_BINARY, bin / "caskdem");
  const std::string environment = "cd " + std::string(CASKDEM_SOURCE_DIR) + " && PATH=" + bin.path().string() + ":$PATH ";
  const testing::Outcome main_job = testing::run_shell(
      environment + "caskdem ensemble ensembles/model-1-3-builtin.toml --out results/model-1-3-builtin.h5 --quiet");
  ASSERT_EQ(main_job.status, 0) << main_job.output;
  for (const std::string& line : lines) {
#ifndef CASKDEM_WITH_MPI
    if (line.rfind("mpirun", 0) == 0) {
      std::printf("not run (this build has no MPI): %s\n", line.c_str());
      continue;
    }
#endif
    const testing::Outcome o = testing::run_shell(environment + line);
    EXPECT_EQ(o.status, 0) << line << "\n" << o.output;
    std::printf("ran: %s\n", line.c_str());
  }
  // The diagnosis' and the plan's histories state their units, as every HDF5 file does (the
  // others are checked in tests/casefile/test_output_formats.cpp).
  for (const char* file : {"diagnosis/histories.h5", "diagnosis/plan-histories.h5", "plan/plan-histories.h5"}) {
    const testing::Outcome units = testing::run_shell(
        "/usr/bin/python3 -c \"import h5py; missing = []; "
        "h5py.File('" +
        std::string(CASKDEM_SOURCE_DIR) + "/results/measured/" + file +
        "', 'r').visititems("
        "lambda n, i: missing.append(n) if isinstance(i, h5py.Dataset) and i.dtype.kind in 'fiub' and 'units' not in "
        "i.attrs else None); print('without units:', missing)\"");
    EXPECT_NE(units.output.find("without units: []"), std::string::npos) << file << "\n" << units.output;
  }
}

}  // namespace
}  // namespace caskdem
