// Sa(T, zeta) as an ensemble's intensity measure: each realisation's motion is scaled so that
// the spectral acceleration of the scaled motion, as the run samples it, is the stripe's
// level; the result file names the period and damping, and `caskdem risk` sets the curves
// against an SA(T) hazard of that period only (and refuses another damping than 5 %).

#include <cmath>
#include <regex>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ensemble/plan.h"
#include "motion/response_spectrum.h"
#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;

class SpectralMeasure : public testing::TemporaryFiles {
 protected:
  std::filesystem::path ensemble(const std::string& damping) const {
    std::string text = testing::file_text(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
    text = std::regex_replace(text, std::regex("measure = \"pga\"\n"),
                              "measure = \"sa\"\nperiod = \"0.5 s\"\n" + damping);
    text = std::regex_replace(text, std::regex("realisations = 64"), "realisations = 32");
    return write("sa.toml", text);
  }
};

TEST_F(SpectralMeasure, EachRealisationsScaledMotionHasTheStripesSpectralAcceleration) {
  const EnsemblePlan plan(load_ensemble(ensemble("")), InstructionSet::scalar);
  const double dt = plan.model().time_step;
  for (std::int64_t i : {0L, 33L, 70L, 127L}) {
    const RealisationInput in = plan.realisation(i);
    const motion::TableMotion& m = plan.motion(in.motion);
    motion::Record scaled;
    scaled.time_step = dt;
    const auto steps = static_cast<std::int64_t>(std::ceil(m.duration() / dt));
    scaled.acceleration.resize(steps + 1);
    motion::sample_acceleration(m, dt, 0, static_cast<int>(steps + 1), scaled.acceleration.data());
    for (double& a : scaled.acceleration) a *= in.scale_factor;
    EXPECT_NEAR(motion::spectral_acceleration(scaled, 0.5, 0.05) / in.level, 1.0, 1e-12) << "realisation " << i;
  }
}

TEST_F(SpectralMeasure, RiskTakesOnlyAHazardOfThatPeriodAndFivePercentDamping) {
  const auto result = dir_ / "sa.h5";
  ASSERT_EQ(testing::run_caskdem("ensemble " + ensemble("").string() + " --out " + result.string() + " --threads 1 --quiet --no-plot").status, 0);
  std::string curve = "SA(0.5) [g], annual frequency\n";
  for (int i = 0; i <= 40; ++i) {
    const double a = 0.002 * std::pow(25000.0, i / 40.0);
    curve += std::to_string(a) + ", " + std::to_string(1e-4 * std::pow(a, -2.0)) + "\n";
  }
  const testing::Outcome ok = testing::run_caskdem("risk " + result.string() + " --hazard " + write("sa05.csv", curve).string() + " --no-plot");
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_THAT(ok.output, HasSubstr("SA(0.5)"));
  const testing::Outcome other = testing::run_caskdem(
      "risk " + result.string() + " --hazard " + write("sa1.csv", std::regex_replace(curve, std::regex("SA\\(0.5\\)"), "SA(1.0)")).string());
  EXPECT_EQ(other.status, 2);
  EXPECT_THAT(other.output, HasSubstr("its fragility curves are of SA(0.5) but the hazard curve"));

  const auto damped = dir_ / "sa10.h5";
  ASSERT_EQ(testing::run_caskdem("ensemble " + ensemble("damping_ratio = 0.10\n").string() + " --out " + damped.string() +
                                 " --threads 1 --quiet --no-plot").status, 0);
  const testing::Outcome refused = testing::run_caskdem("risk " + damped.string() + " --hazard " + (dir_ / "sa05.csv").string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_THAT(refused.output, HasSubstr("Sa at 10 % damping; expected 5 %"));
}

TEST_F(SpectralMeasure, APeriodOnAnotherMeasureOrOutOfRangeIsRefused) {
  std::string text = testing::file_text(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
  const auto pga = write("pga.toml", std::regex_replace(text, std::regex("measure = \"pga\"\n"), "measure = \"pga\"\nperiod = \"1 s\"\n"));
  EXPECT_THAT(testing::input_error_of([&] { load_ensemble(pga); }, "a period on PGA"),
              HasSubstr("key intensity.period: only measure = \"sa\" has a period"));
  const auto none = write("none.toml", std::regex_replace(text, std::regex("measure = \"pga\"\n"), "measure = \"sa\"\n"));
  EXPECT_THAT(testing::input_error_of([&] { load_ensemble(none); }, "sa without a period"), HasSubstr("period"));
  const auto zero = write("zero.toml", std::regex_replace(text, std::regex("measure = \"pga\"\n"), "measure = \"sa\"\nperiod = \"0 s\"\n"));
  EXPECT_THAT(testing::input_error_of([&] { load_ensemble(zero); }, "a period of 0"), HasSubstr("expected a period from"));
}

}  // namespace
}  // namespace caskdem
