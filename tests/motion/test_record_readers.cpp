// Record readers against the shared records' README table (dt, npts, PGA as published by
// the data's sources) and against malformed files, whose errors must name the file, the line
// and what was expected.

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/units.h"
#include "motion/record.h"
#include "support/temporary_files.h"

namespace caskdem::motion {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const fs::path motions_dir = fs::path(CASKDEM_SHARED_DIR) / "motions";

// ---- the shared records -----------------------------------------------------------------

struct SharedRecord {
  const char* file;
  bool needs_unit;  // column files do not state their unit (all these are in g)
  double dt;        // s, README
  std::size_t npts;  // README
  double pga_g;     // README, 3 significant digits
};

// The README's table, copied by hand.
const SharedRecord shared_records[] = {
    {"elcentro1940_ns_RSN6.AT2", false, 0.01, 5372, 0.281},
    {"elcentro1940_ns_IELC180_oldpeer.AT2", false, 0.01, 4000, 0.313},
    {"taft1952_RSN15.AT2", false, 0.01, 5435, 0.159},
    {"kobe1995_takatori090.csv", true, 0.01, 4015, 0.616},
    {"chichi1999_tcu068_090.csv", true, 0.005, 13102, 0.566},
    {"northridge1994_vsp360.csv", true, 0.005, 9327, 0.934},
    {"northridge1994_castaic090.dat", true, 0.01, 3989, 0.568},
};

void PrintTo(const SharedRecord& record, std::ostream* out) { *out << record.file; }

class SharedRecords : public ::testing::TestWithParam<SharedRecord> {};

TEST_P(SharedRecords, ReadWithTheirPublishedStepLengthAndPga) {
  const SharedRecord& expected = GetParam();
  ReadOptions options;
  if (expected.needs_unit) options.unit = AccelerationUnit::g;
  const Record record = read_record(motions_dir / expected.file, options);
  EXPECT_EQ(record.acceleration.size(), expected.npts);
  // Time columns are printed with at most 4 decimals of dt = 0.01 or 0.005: their mean step
  // is the nominal one to rounding of the decimal times (~1e-15 s).
  EXPECT_NEAR(record.time_step, expected.dt, 1e-12);
  // The README's PGA has 3 significant digits: rounding alone is up to 0.0005 / 0.159 = 0.3 %.
  const double pga_g = units::si_to_g(peak_ground_acceleration(record));
  EXPECT_NEAR(pga_g, expected.pga_g, 0.005 * expected.pga_g);
  for (const double a : record.acceleration) ASSERT_TRUE(std::isfinite(a));
}

INSTANTIATE_TEST_SUITE_P(Motions, SharedRecords, ::testing::ValuesIn(shared_records),
                         [](const ::testing::TestParamInfo<SharedRecord>& info) {
                           std::string name = fs::path(info.param.file).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(SharedRecords, FirstAndLastValuesAreTheFilesInSi) {
  // Values copied from the files by eye, converted with standard gravity.
  const Record nga = read_record(motions_dir / "elcentro1940_ns_RSN6.AT2");
  EXPECT_DOUBLE_EQ(nga.acceleration.front(), 0.9984852e-3 * 9.80665);
  EXPECT_DOUBLE_EQ(nga.acceleration.back(), -0.1790158e-3 * 9.80665);

  const Record old = read_record(motions_dir / "elcentro1940_ns_IELC180_oldpeer.AT2");
  EXPECT_DOUBLE_EQ(old.acceleration.front(), -0.6403182e-2 * 9.80665);

  ReadOptions g;
  g.unit = AccelerationUnit::g;
  const Record bom = read_record(motions_dir / "northridge1994_vsp360.csv", g);
  EXPECT_DOUBLE_EQ(bom.acceleration.front(), 3.40e-4 * 9.80665);
  EXPECT_DOUBLE_EQ(bom.acceleration.back(), -9.62e-4 * 9.80665);

  const Record dat = read_record(motions_dir / "northridge1994_castaic090.dat", g);
  EXPECT_DOUBLE_EQ(dat.acceleration.front(), -0.0012 * 9.80665);
  EXPECT_DOUBLE_EQ(dat.acceleration.back(), -0.0001 * 9.80665);
}

TEST(SharedRecords, AnAt2GivenAUnitOtherThanGIsAnError) {
  ReadOptions gal;
  gal.unit = AccelerationUnit::gal;
  const fs::path file = motions_dir / "taft1952_RSN15.AT2";
  try {
    read_record(file, gal);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("taft1952_RSN15.AT2"), HasSubstr("gal"), HasSubstr("expected unit g")));
  }
}

// ---- small files written by the tests -----------------------------------------------------

class MotionFiles : public testing::TemporaryFiles {
 protected:
  static std::string error_of(const fs::path& file, const ReadOptions& options) {
    return testing::input_error_of([&] { read_record(file, options); }, file.string());
  }
  static ReadOptions in_g() {
    ReadOptions options;
    options.unit = AccelerationUnit::g;
    return options;
  }
};

const std::string at2_header =
    "PEER NGA STRONG MOTION DATABASE RECORD\n"
    "Test, 1/1/2000, Station, 000\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n";

TEST_F(MotionFiles, MissingFile) {
  const std::string message = error_of(dir_ / "no_such_record.AT2", {});
  EXPECT_THAT(message, AllOf(HasSubstr("no_such_record.AT2"), HasSubstr("no such file"), HasSubstr("expected")));
}

TEST_F(MotionFiles, ADirectoryIsNotARecord) {
  EXPECT_THAT(error_of(dir_, {}), AllOf(HasSubstr(dir_.string()), HasSubstr("directory"), HasSubstr("expected")));
}

// Neither a FIFO (opening it would wait for a writer) nor a device (/dev/zero reads without
// end) is read: both are refused before they are opened.
TEST_F(MotionFiles, ADeviceOrAFifoIsRefusedBeforeItIsOpened) {
  EXPECT_THAT(error_of("/dev/zero", in_g()),
              AllOf(HasSubstr("/dev/zero: is not a regular file"), HasSubstr("expected an acceleration record file")));
  const fs::path fifo = dir_ / "record.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(error_of(fifo, in_g()), HasSubstr(fifo.string() + ": is not a regular file"));
}

// A step in another unit (`DT= 1000 SEC`, a time column in ms) or a record of hours is
// refused on the line the step comes from, not run as a 2,000 s record of three samples.
TEST_F(MotionFiles, ATimeStepAboveATenthOfASecondOrARecordOfHoursIsRefused) {
  const auto at2 = write("slow.AT2", at2_header + "NPTS=     3, DT=  1000 SEC\n  .1E-01  .2E-01  .3E-01\n");
  EXPECT_THAT(error_of(at2, {}), AllOf(HasSubstr("slow.AT2:4:"), HasSubstr("the time step is 1000 s"),
                                        HasSubstr("expected at most 0.1 s")));
  const auto milliseconds = write("ms.csv", "t,a\n0,0.1\n10,0.2\n20,0.1\n");
  EXPECT_THAT(error_of(milliseconds, in_g()), AllOf(HasSubstr("ms.csv:2:"), HasSubstr("the time step is 10 s")));
  std::string zeros;
  for (int k = 0; k < 100'002; ++k) zeros += "0\n";
  ReadOptions tenth = in_g();
  tenth.time_step = 0.1;
  EXPECT_THAT(error_of(write("hours.txt", zeros), tenth),
              AllOf(HasSubstr("hours.txt:1:"), HasSubstr("the record lasts 10000.1 s"), HasSubstr("expected at most 10000 s")));
}

TEST_F(MotionFiles, NonNumericValueInTheData) {
  const auto file = write("bad_value.csv", "# comment\nt,a\n0.00,0.1\n0.01,0.2\n0.02,abc\n0.03,0.1\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("bad_value.csv:5:"), HasSubstr("'abc'"), HasSubstr("expected 2 numbers")));
}

TEST_F(MotionFiles, WrongColumnCount) {
  const auto file = write("columns.txt", "0.00 0.1\n0.01 0.2\n0.02 0.3 0.4\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("columns.txt:3:"), HasSubstr("found 3 values"), HasSubstr("expected 2")));
}

TEST_F(MotionFiles, ThreeColumnsFromTheStart) {
  const auto file = write("three.txt", "time a b\n0.00 0.1 0.2\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("three.txt:2:"), HasSubstr("3 values"), HasSubstr("expected 2 columns")));
}

TEST_F(MotionFiles, At2WithFewerValuesThanNpts) {
  const auto file = write("short.AT2", at2_header + "NPTS=     6, DT=   .0100 SEC\n  .1E-01  .2E-01  .3E-01\n  .4E-01  .5E-01\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("short.AT2:4:"), HasSubstr("found 5 values"), HasSubstr("expected exactly NPTS = 6")));
}

TEST_F(MotionFiles, At2WithMoreValuesThanNpts) {
  const auto file = write("long.AT2", at2_header + "NPTS=     2, DT=   .0100 SEC\n  .1E-01  .2E-01\n  .3E-01\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("long.AT2:6:"), HasSubstr("more values than NPTS"), HasSubstr("expected exactly NPTS = 2")));
}

TEST_F(MotionFiles, At2WithNegativeDt) {
  const auto file = write("negative_dt.AT2", at2_header + "NPTS=     2, DT=  -.0100 SEC\n  .1E-01  .2E-01\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("negative_dt.AT2:4:"), HasSubstr("-.0100"), HasSubstr("expected a positive time step")));
}

TEST_F(MotionFiles, At2WithNonNumericValue) {
  const auto file = write("word.AT2", at2_header + "NPTS=     3, DT=   .0100 SEC\n  .1E-01\n  .2E-01 x.3\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("word.AT2:6:"), HasSubstr("'x.3'"), HasSubstr("expected numbers")));
}

TEST_F(MotionFiles, At2OfVelocityIsRejected) {
  const auto file = write("vel.VT2", "PEER\nTest\nVELOCITY TIME SERIES IN UNITS OF CM/S\nNPTS=     1, DT=   .0100 SEC\n .1\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("vel.VT2:3:"), HasSubstr("CM/S"), HasSubstr("expected an acceleration record")));
}

TEST_F(MotionFiles, OldStyleNptsLineAndContentDetection) {
  // An AT2 under another extension is recognised by its NPTS line; values may be D-exponent.
  const auto file = write("old_style.txt", "PEER\nTest\nACCELERATION IN G\n   3    0.02000    NPTS, DT\n .1D+00 -.2E+00\n .3\n");
  const Record record = read_record(file);
  ASSERT_EQ(record.acceleration.size(), 3u);
  EXPECT_DOUBLE_EQ(record.time_step, 0.02);
  EXPECT_DOUBLE_EQ(record.acceleration[0], units::g_to_si(0.1));
  EXPECT_DOUBLE_EQ(record.acceleration[1], units::g_to_si(-0.2));
  EXPECT_DOUBLE_EQ(record.acceleration[2], units::g_to_si(0.3));
}

TEST_F(MotionFiles, ColumnsUnderAnAt2NameNeedAUnit) {
  const auto file = write("columns.AT2", "0 1\n0.5 2\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("columns.AT2"), HasSubstr("unit"), HasSubstr("expected the unit to be given")));
}

TEST_F(MotionFiles, ExplicitPeerFormatOnAColumnFile) {
  const auto file = write("not_peer.csv", "a\nb\nc\n0,1\n");
  ReadOptions options;
  options.format = RecordFormat::peer_old;
  EXPECT_THAT(error_of(file, options), AllOf(HasSubstr("not_peer.csv:4:"), HasSubstr("'0,1'"), HasSubstr("expected the PEER header line")));
}

TEST_F(MotionFiles, IrregularTimeColumn) {
  const auto file = write("irregular.csv", "t,a\n0.00,0.1\n0.01,0.2\n0.02,0.3\n0.04,0.4\n0.05,0.5\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("irregular.csv:5:"), HasSubstr("0.02 s"), HasSubstr("expected uniform sampling")));
}

TEST_F(MotionFiles, MissingSampleIsFoundWhereItIs) {
  // One missing sample in 1000 moves the mean step by 0.1 %: the error must point at the gap,
  // not at the first line that differs from the mean.
  std::string text;
  for (int k = 0; k <= 1000; ++k)
    if (k != 700) text += std::to_string(k * 0.01) + "\t0.5\n";
  const auto file = write("gap.txt", text);
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("gap.txt:701:"), HasSubstr("expected uniform sampling")));
}

TEST_F(MotionFiles, DecreasingTime) {
  const auto file = write("backwards.csv", "0.02,1\n0.01,1\n0.00,1\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("backwards.csv:2:"), HasSubstr("expected increasing")));
}

TEST_F(MotionFiles, NanValue) {
  const auto file = write("nan.csv", "t,a\n0.00,0.1\n0.01,nan\n0.02,0.3\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("nan.csv:3:"), HasSubstr("nan"), HasSubstr("expected finite")));
}

TEST_F(MotionFiles, NanValueInAt2) {
  const auto file = write("nan.AT2", at2_header + "NPTS=     2, DT=   .0100 SEC\n  .1E-01  NaN\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("nan.AT2:5:"), HasSubstr("NaN"), HasSubstr("expected finite")));
}

// A sample no ground motion can have (a value in another unit, or a corrupt field) is refused
// where it is read, before a unit conversion or a scaling overflows: the file, the line, the
// value as written and the bound are named. Each reader has its own case.
TEST_F(MotionFiles, At2NgaWest2SampleBeyondTheLargestAcceleration) {
  const auto file = write("huge.AT2", at2_header + "NPTS=     3, DT=   .0100 SEC\n  .1E-01  .2E-01\n  .5400000E+306\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("huge.AT2:6:"), HasSubstr("'.5400000E+306'"),
                                        HasSubstr("expected accelerations of at most 1000 m/s^2 (about 100 g)")));
}

TEST_F(MotionFiles, At2OldFormSampleBeyondTheLargestAcceleration) {
  // 102 g is 1000.3 m/s^2: just above the bound, and in the old D-exponent notation.
  const auto file = write("huge_old.AT2", "PEER\nTest\nACCELERATION IN G\n   3    0.02000    NPTS, DT\n .1D+00 -.102D+03\n .3\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("huge_old.AT2:5:"), HasSubstr("'-.102D+03'"),
                                        HasSubstr("expected accelerations of at most 1000 m/s^2")));
}

TEST_F(MotionFiles, ColumnSampleBeyondTheLargestAcceleration) {
  const auto two = write("huge.csv", "t,a\n0.00,0.1\n0.01,5.4e305\n0.02,0.3\n");
  EXPECT_THAT(error_of(two, in_g()), AllOf(HasSubstr("huge.csv:3:"), HasSubstr("'5.4e305'"),
                                           HasSubstr("expected accelerations of at most 1000 m/s^2 (about 100 g)")));

  ReadOptions gal;
  gal.unit = AccelerationUnit::gal;
  gal.time_step = 0.01;
  const auto one = write("huge_gal.txt", "Accelerations in gal\n10\n-100001\n30\n");
  EXPECT_THAT(error_of(one, gal), AllOf(HasSubstr("huge_gal.txt:3:"), HasSubstr("'-100001'"),
                                        HasSubstr("expected accelerations of at most 1000 m/s^2")));

  // The bound itself is a ground motion.
  ReadOptions si;
  si.unit = AccelerationUnit::si;
  const auto edge = write("edge.csv", "0,1000\n0.01,-1000\n");
  const Record record = read_record(edge, si);
  EXPECT_EQ(peak_ground_acceleration(record), 1000.0);
}

TEST_F(MotionFiles, EmptyFile) {
  const auto empty = write("empty.csv", "");
  EXPECT_THAT(error_of(empty, in_g()), AllOf(HasSubstr("empty.csv"), HasSubstr("empty"), HasSubstr("expected")));
  const auto blank = write("blank.txt", "\n  \r\n\t\n");
  EXPECT_THAT(error_of(blank, in_g()), AllOf(HasSubstr("blank.txt"), HasSubstr("empty"), HasSubstr("expected")));
}

TEST_F(MotionFiles, HeaderOnly) {
  const auto file = write("header_only.csv", "# a comment\nt,a\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("header_only.csv"), HasSubstr("no data"), HasSubstr("expected")));
}

TEST_F(MotionFiles, ColumnFileWithoutUnit) {
  const auto file = write("no_unit.csv", "t,a\n0,1\n0.01,2\n");
  EXPECT_THAT(error_of(file, {}), AllOf(HasSubstr("no_unit.csv"), HasSubstr("unit"), HasSubstr("g, gal or m/s^2"), HasSubstr("expected")));
}

// A first data row with a bad field is an error, not a header to drop (a record one sample
// short, silently); a title that begins with a number but is not shaped like the data stays a
// header.
TEST_F(MotionFiles, AMalformedFirstDataRowIsAnErrorNotAHeader) {
  const auto file = write("first_row.csv", "t,a\n0.00,0.1x\n0.01,0.2\n0.02,0.3\n");
  EXPECT_THAT(error_of(file, in_g()), AllOf(HasSubstr("first_row.csv:2:"), HasSubstr("'0.1x'"),
                                             HasSubstr("malformed first data row")));
  const auto titled = write("titled.txt", "1995 Kobe earthquake, KJMA\nt a\n0 0.1\n0.01 0.2\n");
  const Record record = read_record(titled, in_g());
  EXPECT_EQ(record.acceleration.size(), 2u);
}

// A header that states the acceleration's unit is read in it without one given; a given unit
// must agree with it; a header that states none still needs one.
TEST_F(MotionFiles, AUnitStatedInTheHeaderIsTheRecordsUnit) {
  const struct {
    const char* header;
    double si_per_unit;
  } headers[] = {{"t, Accel[g]", units::standard_gravity},
                 {"time (s); Acceleration (g's)", units::standard_gravity},
                 {"t acc (cm/s^2)", 0.01},
                 {"Time [s], a [m/s2]", 1.0}};
  for (const auto& h : headers) {
    const auto file = write("stated.csv", std::string(h.header) + "\n0 0.5\n0.01 -1\n");
    const Record record = read_record(file, {});
    ASSERT_EQ(record.acceleration.size(), 2u) << h.header;
    EXPECT_DOUBLE_EQ(record.acceleration[0], 0.5 * h.si_per_unit) << h.header;
  }
  ReadOptions gal;
  gal.unit = AccelerationUnit::gal;
  const auto in_g_header = write("g_header.csv", "t, Accel[g]\n0, 0.5\n0.01, -1\n");
  EXPECT_THAT(error_of(in_g_header, gal), AllOf(HasSubstr("g_header.csv:1:"), HasSubstr("states unit g but gal was given")));
  EXPECT_EQ(read_record(in_g_header, in_g()).acceleration.size(), 2u);
  const auto feet = write("feet.csv", "t, a [ft/s^2]\n0, 0.5\n0.01, -1\n");
  EXPECT_THAT(error_of(feet, in_g()), AllOf(HasSubstr("feet.csv:1:"), HasSubstr("'ft/s^2'"), HasSubstr("expected an acceleration unit")));
  const auto seconds_only = write("seconds.csv", "t (s), a\n0, 0.5\n0.01, -1\n");
  EXPECT_THAT(error_of(seconds_only, {}), AllOf(HasSubstr("seconds.csv:1:"), HasSubstr("does not state its unit")));
}

TEST_F(MotionFiles, SingleColumnNeedsATimeStep) {
  const auto file = write("one_column.txt", "Accelerations in gal\n10\n-20\n30\n");
  ReadOptions options;
  options.unit = AccelerationUnit::gal;
  EXPECT_THAT(error_of(file, options), AllOf(HasSubstr("one_column.txt:2:"), HasSubstr("time step"), HasSubstr("expected")));
  options.time_step = 0.02;
  const Record record = read_record(file, options);
  ASSERT_EQ(record.acceleration.size(), 3u);
  EXPECT_DOUBLE_EQ(record.time_step, 0.02);
  EXPECT_DOUBLE_EQ(record.acceleration[1], -0.20);  // 20 gal = 0.2 m/s^2
}

TEST_F(MotionFiles, GivenTimeStepMustAgreeWithTheTimeColumn) {
  const auto file = write("step.csv", "0,1\n0.01,2\n0.02,3\n");
  ReadOptions options = in_g();
  options.time_step = 0.02;
  EXPECT_THAT(error_of(file, options), AllOf(HasSubstr("step.csv:1:"), HasSubstr("expected them to agree")));
}

TEST_F(MotionFiles, SeparatorsBomCrlfAndSiUnits) {
  ReadOptions si;
  si.unit = AccelerationUnit::si;
  for (const std::string& text : {std::string("\xEF\xBB\xBFtime;acc\r\n0;1.5\r\n0,5;2.5\r\n"),  // decimal comma: not numeric
                                  std::string("t\ta\n0\t1.5\n0.05\t2.5\n0.1\t-3\n"),
                                  std::string("\xEF\xBB\xBF# x\r\nt;a\r\n0;1.5\r\n0.05;2.5\r\n0.1;-3\r\n"),
                                  std::string("Free text: 1.5 Hz\n t , a \n0 , 1.5,\n0.05, 2.5,\n0.1 , -3,\n"),
                                  std::string("0   1.5\n\n0.05  +2.5\n# note\n0.1  -3e0\n")}) {
    const auto file = write("sep.txt", text);
    if (text.find("0,5") != std::string::npos) {
      EXPECT_THAT(error_of(file, si), AllOf(HasSubstr("sep.txt:3:"), HasSubstr("'0,5'"), HasSubstr("expected 2 numbers")));
      continue;
    }
    const Record record = read_record(file, si);
    ASSERT_EQ(record.acceleration.size(), 3u) << text;
    EXPECT_DOUBLE_EQ(record.time_step, 0.05) << text;
    EXPECT_DOUBLE_EQ(record.acceleration[0], 1.5) << text;
    EXPECT_DOUBLE_EQ(record.acceleration[2], -3.0) << text;
  }
}

TEST(ParseOptions, UnitsFormats) {
  EXPECT_EQ(parse_acceleration_unit("g"), AccelerationUnit::g);
  EXPECT_EQ(parse_acceleration_unit("gal"), AccelerationUnit::gal);
  EXPECT_EQ(parse_acceleration_unit("Gal"), AccelerationUnit::gal);
  EXPECT_EQ(parse_acceleration_unit("cm/s^2"), AccelerationUnit::gal);
  EXPECT_EQ(parse_acceleration_unit("m/s^2"), AccelerationUnit::si);
  EXPECT_EQ(parse_acceleration_unit("m/s2"), AccelerationUnit::si);
  EXPECT_EQ(parse_acceleration_unit("G"), std::nullopt);
  EXPECT_EQ(parse_acceleration_unit("ft/s^2"), std::nullopt);
  EXPECT_EQ(parse_acceleration_unit(""), std::nullopt);

  EXPECT_EQ(parse_record_format("automatic"), RecordFormat::automatic);
  EXPECT_EQ(parse_record_format("peer_nga_west2"), RecordFormat::peer_nga_west2);
  EXPECT_EQ(parse_record_format("peer_old"), RecordFormat::peer_old);
  EXPECT_EQ(parse_record_format("columns"), RecordFormat::columns);
  EXPECT_EQ(parse_record_format("at2"), std::nullopt);
}

}  // namespace
}  // namespace caskdem::motion
