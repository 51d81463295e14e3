// read_measured_test against small CSV files written by the tests: clean files must read
// exactly (every value, the step, all masks 1, no issues) whatever the column order,
// separator, byte-order mark, line ends or comments; each imperfection must be repaired or
// masked as measured_test.h says, with one issue line; and each unusable file must be an
// InputError naming the file, the line or channel, and what was expected.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "diagnosis/measured_test.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::Each;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::Not;
using ::testing::SizeIs;

// ---- a smooth test with no imperfection ----------------------------------------------------
// Smooth and free of flat extremes, so nothing in it looks clipped or constant.

double table_of(double t) { return 0.1 + std::sin(3.0 * t); }
double vertical_of(double t) { return 0.3 * std::cos(5.0 * t); }
double theta_of(double t) { return 0.01 * std::sin(2.0 * t + 0.3); }
double slide_of(double t) { return 0.001 * t * t; }
double theta_dot_of(double t) { return 0.02 * std::cos(2.0 * t + 0.3); }

// Seventeen significant digits: the value read back is the same double.
std::string exact(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// One column of a file: its header name and its field on each row (row k at time t).
struct Column {
  std::string name;
  std::function<std::string(std::size_t k, double t)> field;
};

Column column_of(const std::string& name, double (*value)(double)) {
  return {name, [value](std::size_t, double t) { return exact(value(t)); }};
}

Column time_column() { return column_of("t", [](double t) { return t; }); }

// The column with the fields of some rows replaced (missing values, bad text, ...).
Column with_fields(Column column, std::map<std::size_t, std::string> replaced) {
  auto field = column.field;
  column.field = [field, replaced](std::size_t k, double t) {
    const auto it = replaced.find(k);
    return it == replaced.end() ? field(k, t) : it->second;
  };
  return column;
}

std::vector<Column> clean_columns() {
  return {time_column(),
          column_of("table_acc", table_of),
          column_of("theta", theta_of),
          column_of("slide", slide_of),
          column_of("theta_dot", theta_dot_of),
          column_of("table_acc_v", vertical_of)};
}

// The four required channels only.
std::vector<Column> required_columns() {
  auto columns = clean_columns();
  columns.resize(4);
  return columns;
}

// Replaces the column named `name`.
std::vector<Column> replacing(std::vector<Column> columns, const Column& column) {
  for (Column& c : columns)
    if (c.name == column.name) c = column;
  return columns;
}

std::vector<double> uniform_times(std::size_t n, double step, double start = 0.0) {
  std::vector<double> t;
  for (std::size_t k = 0; k < n; ++k) t.push_back(start + static_cast<double>(k) * step);
  return t;
}

// A header and one row per time; the header is line 1, row k is line k + 2.
std::string csv_text(const std::vector<Column>& columns, const std::vector<double>& times,
                     const std::string& separator = ",", const std::string& line_end = "\n") {
  std::string text;
  for (std::size_t c = 0; c < columns.size(); ++c) text += (c ? separator : "") + columns[c].name;
  text += line_end;
  for (std::size_t k = 0; k < times.size(); ++k) {
    for (std::size_t c = 0; c < columns.size(); ++c) text += (c ? separator : "") + columns[c].field(k, times[k]);
    text += line_end;
  }
  return text;
}

// 1/64 s: every time k * step is exact, so times and values can be compared exactly.
constexpr double exact_step = 1.0 / 64.0;
constexpr std::size_t rows = 40;

class MeasuredTestFiles : public testing::TemporaryFiles {
 protected:
  static std::string error_of(const fs::path& file) {
    return testing::input_error_of([&] { read_measured_test(file); }, file.string());
  }
};

// Every channel of the clean test, exactly, with nothing masked or reported.
void expect_clean(const MeasuredTest& test, std::size_t n, double step) {
  EXPECT_THAT(test.issues, IsEmpty());
  EXPECT_EQ(test.time_step, step);
  ASSERT_THAT(test.time, SizeIs(n));
  ASSERT_THAT(test.table_acceleration, SizeIs(n));
  ASSERT_THAT(test.rotation, SizeIs(n));
  ASSERT_THAT(test.slide, SizeIs(n));
  ASSERT_TRUE(test.has_angular_velocity);
  ASSERT_TRUE(test.has_vertical);
  ASSERT_THAT(test.angular_velocity, SizeIs(n));
  ASSERT_THAT(test.vertical_table_acceleration, SizeIs(n));
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * step;
    EXPECT_EQ(test.time[k], t);
    EXPECT_EQ(test.table_acceleration[k], table_of(t));
    EXPECT_EQ(test.rotation[k], theta_of(t));
    EXPECT_EQ(test.slide[k], slide_of(t));
    EXPECT_EQ(test.angular_velocity[k], theta_dot_of(t));
    EXPECT_EQ(test.vertical_table_acceleration[k], vertical_of(t));
  }
  EXPECT_THAT(test.rotation_valid, AllOf(SizeIs(n), Each(1)));
  EXPECT_THAT(test.slide_valid, AllOf(SizeIs(n), Each(1)));
  EXPECT_THAT(test.angular_velocity_valid, AllOf(SizeIs(n), Each(1)));
}

// ---- clean files ---------------------------------------------------------------------------

TEST_F(MeasuredTestFiles, ACleanFileReadsExactly) {
  const auto file = write("run1.csv", csv_text(clean_columns(), uniform_times(rows, exact_step)));
  const MeasuredTest test = read_measured_test(file);
  EXPECT_EQ(test.name, "run1");
  EXPECT_EQ(test.file, file);
  expect_clean(test, rows, exact_step);
  EXPECT_DOUBLE_EQ(test.duration(), (rows - 1) * exact_step);
}

TEST_F(MeasuredTestFiles, TheColumnOrderDoesNotMatter) {
  const auto c = clean_columns();  // t, table_acc, theta, slide, theta_dot, table_acc_v
  const std::vector<Column> permuted{c[3], c[5], c[2], c[0], c[4], c[1]};
  expect_clean(read_measured_test(write("permuted.csv", csv_text(permuted, uniform_times(rows, exact_step)))), rows,
               exact_step);
}

TEST_F(MeasuredTestFiles, AByteOrderMarkCrlfLineEndsAndCommentsAreAccepted) {
  std::string text = csv_text(clean_columns(), uniform_times(rows, exact_step), ",", "\r\n");
  // Comments before the header and among the rows, and a blank line.
  text.insert(text.find("\r\n0.015625") + 2, "# the shaker warmed up here\r\n\r\n");
  text = "\xEF\xBB\xBF# shaking-table run 1\r\n  # units SI\r\n" + text + "# end\r\n";
  expect_clean(read_measured_test(write("bom.csv", text)), rows, exact_step);
}

TEST_F(MeasuredTestFiles, SemicolonAndTabSeparatorsAreAccepted) {
  for (const std::string separator : {";", "\t"}) {
    SCOPED_TRACE("separator '" + separator + "'");
    const auto file = write("separated.csv", csv_text(clean_columns(), uniform_times(rows, exact_step), separator));
    expect_clean(read_measured_test(file), rows, exact_step);
  }
}

// A header may declare a column's unit after its name; the values are read into SI.
TEST_F(MeasuredTestFiles, DeclaredUnitsAreReadIntoSi) {
  const double g = 9.80665, degree = std::numbers::pi / 180.0;
  const std::vector<Column> columns = {
      column_of("t [ms]", [](double t) { return 1000.0 * t; }),
      column_of("table_acc [g]", [](double t) { return table_of(t) / 9.80665; }),
      column_of("theta (deg)", [](double t) { return theta_of(t) / (std::numbers::pi / 180.0); }),
      column_of("slide [mm]", [](double t) { return 1000.0 * slide_of(t); })};
  const MeasuredTest test = read_measured_test(write("units.csv", csv_text(columns, uniform_times(rows, exact_step))));
  EXPECT_THAT(test.issues, IsEmpty());
  EXPECT_TRUE(test.table_unit_declared);
  EXPECT_NEAR(test.time_step, exact_step, 1e-15);
  for (std::size_t k = 0; k < rows; ++k) {
    const double t = static_cast<double>(k) * exact_step;
    EXPECT_NEAR(test.table_acceleration[k], table_of(t), 1e-12 * g);
    EXPECT_NEAR(test.rotation[k], theta_of(t), 1e-14 * degree);
    EXPECT_NEAR(test.slide[k], slide_of(t), 1e-15);
  }
}

TEST_F(MeasuredTestFiles, AnUnknownUnitIsRefusedAtTheHeader) {
  auto columns = required_columns();
  columns[1].name = "table_acc [furlong/s^2]";
  const auto file = write("furlong.csv", csv_text(columns, uniform_times(rows, exact_step)));
  EXPECT_THAT(error_of(file), AllOf(HasSubstr(file.string() + ":1:"), HasSubstr("the unit 'furlong/s^2' of the column "
                                                                                "'table_acc'; expected one of m/s^2")));
}

// Undeclared columns read as SI that no cask on a table shows in SI, but would in mm or degrees,
// are reported with the header that declares them; the values are kept as read.
TEST_F(MeasuredTestFiles, SiColumnsThatLookLikeOtherUnitsAreReported) {
  auto columns = replacing(required_columns(), column_of("slide", [](double t) { return 1000.0 * slide_of(t) + 2.0; }));
  const MeasuredTest mm = read_measured_test(write("mm.csv", csv_text(columns, uniform_times(rows, exact_step))));
  EXPECT_THAT(mm.issues, ElementsAre(AllOf(HasSubstr("mm.csv: slide: peaks at"), HasSubstr("'slide [mm]'"))));
  columns = replacing(required_columns(), column_of("theta", [](double t) { return 3.0 * std::sin(t) + 2.0; }));
  const MeasuredTest degrees = read_measured_test(write("deg.csv", csv_text(columns, uniform_times(rows, exact_step))));
  EXPECT_THAT(degrees.issues, ElementsAre(AllOf(HasSubstr("deg.csv: theta: peaks at"), HasSubstr("'theta [deg]'"))));
}

TEST_F(MeasuredTestFiles, TheFirstTimeBecomesZero) {
  // Times 2.5 + k/64 are exact too; the values belong to the file's times.
  const double start = 2.5;
  const auto test = read_measured_test(write("late.csv", csv_text(clean_columns(), uniform_times(rows, exact_step, start))));
  EXPECT_THAT(test.issues, IsEmpty());
  ASSERT_THAT(test.time, SizeIs(rows));
  for (std::size_t k = 0; k < rows; ++k) {
    EXPECT_EQ(test.time[k], static_cast<double>(k) * exact_step);
    EXPECT_EQ(test.rotation[k], theta_of(start + static_cast<double>(k) * exact_step));
  }
}

TEST_F(MeasuredTestFiles, DecimalTimesAreUniformSampling) {
  // Times written "0.01", "0.02", ...: their differences vary by rounding alone, far inside
  // the 1e-6 tolerance, so nothing is resampled. Each time below 0.5 s is within half an ulp
  // (2.8e-17 s) of its decimal, so every step, and the median, is within 1e-16 s of 0.01 s.
  Column decimal_time{"t", [](std::size_t k, double) {
                        char text[32];
                        std::snprintf(text, sizeof text, "%.2f", static_cast<double>(k) * 0.01);
                        return std::string(text);
                      }};
  const auto test = read_measured_test(write("decimal.csv", csv_text(replacing(clean_columns(), decimal_time),
                                                                     uniform_times(rows, 0.01))));
  EXPECT_THAT(test.issues, IsEmpty());
  EXPECT_NEAR(test.time_step, 0.01, 1e-16);
  EXPECT_THAT(test.rotation_valid, Each(1));
}

TEST_F(MeasuredTestFiles, OptionalColumnsMayBeAbsent) {
  const auto test = read_measured_test(write("required.csv", csv_text(required_columns(), uniform_times(rows, exact_step))));
  EXPECT_THAT(test.issues, IsEmpty());
  EXPECT_FALSE(test.has_angular_velocity);
  EXPECT_FALSE(test.has_vertical);
  EXPECT_THAT(test.angular_velocity, IsEmpty());
  EXPECT_THAT(test.angular_velocity_valid, IsEmpty());
  EXPECT_THAT(test.vertical_table_acceleration, IsEmpty());
  EXPECT_THAT(test.rotation_valid, AllOf(SizeIs(rows), Each(1)));
}

TEST_F(MeasuredTestFiles, AnUnknownColumnIsIgnoredWithAnIssue) {
  auto columns = clean_columns();
  columns.insert(columns.begin() + 2, Column{"operator_note", [](std::size_t, double) { return std::string("ok"); }});
  const auto test = read_measured_test(write("noted.csv", csv_text(columns, uniform_times(rows, exact_step))));
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("noted.csv"), HasSubstr("operator_note"), HasSubstr("column 3"),
                                    HasSubstr("ignored"), Not(HasSubstr("did you mean"))));
  auto rest = test;
  rest.issues.clear();
  expect_clean(rest, rows, exact_step);
}

TEST_F(MeasuredTestFiles, AMisspeltOptionalColumnIsNamedWithTheChannelItMeant) {
  // An optional channel misspelt would be ignored without a word about it: the issue names
  // the absent channel the column is two edits from.
  auto columns = required_columns();
  columns.push_back(Column{"Theta_Dott", [](std::size_t, double) { return std::string("0.1"); }});
  const auto test = read_measured_test(write("misspelt.csv", csv_text(columns, uniform_times(rows, exact_step))));
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("Theta_Dott"), HasSubstr("column 5"), HasSubstr("ignored"),
                                    HasSubstr("did you mean 'theta_dot'?")));
  EXPECT_FALSE(test.has_angular_velocity);
}

// ---- resampling ----------------------------------------------------------------------------

TEST_F(MeasuredTestFiles, IrregularSamplingIsResampledByLinearInterpolation) {
  // Steps of 0.01 s but rows 12 to 14 late by 0.004 s: steps 0.014, 0.01, 0.01, 0.006. Every
  // channel is linear in t, which linear interpolation reproduces to rounding. theta is
  // missing on row 13, so the grid samples at 0.13 s (between rows 12 and 13) and 0.14 s
  // (between rows 13 and 14) are missing, and no other.
  const double start = 0.3, step = 0.01;
  const std::size_t n = 40;
  std::vector<double> times = uniform_times(n, step, start);
  for (std::size_t k = 12; k <= 14; ++k) times[k] += 0.004;
  const auto linear = [](double a, double b) { return [a, b](double t) { return a + b * t; }; };
  const auto table = linear(2.0, 3.0), theta = linear(0.01, -0.02), slide = linear(-0.001, 0.004);
  const std::vector<Column> columns{
      time_column(),
      {"table_acc", [&](std::size_t, double t) { return exact(table(t)); }},
      with_fields({"theta", [&](std::size_t, double t) { return exact(theta(t)); }}, {{13, "nan"}}),
      {"slide", [&](std::size_t, double t) { return exact(slide(t)); }},
  };
  const auto test = read_measured_test(write("jittery.csv", csv_text(columns, times)));

  EXPECT_NEAR(test.time_step, step, 1e-15);  // the median step, from decimal times
  ASSERT_THAT(test.time, SizeIs(n));
  // Rounding only: times and values of order 1, slopes of order 1.
  constexpr double rounding = 1e-14;
  for (std::size_t k = 0; k < n; ++k) {
    const double file_time = start + test.time[k];
    EXPECT_EQ(test.time[k], static_cast<double>(k) * test.time_step);
    EXPECT_NEAR(test.table_acceleration[k], table(file_time), rounding) << k;
    EXPECT_NEAR(test.slide[k], slide(file_time), rounding) << k;
    if (k == 13 || k == 14) {
      EXPECT_EQ(test.rotation_valid[k], 0) << k;
      EXPECT_TRUE(std::isnan(test.rotation[k])) << k;
    } else {
      EXPECT_EQ(test.rotation_valid[k], 1) << k;
      EXPECT_NEAR(test.rotation[k], theta(file_time), rounding) << k;
    }
  }
  ASSERT_THAT(test.issues, SizeIs(2));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("jittery.csv: t:"), HasSubstr("irregular"), HasSubstr("from 0.006 s"),
                                    HasSubstr("to 0.014 s"), HasSubstr("lines 13 and 14"),
                                    HasSubstr("resampled onto t = k * 0.01 s")));
  EXPECT_THAT(test.issues[1], AllOf(HasSubstr("jittery.csv: theta:"), HasSubstr("2 missing samples"),
                                    HasSubstr("t = 0.13 s"), HasSubstr("masked")));
}

// ---- gaps ----------------------------------------------------------------------------------

TEST_F(MeasuredTestFiles, AGapInThetaIsMasked) {
  const auto columns = replacing(clean_columns(), with_fields(column_of("theta", theta_of), {{7, "nan"}, {8, "NaN"}, {9, ""}}));
  const auto test = read_measured_test(write("gappy.csv", csv_text(columns, uniform_times(rows, exact_step))));
  ASSERT_THAT(test.issues, SizeIs(1));
  // Row 7 is t = 7/64 = 0.109375 s, on line 9.
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("gappy.csv: theta:"), HasSubstr("3 missing samples"), HasSubstr("1 gap"),
                                    HasSubstr("t = 0.109375 s"), HasSubstr("line 9"), HasSubstr("masked")));
  for (std::size_t k = 0; k < rows; ++k) {
    const bool in_gap = k >= 7 && k <= 9;
    EXPECT_EQ(test.rotation_valid[k], in_gap ? 0 : 1) << k;
    if (in_gap)
      EXPECT_TRUE(std::isnan(test.rotation[k])) << k;
    else
      EXPECT_EQ(test.rotation[k], theta_of(static_cast<double>(k) * exact_step)) << k;
  }
  EXPECT_THAT(test.slide_valid, Each(1));
}

TEST_F(MeasuredTestFiles, ShortGapsInTheTableAreBridged) {
  // A linear table acceleration (which bridging reproduces to rounding); 5 samples missing
  // inside (5 * 0.01 s, the longest bridged) and 2 at the start (held at the first value).
  const double step = 0.01;
  const auto table = [](double t) { return 1.0 + 2.0 * t; };
  const Column gappy = with_fields({"table_acc", [&](std::size_t, double t) { return exact(table(t)); }},
                                   {{0, ""}, {1, "nan"}, {10, ""}, {11, ""}, {12, "nan"}, {13, ""}, {14, ""}});
  const auto test = read_measured_test(write("bridged.csv", csv_text(replacing(required_columns(), gappy),
                                                                     uniform_times(rows, step))));
  ASSERT_THAT(test.table_acceleration, SizeIs(rows));
  EXPECT_EQ(test.table_acceleration[0], table(2 * step));
  EXPECT_EQ(test.table_acceleration[1], table(2 * step));
  for (std::size_t k = 2; k < rows; ++k)
    EXPECT_NEAR(test.table_acceleration[k], table(static_cast<double>(k) * step), 1e-14) << k;
  ASSERT_THAT(test.issues, SizeIs(2));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("bridged.csv: table_acc:"), HasSubstr("2 missing samples"),
                                    HasSubstr("at the start"), HasSubstr("held")));
  EXPECT_THAT(test.issues[1], AllOf(HasSubstr("bridged.csv: table_acc:"), HasSubstr("5 missing samples in 1 gap"),
                                    HasSubstr("the longest 0.05 s"),
                                    HasSubstr("bridged by linear interpolation"), HasSubstr("t = 0.1 s")));
}

TEST_F(MeasuredTestFiles, AShortGapAtTheEndOfTheVerticalTableIsHeld) {
  const Column gappy = with_fields(column_of("table_acc_v", vertical_of), {{rows - 1, "nan"}});
  const auto test = read_measured_test(write("tail.csv", csv_text(replacing(clean_columns(), gappy),
                                                                  uniform_times(rows, exact_step))));
  ASSERT_TRUE(test.has_vertical);
  EXPECT_EQ(test.vertical_table_acceleration[rows - 1], vertical_of((rows - 2) * exact_step));
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("tail.csv: table_acc_v:"), HasSubstr("to the end"), HasSubstr("held")));
}

TEST_F(MeasuredTestFiles, ALongGapInTheTableIsAnError) {
  // 6 samples of 0.01 s: 0.06 s, longer than the 0.05 s bridged. Row 10 is on line 12.
  const Column gappy = with_fields(column_of("table_acc", table_of),
                                   {{10, ""}, {11, ""}, {12, ""}, {13, ""}, {14, ""}, {15, ""}});
  const auto file = write("holey.csv", csv_text(replacing(clean_columns(), gappy), uniform_times(rows, 0.01)));
  EXPECT_THAT(error_of(file), AllOf(HasSubstr("holey.csv:12:"), HasSubstr("table_acc:"), HasSubstr("6 missing samples"),
                                    HasSubstr("t = 0.1 s"), HasSubstr("expected"), HasSubstr("no longer than 0.05 s")));
}

TEST_F(MeasuredTestFiles, ALongGapAtTheStartOfTheTableIsAnError) {
  std::map<std::size_t, std::string> missing;
  for (std::size_t k = 0; k < 8; ++k) missing[k] = "nan";
  const auto file = write("late_start.csv", csv_text(replacing(clean_columns(), with_fields(column_of("table_acc", table_of), missing)),
                                                     uniform_times(rows, 0.01)));
  EXPECT_THAT(error_of(file), AllOf(HasSubstr("late_start.csv:2:"), HasSubstr("table_acc:"),
                                    HasSubstr("8 missing samples"), HasSubstr("t = 0 s"), HasSubstr("expected")));
}

TEST_F(MeasuredTestFiles, AnOptionalColumnWithNoValuesIsNotUsed) {
  const auto empty = [](std::size_t, double) { return std::string(); };
  auto columns = replacing(clean_columns(), Column{"theta_dot", empty});
  columns = replacing(columns, Column{"table_acc_v", empty});
  const auto test = read_measured_test(write("empty.csv", csv_text(columns, uniform_times(rows, exact_step))));
  EXPECT_FALSE(test.has_angular_velocity);
  EXPECT_FALSE(test.has_vertical);
  EXPECT_THAT(test.issues, ElementsAre(AllOf(HasSubstr("empty.csv: table_acc_v:"), HasSubstr("no values")),
                                       AllOf(HasSubstr("empty.csv: theta_dot:"), HasSubstr("no values"))));
}

// ---- clipped and dead sensors --------------------------------------------------------------

// theta = 0.01 sin(2 pi t) cut at 0.008 rad: flat runs at the top of both peaks in 2 s.
constexpr double clip_level = 0.008;
double clipped_theta(double t) { return std::min(0.01 * std::sin(2.0 * std::numbers::pi * t), clip_level); }

TEST_F(MeasuredTestFiles, ClippedThetaIsMasked) {
  const std::size_t n = 200;
  const auto test = read_measured_test(write("clipped.csv", csv_text(replacing(clean_columns(), column_of("theta", clipped_theta)),
                                                                     uniform_times(n, 0.01))));
  std::size_t clipped = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const bool at_clip = test.rotation[k] == clip_level;
    clipped += at_clip;
    EXPECT_EQ(test.rotation_valid[k], at_clip ? 0 : 1) << k;
  }
  EXPECT_GE(clipped, 2 * 3u);  // two runs of at least three samples
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("clipped.csv: theta:"), HasSubstr("clipped at its maximum, 0.008 rad"),
                                    HasSubstr(std::to_string(clipped) + " samples in 2 runs"), HasSubstr("masked")));
}

TEST_F(MeasuredTestFiles, AClippedTableIsReportedButKept) {
  const std::size_t n = 200;
  const auto table = [](double t) { return std::max(3.0 * std::sin(2.0 * std::numbers::pi * t), -2.5); };
  const Column clipped{"table_acc", [&](std::size_t, double t) { return exact(table(t)); }};
  const auto test = read_measured_test(write("table_clipped.csv", csv_text(replacing(clean_columns(), clipped),
                                                                         uniform_times(n, 0.01))));
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(test.table_acceleration[k], table(static_cast<double>(k) * 0.01)) << k;
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("table_clipped.csv: table_acc:"), HasSubstr("minimum, -2.5 m/s^2"),
                                    HasSubstr("simulations will see the clipped input")));
}

TEST_F(MeasuredTestFiles, AConstantSlideIsMasked) {
  const Column dead{"slide", [](std::size_t, double) { return std::string("0.05"); }};
  const auto test = read_measured_test(write("dead.csv", csv_text(replacing(clean_columns(), dead), uniform_times(rows, exact_step))));
  EXPECT_THAT(test.slide_valid, AllOf(SizeIs(rows), Each(0)));
  EXPECT_THAT(test.rotation_valid, Each(1));
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], AllOf(HasSubstr("dead.csv: slide:"), HasSubstr("constant (sensor dead?): not used"),
                                    HasSubstr("0.05 m")));
}

TEST_F(MeasuredTestFiles, AConstantTableIsAnError) {
  const Column still{"table_acc", [](std::size_t, double) { return std::string("0"); }};
  const auto file = write("still.csv", csv_text(replacing(clean_columns(), still), uniform_times(rows, exact_step)));
  EXPECT_THAT(error_of(file), AllOf(HasSubstr("still.csv"), HasSubstr("table_acc:"), HasSubstr("constant"),
                                    HasSubstr("expected a varying table acceleration")));
}

// ---- unusable files ------------------------------------------------------------------------

TEST_F(MeasuredTestFiles, AMissingColumnIsAnErrorListingTheColumnsFound) {
  auto columns = required_columns();
  columns.erase(columns.begin() + 3);  // slide
  const auto file = write("no_slide.csv", "# run 4\n" + csv_text(columns, uniform_times(rows, exact_step)));
  EXPECT_THAT(error_of(file), AllOf(HasSubstr("no_slide.csv:2:"), HasSubstr("missing required column 'slide'"),
                                    HasSubstr("found the columns 't', 'table_acc', 'theta'"), HasSubstr("expected")));
}

TEST_F(MeasuredTestFiles, ARowWithTheWrongNumberOfFieldsIsAnError) {
  std::string text = csv_text(required_columns(), uniform_times(rows, exact_step));
  // Drop the last field of row 5 (line 7).
  std::size_t at = 0;
  for (int line = 1; line < 7; ++line) at = text.find('\n', at) + 1;
  const std::size_t end = text.find('\n', at);
  text.erase(text.rfind(',', end), end - text.rfind(',', end));
  EXPECT_THAT(error_of(write("short_row.csv", text)),
              AllOf(HasSubstr("short_row.csv:7:"), HasSubstr("found 3 fields"), HasSubstr("expected 4")));
}

TEST_F(MeasuredTestFiles, ANonNumericValueIsAnError) {
  const auto columns = replacing(required_columns(), with_fields(column_of("theta", theta_of), {{6, "0.01rad"}}));
  EXPECT_THAT(error_of(write("text.csv", csv_text(columns, uniform_times(rows, exact_step)))),
              AllOf(HasSubstr("text.csv:8:"), HasSubstr("'0.01rad'"), HasSubstr("theta"), HasSubstr("expected a number")));
}

TEST_F(MeasuredTestFiles, DecreasingTimeIsAnError) {
  auto times = uniform_times(rows, exact_step);
  times[20] = times[18];  // row 20, line 22
  EXPECT_THAT(error_of(write("backwards.csv", csv_text(required_columns(), times))),
              AllOf(HasSubstr("backwards.csv:22:"), HasSubstr("t = 0.28125 s"), HasSubstr("line 21"),
                    HasSubstr("expected strictly increasing times")));
}

TEST_F(MeasuredTestFiles, AMissingTimeIsAnError) {
  const auto columns = replacing(required_columns(), with_fields(time_column(), {{3, "nan"}}));
  EXPECT_THAT(error_of(write("timeless.csv", csv_text(columns, uniform_times(rows, exact_step)))),
              AllOf(HasSubstr("timeless.csv:5:"), HasSubstr("missing"), HasSubstr("expected a time")));
}

TEST_F(MeasuredTestFiles, TooFewRowsIsAnError) {
  EXPECT_THAT(error_of(write("tiny.csv", csv_text(required_columns(), uniform_times(9, exact_step)))),
              AllOf(HasSubstr("tiny.csv"), HasSubstr("found 9 data rows"), HasSubstr("expected at least 10")));
}

TEST_F(MeasuredTestFiles, AValueNoCaskOnATableCouldShowIsAnError) {
  // Finite but absurd: a field in other units or corrupt (1e300 would overflow the squares of
  // the error measures). Row 6 is line 8.
  const auto columns = replacing(required_columns(), with_fields(column_of("table_acc", table_of), {{6, "1e300"}}));
  EXPECT_THAT(error_of(write("huge.csv", csv_text(columns, uniform_times(rows, exact_step)))),
              AllOf(HasSubstr("huge.csv:8:"), HasSubstr("'1e300'"), HasSubstr("table_acc"),
                    HasSubstr("expected at most 1000 m/s^2")));
  const auto degrees = replacing(required_columns(), with_fields(column_of("theta", theta_of), {{3, "12.5"}}));
  EXPECT_THAT(error_of(write("degrees.csv", csv_text(degrees, uniform_times(rows, exact_step)))),
              AllOf(HasSubstr("degrees.csv:5:"), HasSubstr("'12.5'"), HasSubstr("theta"),
                    HasSubstr("expected at most 2 pi rad")));
}

TEST_F(MeasuredTestFiles, ASamplingStepBelowAMicrosecondIsAnError) {
  EXPECT_THAT(error_of(write("fast.csv", csv_text(required_columns(), uniform_times(rows, 1e-9)))),
              AllOf(HasSubstr("fast.csv"), HasSubstr("t:"), HasSubstr("median sampling step is 1e-09 s"),
                    HasSubstr("expected at least 1e-06 s")));
}

// A time column in milliseconds read as seconds, or a corrupt one, is refused (as records are),
// not taken as a test sampled once a second.
TEST_F(MeasuredTestFiles, ASamplingStepAboveATenthOfASecondIsAnError) {
  EXPECT_THAT(error_of(write("slow.csv", csv_text(required_columns(), uniform_times(rows, 1.0)))),
              AllOf(HasSubstr("slow.csv"), HasSubstr("t:"), HasSubstr("median sampling step is 1 s"),
                    HasSubstr("expected at most 0.1 s")));
}

TEST_F(MeasuredTestFiles, AJumpInTimeIsAGapInTheTable) {
  // Rows 20 on are 1 s late: resampling would invent the table motion across that second.
  auto times = uniform_times(rows, 0.01);
  for (std::size_t k = 20; k < rows; ++k) times[k] += 1.0;
  EXPECT_THAT(error_of(write("jump.csv", csv_text(required_columns(), times))),
              AllOf(HasSubstr("jump.csv:22:"), HasSubstr("t jumps from 0.19 s (line 21) to 1.2 s"),
                    HasSubstr("a gap of 1 s"), HasSubstr("expected gaps of at most 0.05 s")));
  // A late row within the bridged gap is irregular sampling, resampled (as above).
  times = uniform_times(rows, 0.01);
  for (std::size_t k = 20; k < rows; ++k) times[k] += 0.04;
  const auto test = read_measured_test(write("late.csv", csv_text(required_columns(), times)));
  ASSERT_THAT(test.issues, SizeIs(1));
  EXPECT_THAT(test.issues[0], HasSubstr("irregular sampling"));
}

TEST_F(MeasuredTestFiles, NoUsableResponseChannelIsAnError) {
  const Column dead_theta{"theta", [](std::size_t, double) { return std::string("0.001"); }};
  const Column empty_slide{"slide", [](std::size_t, double) { return std::string(); }};
  const auto columns = replacing(replacing(required_columns(), dead_theta), empty_slide);
  EXPECT_THAT(error_of(write("blind.csv", csv_text(columns, uniform_times(rows, exact_step)))),
              AllOf(HasSubstr("blind.csv"), HasSubstr("neither theta nor slide has a usable sample"),
                    HasSubstr("expected at least one response channel")));
}

TEST_F(MeasuredTestFiles, AnEmptyFileIsAnError) {
  EXPECT_THAT(error_of(write("blank.csv", "# nothing yet\n\n")),
              AllOf(HasSubstr("blank.csv"), HasSubstr("no header row"), HasSubstr("expected a header row")));
}

}  // namespace
}  // namespace caskdem::diagnosis
