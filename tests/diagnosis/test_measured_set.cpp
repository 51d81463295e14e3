// read_measured_set on small directories written by the tests: a usable directory splits
// into the held-out tests named in specimen.toml and the rest; each unusable directory is
// one InputError that names the file (and key or column) at fault and what was expected.
// A fault inside a test file is reported as that file's fault, before the count of files.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kSpecimen = synthetic_specimen_text();

// A smooth 2 s test at 100 Hz with the four required channels (or without `slide`).
std::string test_csv(bool with_slide = true) {
  std::string text = with_slide ? "t,table_acc,theta,slide\n" : "t,table_acc,theta\n";
  char line[128];
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.01 * k;
    if (with_slide) {
      std::snprintf(line, sizeof line, "%.2f,%.9g,%.9g,%.9g\n", t, std::sin(6.0 * t), 1e-3 * std::sin(4.0 * t + 0.2),
                    1e-4 * t * t);
    } else {
      std::snprintf(line, sizeof line, "%.2f,%.9g,%.9g\n", t, std::sin(6.0 * t), 1e-3 * std::sin(4.0 * t + 0.2));
    }
    text += line;
  }
  return text;
}

class MeasuredSetDirectory : public testing::TemporaryFiles {
 protected:
  std::string error_of() const {
    return testing::input_error_of([&] { read_measured_set(dir_); }, dir_.string());
  }
};

TEST_F(MeasuredSetDirectory, TestsSplitIntoTrainingAndTheNamedHeldOutTests) {
  write("specimen.toml", kSpecimen + "[diagnosis]\nheldout = [\"run_b\"]\n");
  for (const char* name : {"run_a.csv", "run_b.csv", "run_c.csv"}) write(name, test_csv());
  const MeasuredSet set = read_measured_set(dir_);
  ASSERT_EQ(set.tests.size(), 3u);
  EXPECT_EQ(set.tests[1].name, "run_b");
  EXPECT_THAT(set.training, ElementsAre(0, 2));
  EXPECT_THAT(set.heldout, ElementsAre(1));
  EXPECT_FALSE(set.vertical_measured);
}

// A table column in g read as SI is too weak for the rocking the cask shows (rocking needs
// g tan(alpha)): reported on each such test, naming the header that declares g; declared, the
// same numbers read as the SI ones.
TEST_F(MeasuredSetDirectory, ATableInGWithoutItsUnitIsReported) {
  write_synthetic_measured_set(dir_ / "si", SyntheticSpec{});
  fs::create_directories(dir_ / "g");
  fs::create_directories(dir_ / "declared");
  for (const auto& entry : fs::directory_iterator(dir_ / "si")) {
    const fs::path name = entry.path().filename();
    if (entry.path().extension() != ".csv") {
      fs::copy_file(entry.path(), dir_ / "g" / name);
      fs::copy_file(entry.path(), dir_ / "declared" / name);
      continue;
    }
    std::ifstream in(entry.path());
    std::ofstream g(dir_ / "g" / name), declared(dir_ / "declared" / name);
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      if (line.rfind("t,", 0) == 0) {
        g << line << "\n";
        declared << std::regex_replace(line, std::regex("table_acc(_v)?"), "table_acc$1 [g]") << "\n";
        continue;
      }
      // The table columns (the 2nd, and table_acc_v the 5th when present) divided by g.
      std::vector<std::string> fields;
      std::stringstream row(line);
      for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
      for (std::size_t c : {std::size_t(1), std::size_t(4)}) {
        if (c < fields.size()) {
          char text[40];
          std::snprintf(text, sizeof text, "%.17g", std::stod(fields[c]) / 9.80665);
          fields[c] = text;
        }
      }
      std::string joined;
      for (std::size_t c = 0; c < fields.size(); ++c) joined += (c ? "," : "") + fields[c];
      g << joined << "\n";
      declared << joined << "\n";
    }
  }
  const MeasuredSet si = read_measured_set(dir_ / "si"), g = read_measured_set(dir_ / "g"),
                    declared = read_measured_set(dir_ / "declared");
  int reported = 0;
  for (const MeasuredTest& test : g.tests) {
    for (const std::string& issue : test.issues) {
      if (issue.find("table_acc: peaks at") == std::string::npos) continue;
      EXPECT_THAT(issue, AllOf(HasSubstr("under half of g tan(alpha)"), HasSubstr("'table_acc [g]'")));
      ++reported;
    }
  }
  EXPECT_GE(reported, 4) << "the tests in which the cask rocked";
  for (std::size_t t = 0; t < si.tests.size(); ++t) {
    EXPECT_THAT(declared.tests[t].issues, ::testing::IsEmpty());
    for (std::size_t k = 0; k < si.tests[t].table_acceleration.size(); ++k)
      ASSERT_NEAR(declared.tests[t].table_acceleration[k], si.tests[t].table_acceleration[k], 1e-12);
  }
}

TEST_F(MeasuredSetDirectory, AMissingDirectoryIsAnError) {
  fs::remove_all(dir_);
  EXPECT_THAT(error_of(), AllOf(HasSubstr(dir_.string()), HasSubstr("not a directory"), HasSubstr("specimen.toml")));
}

TEST_F(MeasuredSetDirectory, AMissingSpecimenIsAnError) {
  write("run_a.csv", test_csv());
  write("run_b.csv", test_csv());
  EXPECT_THAT(error_of(), HasSubstr("specimen.toml"));
}

TEST_F(MeasuredSetDirectory, OneTestIsTooFew) {
  write("specimen.toml", kSpecimen);
  write("run_a.csv", test_csv());
  EXPECT_THAT(error_of(), AllOf(HasSubstr("found 1 test files"), HasSubstr("needs at least 2")));
}

TEST_F(MeasuredSetDirectory, AFaultInsideTheOnlyTestIsReportedBeforeTheCount) {
  write("specimen.toml", kSpecimen);
  write("run_a.csv", test_csv(false));
  EXPECT_THAT(error_of(), AllOf(HasSubstr("run_a.csv"), HasSubstr("missing required column 'slide'")));
}

TEST_F(MeasuredSetDirectory, AnUnknownHeldOutTestIsAnError) {
  write("specimen.toml", kSpecimen + "[diagnosis]\nheldout = [\"run_z\"]\n");
  write("run_a.csv", test_csv());
  write("run_b.csv", test_csv());
  EXPECT_THAT(error_of(), AllOf(HasSubstr("specimen.toml"), HasSubstr("diagnosis.heldout"), HasSubstr("\"run_z\"")));
}

TEST_F(MeasuredSetDirectory, EveryTestHeldOutLeavesNothingToFit) {
  write("specimen.toml", kSpecimen + "[diagnosis]\nheldout = [\"run_a\", \"run_b\"]\n");
  write("run_a.csv", test_csv());
  write("run_b.csv", test_csv());
  EXPECT_THAT(error_of(), AllOf(HasSubstr("specimen.toml"), HasSubstr("training"), HasSubstr("got 0 and 2")));
}

// A step beyond the explicit scheme's stability limit (dt = f_s 2 sqrt(m/k), stable below
// f_s of about 0.5 undamped, less with damping) is refused when the directory is read, naming
// specimen.toml, not minutes into a fit.
TEST_F(MeasuredSetDirectory, AnUnstableTimeStepIsRefusedWithTheSpecimen) {
  const std::string unstable = std::regex_replace(kSpecimen, std::regex("safety_factor = [0-9.]+"), "safety_factor = 1");
  ASSERT_NE(unstable, kSpecimen);
  write("specimen.toml", unstable);
  write("run_a.csv", test_csv());
  write("run_b.csv", test_csv());
  EXPECT_THAT(error_of(), AllOf(HasSubstr("specimen.toml"), HasSubstr("stability limit")));
}

// Each measured test lasts as long as its CSV: a duration in specimen.toml would go unused.
TEST_F(MeasuredSetDirectory, ADurationInTheSpecimenIsRefused) {
  write("specimen.toml", std::regex_replace(kSpecimen, std::regex("\\[integration\\]\n"), "[integration]\nduration = \"5 s\"\n"));
  write("run_a.csv", test_csv());
  write("run_b.csv", test_csv());
  EXPECT_THAT(error_of(), AllOf(HasSubstr("specimen.toml"), HasSubstr("integration.duration"), HasSubstr("not used")));
}

// A [diagnosis] setting outside its range: the line, the key it names, what was expected.
struct OutOfRangeSetting {
  const char* line;
  const char* key;
  const char* expected;
};

// How ctest and gtest name a case (else they print its bytes).
void PrintTo(const OutOfRangeSetting& c, std::ostream* os) { *os << c.line; }

class DiagnosisSettingOutOfRange : public MeasuredSetDirectory,
                                   public ::testing::WithParamInterface<OutOfRangeSetting> {};

TEST_P(DiagnosisSettingOutOfRange, IsNamedWithItsRange) {
  const OutOfRangeSetting c = GetParam();
  write("specimen.toml", kSpecimen + "[diagnosis]\n" + c.line + "\n");
  write("run_a.csv", test_csv());
  write("run_b.csv", test_csv());
  EXPECT_THAT(error_of(), AllOf(HasSubstr("specimen.toml"), HasSubstr(c.key), HasSubstr(c.expected)));
}

INSTANTIATE_TEST_SUITE_P(
    Settings, DiagnosisSettingOutOfRange,
    ::testing::Values(OutOfRangeSetting{"input_realisations = 0", "diagnosis.input_realisations", "expected 1 to 64"},
                      OutOfRangeSetting{"exploration = 8", "diagnosis.exploration", "expected 16 to 100000"}),
    [](const ::testing::TestParamInfo<OutOfRangeSetting>& info) {
      const std::string line = info.param.line;
      return line.substr(0, line.find(' '));
    });

}  // namespace
}  // namespace caskdem::diagnosis
