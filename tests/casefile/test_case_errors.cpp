// Bad case files: one InputError that names the file, the line or key, and what was
// expected; never a crash or a silent default.

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "casefile/case_file.h"
#include "core/error.h"
#include "support/paper_cases.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Variants of the shipped 1/3 model case, one line replaced (or removed, or added).
class CaseErrors : public testing::TemporaryFiles {
 protected:
  std::filesystem::path variant(const std::string& name, const std::string& find, const std::string& replace) const {
    return variant_of(testing::case_path("model-1-3-sine.toml"), name + ".toml", find, replace);
  }
  // The case's exponential friction law replaced by a `table`.
  std::filesystem::path friction_table_variant(const std::string& name, const std::string& table) const {
    return variant(name, "law = \"exponential\"\nstatic = 0.60\nkinetic = 0.45\ndecay_speed = \"5 cm/s\"",
                   "law = \"table\"\ntable = " + table);
  }
};

std::string error_of(const std::filesystem::path& file) {
  try {
    (void)load_case(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

int line_of(const std::filesystem::path& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find(text) != std::string::npos) return n;
  }
  return -1;
}

TEST_F(CaseErrors, ShippedCasesLoad) {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(CASKDEM_SOURCE_DIR) + "/cases")) {
    EXPECT_NO_THROW((void)load_case(entry.path())) << entry.path();
  }
}

TEST_F(CaseErrors, MissingFile) {
  EXPECT_THAT(error_of("/nonexistent/case.toml"), HasSubstr("/nonexistent/case.toml: no such file"));
}

TEST_F(CaseErrors, NegativeMass) {
  const auto file = variant("negative-mass", "density = \"8.743 g/cm^3\"", "mass = \"-12.6 t\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(file.string() + ":" + std::to_string(line_of(file, "mass = "))));
  EXPECT_THAT(e, HasSubstr("key cask.mass"));
  EXPECT_THAT(e, HasSubstr("expected a positive value"));
}

TEST_F(CaseErrors, FrictionCoefficientThatIsNotANumber) {
  const auto file = variant("friction-nan", "static = 0.60", "static = \"high\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(":" + std::to_string(line_of(file, "static = ")) + ": key friction.static"));
  EXPECT_THAT(e, HasSubstr("expected a number"));
}

TEST_F(CaseErrors, UnknownKeyNamesItAndTheKnownOnes) {
  const auto file = variant("unknown-key", "height = \"2.033 m\"", "height = \"2.033 m\"\nhieght = \"2.0 m\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(":" + std::to_string(line_of(file, "hieght")) + ": unknown key cask.hieght"));
  EXPECT_THAT(e, HasSubstr("height"));
}

TEST_F(CaseErrors, AMisspeltOptionalKeyIsNamedWithTheKeyItMeant) {
  // ramp_cycles is optional, so its misspelling is only an unknown key: the message says
  // which known key the table lacks that it is one edit from. A name far from every key gets
  // no guess.
  const auto misspelt = variant("ramp", "ramp_cycles = 2", "ramp_cycle = 2");
  EXPECT_THAT(error_of(misspelt), HasSubstr(":" + std::to_string(line_of(misspelt, "ramp_cycle")) +
                                            ": unknown key motion.ramp_cycle; did you mean ramp_cycles?"));
  const auto foreign = variant("foreign", "ramp_cycles = 2", "ramp_cycles = 2\nwobble = 2");
  EXPECT_THAT(error_of(foreign), Not(HasSubstr("did you mean")));
}

TEST_F(CaseErrors, AMisspeltRequiredKeyIsNamedInTheMissingKeysMessage) {
  const auto file = variant("diamter", "diameter = \"0.95 m\"", "diamter = \"0.95 m\"");
  EXPECT_THAT(error_of(file), HasSubstr("missing key cask.diameter: expected a length (is diamter, line " +
                                        std::to_string(line_of(file, "diamter")) + ", a misspelling of it?)"));
}

TEST_F(CaseErrors, WrongUnitNamesTheAcceptedOnes) {
  const auto file = variant("wrong-unit", "diameter = \"0.95 m\"", "diameter = \"0.95 kg\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("key cask.diameter"));
  EXPECT_THAT(e, HasSubstr("accepted: m, cm, mm"));
}

TEST_F(CaseErrors, KeyOfAnotherFrictionLaw) {
  const auto file = variant("law-key", "law = \"exponential\"", "law = \"constant\"\ncoefficient = 0.6");
  EXPECT_THAT(error_of(file), HasSubstr("key friction.static: does not apply to friction law \"constant\""));
}

// The error names the file, the table's line and key, and says `expected`.
void expect_friction_table_refused(const std::filesystem::path& file, const std::string& expected) {
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(file.string() + ":" + std::to_string(line_of(file, "table = ")) + ": key friction.table"));
  EXPECT_THAT(e, HasSubstr(expected));
}

// An infinite friction coefficient would make a contact's limit inf x 0 = NaN where it opens
// (and the friction floor of kernels/friction_law.h assumes finite coefficients).
TEST_F(CaseErrors, AnInfiniteTabulatedFrictionIsRefused) {
  expect_friction_table_refused(friction_table_variant("friction-inf", "[[0.0, 0.6], [0.1, inf]]"),
                                "expected two finite numbers in each pair");
}

TEST_F(CaseErrors, AFrictionTableWithRowsTooCloseForItsSlopeIsRefused) {
  expect_friction_table_refused(friction_table_variant("friction-slope", "[[0.0, 0.6], [1e-310, 0.3]]"),
                                "rows 1 and 2 are too close in speed");
}

TEST_F(CaseErrors, TomlSyntaxErrorGivesLine) {
  const auto file = variant("syntax", "cycles = 10", "cycles = = 10");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(":" + std::to_string(line_of(file, "cycles = =")) + ": not valid TOML"));
}

TEST_F(CaseErrors, GeometryProblemNamesTheTable) {
  const auto file = variant("rounding", "rounding = \"0.5 cm\"", "rounding = \"40 cm\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("[cask]"));
  EXPECT_THAT(e, HasSubstr("rounding"));
}

TEST_F(CaseErrors, ADurationInTheWrongUnitIsRefused) {
  // 1e30 s of steps overflowed their count: a negative step count and end time, exit 0.
  const auto file = variant("long", "safety_factor = 0.01", "safety_factor = 0.01\nduration = \"1e30 s\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(":" + std::to_string(line_of(file, "duration = ")) + ": key integration.duration"));
  EXPECT_THAT(e, HasSubstr("expected a value between 0 and 100000, got 1e+30"));
}

TEST_F(CaseErrors, MessagesShowSmallValuesAsGiven) {
  // Printed with %f, 1e-9 read "got 0.000000".
  const auto file = variant("tiny-step", "safety_factor = 0.01", "safety_factor = 1e-9");
  EXPECT_THAT(error_of(file), HasSubstr("key integration.safety_factor: expected a value between 1e-06 and 1, got 1e-09"));
}

TEST_F(CaseErrors, AnUnknownSliderIsRefusedWithTheSchemes) {
  const auto file = variant("slider", "safety_factor = 0.01", "safety_factor = 0.01\nslider = \"full-step\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr(":" + std::to_string(line_of(file, "slider = ")) + ": key integration.slider"));
  EXPECT_THAT(e, HasSubstr("\"half-step\", \"whole-step\""));
}

TEST_F(CaseErrors, TheSliderIsReadFromTheCase) {
  const auto file = variant("whole-step", "safety_factor = 0.01", "safety_factor = 0.01\nslider = \"whole-step\"");
  EXPECT_EQ(load_case(file).model.whole_step_terms, kWholeStepSlider);
  EXPECT_EQ(load_case(testing::case_path("model-1-3-sine.toml")).model.whole_step_terms, 0) << "the paper's by default";
}

TEST_F(CaseErrors, TheNormalLawAndItsDamperAreReadAndCheckedWithTheirKeys) {
  const std::string contact = "shear_stiffness = \"2.21e3 bar/cm\"";
  const auto hertz = variant("hertz", contact, contact + "\nnormal_law = \"hunt-crossley\"\nimpact_damping = \"2 s/m\"");
  const Case c = load_case(hertz);
  EXPECT_EQ(c.model.normal_law, NormalLaw::hunt_crossley);
  EXPECT_EQ(c.parameters.impact_damping, 2.0);
  EXPECT_EQ(load_case(testing::case_path("model-1-3-sine.toml")).model.normal_law, NormalLaw::linear)
      << "the paper's by default";
  const auto unknown = variant("hertz-law", contact, contact + "\nnormal_law = \"hertz\"");
  const std::string e = error_of(unknown);
  EXPECT_THAT(e, HasSubstr(":" + std::to_string(line_of(unknown, "normal_law = ")) + ": key contact.normal_law"));
  EXPECT_THAT(e, HasSubstr("\"linear\", \"hunt-crossley\""));
  const auto negative = variant("negative-damper", contact, contact + "\nimpact_damping = \"-1 s/m\"");
  EXPECT_THAT(error_of(negative), HasSubstr("key contact.impact_damping"));
  const auto unitless = variant("damper-unit", contact, contact + "\nimpact_damping = \"2 m/s\"");
  EXPECT_THAT(error_of(unitless), HasSubstr("key contact.impact_damping: unit \"m/s\" is not an inverse speed unit (accepted: s/m, s/cm)"));
}

TEST_F(CaseErrors, ShakingLongerThanADayIsRefused) {
  const auto file = variant("cycles", "cycles = 10", "cycles = 1e15");
  EXPECT_THAT(error_of(file), HasSubstr("key motion.cycles: expected at most 100000 s of shaking"));
}

TEST_F(CaseErrors, ARecordScaledByZeroIsRefused) {
  // A factor of 0 ran a motionless case. Checked when the case is read, before the record.
  const auto file = variant_of(testing::case_path("model-1-3-elcentro-400gal.toml"), "still-record.toml",
                               "target_pga = \"400 gal\"", "scale = 0");
  EXPECT_THAT(error_of(file), HasSubstr("key motion.scale: expected a non-zero factor"));
}

TEST_F(CaseErrors, AnAllZeroRecordScaledToATargetNamesTheRecordAndTheKey) {
  // No factor brings a zero PGA to 400 gal: the record's file, the key that asked and the
  // case's motion are named, not the library function that found it.
  std::string zeros = "t,acc\n";
  for (int k = 0; k < 100; ++k) zeros += std::to_string(0.01 * k) + ",0\n";
  const auto record = write("still.csv", zeros);
  const auto file = variant_of(testing::case_path("model-1-3-elcentro-400gal.toml"), "zero-record.toml",
                               "file = \"../../shared/motions/elcentro1940_ns_RSN6.AT2\"",
                               "file = \"still.csv\"\nunit = \"g\"");
  std::string message = "no error";
  try {
    (void)make_motion(load_case(file).horizontal);
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr(record.filename().string() + ": the record's accelerations are all zero, so no scale "
                                                             "factor brings its PGA to the target"));
  EXPECT_THAT(message, HasSubstr("(asked for by target_pga of the motion at " + file.string() + ":" +
                                 std::to_string(line_of(file, "kind = \"record\"")) + ")"));
}

TEST_F(CaseErrors, MissingRequiredKey) {
  const auto file = variant("missing", "diameter = \"0.95 m\"\n", "");
  EXPECT_THAT(error_of(file), HasSubstr("missing key cask.diameter: expected a length"));
}

}  // namespace
}  // namespace caskdem

namespace caskdem {
namespace {

// A distributed footprint pivots on the rim and needs a number of contacts it can hold: the
// two-corner gyration rule beside it, too few or too many points, or points on a two-corner
// footprint are each one error naming the key.
class FootprintErrors : public testing::TemporaryFiles {
 protected:
  std::filesystem::path variant(const std::string& name, const std::string& replace) const {
    return variant_of(testing::case_path("model-1-3-sine.toml"), name + ".toml",
                      "half_width = \"gyration\"      # the paper's 2D half-width: r/2 (docs/model.md, \"Cask section\")",
                      replace);
  }
};

TEST_F(FootprintErrors, EachIsNamed) {
  EXPECT_NO_THROW((void)load_case(variant("distributed", "footprint = \"distributed\"")));
  EXPECT_NO_THROW((void)load_case(variant("radius", "footprint = \"distributed\"\nhalf_width = \"radius\"")));
  EXPECT_THAT(error_of(variant("gyration", "footprint = \"distributed\"\nhalf_width = \"gyration\"")),
              HasSubstr("cask.half_width"));
  EXPECT_THAT(error_of(variant("two", "footprint = \"distributed\"\nfootprint_points = 2")),
              HasSubstr("cask.footprint_points"));
  EXPECT_THAT(error_of(variant("many", "footprint = \"distributed\"\nfootprint_points = 17")),
              HasSubstr("3 to 16"));
  EXPECT_THAT(error_of(variant("corners", "footprint_points = 9")), HasSubstr("only a distributed footprint"));
  EXPECT_THAT(error_of(variant("unknown", "footprint = \"ring\"")), HasSubstr("cask.footprint"));
}

// A 3D cask's keys: the planar footprint rules, a polygon, a pair on a planar case, the vertical
// given twice, a pair's keys without a pair: each one error naming the key and its line.
class ThreeDimensionalErrors : public testing::TemporaryFiles {
 protected:
  std::filesystem::path variant(const std::string& name, const std::string& find, const std::string& replace,
                                const std::string& source = "model-1-3-kobe-3d.toml") const {
    return variant_of(testing::case_path(source), name + ".toml", find, replace);
  }
};

TEST_F(ThreeDimensionalErrors, EachIsNamedWithItsLine) {
  const Case c = load_case(testing::case_path("model-1-3-kobe-3d.toml"));
  EXPECT_EQ(c.cask.dimensions, 3);
  EXPECT_FALSE(c.horizontal.pair.empty());
  EXPECT_EQ(c.horizontal.pair_measure, MotionSpec::PairMeasure::rotd50);

  struct Bad {
    std::filesystem::path file;
    std::string line_text, key, message;
  };
  const std::vector<Bad> cases = {
      {variant("four", "dimensions = 3", "dimensions = 4"), "dimensions = 4", "cask.dimensions", "expected 2"},
      {variant("footprint", "dimensions = 3", "dimensions = 3\nfootprint = \"distributed\""), "footprint =",
       "cask.footprint", "whole circular base"},
      {variant("half-width", "dimensions = 3", "dimensions = 3\nhalf_width = \"radius\""), "half_width =",
       "cask.half_width", "whole circular base"},
      {variant("planar-pair", "kind = \"record\"", "kind = \"record\"\npair = \"H2.AT2\"",
               "model-1-3-elcentro-400gal.toml"),
       "pair =", "motion.pair", "only a 3D cask"},
      {variant("planar-incidence", "kind = \"record\"", "kind = \"record\"\nincidence = \"30 deg\"",
               "model-1-3-elcentro-400gal.toml"),
       "incidence =", "motion.incidence", "only a 3D cask"},
      {variant("planar-axial", "shape = \"cylinder\"", "shape = \"cylinder\"\naxial_inertia = \"2000 kg m^2\"",
               "model-1-3-elcentro-400gal.toml"),
       "axial_inertia =", "cask.axial_inertia", "only a 3D cask"},
      {variant("twice", "similarity_scale = 3", "similarity_scale = 3\n[motion.vertical]\nkind = \"none\""),
       "vertical_file =", "motion.vertical_file", "not both"},
      {variant("measure", "intensity = \"rotd50\"", "intensity = \"rotd90\""), "intensity =", "motion.intensity",
       "rotd100"},
      {variant("no-pair", "pair = ", "# pair = "), "vertical_file =", "motion.vertical_file",
       "only a horizontal pair"},
      {variant("factor", "target_pga = \"400 gal\"", "scale = 0.5"), "intensity =", "motion.intensity",
       "give one of them"},
  };
  for (const Bad& b : cases) {
    const std::string e = error_of(b.file);
    EXPECT_THAT(e, HasSubstr(b.file.string() + ":" + std::to_string(line_of(b.file, b.line_text)))) << b.key;
    EXPECT_THAT(e, HasSubstr(b.key));
    EXPECT_THAT(e, HasSubstr(b.message));
  }
}

}  // namespace
}  // namespace caskdem
