// What `--resume` and `plot` trust is checked before HDF5 reads it: a result file cut short
// or with flipped bits is refused with one message and exit status 2, never a crash, a hang
// (a damaged global heap made HDF5 loop) or a silently wrong result; and a checkpoint that
// cannot be written whole (a file-size limit standing in for a full disk) leaves the previous
// file byte for byte, with no temporary file behind.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;
using testing::Outcome;
using ResultIntegrity = testing::TemporaryFiles;

const std::string kEnsemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml";

std::vector<char> bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::filesystem::path& file, const std::vector<char>& bytes) {
  std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// `timeout` makes a hang a failure of this test rather than a stalled test run.
Outcome caskdem_within_a_minute(const std::string& arguments) {
  return testing::run_shell("timeout 60 " + std::string(CASKDEM_BINARY) + " " + arguments);
}

TEST_F(ResultIntegrity, ADamagedResultFileIsRefusedByResumeAndPlot) {
  const auto whole = dir_ / "whole.h5";
  ASSERT_EQ(caskdem_within_a_minute("ensemble " + kEnsemble + " --out " + whole.string() + " --threads 1 --quiet --no-plot")
                .status,
            0);
  const std::vector<char> intact = bytes_of(whole);
  ASSERT_GT(intact.size(), 4096u);

  // Cuts at 16 places and single bit flips at 16 (deterministic: every part of the file, from
  // the seal through HDF5's superblock, heaps and datasets to the last byte).
  std::vector<std::vector<char>> damaged;
  for (int k = 0; k < 16; ++k) {
    const std::size_t at = intact.size() * static_cast<std::size_t>(k) / 16;
    damaged.emplace_back(intact.begin(), intact.begin() + static_cast<std::ptrdiff_t>(at));
    std::vector<char> flipped = intact;
    const std::size_t bit = (intact.size() * 8 * static_cast<std::size_t>(2 * k + 1)) / 32;
    flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
    damaged.push_back(std::move(flipped));
  }
  const auto file = dir_ / "damaged.h5";
  for (std::size_t d = 0; d < damaged.size(); ++d) {
    write_bytes(file, damaged[d]);
    const Outcome plot = caskdem_within_a_minute("plot " + file.string() + " --out " + (dir_ / "p.png").string());
    EXPECT_EQ(plot.status, 2) << "damage " << d << ": " << plot.output;
    EXPECT_THAT(plot.output, HasSubstr(file.string() + ": ")) << d;
    EXPECT_EQ(std::count(plot.output.begin(), plot.output.end(), '\n'), 1) << "one message: " << plot.output;

    write_bytes(file, damaged[d]);
    const Outcome resume = caskdem_within_a_minute("ensemble " + kEnsemble + " --out " + file.string() +
                                                   " --resume --threads 1 --quiet --no-plot");
    EXPECT_EQ(resume.status, 2) << "damage " << d << ": " << resume.output;
    EXPECT_THAT(resume.output, HasSubstr(file.string() + ": ")) << d;
    EXPECT_EQ(bytes_of(file), damaged[d]) << "a refused file is left as it was: " << d;
  }

  // The intact file still resumes and plots.
  write_bytes(file, intact);
  EXPECT_EQ(caskdem_within_a_minute("plot " + file.string() + " --out " + (dir_ / "p.png").string()).status, 0);
  EXPECT_EQ(caskdem_within_a_minute("ensemble " + kEnsemble + " --out " + file.string() +
                                    " --resume --threads 1 --quiet --no-plot")
                .status,
            0);
}

TEST_F(ResultIntegrity, ACheckpointThatCannotBeWrittenWholeLeavesThePreviousOne) {
  const auto file = dir_ / "results.h5";
  ASSERT_EQ(caskdem_within_a_minute("ensemble " + kEnsemble + " --out " + file.string() + " --threads 1 --quiet --no-plot")
                .status,
            0);
  const std::vector<char> before = bytes_of(file);
  // A file-size limit below the file's size: every write of the new file fails part-way.
  const std::size_t limit_blocks = before.size() / 2 / 1024;
  const Outcome o = testing::run_shell("ulimit -f " + std::to_string(limit_blocks) + "; timeout 60 " +
                                       std::string(CASKDEM_BINARY) + " ensemble " + kEnsemble + " --out " +
                                       file.string() + " --resume --threads 1 --quiet --no-plot");
  EXPECT_NE(o.status, 0) << o.output;
  EXPECT_NE(o.status, -1) << "a message and an exit status, not a signal: " << o.output;
  EXPECT_THAT(o.output, HasSubstr("cannot be written whole"));
  EXPECT_THAT(o.output, HasSubstr(file.string() + " is left as it was"));
  EXPECT_EQ(bytes_of(file), before);
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    EXPECT_THAT(entry.path().filename().string(), ::testing::Not(HasSubstr(".partial"))) << "no temporary left";
  }
}

}  // namespace
}  // namespace caskdem
