#pragma once
// For tests that write files: a fresh directory per test (removed afterwards), and the
// message of the InputError that reading a bad file throws.

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"

namespace caskdem::testing {

// A fresh, empty directory that belongs to the running test alone, removed when this object
// goes. ctest runs every test in its own process and several at once, so a directory name two
// tests share lets one delete the other's files half-way; the test's full name and the
// process id make the name unique.
class TestDirectory {
 public:
  // `purpose` tells apart two directories of one test.
  explicit TestDirectory(const std::string& purpose = "") {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "caskdem_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                       std::to_string(::getpid()) + (purpose.empty() ? "" : "_" + purpose);
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests' names hold '/'
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TestDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TestDirectory(const TestDirectory&) = delete;
  TestDirectory& operator=(const TestDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// The whole file as text (empty when it cannot be read).
inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A fixture for tests that write small input files into their own directory.
class TemporaryFiles : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = directory_.path(); }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  // The file `source` with its first `find` replaced by `replace`, written here as `name`.
  std::filesystem::path variant_of(const std::filesystem::path& source, const std::string& name,
                                   const std::string& find, const std::string& replace) const {
    std::string text = file_text(source);
    const auto at = text.find(find);
    EXPECT_NE(at, std::string::npos) << source << " has no \"" << find << "\"";
    if (at != std::string::npos) text.replace(at, find.size(), replace);
    return write(name, text);
  }

  TestDirectory directory_;
  std::filesystem::path dir_;
};

// The message of the InputError that `read` throws; a test failure naming `what` when none is.
template <class Read>
std::string input_error_of(Read&& read, const std::string& what) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << what;
  return {};
}

}  // namespace caskdem::testing
