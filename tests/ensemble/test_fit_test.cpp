// The fit test with motions clustered (ensemble/fit_test.h) against data whose truth is known:
// stripes drawn from a lognormal curve with each motion's probability beta-distributed about it
// (a known intraclass correlation), or from a curve of another shape. Its size must be its
// nominal 5 % whether or not the motions differ (where the binomial test's is not), it must
// reject a curve of the wrong shape, and the record-to-record estimate must find the correlation
// the data were made with.

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "ensemble/fit_test.h"

namespace caskdem::fragility {
namespace {

constexpr double kMedian = 0.5, kBeta = 0.4;

double lognormal(double x) { return 0.5 * std::erfc(-std::log(x / kMedian) / kBeta / std::sqrt(2.0)); }

// Stripes at 10 levels from 0.15 to 1.6, `motions` motions of `runs` realisations each; a
// motion's probability at a stripe drawn from the beta law of mean truth(x) and correlation rho.
template <class Truth>
std::vector<Cell> sample(Truth&& truth, int motions, int runs, double rho, std::mt19937_64& random) {
  std::vector<Cell> cells;
  for (int j = 0; j < 10; ++j) {
    const double level = 0.15 * std::pow(1.6 / 0.15, j / 9.0);
    const double p = truth(level);
    for (int m = 0; m < motions; ++m) {
      double q = p;
      if (rho > 0.0) {
        std::gamma_distribution<double> ga(p * (1.0 - rho) / rho), gb((1.0 - p) * (1.0 - rho) / rho);
        const double x = ga(random), y = gb(random);
        q = x + y > 0.0 ? x / (x + y) : p;
      }
      std::binomial_distribution<std::int64_t> draw(runs, q);
      cells.push_back({j, level, runs, draw(random)});
    }
  }
  return cells;
}

struct Rates {
  double clustered = 0.0, binomial = 0.0, rho = 0.0;
  int datasets = 0;
};

template <class Truth>
Rates rejection_rates(Truth&& truth, int motions, int runs, double rho, int datasets, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  Rates rates;
  for (int d = 0; d < datasets; ++d) {
    const std::vector<Cell> cells = sample(truth, motions, runs, rho, random);
    const LognormalFit fit = fit_cells(cells);
    if (!fit.fitted) continue;
    const FitTest test = test_fit(fit, cells, 99, seed + d);
    ++rates.datasets;
    rates.clustered += test.rejected;
    rates.binomial += test.binomial_p < kRejectionLevel;
    rates.rho += test.record_to_record;
  }
  rates.clustered /= rates.datasets;
  rates.binomial /= rates.datasets;
  rates.rho /= rates.datasets;
  return rates;
}

// With 100 datasets a true 5 % rejection rate lies in [0.01, 0.10] with 97 % probability.
TEST(FitTest, HoldsItsSizeWhenTheMotionsDoNotDiffer) {
  const Rates r = rejection_rates(lognormal, 8, 10, 0.0, 100, 11);
  std::printf("independent runs: rejected %.3f (binomial %.3f), rho %.3f\n", r.clustered, r.binomial, r.rho);
  EXPECT_GE(r.clustered, 0.01);
  EXPECT_LE(r.clustered, 0.10);
  EXPECT_LE(r.rho, 0.05);
}

// The main job's design (8 motions of 10 runs) with the motions differing as records do: the
// binomial test rejects the true curve most of the time, the clustered one at its 5 %.
TEST(FitTest, HoldsItsSizeWhenTheMotionsDifferWhereTheBinomialTestFails) {
  const Rates r = rejection_rates(lognormal, 8, 10, 0.3, 100, 12);
  std::printf("rho 0.3: rejected %.3f (binomial %.3f), rho estimated %.3f\n", r.clustered, r.binomial, r.rho);
  EXPECT_GE(r.clustered, 0.01);
  EXPECT_LE(r.clustered, 0.10);
  EXPECT_GE(r.binomial, 0.3) << "the binomial test takes record-to-record scatter for misfit";
}

// A curve of another shape (two populations: half the casks fail early, half late) is rejected.
TEST(FitTest, RejectsACurveOfTheWrongShape) {
  const auto mixture = [](double x) {
    const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
    return 0.5 * phi(std::log(x / 0.25) / 0.1) + 0.5 * phi(std::log(x / 1.2) / 0.1);
  };
  const Rates r = rejection_rates(mixture, 8, 10, 0.05, 20, 13);
  std::printf("two populations: rejected %.3f (binomial %.3f)\n", r.clustered, r.binomial);
  EXPECT_GE(r.clustered, 0.8);
}

// The ANOVA estimate of the intraclass correlation finds the correlation the data were made
// with (many motions, so that its own scatter is small).
TEST(FitTest, RecordToRecordFindsTheCorrelationOfTheData) {
  for (double rho : {0.1, 0.3, 0.5}) {
    std::mt19937_64 random(14);
    const std::vector<Cell> cells = sample(lognormal, 60, 40, rho, random);
    const LognormalFit fit = fit_cells(cells);
    ASSERT_TRUE(fit.fitted);
    const FitTest test = test_fit(fit, cells, 0, 1);
    EXPECT_TRUE(test.record_to_record_estimated);
    EXPECT_NEAR(test.record_to_record, rho, 0.06) << "rho " << rho;
    EXPECT_NEAR(test.design_effect, 1.0 + 39.0 * test.record_to_record, 1e-9);
  }
}

// One motion: nothing to compare motions with, and the test is the binomial one by simulation.
TEST(FitTest, OneMotionIsTestedAsIndependentRuns) {
  std::mt19937_64 random(15);
  const std::vector<Cell> cells = sample(lognormal, 1, 100, 0.0, random);
  const LognormalFit fit = fit_cells(cells);
  ASSERT_TRUE(fit.fitted);
  const FitTest test = test_fit(fit, cells, 199, 3);
  EXPECT_TRUE(test.evaluated);
  EXPECT_FALSE(test.record_to_record_estimated);
  EXPECT_EQ(test.record_to_record, 0.0);
  EXPECT_NEAR(test.p_value, test.binomial_p, 0.15) << "the simulated null is the binomial one";
}

TEST(FitTest, RefusesMalformedCells) {
  const LognormalFit fit{true, "", 0.5, 0.4, 0.0};
  EXPECT_THROW(test_fit(fit, {{0, -1.0, 10, 1}}, 10, 1), std::invalid_argument);
  EXPECT_THROW(test_fit(fit, {{0, 1.0, 10, 11}}, 10, 1), std::invalid_argument);
  EXPECT_FALSE(test_fit(LognormalFit{}, {{0, 1.0, 10, 1}}, 10, 1).evaluated);
}

}  // namespace
}  // namespace caskdem::fragility
