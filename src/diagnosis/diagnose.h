#pragma once
// The diagnosis: from measured tests to "this is where the model disagrees, this is the
// most likely physical cause, this is how much the extended model gains on tests it was not
// fitted to".
//
//  1. Calibrate the baseline (friction, damping ratio, stiffness scale) on the training tests,
//     for a cylinder on each footprint rule (two corners at the gyration half-width or the
//     radius, or a distributed base; footprint.h), and keep the rule the held-out tests prefer
//     (by at least minimum_gain; the stated one otherwise), a choice that must still hold once
//     the chosen baseline is refitted from the mechanisms' fits (step 3), else it is withdrawn
//     and steps 2 to 5 are made again on the stated rule. Judge the baseline's adequacy
//     (adequacy.h): does it fit every test within noise, with plausible values?
//  2. Measure its discrepancy on every test (src/diagnosis/measures.h) and look for structure
//     in it: residuals against amplitude, sliding speed, impact speed, rotation sign, vertical
//     acceleration and time (a lag between simulated and measured rotation).
//  3. For each mechanism, baseline + mechanism fitted (all parameters) on the training tests;
//     then its profile (profile.h): J minimised over the baseline's parameters at each point of
//     a grid across the mechanism's own, which shows whether some value of the mechanism lowers
//     J where the fit did not find one (its likelihood ratio against the baseline and its
//     intervals are reported; refit_from_profile repeats such a fit from the profile's minimum).
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
//     A mechanism and the model it extends are compared on the held-out tests at common
//     tolerances, per test and measure the larger of the two models' own: at their own, a fit
//     with more or larger standard errors would get wider tolerances and a smaller error at
//     equal predictions, rewarding vagueness. A mechanism whose switch (a gain, a ratio) is at
//     its off value within its standard error is the model it extends: never significant.
//  5. The cause is the mechanism with the largest held-out gain among the significant ones:
//     held-out gain >= minimum_gain, BIC lower by at least -maximum_bic_delta, and the held-out
//     error lower on at least half of the held-out tests. None significant: "none" when the
//     calibrated baseline is adequate (it fits every test within noise with plausible values;
//     adequacy.h), else "unexplained": it misfits, and no mechanism of the library explains
//     it; the misfitting tests and measures, the implausible values and what to check are
//     named. Then each remaining mechanism is
//     fitted on top of the cause, the cause's model is refitted from those pairs' values of its
//     parameters (a pair must not gain by a better fit of the cause alone), and a pair
//     significant against the better fit of the cause is reported as a second effect. The
//     cause itself is never changed by this second look.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "diagnosis/adequacy.h"
#include "diagnosis/earlier_fits.h"
#include "diagnosis/fitting.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/measures.h"
#include "diagnosis/profile.h"
#include "kernels/block.h"

namespace caskdem::diagnosis {

struct DiagnosisOptions {
  InstructionSet isa = InstructionSet::automatic;
  int threads = 0;  // 0: OpenMP's default
  double minimum_gain = 0.2;
  double maximum_bic_delta = -10.0;
  double minimum_improved_fraction = 0.5;
  bool look_for_second_effect = true;
  // A cylindrical specimen's baseline is calibrated on every footprint rule (footprint.h) and
  // the one the held-out tests prefer by at least minimum_gain replaces the stated one.
  bool choose_footprint = true;
  // The baseline is also calibrated on the other normal law (kernels/contact_law.h: linear or
  // Hunt-Crossley), on each footprint tried, and the form the held-out tests prefer by at least
  // minimum_gain replaces the stated one. Off by default: it doubles the calibrations.
  bool compare_normal_laws = false;
  // Standard errors of the baseline, and of the cause if there is one, raised to the jackknife's
  // where larger (refits without each training test; fitting.h). Costs a fit per training test.
  // Off here (the tests need no errors); the commands turn it on unless asked not to.
  bool jackknife = false;
  // Each mechanism's profile over its own parameters (profile.h) after the fits; the grid
  // points' searches take half the [diagnosis] evaluations each (at least 10).
  bool profile = true;
  ProfileOptions profile_options;
  // A fit is searched again from its profile's minimum where that is below the fit's J by more
  // than the profile's bound (diagnose --refit-from-profile). Off by default: what it does to
  // the rates is measured in docs/diagnosis-accuracy.md ("The second round").
  bool refit_from_profile = false;
  // An earlier diagnosis of this cask (earlier_fits.h): each of its fits joins the starts of the
  // fit of the same model and form here.
  std::optional<EarlierFits> earlier;
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
  // Per test, per measure: the tolerances each held-out test was judged with (empty for the
  // training tests).
  std::vector<std::vector<double>> heldout_tolerance;
  Adequacy adequacy;  // does it fit within noise, with plausible values (adequacy.h)
};

struct CandidateScore {
  Mechanism mechanism;
  ModelFit model;
  // Both judged on the held-out tests at common tolerances (the larger of the two models' own).
  double heldout_error = 0.0;            // the candidate's
  double reference_heldout_error = 0.0;  // the model it extends
  // 1 - heldout_error / reference_heldout_error; zero when the switch is at its off value (the
  // fit is then the model it extends, and any difference is the other parameters' wander).
  double heldout_gain = 0.0;
  double heldout_gain_as_fitted = 0.0;  // the ratio's own value, whatever the switch
  double bic_delta = 0.0;        // against the reference model (negative: better)
  double aic_delta = 0.0;
  int heldout_tests_improved = 0;
  std::vector<double> measure_gain;  // per measure, over the held-out tests (zero at the off value)
  // The mechanism's switch is at its off value (within its standard error): the fit is the
  // model it extends, whatever its gain says.
  bool at_off_value = false;
  bool significant = false;
  // The mechanism's profile (profile.h), when one was made: its likelihood-ratio statistic
  // against the baseline and the interval of each own parameter.
  std::optional<Profile> profile;
};

struct StructureRow {
  std::string variable;   // what the residual is set against
  std::string residual;   // which residual
  double statistic = 0.0; // correlation across tests, or mean / t for a sign or lag
  std::string statistic_name;
  std::string points_to;  // mechanisms this pattern suggests
};

// The baseline calibrated on one footprint rule, judged on the held-out tests at tolerances
// common to every rule tried.
// One model form tried: a footprint rule (empty for a polygon section) and a normal law.
struct FootprintScore;
// "distributed", "distributed, hunt-crossley law" where the laws were compared, "hunt-crossley law".
std::string form_label(const FootprintScore& score, bool laws_compared);
struct FootprintScore {
  std::string footprint;       // footprint_name
  std::string normal_law;      // normal_law_name
  bool stated = false;         // the specimen's own rule and law
  bool chosen = false;
  // Chosen on its first calibration, but below the minimum gain once its baseline was refitted
  // from the mechanisms' fits and the forms judged again: the diagnosis was made again on the
  // stated form. gain_when_chosen is its gain on that first calibration.
  bool withdrawn = false;
  double gain_when_chosen = 0.0;
  double heldout_error = 0.0;
  double heldout_gain = 0.0;   // against the stated rule
  ModelFit baseline;
};

// Whether the diagnosis tried more than one normal law.
bool laws_compared(const std::vector<FootprintScore>& forms);

struct Diagnosis {
  // A mechanism's name; "footprint" when no mechanism is significant but another footprint rule
  // fits better than the stated one; "normal_law" likewise for the other normal law (with
  // DiagnosisOptions::compare_normal_laws); "unexplained" when the baseline misfits and nothing
  // explains it; "none" when it fits within noise.
  std::string cause = "none";
  std::string footprint;                    // the rule the mechanisms were fitted on
  std::string normal_law;                   // the normal law they were fitted on
  bool normal_law_changed = false;          // another law than the stated one predicts the held-out tests better
  bool footprint_changed = false;           // it is not the specimen's stated rule
  std::vector<FootprintScore> footprints;   // every rule tried (empty: not a cylinder, or not asked)
  double minimum_gain = 0.2;                // the held-out gain a form or mechanism must reach
  Case specimen;                            // the specimen the fits were made on (on the rule kept)
  std::string second_cause;  // empty when no second effect
  ModelFit baseline;
  std::vector<CandidateScore> ranking;         // by held-out gain
  std::vector<CandidateScore> second_ranking;  // on top of the cause
  // The cause's model refitted from the pairs' values of its parameters, when that fits the
  // training tests better than the cause's own fit: what the pairs are scored against. The
  // cause's score in `ranking` stays that of its own fit.
  std::optional<ModelFit> cause_refit;
  std::vector<StructureRow> structure;
  // The earlier diagnosis whose fits joined the starts (DiagnosisOptions::earlier); empty: none.
  std::string started_from;
  // The choices it was made with (DiagnosisOptions), written beside its answer so that a run
  // can be repeated and read as what it was.
  struct Choices {
    bool choose_footprint = true, compare_normal_laws = false, profile = true, refit_from_profile = false;
    bool look_for_second_effect = true, jackknife = false;
    double minimum_gain = 0.2, maximum_bic_delta = -10.0, minimum_improved_fraction = 0.5;
  } choices;
  double wall_seconds = 0.0;
};

// Step 1 alone (`caskdem calibrate-measured`).
ModelFit calibrate_baseline(const MeasuredSet& set, const DiagnosisOptions& options);

Diagnosis diagnose(const MeasuredSet& set, const DiagnosisOptions& options);

// One mechanism's profile on a data set (profile.h), as diagnose() makes it: every grid point's
// search over the baseline's parameters starts from `baseline` (the baseline's fitted values);
// `fitted`, whole points of the model whose mechanism values join the grid (profile_mechanism).
Profile profile_on(const MeasuredSet& set, Mechanism mechanism, const std::vector<double>& baseline,
                   const DiagnosisOptions& options, const std::vector<std::vector<double>>& fitted = {});

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

// A model judged at one point as a fit's result is: every test's residuals and loss, the held-out
// tests judged as predictions with `heldout_standard_error` (none: at the point alone).
ModelFit judged_fit(const MeasuredSet& set, const std::vector<Mechanism>& mechanisms, const std::vector<double>& point,
                    const std::vector<double>& heldout_standard_error, const DiagnosisOptions& options);

// How a mechanism's fit (`candidate`, whose model adds `mechanism` to `reference`'s) scores
// against the model it extends, as the diagnosis ranks it.
CandidateScore score_candidate(const MeasuredSet& set, Mechanism mechanism, const ModelFit& candidate,
                               const ModelFit& reference, const DiagnosisOptions& options);

// The simulated histories of a fitted model on every test (for reports and plots).
std::vector<SimulatedHistory> fitted_histories(const MeasuredSet& set, const ModelFit& fit, InstructionSet isa);

}  // namespace caskdem::diagnosis
