// Long runs never lose finished work: an ensemble killed (SIGKILL) in the middle leaves a
// valid HDF5 file with the mask of completed realisations, and `--resume` finishes it into
// the same results as an uninterrupted run; planar and 3D alike.

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/hdf5_file.h"
#include "support/command_line.h"
#include "support/temporary_files.h"

extern char** environ;

namespace caskdem {
namespace {

const std::string kEnsemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/resume.toml";

using testing::run_caskdem;
using Resume = testing::TemporaryFiles;

std::int64_t completed_in(const std::filesystem::path& file) {
  try {
    return hdf5::open_file(file).integer_attribute("completed");
  } catch (const std::exception&) {
    return -1;
  }
}

// Runs `ensemble`, kills a second run of it part-way, resumes that and compares the two files:
// every realisation's results (and `more` datasets) and the fitted limit states.
void killed_run_resumes(const std::string& ensemble, const std::filesystem::path& directory,
                        const std::vector<const char*>& more) {
  const std::string& kEnsemble = ensemble;
  const auto whole = directory / "whole.h5";
  const auto interrupted = directory / "interrupted.h5";
  ASSERT_EQ(run_caskdem("ensemble " + kEnsemble + " --out " + whole.string() + " --threads 2 --quiet --no-plot").status, 0);

  // Start the same run and kill it once some, but not all, realisations are done.
  std::vector<std::string> args = {CASKDEM_BINARY, "ensemble", kEnsemble, "--out", interrupted.string(),
                                   "--threads", "1", "--quiet", "--no-plot"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, CASKDEM_BINARY, nullptr, nullptr, argv.data(), environ), 0);
  const std::int64_t total = hdf5::open_file(whole).integer_attribute("realisations");
  std::int64_t seen = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    seen = completed_in(interrupted);
    if (seen >= total / 5) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be interrupted";

  // The file left behind is valid and partial.
  const std::int64_t left = completed_in(interrupted);
  ::testing::Test::RecordProperty("completed_when_killed", std::to_string(left) + " of " + std::to_string(total));
  ASSERT_GT(left, 0);
  ASSERT_LT(left, total);
  EXPECT_FALSE(hdf5::open_file(interrupted).has("limit_states"));

  const testing::Outcome resumed =
      run_caskdem("ensemble " + kEnsemble + " --out " + interrupted.string() + " --resume --threads 2 --no-plot");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_THAT(resumed.output, ::testing::HasSubstr(std::to_string(total - left) + " realisations in this run"));

  const hdf5::Group a = hdf5::open_file(whole);
  const hdf5::Group b = hdf5::open_file(interrupted);
  const hdf5::Group ra = a.open_group("realisations"), rb = b.open_group("realisations");
  for (const char* name : {"max_abs_rotation", "max_abs_slide", "residual_slide", "max_uplift", "end_time",
                           "tip_over_time", "instability_time", "friction_static", "scale_factor", "level"}) {
    EXPECT_EQ(ra.read_doubles(name), rb.read_doubles(name)) << name;
  }
  for (const char* name : more) EXPECT_EQ(ra.read_doubles(name), rb.read_doubles(name)) << name;
  for (const char* name : {"status", "impacts", "stripe", "motion"}) {
    EXPECT_EQ(ra.read_integers(name), rb.read_integers(name)) << name;
  }
  EXPECT_EQ(rb.read_bytes("completed"), std::vector<std::uint8_t>(total, 1));
  for (const char* state : {"tip_over", "rotation_ratio_0.3"}) {
    const hdf5::Group la = a.open_group("limit_states").open_group(state);
    const hdf5::Group lb = b.open_group("limit_states").open_group(state);
    EXPECT_EQ(la.integer_attribute("fitted"), lb.integer_attribute("fitted")) << state;
    EXPECT_EQ(la.read_integers("count"), lb.read_integers("count")) << state;
    if (la.integer_attribute("fitted")) {
      EXPECT_EQ(la.double_attribute("median"), lb.double_attribute("median")) << state;
      EXPECT_EQ(la.double_attribute("log_std"), lb.double_attribute("log_std")) << state;
      EXPECT_EQ(la.read_doubles("band_lower"), lb.read_doubles("band_lower")) << state;
      EXPECT_EQ(la.read_doubles("band_upper"), lb.read_doubles("band_upper")) << state;
    }
  }
}

TEST_F(Resume, KilledRunResumesToTheUninterruptedResult) { killed_run_resumes(kEnsemble, dir_, {}); }

// The 3D cask's realisations keep their incidences and spins through a kill and a resume.
TEST_F(Resume, Killed3DRunResumesToTheUninterruptedResult) {
  killed_run_resumes(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/resume-3d.toml", dir_,
                     {"incidence", "spin"});
}

TEST_F(Resume, RefusesAFileOfAnotherEnsemble) {
  const auto result = dir_ / "result.h5";
  const auto small = variant_of(kEnsemble, "small.toml", "realisations = 600", "realisations = 4");
  ASSERT_EQ(run_caskdem("ensemble " + small.string() + " --out " + result.string() + " --quiet --no-plot").status, 0);
  const testing::Outcome refused =
      run_caskdem("ensemble " + kEnsemble + " --out " + result.string() + " --resume --quiet --no-plot");
  EXPECT_EQ(refused.status, 2);
  EXPECT_THAT(refused.output, ::testing::HasSubstr("different ensemble"));
}

}  // namespace
}  // namespace caskdem
