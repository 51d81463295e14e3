// The calibrated baseline's adequacy (src/diagnosis/adequacy.h): a goodness-of-fit p-value
// against chi-square, the tests and measures that misfit, and calibrated values no specimen
// has. The chi-square survival function is checked against the published table (Abramowitz &
// Stegun, table 26.8); the rest on residuals made to fit or misfit, and on synthetic data whose
// specimen file states the geometry rule the data were made with, or the wrong one.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "diagnosis/adequacy.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/measures.h"
#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

using testing::TestDirectory;

TEST(Adequacy, ChiSquareSurvivalMatchesThePublishedTable) {
  // (x, nu, upper-tail probability) from the table's 5 % and 1 % points.
  const struct {
    double x;
    int nu;
    double p;
  } rows[] = {{3.841, 1, 0.05}, {6.635, 1, 0.01}, {18.307, 10, 0.05}, {23.209, 10, 0.01}, {79.082, 60, 0.05}, {88.379, 60, 0.01}};
  for (const auto& row : rows) EXPECT_NEAR(chi_square_survival(row.x, row.nu) / row.p, 1.0, 2e-3) << row.x << ", " << row.nu;
}

struct Made {
  TestDirectory directory;
  MeasuredSet set;
};

void make(Made& made, bool radius_rule) {
  SyntheticSpec spec;
  spec.seed = 4;
  write_synthetic_measured_set(made.directory.path(), spec);
  if (radius_rule) {
    // The same data, the specimen file stating the other two-corner rule.
    const std::filesystem::path file = made.directory.path() / "specimen.toml";
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "half_width = \"gyration\"";
    text.replace(text.find(from), from.size(), "half_width = \"radius\"");
    std::ofstream(file) << text;
  }
  made.set = read_measured_set(made.directory.path());
}

TEST(Adequacy, ResidualsWithinTheirTolerancesFitAndManyBeyondDoNot) {
  Made made;
  make(made, false);
  const std::vector<Parameter> parameters = ModelVariant(made.set.specimen, {}, true).parameters();
  FitResult fit;
  fit.best = {0.35, 0.03, 1.0};
  fit.objective = 0.0;
  // The training objective at any other point: far above the fit's (the data exclude it).
  const PointObjective excludes_everything = [](const std::vector<double>&) { return 1e6; };
  const std::vector<double> nominal = fit.best;
  const std::size_t tests = made.set.tests.size(), measures = measure_names().size();
  const std::vector<std::vector<std::uint8_t>> compared(tests, std::vector<std::uint8_t>(measures, 1));
  const auto judged = [&](double r) {
    const std::vector<std::vector<double>> residuals(tests, std::vector<double>(measures, r));
    std::vector<double> loss(tests, robust_loss(residuals[0]));
    return judge_adequacy(made.set, parameters, fit, nominal, loss, residuals, compared, excludes_everything);
  };
  const Adequacy fits = judged(0.8);
  EXPECT_TRUE(fits.adequate);
  EXPECT_GT(fits.p_value, 0.1);
  EXPECT_TRUE(fits.misfits.empty());
  const Adequacy misfits = judged(3.5);
  EXPECT_FALSE(misfits.fits_within_noise);
  EXPECT_FALSE(misfits.adequate);
  EXPECT_EQ(misfits.misfitting_tests.size(), tests);
  EXPECT_EQ(misfits.misfits.size(), tests * measures);
  EXPECT_FALSE(misfits.checks.empty());

  // Within noise but at a friction twice the stated one: implausible, so not adequate.
  fit.best = {0.70, 0.03, 1.0};
  const std::vector<std::vector<double>> small(tests, std::vector<double>(measures, 0.5));
  const Adequacy slippery =
      judge_adequacy(made.set, parameters, fit, nominal, std::vector<double>(tests, robust_loss(small[0])), small, compared,
                     excludes_everything);
  EXPECT_TRUE(slippery.fits_within_noise);
  EXPECT_FALSE(slippery.adequate);
  ASSERT_EQ(slippery.implausible.size(), 1u);
  EXPECT_EQ(slippery.implausible[0].parameter, "friction");
  // ... unless the data do not exclude the stated friction (the objective there within the
  // likelihood-ratio bound of the fit's): a value the tests barely determine is no misfit.
  const Adequacy undetermined = judge_adequacy(made.set, parameters, fit, nominal,
                                               std::vector<double>(tests, robust_loss(small[0])), small, compared,
                                               [](const std::vector<double>&) { return kLikelihoodRatioBound - 1.0; });
  EXPECT_TRUE(undetermined.adequate);
}

// Six tests' residuals, every measure at `r`.
std::vector<std::vector<double>> uniform_residuals(double r) {
  return std::vector<std::vector<double>>(6, std::vector<double>(measure_names().size(), r));
}

TEST(Adequacy, ASlidingMisfitInTwoTestsIsNotAveragedAway) {
  // The independent generator's hidden Stribeck friction, as the baseline meets it: every
  // measure within a tolerance but the sliding of two tests, under-predicted by 4 to 5.
  std::vector<std::vector<double>> residuals = uniform_residuals(0.8);
  for (int t : {1, 4}) {
    residuals[t][measure_index("max_sliding")] = t == 1 ? -5.0 : -4.1;
    residuals[t][measure_index("residual_sliding")] = t == 1 ? -4.6 : -3.8;
  }
  const std::vector<std::vector<std::uint8_t>> compared(6, std::vector<std::uint8_t>(measure_names().size(), 1));
  double loss = 0.0;
  for (const auto& r : residuals) loss += robust_loss(r);
  const int dof = 60 - 3;
  ASSERT_GT(chi_square_survival(loss, dof), kAdequacyLevel) << "the global test alone would call it adequate";
  const std::vector<FamilyFit> families = judge_families(residuals, compared);
  ASSERT_EQ(families.size(), measure_families().size());
  for (const FamilyFit& f : families) {
    EXPECT_EQ(f.misfits, f.family == "sliding") << f.family << " p " << f.p_value;
    if (f.family == "sliding") {
      EXPECT_EQ(f.residuals, 18);
      EXPECT_LT(f.mean_magnitude_residual, 0.0);             // under-predicted
      EXPECT_DOUBLE_EQ(f.holm_level, kAdequacyLevel / 4.0);  // the smallest p-value meets Bonferroni's level
    }
  }
  // Every residual within a tolerance: no family misfits.
  for (const FamilyFit& f : judge_families(uniform_residuals(0.8), compared)) EXPECT_FALSE(f.misfits) << f.family;
  // A measure that is not compared does not count.
  std::vector<std::vector<std::uint8_t>> without_sliding = compared;
  for (auto& c : without_sliding) c[measure_index("max_sliding")] = c[measure_index("residual_sliding")] = 0;
  for (const FamilyFit& f : judge_families(residuals, without_sliding)) {
    EXPECT_FALSE(f.misfits) << f.family;
    if (f.family == "sliding") {
      EXPECT_EQ(f.residuals, 6);
    }
  }
}

TEST(Adequacy, FamiliesKeepTheFamilyWiseFalseAlarmRate) {
  // Holm's step-down keeps the chance that any family of a model that fits within noise is
  // called a misfit at or below the level, whatever the families' dependence (Holm 1979). Here
  // each residual is a standard normal draw, the noise a tolerance allows; pseudo-Huber is at
  // most r^2, so the rate is below the level.
  const std::size_t measures = measure_names().size();
  const std::vector<std::vector<std::uint8_t>> compared(6, std::vector<std::uint8_t>(measures, 1));
  std::mt19937_64 random(20261127);
  std::normal_distribution<double> normal;
  const int sets = 200000;
  int alarms = 0;
  std::vector<std::vector<double>> residuals(6, std::vector<double>(measures));
  for (int s = 0; s < sets; ++s) {
    for (auto& test : residuals) {
      for (double& r : test) r = normal(random);
    }
    const std::vector<FamilyFit> families = judge_families(residuals, compared);
    alarms += std::any_of(families.begin(), families.end(), [](const FamilyFit& f) { return f.misfits; });
  }
  // At most the level, with three binomial standard deviations of this many sets.
  const double expected = kAdequacyLevel * sets;
  RecordProperty("false_alarms", alarms);
  EXPECT_LE(alarms, expected + 3.0 * std::sqrt(expected)) << alarms << " of " << sets;
  // And the test has power: one measure of every test off by 3 tolerances is found.
  for (auto& test : residuals) std::fill(test.begin(), test.end(), 0.0);
  for (auto& test : residuals) test[measure_index("rotation_asymmetry")] = 3.0;
  const std::vector<FamilyFit> shifted = judge_families(residuals, compared);
  for (const FamilyFit& f : shifted) EXPECT_EQ(f.misfits, f.family == "asymmetry") << f.family;
}

TEST(Adequacy, TheBaselineOnItsOwnRuleFitsAndOnTheWrongRuleDoesNot) {
  DiagnosisOptions options;
  options.threads = 2;
  Made right, wrong;
  make(right, false);
  make(wrong, true);
  const ModelFit on_right = calibrate_baseline(right.set, options);
  RecordProperty("p_value_right_rule", std::to_string(on_right.adequacy.p_value));
  EXPECT_TRUE(on_right.adequacy.adequate) << "p " << on_right.adequacy.p_value << ", RMS " << on_right.adequacy.rms_residual;
  const ModelFit on_wrong = calibrate_baseline(wrong.set, options);
  RecordProperty("p_value_wrong_rule", std::to_string(on_wrong.adequacy.p_value));
  EXPECT_FALSE(on_wrong.adequacy.adequate);
  const bool stiffness_named = std::any_of(on_wrong.adequacy.implausible.begin(), on_wrong.adequacy.implausible.end(),
                                           [](const ImplausibleValue& v) { return v.parameter == "stiffness_scale"; });
  EXPECT_TRUE(stiffness_named || !on_wrong.adequacy.fits_within_noise);
}

}  // namespace
}  // namespace caskdem::diagnosis
