// The lockstep fitter on objectives with known answers: it finds the minimum of a quadratic
// bowl, evaluates its searches as populations (several points per call), its standard errors
// equal the bowl's widths, on linear and logarithmic parameters alike, its starts reach a
// narrow well beside a broad bowl, an earlier fit's point searched also never leaves it above the
// fit without that point, and its jackknife over clusters gives the standard error of a mean
// exactly.

#include <cmath>
#include <mutex>

#include <gtest/gtest.h>

#include "diagnosis/fitting.h"

namespace caskdem::diagnosis {
namespace {

TEST(Fitting, FindsTheMinimumOfABowlAndItsWidths) {
  // J = J0 + ((x0 - 3.7)/0.2)^2 + ((ln x1 - ln 2)/0.1)^2 + ((x2 + 1)/0.5)^2 with J0 = N - k, so the
  // residual variance J*/(N - k) is 1 and the covariance 2 H^-1 is diagonal: 0.2^2, 0.1^2, 0.5^2
  // (the second in ln x1: a standard error of 2 * 0.1 in x1).
  const std::vector<Parameter> space = {
      {"a", "", 0.0, 10.0, false, 5.0}, {"b", "", 0.01, 100.0, true, 1.0}, {"c", "", -5.0, 5.0, false, 0.0}};
  const int residuals = 20;
  const double floor = residuals - 3;
  int calls = 0, points = 0;
  std::mutex count;
  const PopulationObjective bowl = [&](const std::vector<std::vector<double>>& population) {
    {
      std::lock_guard<std::mutex> lock(count);
      ++calls;
      points += static_cast<int>(population.size());
    }
    std::vector<double> values;
    for (const auto& x : population) {
      const double a = (x[0] - 3.7) / 0.2, b = (std::log(x[1]) - std::log(2.0)) / 0.1, c = (x[2] + 1.0) / 0.5;
      values.push_back(floor + a * a + b * b + c * c);
    }
    return values;
  };
  FitOptions options;
  options.starts = 6;
  options.evaluations = 120;
  const FitResult fit = fit_parameters(space, {{5.0, 1.0, 0.0}}, bowl, options, residuals);
  EXPECT_NEAR(fit.best[0], 3.7, 1e-3);
  EXPECT_NEAR(fit.best[1], 2.0, 1e-3);
  EXPECT_NEAR(fit.best[2], -1.0, 1e-3);
  EXPECT_NEAR(fit.objective, floor, 1e-4);
  ASSERT_EQ(fit.standard_error.size(), 3u);
  // Central differences are exact for a quadratic in unit coordinates (x0, x2, ln x1).
  EXPECT_NEAR(fit.standard_error[0], 0.2, 1e-6);
  EXPECT_NEAR(fit.standard_error[1], 2.0 * 0.1, 1e-3);
  EXPECT_NEAR(fit.standard_error[2], 0.5, 1e-6);
  // The six searches ran in lockstep: populations of several points.
  EXPECT_EQ(fit.evaluations, points);
  EXPECT_EQ(fit.populations, calls);
  EXPECT_GT(double(points) / calls, 3.0);
}

TEST(Fitting, SameResultEveryTime) {
  const std::vector<Parameter> space = {{"a", "", -2.0, 2.0, false, 0.0}, {"b", "", -2.0, 2.0, false, 0.0}};
  // A wavy objective with several local minima: the searches' order must not depend on threads.
  const PopulationObjective wavy = [](const std::vector<std::vector<double>>& population) {
    std::vector<double> values;
    for (const auto& x : population) {
      values.push_back(x[0] * x[0] + x[1] * x[1] + 0.5 * std::sin(5.0 * x[0]) * std::cos(4.0 * x[1]));
    }
    return values;
  };
  FitOptions options;
  options.starts = 8;
  options.evaluations = 80;
  const FitResult first = fit_parameters(space, {{1.0, 1.0}}, wavy, options, 10);
  for (int repeat = 0; repeat < 5; ++repeat) {
    const FitResult again = fit_parameters(space, {{1.0, 1.0}}, wavy, options, 10);
    EXPECT_EQ(again.best, first.best);
    EXPECT_EQ(again.evaluations, first.evaluations);
  }
}

TEST(Fitting, StartsSpreadOverTheBasinsExplored) {
  // A broad bowl around a = (-1, -1) beside a narrower, deeper well at b = (1.2, 1.2):
  // J = 0.5 |x - a|^2 - 6 exp(-|x - b|^2 / (2 0.6^2)), whose minimum is in the well, at
  // x = y = 1.0698 (J = -1.4399, where the bowl's pull balances the well's; against J(a) = 0).
  // The sample's best points all lie in the bowl, so two searches started from the best points
  // both end there; with one start per basin (no better point within half the box) the second
  // starts from the well's best sampled point and finds the minimum.
  const std::vector<Parameter> space = {{"a", "", -2.0, 2.0, false, -1.5}, {"b", "", -2.0, 2.0, false, -1.5}};
  const PopulationObjective bowl_and_well = [](const std::vector<std::vector<double>>& population) {
    std::vector<double> values;
    for (const auto& x : population) {
      const double to_a = (x[0] + 1.0) * (x[0] + 1.0) + (x[1] + 1.0) * (x[1] + 1.0);
      const double to_b = (x[0] - 1.2) * (x[0] - 1.2) + (x[1] - 1.2) * (x[1] - 1.2);
      values.push_back(0.5 * to_a - 6.0 * std::exp(-to_b / (2.0 * 0.6 * 0.6)));
    }
    return values;
  };
  FitOptions options;
  options.starts = 2;
  options.exploration = 64;
  options.evaluations = 60;
  options.standard_errors = false;
  options.basin_radius = 0.0;
  const FitResult crowded = fit_parameters(space, {{-1.5, -1.5}}, bowl_and_well, options, 10);
  EXPECT_NEAR(crowded.best[0], -1.0, 1e-2);  // the best points alone end in the bowl
  options.basin_radius = 0.5;
  const FitResult spread = fit_parameters(space, {{-1.5, -1.5}}, bowl_and_well, options, 10);
  EXPECT_NEAR(spread.best[0], 1.0698, 2e-3);
  EXPECT_NEAR(spread.best[1], 1.0698, 2e-3);
  EXPECT_NEAR(spread.objective, -1.4399, 1e-4);
  EXPECT_TRUE(spread.standard_error.empty());  // none asked for
}

// An earlier fit's point searched also (`searched_also`, caskdem diagnose --start-from) ends the
// fit at or below both that point's J and the fit without it. A cone at a = (-1, -1) with its
// minimum 0 (no quadratic model fits it, so short searches stop short of the bottom), beside a
// well, another cone, at b = (1.5, 1.5) with its minimum J_b between what the first cone's search
// reaches in the first round and after the second: with searches this short the first round
// stops above that cone's bottom, and the second round, around its end, goes lower. The earlier
// point, the well's bottom, ends the first round lowest; a second round only around it would
// leave the fit at J_b, above the fit without it.
TEST(Fitting, AnEarlierPointNeverLeavesTheFitAboveTheFitWithoutIt) {
  const std::vector<Parameter> space = {{"a", "", -2.0, 2.0, false, -1.5}, {"b", "", -2.0, 2.0, false, -1.5}};
  double well_bottom = 0.0;
  const PopulationObjective bowl_and_well = [&](const std::vector<std::vector<double>>& population) {
    std::vector<double> values;
    for (const auto& x : population) {
      const double to_a = (x[0] + 1.0) * (x[0] + 1.0) + (x[1] + 1.0) * (x[1] + 1.0);
      const double to_b = (x[0] - 1.5) * (x[0] - 1.5) + (x[1] - 1.5) * (x[1] - 1.5);
      values.push_back(std::min(std::sqrt(to_a), well_bottom + std::sqrt(to_b)));
    }
    return values;
  };
  FitOptions options;
  options.starts = 1;
  options.exploration = 16;
  options.evaluations = 8;
  options.standard_errors = false;
  well_bottom = 1e9;  // no well: the first cone alone
  options.refinement = 0;
  const FitResult first_round = fit_parameters(space, {{-1.5, -1.5}}, bowl_and_well, options, 10);
  options.refinement = 96;
  const FitResult cold = fit_parameters(space, {{-1.5, -1.5}}, bowl_and_well, options, 10);
  RecordProperty("J after the first round", std::to_string(first_round.objective));
  RecordProperty("J of the fit", std::to_string(cold.objective));
  ASSERT_LT(cold.objective, 0.5 * first_round.objective) << "the second round must go lower, or the case is not made";
  ASSERT_LT(first_round.objective, 1.0) << "the first round must reach the bowl";

  well_bottom = 0.5 * (first_round.objective + cold.objective);
  const FitResult without = fit_parameters(space, {{-1.5, -1.5}}, bowl_and_well, options, 10);
  EXPECT_EQ(without.best, cold.best) << "the well lies beyond the bowl's searches";
  const FitResult started = fit_parameters(space, {{-1.5, -1.5}}, bowl_and_well, options, 10, {{1.5, 1.5}});
  EXPECT_LE(started.objective, well_bottom);
  EXPECT_LE(started.objective, without.objective);
  EXPECT_EQ(started.best, without.best);
  EXPECT_GT(started.evaluations, without.evaluations) << "the well was searched, and around it";
}

TEST(Fitting, NoStandardErrorForAValueOnItsSearchBound) {
  // The bowl's minimum in a lies beyond the box (a = 3 against a high of 2): the fit stops on the
  // bound, where the curvature says nothing of a's uncertainty; b's width is still 0.25.
  const std::vector<Parameter> space = {{"a", "", 0.0, 2.0, false, 1.0}, {"b", "", -2.0, 2.0, false, 0.0}};
  const int residuals = 12;
  const PopulationObjective beyond = [&](const std::vector<std::vector<double>>& population) {
    std::vector<double> values;
    for (const auto& x : population) {
      const double a = (x[0] - 3.0) / 0.5, b = (x[1] - 0.5) / 0.25;
      values.push_back(residuals - 2 + a * a + b * b);
    }
    return values;
  };
  FitOptions options;
  options.starts = 2;
  options.evaluations = 80;
  const FitResult fit = fit_parameters(space, {{1.0, 0.0}}, beyond, options, residuals);
  EXPECT_DOUBLE_EQ(fit.best[0], 2.0);
  EXPECT_TRUE(at_search_bound(space[0], fit.best[0]));
  EXPECT_FALSE(at_search_bound(space[1], fit.best[1]));
  EXPECT_FALSE(standard_error_of(fit, space, 0).has_value());
  ASSERT_TRUE(standard_error_of(fit, space, 1).has_value());
  // J* = residuals - 2 + 4 on the bound, so the variance J*/(N - k) is 1.4 and SE = 0.25 sqrt(1.4).
  EXPECT_NEAR(*standard_error_of(fit, space, 1), 0.25 * std::sqrt(1.4), 1e-3);
}

TEST(Fitting, JackknifeOverClustersIsTheStandardErrorOfTheirMean) {
  // Cluster t pulls x to m_t and ln y to ln c_t: J_t = (x - m_t)^2 + ((ln y - ln c_t) / 0.1)^2.
  // Without cluster t the optimum is the others' mean, and the jackknife's standard error of a
  // mean is exactly sd / sqrt(G): for x, that of m; for y, y* times that of ln c.
  const std::vector<double> m = {1.0, 1.3, 0.8, 1.6, 1.1}, c = {2.0, 2.5, 1.8, 2.2, 3.0};
  const int clusters = static_cast<int>(m.size());
  const std::vector<Parameter> space = {{"x", "", 0.0, 4.0, false, 2.0}, {"y", "", 0.1, 10.0, true, 1.0}};
  const LeaveOneOutObjective objective = [&](const std::vector<std::vector<double>>& points, int left_out) {
    std::vector<double> values;
    for (const auto& p : points) {
      double j = 0.0;
      for (int t = 0; t < clusters; ++t) {
        if (t == left_out) continue;
        const double b = (std::log(p[1]) - std::log(c[t])) / 0.1;
        j += (p[0] - m[t]) * (p[0] - m[t]) + b * b;
      }
      values.push_back(j);
    }
    return values;
  };
  const PopulationObjective all = [&](const std::vector<std::vector<double>>& points) { return objective(points, -1); };
  auto mean_and_sd = [](std::vector<double> v) {
    double mean = 0.0, ss = 0.0;
    for (double x : v) mean += x / double(v.size());
    for (double x : v) ss += (x - mean) * (x - mean);
    return std::pair{mean, std::sqrt(ss / double(v.size() - 1))};
  };
  std::vector<double> log_c;
  for (double v : c) log_c.push_back(std::log(v));
  const auto [mean_m, sd_m] = mean_and_sd(m);
  const auto [mean_log_c, sd_log_c] = mean_and_sd(log_c);
  FitOptions options;
  options.starts = 2;
  options.evaluations = 100;
  // With 1000 residuals the curvature's errors are small (s^2 = J*/998), and the jackknife's win.
  FitResult fit = fit_parameters(space, {{2.0, 1.0}}, all, options, 1000);
  ASSERT_NEAR(fit.best[0], mean_m, 1e-4);
  ASSERT_NEAR(std::log(fit.best[1]), mean_log_c, 1e-4);
  EXPECT_EQ(fit.uncertainty_method, "curvature");
  ASSERT_EQ(fit.standard_error.size(), 2u);
  const std::vector<double> curvature = fit.standard_error;
  jackknife_errors(space, fit, {{2.0, 1.0}}, objective, clusters, options);
  ASSERT_EQ(fit.standard_error.size(), 2u);
  EXPECT_EQ(fit.uncertainty_method, "larger of the jackknife over 5 tests and the curvature");
  EXPECT_NEAR(fit.standard_error[0], sd_m / std::sqrt(double(clusters)), 1e-3);
  EXPECT_NEAR(fit.standard_error[1], fit.best[1] * sd_log_c / std::sqrt(double(clusters)), 1e-3);
  EXPECT_LT(curvature[0], fit.standard_error[0]);
  EXPECT_LT(curvature[1], fit.standard_error[1]);
  // With 10 residuals s^2 = J*/8 is large: x's curvature error, sqrt(s^2 / 5), is the larger and stays.
  FitResult few = fit_parameters(space, {{2.0, 1.0}}, all, options, 10);
  const double curvature_x = few.standard_error.at(0);
  EXPECT_NEAR(curvature_x, std::sqrt(few.objective / 8.0 / 5.0), 1e-4);
  jackknife_errors(space, few, {{2.0, 1.0}}, objective, clusters, options);
  EXPECT_EQ(few.standard_error[0], curvature_x);
}

TEST(Fitting, UnitCoordinatesRoundTrip) {
  const Parameter linear{"x", "", -3.0, 5.0, false, 0.0}, logarithmic{"y", "", 1e-3, 10.0, true, 1.0};
  for (double v : {-3.0, -1.0, 0.0, 4.9}) EXPECT_NEAR(from_unit(linear, to_unit(linear, v)), v, 1e-12);
  for (double v : {1e-3, 0.02, 1.0, 9.0}) EXPECT_NEAR(from_unit(logarithmic, to_unit(logarithmic, v)) / v, 1.0, 1e-12);
}

}  // namespace
}  // namespace caskdem::diagnosis
