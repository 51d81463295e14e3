// Past one machine: the same ensemble run as one process and as 2 and 3 MPI ranks
// (mpirun, oversubscribed on this 2-core machine) gives the same file: every realisation's
// results and the fitted fragility, bit for bit. A rank killed mid-run ends the job and
// leaves a resumable file, and --resume under MPI completes it to the same results.

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "io/hdf5_file.h"
#include "support/command_line.h"
#include "support/temporary_files.h"

extern char** environ;

namespace caskdem {
namespace {

const std::string kEnsemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mpi.toml";
// Open MPI refuses to run as root unless told; CI runs as root. --bind-to none lets three
// ranks share two cores.
const std::string kMpirun = std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") + CASKDEM_MPIEXEC +
                            " --oversubscribe --bind-to none";

using testing::run_shell;

// A rank of the job writing `output`: a process whose program is caskdem (not mpirun, not a
// shell) and whose arguments name the output file.
pid_t find_rank(const std::string& output) {
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "cmdline");
    std::string argument;
    std::vector<std::string> argv;
    while (std::getline(in, argument, '\0')) argv.push_back(argument);
    if (argv.empty() || argv[0] != CASKDEM_BINARY) continue;
    if (std::find(argv.begin(), argv.end(), output) != argv.end()) return static_cast<pid_t>(std::stol(name));
  }
  return 0;
}

void expect_same_results(const std::filesystem::path& a_file, const std::filesystem::path& b_file) {
  const hdf5::Group a = hdf5::open_file(a_file), b = hdf5::open_file(b_file);
  const hdf5::Group ra = a.open_group("realisations"), rb = b.open_group("realisations");
  for (const char* name : {"max_abs_rotation", "max_abs_slide", "residual_slide", "max_uplift", "end_time",
                           "tip_over_time", "instability_time", "friction_static", "scale_factor"}) {
    EXPECT_EQ(ra.read_doubles(name), rb.read_doubles(name)) << name;
  }
  for (const char* name : {"status", "impacts", "stripe", "motion"}) EXPECT_EQ(ra.read_integers(name), rb.read_integers(name)) << name;
  EXPECT_EQ(ra.read_bytes("completed"), rb.read_bytes("completed"));
  for (const char* state : {"tip_over", "rotation_ratio_0.3"}) {
    const hdf5::Group la = a.open_group("limit_states").open_group(state);
    const hdf5::Group lb = b.open_group("limit_states").open_group(state);
    EXPECT_EQ(la.read_integers("count"), lb.read_integers("count")) << state;
    ASSERT_EQ(la.integer_attribute("fitted"), lb.integer_attribute("fitted")) << state;
    if (la.integer_attribute("fitted")) {
      EXPECT_EQ(la.double_attribute("median"), lb.double_attribute("median")) << state;
      EXPECT_EQ(la.double_attribute("log_std"), lb.double_attribute("log_std")) << state;
      EXPECT_EQ(la.read_doubles("band_upper"), lb.read_doubles("band_upper")) << state;
    }
  }
}

TEST(Mpi, TwoAndThreeRanksGiveTheSingleProcessFile) {
  const testing::TestDirectory directory;
  const auto single = directory / "single.h5";
  ASSERT_EQ(run_shell(std::string(CASKDEM_BINARY) + " ensemble " + kEnsemble + " --out " + single.string() +
                      " --threads 2 --quiet --no-plot")
                .status,
            0);
  for (int ranks : {2, 3}) {
    const auto distributed = directory / ("ranks" + std::to_string(ranks) + ".h5");
    const testing::Outcome run = run_shell(kMpirun + " -n " + std::to_string(ranks) + " " + CASKDEM_BINARY +
                                           " ensemble " + kEnsemble + " --out " + distributed.string() +
                                           " --threads 1 --quiet --no-plot");
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find(std::to_string(ranks) + " ranks"), std::string::npos) << run.output;
    expect_same_results(single, distributed);
  }
}

// The 3D lanes too: each rank's realisations, with their incidences and spins, as one process's.
TEST(Mpi, TwoRanksGiveTheSingleProcess3DFile) {
  const testing::TestDirectory directory;
  const std::string ensemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mpi-3d.toml";
  const auto single = directory / "single3d.h5", distributed = directory / "ranks3d.h5";
  ASSERT_EQ(run_shell(std::string(CASKDEM_BINARY) + " ensemble " + ensemble + " --out " + single.string() +
                      " --threads 2 --quiet --no-plot")
                .status,
            0);
  const testing::Outcome run = run_shell(kMpirun + " -n 2 " + CASKDEM_BINARY + " ensemble " + ensemble + " --out " +
                                         distributed.string() + " --threads 1 --quiet --no-plot");
  ASSERT_EQ(run.status, 0) << run.output;
  expect_same_results(single, distributed);
  const hdf5::Group a = hdf5::open_file(single).open_group("realisations");
  const hdf5::Group b = hdf5::open_file(distributed).open_group("realisations");
  for (const char* name : {"incidence", "spin"}) EXPECT_EQ(a.read_doubles(name), b.read_doubles(name)) << name;
  EXPECT_EQ(hdf5::open_file(single).integer_attribute("dimensions"), 3);
}

TEST(Mpi, KilledRankLeavesAResumableFile) {
  const testing::TestDirectory directory;
  const auto single = directory / "single-for-resume.h5";
  ASSERT_EQ(run_shell(std::string(CASKDEM_BINARY) + " ensemble " + std::string(CASKDEM_SOURCE_DIR) +
                      "/tests/ensemble/data/resume.toml --out " + single.string() + " --threads 2 --quiet --no-plot")
                .status,
            0);
  const auto file = directory / "killed.h5";
  // A longer ensemble than the comparison's, so that there is time to kill a rank. Start a
  // 2-rank job and kill one of its ranks (a caskdem process newer than mpirun) once the file
  // shows completed work.
  const std::string ensemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/resume.toml";
  const std::string job = kMpirun + " -n 2 " + CASKDEM_BINARY + " ensemble " + ensemble + " --out " + file.string() +
                          " --threads 1 --quiet --no-plot >/dev/null 2>&1";
  std::string shell_path = "/bin/sh", flag = "-c", command = job;
  char* argv[] = {shell_path.data(), flag.data(), command.data(), nullptr};
  pid_t launcher = 0;
  ASSERT_EQ(posix_spawn(&launcher, "/bin/sh", nullptr, nullptr, argv, environ), 0);
  bool killed = false, finished = false;
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline && !finished) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    finished = ::waitpid(launcher, &status, WNOHANG) == launcher;
    if (killed || finished) continue;
    std::int64_t completed = -1;
    try {
      completed = hdf5::open_file(file).integer_attribute("completed");
    } catch (const std::exception&) {
    }
    if (completed > 0) {
      const pid_t rank = find_rank(file.string());
      killed = rank > 0 && ::kill(rank, SIGKILL) == 0;
    }
  }
  if (!finished) ::waitpid(launcher, &status, 0);
  ASSERT_TRUE(killed) << "the job finished before a rank could be killed";
  EXPECT_NE(WEXITSTATUS(status), 0) << "the job must fail when a rank dies";

  const std::int64_t left = hdf5::open_file(file).integer_attribute("completed");
  const std::int64_t total = hdf5::open_file(file).integer_attribute("realisations");
  RecordProperty("completed_when_killed", std::to_string(left) + " of " + std::to_string(total));
  EXPECT_LT(left, total);
  const testing::Outcome resumed = run_shell(kMpirun + " -n 2 " + CASKDEM_BINARY + " ensemble " + ensemble +
                                             " --out " + file.string() + " --resume --threads 1 --quiet --no-plot");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(single, file);
}

}  // namespace
}  // namespace caskdem
