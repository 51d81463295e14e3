#pragma once
// How every model of a diagnosis is judged (diagnose.h): the yardstick (each test's tolerances
// and the table inputs it is simulated with), the training objective J over a population of
// points, every test's loss and residuals at one point, the held-out error and the
// information criteria. Shared by the diagnosis's steps (diagnose.cpp), not a user's API.

#include <cstddef>
#include <vector>

#include "diagnosis/diagnose.h"
#include "diagnosis/fitting.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/measures.h"
#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

// The tolerances every model of a diagnosis is judged by: from the measurements, widened by
// each test's own predictability around the specimen's nominal parameters.
inline constexpr int kPredictabilityRealisations = 8;

// What every model of a diagnosis is judged by: each test's tolerances and the table inputs it
// is simulated with (the measured channel, then noisy copies; measures.h, marginal_loss).
struct Yardstick {
  std::vector<TestReference> references;          // per test
  std::vector<std::vector<MeasuredTest>> inputs;  // per test, per input realisation
  std::vector<int> predictable_training;          // the training tests that are predictable
};

Yardstick yardstick_of(const MeasuredSet& set, const DiagnosisOptions& options);

// Every test's loss and residuals at one point. The residuals are those of the input
// realisation whose response lands nearest the measured one (the measured channel's, R = 1).
struct Judged {
  std::vector<double> loss;                            // per test
  std::vector<std::vector<double>> residuals;          // per test, per measure
  std::vector<std::vector<double>> heldout_tolerance;  // per test, per measure (judge_at; held-out tests only)
};

// J for every point over the given tests; each (test, input realisation) runs as one block of
// lanes, in parallel. With `first_point`, the first point's losses and residuals per test.
std::vector<double> objective_over(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant,
                                   const std::vector<int>& tests, const std::vector<std::vector<double>>& points,
                                   const DiagnosisOptions& options, Judged* first_point = nullptr);

// The scaled residuals that the losses of some tests sum: every compared measure of each.
int residual_count(const Yardstick& yardstick, const std::vector<int>& tests);

// The error over some tests: sqrt of the mean loss per residual (the RMS of the residuals where
// they are within a few tolerances).
double error_of(const std::vector<double>& loss, const Yardstick& yardstick, const std::vector<int>& tests);

// Every test's loss and residuals at one point (the tests in parallel). The held-out tests are
// judged as predictions: with the standard errors of the fit the point comes from, their
// tolerances also allow the spread of the model's prediction over those errors (none given:
// the point alone).
Judged judge_at(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant,
                const std::vector<double>& point, const std::vector<double>& standard_error,
                const DiagnosisOptions& options);

// Information criteria of a fit with loss J over n residuals and k parameters (diagnose.h).
double bic_of(double j, double n, std::size_t k);
double aic_of(double j, double n, std::size_t k);

// The search effort the data set's [diagnosis] table asks for.
FitOptions fit_options_of(const MeasuredSet& set);

}  // namespace caskdem::diagnosis
