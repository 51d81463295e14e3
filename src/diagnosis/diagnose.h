#pragma once
// The diagnosis: from measured tests to "this is where the model disagrees, this is the
// most likely physical cause, this is how much the extended model gains on tests it was not
// fitted to".
//
//  1. Calibrate the baseline (friction, damping ratio, stiffness scale) on the training tests.
//  2. Measure its discrepancy on every test (src/diagnosis/measures.h) and look for structure
//     in it: residuals against amplitude, sliding speed, impact speed, rotation sign, vertical
//     acceleration and time (a lag between simulated and measured rotation).
//  3. For each mechanism, fit baseline + mechanism (all parameters) on the training tests.
//  4. Score each on the held-out tests (fractional reduction of the held-out error against
//     the baseline) and by the Bayesian information criterion on the training tests, which
//     charges the extra parameters: with N scaled residuals, their loss J (pseudo-Huber:
//     squares within a few tolerances; src/diagnosis/measures.h) and k parameters,
//     BIC = N ln(J/N) + k ln N (Gaussian residuals of unknown common variance where the loss
//     is quadratic). A test simulated with several table inputs (input_realisations) adds its
//     marginal loss (measures.h) in place of one input's loss. A held-out test is judged as a
//     prediction: its tolerances also allow the spread of the model's response over draws of
//     its fitted parameters (measures.h, add_fit_spread), so a fit whose training tests leave
//     a knife-edge held-out test undecided is not charged for the side its point falls on.
//  5. The cause is the mechanism with the largest held-out gain among the significant ones:
//     held-out gain >= minimum_gain, BIC lower by at least -maximum_bic_delta, and the held-out
//     error lower on at least half of the held-out tests. None significant: "none", the model
//     disagrees with the data no more than noise explains. Then each remaining mechanism is
//     fitted on top of the cause, the cause's model is refitted from those pairs' values of its
//     parameters (a pair must not gain by a better fit of the cause alone), and a pair
//     significant against the better fit of the cause is reported as a second effect. The
//     cause itself is never changed by this second look.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "diagnosis/fitting.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/measures.h"
#include "kernels/block.h"

namespace caskdem::diagnosis {

struct DiagnosisOptions {
  InstructionSet isa = InstructionSet::automatic;
  int threads = 0;  // 0: OpenMP's default
  double minimum_gain = 0.2;
  double maximum_bic_delta = -10.0;
  double minimum_improved_fraction = 0.5;
  bool look_for_second_effect = true;
  // Standard errors of the baseline, and of the cause if there is one, raised to the jackknife's
  // where larger (refits without each training test; fitting.h). Costs a fit per training test.
  // Off here (the tests need no errors); the commands turn it on unless asked not to.
  bool jackknife = false;
  std::function<void(const std::string&)> log;  // progress lines (may be empty)
};

struct ModelFit {
  std::vector<Mechanism> mechanisms;
  std::string name;
  std::vector<Parameter> parameters;
  FitResult fit;
  int training_residual_count = 0;
  double bic = 0.0;
  double aic = 0.0;
  std::vector<std::vector<double>> residuals;  // per test (all tests), per measure, at the fitted point
  std::vector<double> loss;                    // per test (all tests), at the fitted point (measures.h, marginal_loss)
  double heldout_error = 0.0;                  // sqrt(loss per residual) over the held-out tests
  // The standard errors (the curvature's) whose prediction spread widened the held-out tests'
  // tolerances (measures.h, add_fit_spread); empty: judged at the point alone.
  std::vector<double> heldout_standard_error;
};

struct CandidateScore {
  Mechanism mechanism;
  ModelFit model;
  double heldout_gain = 0.0;     // 1 - heldout_error(candidate) / heldout_error(reference model)
  double bic_delta = 0.0;        // against the reference model (negative: better)
  double aic_delta = 0.0;
  int heldout_tests_improved = 0;
  std::vector<double> measure_gain;  // per measure, over the held-out tests
  bool significant = false;
};

struct StructureRow {
  std::string variable;   // what the residual is set against
  std::string residual;   // which residual
  double statistic = 0.0; // correlation across tests, or mean / t for a sign or lag
  std::string statistic_name;
  std::string points_to;  // mechanisms this pattern suggests
};

struct Diagnosis {
  std::string cause = "none";
  std::string second_cause;  // empty when no second effect
  ModelFit baseline;
  std::vector<CandidateScore> ranking;         // by held-out gain
  std::vector<CandidateScore> second_ranking;  // on top of the cause
  // The cause's model refitted from the pairs' values of its parameters, when that fits the
  // training tests better than the cause's own fit: what the pairs are scored against. The
  // cause's score in `ranking` stays that of its own fit.
  std::optional<ModelFit> cause_refit;
  std::vector<StructureRow> structure;
  double wall_seconds = 0.0;
};

// Step 1 alone (`caskdem calibrate-measured`).
ModelFit calibrate_baseline(const MeasuredSet& set, const DiagnosisOptions& options);

Diagnosis diagnose(const MeasuredSet& set, const DiagnosisOptions& options);

// J of a model at each point over the training tests but the `left_out`-th (an index into
// set.training): what the jackknife's refits minimise (DiagnosisOptions::jackknife).
std::vector<double> training_objective_without(const MeasuredSet& set, const std::vector<Mechanism>& mechanisms,
                                               const std::vector<std::vector<double>>& points, int left_out,
                                               const DiagnosisOptions& options);

// The diagnosis's own judgement of one point of a model (`caskdem evaluate-measured`): with
// the same tolerances as diagnose(), every test's residuals and loss, the training objective J
// that the fits minimise, the held-out error and the BIC. A fit's numbers in diagnosis.json
// are these at its fitted point; at any other point (a published or a true parameter set)
// they say how that point would have fared.
struct PointEvaluation {
  std::string model;                           // "baseline" or "baseline + a + b"
  std::vector<Parameter> parameters;
  std::vector<double> point;                   // physical values, in the order of `parameters`
  std::vector<std::vector<double>> residuals;  // per test (all tests), per measure
  std::vector<double> loss;                    // per test
  double training_objective = 0.0;             // J over the training tests
  int training_residual_count = 0;
  double heldout_error = 0.0;
  double bic = 0.0;
};

PointEvaluation evaluate_point(const MeasuredSet& set, const std::vector<Mechanism>& mechanisms,
                               const std::vector<double>& point, const std::vector<double>& heldout_standard_error,
                               const DiagnosisOptions& options);

// The simulated histories of a fitted model on every test (for reports and plots).
std::vector<SimulatedHistory> fitted_histories(const MeasuredSet& set, const ModelFit& fit, InstructionSet isa);

}  // namespace caskdem::diagnosis
