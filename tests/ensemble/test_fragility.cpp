// Fragility statistics (src/ensemble/fragility) against what they did not produce: exact
// binomial tail sums and closed forms of Clopper-Pearson, the closed-form MLE through two
// stripes, recovery of a known lognormal within the Fisher-information standard errors, the
// delta-method width of a bootstrap band, and chi-square closed forms.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <numbers>
#include <random>
#include <vector>

#include "core/units.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/fragility.h"

namespace caskdem::fragility {
namespace {

double standard_normal_cdf(double s) { return 0.5 * std::erfc(-s / std::numbers::sqrt2); }
double standard_normal_density(double s) { return std::exp(-0.5 * s * s) / std::sqrt(2.0 * std::numbers::pi); }
double probit(double p) { return boost::math::quantile(boost::math::normal(), p); }

// P(X <= k) for X ~ Binomial(n, p), by direct summation of the terms.
double binomial_cdf(int k, int n, double p) {
  double total = 0.0;
  for (int i = 0; i <= k; ++i)
    total += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * std::log(p) +
                      (n - i) * std::log1p(-p));
  return total;
}

// Root in (0, 1) of a function increasing in p, by bisection to 1e-15.
template <class Function>
double bisect_increasing(Function f, double target) {
  double lo = 0.0, hi = 1.0;
  while (hi - lo > 1e-15) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::vector<double> geometric_levels(double first, double last, int count) {
  std::vector<double> levels(count);
  for (int j = 0; j < count; ++j) levels[j] = first * std::pow(last / first, j / (count - 1.0));
  return levels;
}

// Expected Fisher information of (u = ln median, v = ln beta) for stripes of n runs each:
// I = sum_j n_j phi^2 / (Phi (1 - Phi)) (ds/dtheta)(ds/dtheta)^T with ds/du = -1/beta, ds/dv = -s.
// Returns the standard errors sqrt(diag(I^-1)).
std::array<double, 2> standard_errors(const std::vector<double>& levels, const std::vector<std::int64_t>& trials,
                                      double median, double log_std) {
  double i_uu = 0.0, i_uv = 0.0, i_vv = 0.0;
  for (std::size_t j = 0; j < levels.size(); ++j) {
    const double s = std::log(levels[j] / median) / log_std;
    const double p = standard_normal_cdf(s), density = standard_normal_density(s);
    const double weight = static_cast<double>(trials[j]) * density * density / (p * (1.0 - p));
    i_uu += weight / (log_std * log_std);
    i_uv += weight * s / log_std;
    i_vv += weight * s * s;
  }
  const double determinant = i_uu * i_vv - i_uv * i_uv;
  return {std::sqrt(i_vv / determinant), std::sqrt(i_uu / determinant)};
}

std::vector<std::int64_t> binomial_draws(const std::vector<double>& levels, std::int64_t trials, double median,
                                         double log_std, std::mt19937_64& generator) {
  std::vector<std::int64_t> counts;
  for (double level : levels) {
    std::binomial_distribution<std::int64_t> draw(trials, standard_normal_cdf(std::log(level / median) / log_std));
    counts.push_back(draw(generator));
  }
  return counts;
}

// --- Clopper-Pearson -------------------------------------------------------------------------

TEST(ClopperPearson, NoneOrAllOfTenHaveClosedForms) {
  double lower = -1.0, upper = -1.0;
  // 0 of n: upper solves (1 - p)^n = alpha/2; n of n: lower solves p^n = alpha/2.
  clopper_pearson(0, 10, 0.95, lower, upper);
  EXPECT_EQ(lower, 0.0);
  EXPECT_NEAR(upper, 1.0 - std::pow(0.025, 0.1), 1e-14);
  EXPECT_NEAR(upper, 0.308497, 1e-6);  // as printed in tables of exact limits: 0.3085
  clopper_pearson(10, 10, 0.95, lower, upper);
  EXPECT_NEAR(lower, std::pow(0.025, 0.1), 1e-14);
  EXPECT_EQ(upper, 1.0);
  // 1 of 10: lower solves 1 - (1 - p)^10 = 0.025.
  clopper_pearson(1, 10, 0.95, lower, upper);
  EXPECT_NEAR(lower, 1.0 - std::pow(0.975, 0.1), 1e-14);
  EXPECT_NEAR(upper, 0.445016, 1e-6);  // tables: 0.4450 (also by exact-integer bisection in Python)
}

TEST(ClopperPearson, MatchesBinomialTailInversion) {
  // The interval's ends are where the binomial tails equal (1 - confidence)/2:
  //   P(X >= z | lower) = alpha/2,  P(X <= z | upper) = alpha/2.
  struct Case {
    int count, trials;
    double confidence;
  };
  for (const Case c : {Case{5, 20, 0.95}, Case{17, 40, 0.90}, Case{3, 200, 0.99}, Case{99, 100, 0.95}}) {
    const double tail = 0.5 * (1.0 - c.confidence);
    double lower = 0.0, upper = 0.0;
    clopper_pearson(c.count, c.trials, c.confidence, lower, upper);
    const double lower_reference =
        bisect_increasing([&](double p) { return 1.0 - binomial_cdf(c.count - 1, c.trials, p); }, tail);
    const double upper_reference =
        bisect_increasing([&](double p) { return -binomial_cdf(c.count, c.trials, p); }, -tail);
    EXPECT_NEAR(lower, lower_reference, 1e-10) << c.count << "/" << c.trials;
    EXPECT_NEAR(upper, upper_reference, 1e-10) << c.count << "/" << c.trials;
  }
}

TEST(ClopperPearson, NoTrialsGiveTheWholeRangeAndBadInputThrows) {
  double lower = -1.0, upper = -1.0;
  clopper_pearson(0, 0, 0.95, lower, upper);
  EXPECT_EQ(lower, 0.0);
  EXPECT_EQ(upper, 1.0);
  EXPECT_THROW(clopper_pearson(3, 2, 0.95, lower, upper), std::invalid_argument);
  EXPECT_THROW(clopper_pearson(1, 2, 1.0, lower, upper), std::invalid_argument);
}

TEST(StripeProbabilities, SumsOverMotions) {
  StripeData data;
  data.levels = {0.2, 0.4, 0.8};
  data.trials = {{10, 10, 0}, {5, 20, 0}};
  data.counts = {{0, 4, 0}, {1, 11, 0}};
  const auto stripes = stripe_probabilities(data, 0.95);
  ASSERT_EQ(stripes.size(), 3u);
  EXPECT_EQ(stripes[1].trials, 30);
  EXPECT_EQ(stripes[1].count, 15);
  EXPECT_DOUBLE_EQ(stripes[1].probability, 0.5);
  double lower = 0.0, upper = 0.0;
  clopper_pearson(15, 30, 0.95, lower, upper);
  EXPECT_EQ(stripes[1].lower, lower);
  EXPECT_EQ(stripes[1].upper, upper);
  EXPECT_EQ(stripes[2].probability, 0.0);
  EXPECT_EQ(stripes[2].lower, 0.0);
  EXPECT_EQ(stripes[2].upper, 1.0);
}

// --- Maximum likelihood ----------------------------------------------------------------------

TEST(FitLognormal, TwoStripesAreFittedExactly) {
  // With two stripes the model can match both fractions, which is the saturated maximum:
  // (ln x_j - u) / beta = Phi^-1(p_j), j = 1, 2.
  const std::vector<double> levels = {0.3, 0.8};
  const std::vector<std::int64_t> trials = {1000, 400};
  const std::vector<std::int64_t> counts = {200, 280};  // p = 0.2, 0.7
  const double q1 = probit(0.2), q2 = probit(0.7);
  const double log_std = (std::log(0.8) - std::log(0.3)) / (q2 - q1);
  const double median = std::exp(std::log(0.3) - log_std * q1);
  const LognormalFit fit = fit_lognormal(levels, trials, counts);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  EXPECT_NEAR(fit.median / median - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(fit.log_std / log_std - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(fragility_probability(fit, 0.3), 0.2, 1e-9);
  EXPECT_NEAR(fragility_probability(fit, 0.8), 0.7, 1e-9);
  // ln L = sum ln C(n, z) + z ln p + (n - z) ln(1 - p) at p = z / n.
  double saturated = 0.0;
  for (int j = 0; j < 2; ++j) {
    const double n = static_cast<double>(trials[j]), z = static_cast<double>(counts[j]);
    saturated += std::lgamma(n + 1) - std::lgamma(z + 1) - std::lgamma(n - z + 1) + z * std::log(z / n) +
                 (n - z) * std::log1p(-z / n);
  }
  EXPECT_NEAR(fit.log_likelihood, saturated, 1e-9 * std::abs(saturated));

  // The order of the stripes, and splitting a stripe into two at the same level, change nothing.
  const LognormalFit shuffled = fit_lognormal({0.8, 0.3, 0.3}, {400, 600, 400}, {280, 150, 50});
  ASSERT_TRUE(shuffled.fitted) << shuffled.reason;
  EXPECT_NEAR(shuffled.median / median - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(shuffled.log_std / log_std - 1.0, 0.0, 1e-8);
}

TEST(FitLognormal, ExpectedCountsOfAHugeSampleGiveTheTruth) {
  // z_j = round(n Phi_j) with n = 1e9: the data are the curve to 5e-10, which moves the
  // parameters by ~1e-9 (Phi' ~ 0.1-0.4 over the stripes).
  for (const auto& [median, log_std] : {std::pair{0.5, 0.4}, std::pair{0.05, 1.5}, std::pair{2.0, 0.01}}) {
    const std::vector<double> levels = geometric_levels(median * std::exp(-2.5 * log_std),
                                                        median * std::exp(2.5 * log_std), 12);
    std::vector<std::int64_t> trials(levels.size(), 1'000'000'000), counts;
    for (double level : levels)
      counts.push_back(std::llround(1e9 * standard_normal_cdf(std::log(level / median) / log_std)));
    const LognormalFit fit = fit_lognormal(levels, trials, counts);
    ASSERT_TRUE(fit.fitted) << fit.reason;
    EXPECT_NEAR(fit.median / median - 1.0, 0.0, 1e-8) << median << " " << log_std;
    EXPECT_NEAR(fit.log_std / log_std - 1.0, 0.0, 1e-8) << median << " " << log_std;
  }
}

TEST(FitLognormal, SteepCurveAmongMostlyEmptyOrFullStripesIsFound) {
  // beta = 0.02 with stripes 7 beta apart in ln IM: only the two stripes at s = -3.65, +3.65 are
  // partial; the rest are 0 or n and lie at |s| up to 70, deep in the tails of Phi. With n = 1e12
  // runs the likelihood's gradient is ~1e12 times its curvature scale, which an unscaled L-BFGS
  // does not survive. The rounded counts are the curve to 5e-13, i.e. s to ~1e-9.
  const double median = 2.0, log_std = 0.02;
  const std::vector<double> levels = geometric_levels(0.5, 8.0, 20);
  std::vector<std::int64_t> trials(levels.size(), 1'000'000'000'000), counts;
  for (double level : levels)
    counts.push_back(std::llround(1e12 * standard_normal_cdf(std::log(level / median) / log_std)));
  ASSERT_EQ(std::count_if(counts.begin(), counts.end(), [](auto z) { return z > 0 && z < 1'000'000'000'000; }), 2);
  const LognormalFit fit = fit_lognormal(levels, trials, counts);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  EXPECT_NEAR(fit.median / median - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(fit.log_std / log_std - 1.0, 0.0, 1e-7);
  EXPECT_TRUE(std::isfinite(fit.log_likelihood));
}

TEST(FitLognormal, LargeBinomialSampleGivesTheTruthToTheStandardError) {
  const double median = 0.5, log_std = 0.4;
  const std::vector<double> levels = geometric_levels(0.15, 1.5, 15);
  const std::vector<std::int64_t> trials(levels.size(), 10'000'000);
  std::mt19937_64 generator(20150101);
  const auto counts = binomial_draws(levels, trials[0], median, log_std, generator);
  const LognormalFit fit = fit_lognormal(levels, trials, counts);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  const auto se = standard_errors(levels, trials, median, log_std);
  std::printf("n = 1e7 per stripe: median %.6f (se %.1e), log_std %.6f (se %.1e)\n", fit.median, se[0] * median,
              fit.log_std, se[1] * log_std);
  EXPECT_NEAR(fit.median, median, 1e-3);
  EXPECT_NEAR(fit.log_std, log_std, 1e-3);
  EXPECT_LT(std::abs(std::log(fit.median / median)), 4.0 * se[0]);
  EXPECT_LT(std::abs(std::log(fit.log_std / log_std)), 4.0 * se[1]);
}

TEST(FitLognormal, ErrorsMatchTheFisherInformationOverManySamples) {
  // 400 independent data sets of 15 stripes x 100 runs: the errors of (ln median, ln log_std),
  // divided by the Fisher-information standard errors, must look standard normal.
  const double median = 0.5, log_std = 0.4;
  const std::vector<double> levels = geometric_levels(0.15, 1.5, 15);
  const std::vector<std::int64_t> trials(levels.size(), 100);
  const auto se = standard_errors(levels, trials, median, log_std);
  const int samples = 400;
  std::mt19937_64 generator(7);
  std::array<double, 2> sum = {0, 0}, sum_squares = {0, 0}, largest = {0, 0};
  for (int sample = 0; sample < samples; ++sample) {
    const auto counts = binomial_draws(levels, trials[0], median, log_std, generator);
    const LognormalFit fit = fit_lognormal(levels, trials, counts);
    ASSERT_TRUE(fit.fitted) << fit.reason;
    const std::array<double, 2> error = {std::log(fit.median / median) / se[0],
                                         std::log(fit.log_std / log_std) / se[1]};
    for (int k = 0; k < 2; ++k) {
      sum[k] += error[k];
      sum_squares[k] += error[k] * error[k];
      largest[k] = std::max(largest[k], std::abs(error[k]));
    }
  }
  for (int k = 0; k < 2; ++k) {
    const double mean = sum[k] / samples;
    const double spread = std::sqrt(sum_squares[k] / samples - mean * mean);
    std::printf("%s: mean error %.3f se, spread %.3f se, largest %.2f se\n", k == 0 ? "ln median" : "ln log_std",
                mean, spread, largest[k]);
    EXPECT_LT(std::abs(mean), 3.0 / std::sqrt(samples));        // 3 sigma of a mean of 400
    EXPECT_LT(std::abs(spread - 1.0), 3.0 / std::sqrt(2.0 * samples));  // 3 sigma of a spread of 400
    EXPECT_LT(largest[k], 4.5);
  }
}

TEST(FitLognormal, DegenerateDataAreNotFitted) {
  struct Case {
    const char* what;
    std::vector<double> levels;
    std::vector<std::int64_t> trials, counts;
    const char* reason_contains;
  };
  const std::vector<Case> cases = {
      {"no stripes", {}, {}, {}, "no stripe"},
      {"no runs", {0.2, 0.4}, {0, 0}, {0, 0}, "no stripe"},
      {"no exceedances", {0.2, 0.4, 0.8}, {50, 50, 50}, {0, 0, 0}, "no exceedances"},
      {"all exceed", {0.2, 0.4, 0.8}, {50, 50, 50}, {50, 50, 50}, "every run"},
      {"step", {0.2, 0.4, 0.8, 1.6}, {50, 50, 50, 50}, {0, 0, 50, 50}, "separated"},
      {"one stripe", {0.4}, {50}, {20}, "only one stripe"},
      {"partial between zeros and all", {0.2, 0.4, 0.8}, {50, 50, 50}, {0, 20, 50}, "log_std -> 0"},
      {"decreasing", {0.2, 0.4, 0.8}, {100, 100, 100}, {70, 50, 30}, "log_std"},
      {"flat", {0.2, 0.4, 0.8}, {100, 100, 100}, {50, 50, 50}, "log_std"},
  };
  for (const Case& c : cases) {
    const LognormalFit fit = fit_lognormal(c.levels, c.trials, c.counts);
    EXPECT_FALSE(fit.fitted) << c.what;
    EXPECT_NE(fit.reason.find(c.reason_contains), std::string::npos) << c.what << ": " << fit.reason;
    EXPECT_TRUE(std::isfinite(fit.median) && std::isfinite(fit.log_std) && std::isfinite(fit.log_likelihood))
        << c.what;
    EXPECT_EQ(fragility_probability(fit, 0.5), 0.0) << c.what;
    const Misfit check = misfit(fit, {});
    EXPECT_EQ(check.degrees_of_freedom, 0) << c.what;
  }
  EXPECT_THROW(fit_lognormal({0.2, 0.4}, {10}, {1}), std::invalid_argument);
  EXPECT_THROW(fit_lognormal({0.2, 0.4}, {10, 10}, {1, 11}), std::invalid_argument);
  EXPECT_THROW(fit_lognormal({0.0, 0.4}, {10, 10}, {1, 5}), std::invalid_argument);
}

TEST(FitLognormal, AReasonNamesTheLevelsInTheUsersUnit) {
  // PGA stripes at 0.2, 0.4, 0.8 g, held in m/s^2: the reason a step is not fitted says g.
  const std::vector<double> levels = {units::g_to_si(0.2), units::g_to_si(0.4), units::g_to_si(0.8)};
  const auto in_g = [](double level) { return intensity_text(IntensityMeasure::pga, level); };
  const LognormalFit step = fit_lognormal(levels, {50, 50, 50}, {0, 0, 50}, in_g);
  ASSERT_FALSE(step.fitted);
  EXPECT_NE(step.reason.find("none exceed up to 0.4 g, all exceed from 0.8 g"), std::string::npos) << step.reason;
  const LognormalFit partial = fit_lognormal(levels, {50, 50, 50}, {0, 20, 50}, in_g);
  EXPECT_NE(partial.reason.find("only one stripe (0.4 g)"), std::string::npos) << partial.reason;
  // PGV in cm/s; and without a unit, the number as given.
  const LognormalFit pgv = fit_lognormal({0.2, 0.4}, {50, 50}, {0, 50},
                                         [](double level) { return intensity_text(IntensityMeasure::pgv, level); });
  EXPECT_NE(pgv.reason.find("up to 20 cm/s, all exceed from 40 cm/s"), std::string::npos) << pgv.reason;
  EXPECT_NE(fit_lognormal({0.2, 0.4}, {50, 50}, {0, 50}).reason.find("up to IM 0.2, all exceed from IM 0.4"),
            std::string::npos);
}

TEST(FitLognormal, SparseExceedancesStillFitWithFiniteValues) {
  // One exceedance in a low stripe amid zeros: not separated, so fittable, with the stripes at
  // 0.01 and 100 far in the tails of the fitted curve.
  const LognormalFit fit =
      fit_lognormal({0.01, 0.1, 1.0, 10.0, 100.0}, {1000, 1000, 1000, 1000, 1000}, {0, 1, 0, 999, 1000});
  ASSERT_TRUE(fit.fitted) << fit.reason;
  EXPECT_TRUE(std::isfinite(fit.log_likelihood));
  EXPECT_GT(fit.median, 1.0);
  EXPECT_LT(fit.median, 10.0);
}

// --- Bootstrap -------------------------------------------------------------------------------

// Motions with their own median (record-to-record scatter beta_record) and runs scattered about
// it by beta_run, the way an ensemble's realisations vary with sampled parameters.
StripeData record_data(int motions, int runs, std::uint64_t seed) {
  const double median = 0.5, beta_record = 0.3, beta_run = 0.25;
  StripeData data;
  data.levels = geometric_levels(0.15, 1.5, 10);
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> scatter;
  for (int m = 0; m < motions; ++m) {
    const double record_median = median * std::exp(beta_record * scatter(generator));
    data.trials.emplace_back(data.levels.size(), runs);
    data.counts.push_back(binomial_draws(data.levels, runs, record_median, beta_run, generator));
  }
  return data;
}

StripeData pooled_into_one_motion(const StripeData& data) {
  StripeData pooled;
  pooled.levels = data.levels;
  pooled.trials.emplace_back(data.levels.size(), 0);
  pooled.counts.emplace_back(data.levels.size(), 0);
  for (std::size_t m = 0; m < data.trials.size(); ++m)
    for (std::size_t j = 0; j < data.levels.size(); ++j) {
      pooled.trials[0][j] += data.trials[m][j];
      pooled.counts[0][j] += data.counts[m][j];
    }
  return pooled;
}

LognormalFit fit_totals(const StripeData& data) {
  const StripeData pooled = pooled_into_one_motion(data);
  return fit_lognormal(pooled.levels, pooled.trials[0], pooled.counts[0]);
}

double mean_width(const Band& band) {
  double total = 0.0;
  for (std::size_t i = 0; i < band.im.size(); ++i) total += band.upper[i] - band.lower[i];
  return total / static_cast<double>(band.im.size());
}

TEST(BootstrapBand, IsReproducibleForASeedAndContainsTheFit) {
  const StripeData data = record_data(20, 50, 11);
  const std::vector<double> grid = geometric_levels(0.1, 2.0, 25);
  const Band band = bootstrap_band(data, grid, 500, 0.9, 42);
  const Band again = bootstrap_band(data, grid, 500, 0.9, 42);
  const Band other = bootstrap_band(data, grid, 500, 0.9, 43);
  EXPECT_EQ(band.resampled, "records");
  EXPECT_EQ(band.replicates + band.failed_replicates, 500);
  EXPECT_EQ(band.replicates, 500);
  EXPECT_EQ(band.im, grid);
  EXPECT_EQ(band.lower, again.lower);
  EXPECT_EQ(band.upper, again.upper);
  EXPECT_NE(band.lower, other.lower);
  EXPECT_NE(band.upper, other.upper);

  // Motions without runs (not simulated yet) are not resampled: the band is unchanged.
  StripeData with_empty = data;
  with_empty.trials.insert(with_empty.trials.begin() + 3, std::vector<std::int64_t>(data.levels.size(), 0));
  with_empty.counts.insert(with_empty.counts.begin() + 3, std::vector<std::int64_t>(data.levels.size(), 0));
  with_empty.trials.emplace_back(data.levels.size(), 0);
  with_empty.counts.emplace_back(data.levels.size(), 0);
  const Band padded = bootstrap_band(with_empty, grid, 500, 0.9, 42);
  EXPECT_EQ(padded.lower, band.lower);
  EXPECT_EQ(padded.upper, band.upper);

  const LognormalFit fit = fit_totals(data);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_LE(band.lower[i], fragility_probability(fit, grid[i])) << grid[i];
    EXPECT_GE(band.upper[i], fragility_probability(fit, grid[i])) << grid[i];
    EXPECT_LE(band.lower[i], band.upper[i]);
  }
}

TEST(BootstrapBand, NarrowsWithMoreRecordsAndIsWiderThanResamplingRuns) {
  const std::vector<double> grid = geometric_levels(0.1, 2.0, 25);
  const StripeData few = record_data(20, 50, 5);
  const StripeData many = record_data(80, 50, 6);
  const double few_width = mean_width(bootstrap_band(few, grid, 400, 0.9, 1));
  const double many_width = mean_width(bootstrap_band(many, grid, 400, 0.9, 1));
  // width ~ 1 / sqrt(records): ratio ~ 2, each width with ~16 % sampling scatter (20 records)
  std::printf("mean 90 %% band width: 20 records %.4f, 80 records %.4f, ratio %.2f\n", few_width, many_width,
              few_width / many_width);
  EXPECT_GT(few_width / many_width, 1.3);
  EXPECT_LT(few_width / many_width, 3.0);

  // The same runs pooled into one motion: resampling runs ignores the record-to-record scatter
  // (beta_record = 0.3 against beta_run = 0.25), so its band is much narrower.
  const Band runs_band = bootstrap_band(pooled_into_one_motion(few), grid, 400, 0.9, 1);
  EXPECT_EQ(runs_band.resampled, "realisations");
  std::printf("20 records, resampled as runs: %.4f\n", mean_width(runs_band));
  EXPECT_GT(few_width, 1.5 * mean_width(runs_band));
}

TEST(BootstrapBand, SingleMotionMatchesTheDeltaMethodAtTheMedian) {
  // Resampling the runs of one motion is the binomial bootstrap of the MLE; at IM = median
  // (s = 0) the curve's standard error is phi(0) se(ln median) / beta (delta method), so the
  // 95 % band there is +-1.96 of it.
  StripeData data;
  data.levels = geometric_levels(0.15, 1.5, 15);
  data.trials = {std::vector<std::int64_t>(data.levels.size(), 2000)};
  std::mt19937_64 generator(99);
  data.counts = {binomial_draws(data.levels, 2000, 0.5, 0.4, generator)};
  const LognormalFit fit = fit_lognormal(data.levels, data.trials[0], data.counts[0]);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  const auto se = standard_errors(data.levels, data.trials[0], fit.median, fit.log_std);
  const double expected_width = 2.0 * probit(0.975) * standard_normal_density(0.0) * se[0] / fit.log_std;

  const Band band = bootstrap_band(data, {fit.median}, 2000, 0.95, 2024);
  EXPECT_EQ(band.resampled, "realisations");
  EXPECT_EQ(band.replicates, 2000);
  const double width = band.upper[0] - band.lower[0];
  std::printf("band width at the median: bootstrap %.5f, delta method %.5f\n", width, expected_width);
  EXPECT_NEAR(width / expected_width, 1.0, 0.1);  // quantile noise of 2000 replicates ~ 2-3 %
  EXPECT_NEAR(0.5 * (band.upper[0] + band.lower[0]), 0.5, 0.25 * expected_width);
}

TEST(BootstrapBand, UnfittableDataGiveTheWholeRange) {
  StripeData data;
  data.levels = {0.2, 0.4, 0.8};
  data.trials = {{20, 20, 20}, {20, 20, 20}};
  data.counts = {{0, 0, 20}, {0, 0, 20}};
  const Band band = bootstrap_band(data, {0.3, 0.6}, 50, 0.9, 1);
  EXPECT_EQ(band.replicates, 0);
  EXPECT_EQ(band.failed_replicates, 50);
  EXPECT_EQ(band.lower, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(band.upper, (std::vector<double>{1.0, 1.0}));

  data.counts[1].pop_back();  // a motion without an entry per stripe
  EXPECT_THROW(bootstrap_band(data, {0.3}, 10, 0.9, 1), std::invalid_argument);
  EXPECT_THROW(stripe_probabilities(data, 0.9), std::invalid_argument);
}

// --- Misfit ----------------------------------------------------------------------------------

TEST(Misfit, DataOnTheCurveHaveNoMisfit) {
  StripeData data;
  data.levels = geometric_levels(0.15, 1.5, 12);
  data.trials = {std::vector<std::int64_t>(data.levels.size(), 1'000'000'000)};
  data.counts.emplace_back();
  for (double level : data.levels)
    data.counts[0].push_back(std::llround(1e9 * standard_normal_cdf(std::log(level / 0.5) / 0.4)));
  const LognormalFit fit = fit_lognormal(data.levels, data.trials[0], data.counts[0]);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  const Misfit check = misfit(fit, stripe_probabilities(data, 0.95));
  std::printf("exact data: max |dP| %.2e, chi-square %.2e, p %.6f\n", check.max_abs_difference, check.chi_square,
              check.p_value);
  EXPECT_LT(check.max_abs_difference, 1e-9);  // rounding to integers: 5e-10
  EXPECT_EQ(check.stripes_outside_interval, 0);
  EXPECT_EQ(check.degrees_of_freedom, 10);
  EXPECT_LT(check.chi_square, 1e-3);
  EXPECT_GT(check.p_value, 0.999);
}

TEST(Misfit, ChiSquareAndPValueFollowTheirDefinitions) {
  // Four stripes: two degrees of freedom, where the chi-square survival is exp(-x / 2).
  StripeData data;
  data.levels = {0.2, 0.4, 0.6, 1.0};
  data.trials = {{40, 40, 40, 40}};
  data.counts = {{3, 18, 22, 35}};
  const LognormalFit fit = fit_lognormal(data.levels, data.trials[0], data.counts[0]);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  const auto stripes = stripe_probabilities(data, 0.95);
  double chi_square = 0.0, largest = 0.0;
  int outside = 0;
  for (const StripeProbability& stripe : stripes) {
    const double p = standard_normal_cdf(std::log(stripe.level / fit.median) / fit.log_std);
    const double residual = static_cast<double>(stripe.count) - stripe.trials * p;
    chi_square += residual * residual / (stripe.trials * p * (1.0 - p));
    largest = std::max(largest, std::abs(p - stripe.probability));
    outside += (p < stripe.lower || p > stripe.upper) ? 1 : 0;
  }
  const Misfit check = misfit(fit, stripes);
  EXPECT_EQ(check.degrees_of_freedom, 2);
  EXPECT_NEAR(check.chi_square, chi_square, 1e-12 * chi_square);
  EXPECT_NEAR(check.p_value, std::exp(-0.5 * chi_square), 1e-12);
  EXPECT_NEAR(check.max_abs_difference, largest, 1e-15);
  EXPECT_EQ(check.stripes_outside_interval, outside);
  std::printf("4 stripes: chi-square %.4f, p %.4f\n", check.chi_square, check.p_value);
}

TEST(Misfit, PValuesOfDataFromTheModelAreCalibrated) {
  // Binomial data from the model: about 5 % of the p-values below 0.05.
  const std::vector<double> levels = geometric_levels(0.15, 1.5, 12);
  StripeData data;
  data.levels = levels;
  data.trials = {std::vector<std::int64_t>(levels.size(), 200)};
  std::mt19937_64 generator(3);
  const int samples = 400;
  int rejected = 0;
  for (int sample = 0; sample < samples; ++sample) {
    data.counts = {binomial_draws(levels, 200, 0.5, 0.4, generator)};
    const LognormalFit fit = fit_lognormal(levels, data.trials[0], data.counts[0]);
    ASSERT_TRUE(fit.fitted) << fit.reason;
    rejected += misfit(fit, stripe_probabilities(data, 0.95)).p_value < 0.05 ? 1 : 0;
  }
  const double rate = static_cast<double>(rejected) / samples;
  std::printf("rejection rate at 5 %%: %.3f\n", rate);
  EXPECT_NEAR(rate, 0.05, 3.0 * std::sqrt(0.05 * 0.95 / samples));
}

TEST(Misfit, AStepShapedCurveIsRejected) {
  // 5 % exceed below 0.5 g and 95 % above: no lognormal curve has flat shoulders and a jump.
  StripeData data;
  data.levels = geometric_levels(0.15, 1.5, 15);
  data.trials = {std::vector<std::int64_t>(data.levels.size(), 500)};
  data.counts.emplace_back();
  for (double level : data.levels) data.counts[0].push_back(level < 0.5 ? 25 : 475);
  const LognormalFit fit = fit_lognormal(data.levels, data.trials[0], data.counts[0]);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  const Misfit check = misfit(fit, stripe_probabilities(data, 0.95));
  std::printf("step: max |dP| %.3f, chi-square %.1f (dof %d), p %.2e, %d stripes outside\n",
              check.max_abs_difference, check.chi_square, check.degrees_of_freedom, check.p_value,
              check.stripes_outside_interval);
  EXPECT_EQ(check.degrees_of_freedom, 13);
  EXPECT_GT(check.chi_square, 35.0);  // the 0.999 quantile of chi-square(13) is 34.5
  EXPECT_LT(check.p_value, 1e-10);
  EXPECT_GT(check.max_abs_difference, 0.1);
  EXPECT_GE(check.stripes_outside_interval, 8);  // most of the 15: the shoulders are flat
}

}  // namespace
}  // namespace caskdem::fragility
