#include "diagnosis/judging.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace caskdem::diagnosis {

namespace {

// A training test is predictable when predictability widened its tolerances by at most this
// factor (geometric mean over its measures): a sine whose response follows its input, not a
// chaotic earthquake test.
constexpr double kPredictableWidening = 2.0;

// Draws of a fit's parameters whose spread widens its held-out tests' tolerances
// (predictability.cpp, add_fit_spread).
constexpr int kFitSpreadDraws = 16;

}  // namespace

Yardstick yardstick_of(const MeasuredSet& set, const DiagnosisOptions& options) {
  const ModelVariant baseline(set.specimen, {}, set.vertical_measured);
  Yardstick y;
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    y.references.push_back(reference_of(set.tests[t], baseline.model().stability_angle));
    y.inputs.push_back(input_realisations(set.tests[t], t, set.settings.input_realisations, set.settings.seed));
  }
  std::vector<std::vector<double>> measurement_tolerance;
  for (const TestReference& r : y.references) measurement_tolerance.push_back(r.tolerance);
  add_predictability(y.references, set.tests, baseline, baseline.reference(), kPredictabilityRealisations,
                     set.settings.seed, options.threads);
  for (int t : set.training) {
    const std::vector<double>& widened = y.references[t].tolerance;
    double log_widening = 0.0;
    for (std::size_t m = 0; m < widened.size(); ++m) log_widening += std::log(widened[m] / measurement_tolerance[t][m]);
    if (log_widening / double(widened.size()) <= std::log(kPredictableWidening)) y.predictable_training.push_back(t);
  }
  return y;
}

// J for every point over the given tests; each (test, input realisation) runs as one block of
// lanes, in parallel.
std::vector<double> objective_over(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant,
                                   const std::vector<int>& tests, const std::vector<std::vector<double>>& points,
                                   const DiagnosisOptions& options, Judged* first_point) {
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  // Every test has as many inputs as the yardstick made for it (input_realisations).
  const std::size_t inputs = yardstick.inputs.front().size();
  const std::size_t runs = tests.size() * inputs;
  std::vector<std::vector<double>> loss(runs, std::vector<double>(points.size(), 0.0));
  std::vector<std::vector<double>> first_residuals(runs);
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t i = 0; i < runs; ++i) {
    try {
      const int t = tests[i / inputs];
      const MeasuredTest& input = yardstick.inputs[t][i % inputs];
      const std::vector<SimulatedHistory> histories = simulate_test(variant, input, points, options.isa);
      for (std::size_t p = 0; p < points.size(); ++p) {
        // Judged against the measured test (its response channels), whatever the input.
        const std::vector<double> r = residuals(set.tests[t], yardstick.references[t],
                                                delayed(histories[p], input.time, variant.sensor_delay(points[p])));
        loss[i][p] = robust_loss(r);
        if (first_point && p == 0) first_residuals[i] = r;
      }
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  if (first_point) {
    first_point->loss.assign(set.tests.size(), 0.0);
    first_point->residuals.assign(set.tests.size(), {});
  }
  // Summed over tests in a fixed order, whatever the threads.
  std::vector<double> total(points.size(), 0.0);
  std::vector<double> per_input(inputs);
  for (std::size_t k = 0; k < tests.size(); ++k) {
    for (std::size_t p = 0; p < points.size(); ++p) {
      for (std::size_t r = 0; r < inputs; ++r) per_input[r] = loss[k * inputs + r][p];
      const double test_loss = marginal_loss(per_input);  // the input's own loss when R = 1
      total[p] += test_loss;
      if (first_point && p == 0) {
        const auto nearest = std::min_element(per_input.begin(), per_input.end()) - per_input.begin();
        first_point->loss[tests[k]] = test_loss;
        first_point->residuals[tests[k]] = first_residuals[k * inputs + nearest];
      }
    }
  }
  return total;
}

// The scaled residuals that the losses of some tests sum: every compared measure of each.
int residual_count(const Yardstick& yardstick, const std::vector<int>& tests) {
  std::size_t count = 0;
  for (int t : tests) count += compared_count(yardstick.references[t]);
  return static_cast<int>(count);
}

// The error over some tests: sqrt of the mean loss per residual (the RMS of the residuals where
// they are within a few tolerances).
double error_of(const std::vector<double>& loss, const Yardstick& yardstick, const std::vector<int>& tests) {
  double sum = 0.0;
  for (int t : tests) sum += loss[t];
  const int count = residual_count(yardstick, tests);
  return count > 0 ? std::sqrt(sum / double(count)) : 0.0;
}

// Every test's loss and residuals at one point (the tests in parallel). The held-out tests are
// judged as predictions: with the standard errors of the fit the point comes from, their
// tolerances also allow the spread of the model's prediction over those errors (none given:
// the point alone).
Judged judge_at(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant,
                const std::vector<double>& point, const std::vector<double>& standard_error,
                const DiagnosisOptions& options) {
  // Every test as the fits see it, but the held-out ones when they are judged as predictions.
  std::vector<int> as_fitted;
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    if (standard_error.empty() || !set.is_heldout(t)) as_fitted.push_back(static_cast<int>(t));
  }
  Judged judged;
  (void)objective_over(set, yardstick, variant, as_fitted, {point}, options, &judged);
  judged.heldout_tolerance.assign(set.tests.size(), {});
  for (int t : set.heldout) judged.heldout_tolerance[t] = yardstick.references[t].tolerance;
  if (!standard_error.empty()) {
    Yardstick predictive = yardstick;
    add_fit_spread(predictive.references, set.tests, set.heldout, variant, point, standard_error, kFitSpreadDraws,
                   set.settings.seed, options.threads);
    Judged heldout;
    (void)objective_over(set, predictive, variant, set.heldout, {point}, options, &heldout);
    for (int t : set.heldout) {
      judged.loss[t] = heldout.loss[t];
      judged.residuals[t] = std::move(heldout.residuals[t]);
      judged.heldout_tolerance[t] = predictive.references[t].tolerance;
    }
  }
  return judged;
}

// Information criteria of a fit with loss J over n residuals and k parameters (diagnose.h).
double bic_of(double j, double n, std::size_t k) {
  return n * std::log(std::max(j, 1e-300) / n) + static_cast<double>(k) * std::log(n);
}
double aic_of(double j, double n, std::size_t k) {
  return n * std::log(std::max(j, 1e-300) / n) + 2.0 * static_cast<double>(k);
}

// The search effort the data set's [diagnosis] table asks for.
FitOptions fit_options_of(const MeasuredSet& set) {
  FitOptions o;
  o.starts = set.settings.starts;
  o.evaluations = set.settings.evaluations;
  o.exploration = set.settings.exploration;
  o.seed = set.settings.seed;
  return o;
}
}  // namespace caskdem::diagnosis
