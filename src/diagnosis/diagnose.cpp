#include "diagnosis/diagnose.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>

#include "core/text.h"
#include "diagnosis/footprint.h"
#include "diagnosis/judging.h"
#include "diagnosis/model_form.h"
#include "diagnosis/residual_structure.h"

namespace caskdem::diagnosis {

namespace {

Adequacy adequacy_of(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant, const ModelFit& m,
                     const DiagnosisOptions& options) {
  std::vector<std::vector<std::uint8_t>> compared;
  for (const TestReference& r : yardstick.references) compared.push_back(r.compared);
  const PointObjective training = [&](const std::vector<double>& x) {
    return objective_over(set, yardstick, variant, set.training, {x}, options).front();
  };
  return judge_adequacy(set, m.parameters, m.fit, variant.nominal_baseline(), m.loss, m.residuals, compared, training);
}

// A fit's judgement at its point (m.fit.best, m.fit.objective and m.heldout_standard_error
// set): every test's loss and residuals, the information criteria, the held-out error and the
// adequacy.
void judge_fit(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant, ModelFit& m,
               const DiagnosisOptions& options) {
  Judged judged = judge_at(set, yardstick, variant, m.fit.best, m.heldout_standard_error, options);
  m.loss = std::move(judged.loss);
  m.residuals = std::move(judged.residuals);
  m.heldout_tolerance = std::move(judged.heldout_tolerance);
  m.bic = bic_of(m.fit.objective, m.training_residual_count, m.parameters.size());
  m.aic = aic_of(m.fit.objective, m.training_residual_count, m.parameters.size());
  m.heldout_error = error_of(m.loss, yardstick, set.heldout);
  m.adequacy = adequacy_of(set, yardstick, variant, m, options);
}

// Fits a model; its searches start from `starts` (the model it extends, mechanism off), from
// the specimen's nominal values (mechanism off) and from an earlier diagnosis's fits of the same
// model (DiagnosisOptions::earlier).
ModelFit fit_variant(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant,
                     std::vector<std::vector<double>> starts, const DiagnosisOptions& options) {
  ModelFit m;
  m.mechanisms = variant.mechanisms();
  m.name = variant.name();
  m.parameters = variant.parameters();
  m.training_residual_count = residual_count(yardstick, set.training);
  const PopulationObjective objective = [&](const std::vector<std::vector<double>>& points) {
    return objective_over(set, yardstick, variant, set.training, points, options);
  };
  const FitOptions fit_options = fit_options_of(set);
  auto add_start = [&starts](const std::vector<double>& start) {
    if (std::find(starts.begin(), starts.end(), start) == starts.end()) starts.push_back(start);
  };
  add_start(variant.reference());
  // A first fit on the predictable training tests alone, whose end is one more start: the
  // chaotic tests make the objective a field of narrow basins, while the predictable ones
  // funnel towards the truth from far (measured on a hidden floor layer; tests/diagnosis/
  // test_hidden_effects.cpp). Only when some training tests are unpredictable and at least
  // two are not.
  const std::vector<int>& predictable = yardstick.predictable_training;
  if (predictable.size() >= 2 && predictable.size() < set.training.size()) {
    const PopulationObjective predictable_objective = [&](const std::vector<std::vector<double>>& points) {
      return objective_over(set, yardstick, variant, predictable, points, options);
    };
    FitOptions first_options = fit_options;
    first_options.refinement = 0;
    first_options.standard_errors = false;
    const int predictable_residuals = residual_count(yardstick, predictable);
    const FitResult first = fit_parameters(m.parameters, starts, predictable_objective, first_options, predictable_residuals);
    add_start(first.best);
  }
  // An earlier diagnosis's fits of this model are searched beside the rest, which stay as they are.
  const std::vector<std::vector<double>> earlier =
      options.earlier ? earlier_starts(*options.earlier, set.specimen, variant) : std::vector<std::vector<double>>{};
  m.fit = fit_parameters(m.parameters, starts, objective, fit_options, m.training_residual_count, earlier);

  // The curvature's errors, before any jackknife raises them: what the held-out tests are judged with.
  m.heldout_standard_error = m.fit.standard_error;
  judge_fit(set, yardstick, variant, m, options);
  return m;
}

// J over the training tests but the `left_out`-th (an index into set.training).
LeaveOneOutObjective leave_one_out(const MeasuredSet& set, const Yardstick& yardstick, const ModelVariant& variant,
                                   const DiagnosisOptions& options) {
  return [&set, &yardstick, &variant, options](const std::vector<std::vector<double>>& points, int left_out) {
    std::vector<int> tests;
    for (std::size_t k = 0; k < set.training.size(); ++k) {
      if (static_cast<int>(k) != left_out) tests.push_back(set.training[k]);
    }
    return objective_over(set, yardstick, variant, tests, points, options);
  };
}

// The fit's standard errors from the jackknife over its training tests (fitting.h): the fit
// repeated without each, from its optimum and the model's reference.
void add_jackknife(const MeasuredSet& set, const Yardstick& yardstick, ModelFit& m, const DiagnosisOptions& options) {
  const ModelVariant variant(set.specimen, m.mechanisms, set.vertical_measured);
  const LeaveOneOutObjective without = leave_one_out(set, yardstick, variant, options);
  jackknife_errors(m.parameters, m.fit, {variant.reference()}, without, static_cast<int>(set.training.size()),
                   fit_options_of(set));
}

// The mechanism's switch at its off value: within the standard error the fit gives it, or
// exactly where it has none (a value on its search bound, a curvature not positive definite).
bool at_off_value(const MeasuredSet& set, Mechanism mechanism, const ModelFit& model) {
  const ModelVariant alone(set.specimen, {mechanism}, set.vertical_measured);
  for (const Parameter& p : alone.parameters()) {
    if (!p.mechanism || !p.switches_off) continue;
    for (std::size_t i = 0; i < model.parameters.size(); ++i) {
      if (model.parameters[i].name != p.name) continue;
      const double error = standard_error_of(model.fit, model.parameters, i).value_or(0.0);
      const double round_off = 1e-9 * (p.high - p.low);
      if (std::abs(model.fit.best[i] - p.reference) <= error + round_off) return true;
    }
  }
  return false;
}

// The held-out tests of two models judged at common tolerances: per test and measure the
// larger of the two models' own (each widened by its own fit's spread). At equal predictions
// both then score alike, whatever their standard errors.
std::pair<Judged, Judged> judged_in_common(const MeasuredSet& set, const Yardstick& yardstick, const ModelFit& a,
                                           const ModelFit& b, const DiagnosisOptions& options) {
  Yardstick common = yardstick;
  for (int t : set.heldout) {
    std::vector<double>& tolerance = common.references[t].tolerance;
    for (std::size_t m = 0; m < tolerance.size(); ++m) {
      tolerance[m] = std::max(a.heldout_tolerance[t][m], b.heldout_tolerance[t][m]);
    }
  }
  const auto judged = [&](const ModelFit& fit) {
    const ModelVariant variant(set.specimen, fit.mechanisms, set.vertical_measured);
    Judged j;
    (void)objective_over(set, common, variant, set.heldout, {fit.fit.best}, options, &j);
    return j;
  };
  return {judged(a), judged(b)};
}

CandidateScore score(const MeasuredSet& set, const Yardstick& yardstick, Mechanism mechanism, ModelFit model,
                     const ModelFit& against, const DiagnosisOptions& options) {
  CandidateScore s;
  s.mechanism = mechanism;
  const auto [mine, theirs] = judged_in_common(set, yardstick, model, against, options);
  s.heldout_error = error_of(mine.loss, yardstick, set.heldout);
  s.reference_heldout_error = error_of(theirs.loss, yardstick, set.heldout);
  s.heldout_gain = s.reference_heldout_error > 0.0 ? 1.0 - s.heldout_error / s.reference_heldout_error : 0.0;
  s.bic_delta = model.bic - against.bic;
  s.aic_delta = model.aic - against.aic;
  for (int t : set.heldout) {
    s.heldout_tests_improved += mine.loss[t] < theirs.loss[t];
  }
  for (std::size_t m = 0; m < measure_names().size(); ++m) {
    double sum_mine = 0.0, sum_theirs = 0.0;
    for (int t : set.heldout) {
      sum_mine += mine.residuals[t][m] * mine.residuals[t][m];
      sum_theirs += theirs.residuals[t][m] * theirs.residuals[t][m];
    }
    s.measure_gain.push_back(sum_theirs > 0.0 ? 1.0 - std::sqrt(sum_mine / sum_theirs) : 0.0);
  }
  s.heldout_gain_as_fitted = s.heldout_gain;
  s.at_off_value = at_off_value(set, mechanism, model);
  if (s.at_off_value) {
    // A switch at its off value has no gain by construction; what the ratio shows is the baseline
    // parameters settling elsewhere within their errors, and ranking on it would reward that.
    s.heldout_gain = 0.0;
    s.heldout_tests_improved = 0;
    std::fill(s.measure_gain.begin(), s.measure_gain.end(), 0.0);
  }
  const double improved = double(s.heldout_tests_improved) / double(set.heldout.size());
  s.significant = !s.at_off_value && s.heldout_gain >= options.minimum_gain &&
                  s.bic_delta <= options.maximum_bic_delta && improved >= options.minimum_improved_fraction;
  s.model = std::move(model);
  return s;
}

// A model extended by a mechanism that stays switched off: the model it extends, with the extra
// parameters (at their reference values) charged by the information criterion.
ModelFit switched_off(const ModelFit& extended, const ModelVariant& variant) {
  ModelFit m = extended;
  m.mechanisms = variant.mechanisms();
  m.name = variant.name();
  m.parameters = variant.parameters();
  std::vector<double> x = variant.reference();
  // Its held-out tests were judged as the model it extends: its errors, none for the mechanism's.
  std::vector<double> error(m.parameters.size(), 0.0);
  const bool has_error = !extended.heldout_standard_error.empty();
  for (std::size_t j = 0; j < m.parameters.size(); ++j) {
    for (std::size_t i = 0; i < extended.parameters.size(); ++i) {
      if (m.parameters[j].name != extended.parameters[i].name) continue;
      x[j] = extended.fit.best[i];
      if (has_error) error[j] = extended.heldout_standard_error[i];
    }
  }
  m.fit.best = x;
  m.fit.standard_error.clear();
  m.heldout_standard_error = has_error ? error : std::vector<double>{};
  m.fit.uncertainty_note = "the fit did not improve on the model it extends: the mechanism is switched off";
  m.bic = bic_of(m.fit.objective, m.training_residual_count, m.parameters.size());
  m.aic = aic_of(m.fit.objective, m.training_residual_count, m.parameters.size());
  return m;
}

// The profile's searches take half the [diagnosis] evaluations each (at least 10).
ProfileOptions profile_options_of(const MeasuredSet& set, const DiagnosisOptions& options) {
  ProfileOptions o = options.profile_options;
  o.evaluations = std::max(10, std::min(o.evaluations, set.settings.evaluations / 2));
  return o;
}

void say(const DiagnosisOptions& options, const std::string& line) {
  if (options.log) options.log(line);
}

}  // namespace

std::vector<SimulatedHistory> fitted_histories(const MeasuredSet& set, const ModelFit& fit, InstructionSet isa) {
  const ModelVariant variant(set.specimen, fit.mechanisms, set.vertical_measured);
  std::vector<SimulatedHistory> out;
  for (const MeasuredTest& test : set.tests) {
    out.push_back(delayed(simulate_test(variant, test, {fit.fit.best}, isa)[0], test.time, variant.sensor_delay(fit.fit.best)));
  }
  return out;
}

namespace {

// Searched from the specimen's nominal values and from any `also_from` (another form's fit).
ModelFit fit_baseline(const MeasuredSet& set, const Yardstick& yardstick, const DiagnosisOptions& options,
                      const std::vector<std::vector<double>>& also_from = {}) {
  const ModelVariant baseline(set.specimen, {}, set.vertical_measured);
  say(options, "fitting the baseline (friction, damping ratio, stiffness scale) on " +
                   std::to_string(set.training.size()) + " training tests");
  std::vector<std::vector<double>> starts = {baseline.reference()};
  starts.insert(starts.end(), also_from.begin(), also_from.end());
  return fit_variant(set, yardstick, baseline, starts, options);
}

}  // namespace

ModelFit calibrate_baseline(const MeasuredSet& set, const DiagnosisOptions& options) {
  const Yardstick yardstick = yardstick_of(set, options);
  ModelFit fit = fit_baseline(set, yardstick, options);
  if (options.jackknife) {
    say(options, "standard errors: refitting without each of the " + std::to_string(set.training.size()) +
                     " training tests in turn (jackknife)");
    add_jackknife(set, yardstick, fit, options);
  }
  return fit;
}

PointEvaluation evaluate_point(const MeasuredSet& set, const std::vector<Mechanism>& mechanisms,
                               const std::vector<double>& point, const std::vector<double>& heldout_standard_error,
                               const DiagnosisOptions& options) {
  const ModelVariant variant(set.specimen, mechanisms, set.vertical_measured);
  if (point.size() != variant.parameters().size()) {
    throw std::invalid_argument("evaluate_point: " + std::to_string(point.size()) + " values for the " +
                                std::to_string(variant.parameters().size()) + " parameters of " + variant.name());
  }
  if (!heldout_standard_error.empty() && heldout_standard_error.size() != point.size()) {
    throw std::invalid_argument("evaluate_point: " + std::to_string(heldout_standard_error.size()) +
                                " standard errors for the " + std::to_string(point.size()) + " parameters of " +
                                variant.name());
  }
  PointEvaluation e;
  e.model = variant.name();
  e.parameters = variant.parameters();
  e.point = point;
  const Yardstick yardstick = yardstick_of(set, options);
  Judged judged = judge_at(set, yardstick, variant, point, heldout_standard_error, options);
  e.residuals = std::move(judged.residuals);
  e.loss = std::move(judged.loss);
  // Summed in the order of the training tests, as the fits' objective is.
  for (int t : set.training) e.training_objective += e.loss[t];
  e.training_residual_count = residual_count(yardstick, set.training);
  e.bic = bic_of(e.training_objective, e.training_residual_count, e.parameters.size());
  e.heldout_error = error_of(e.loss, yardstick, set.heldout);
  return e;
}

ModelFit judged_fit(const MeasuredSet& set, const std::vector<Mechanism>& mechanisms, const std::vector<double>& point,
                    const std::vector<double>& heldout_standard_error, const DiagnosisOptions& options) {
  const ModelVariant variant(set.specimen, mechanisms, set.vertical_measured);
  const Yardstick yardstick = yardstick_of(set, options);
  ModelFit m;
  m.mechanisms = variant.mechanisms();
  m.name = variant.name();
  m.parameters = variant.parameters();
  m.fit.best = point;
  m.fit.standard_error = heldout_standard_error;
  m.heldout_standard_error = heldout_standard_error;
  m.training_residual_count = residual_count(yardstick, set.training);
  m.fit.objective = objective_over(set, yardstick, variant, set.training, {point}, options).front();
  judge_fit(set, yardstick, variant, m, options);
  return m;
}

CandidateScore score_candidate(const MeasuredSet& set, Mechanism mechanism, const ModelFit& candidate,
                               const ModelFit& reference, const DiagnosisOptions& options) {
  return score(set, yardstick_of(set, options), mechanism, candidate, reference, options);
}

Profile profile_on(const MeasuredSet& set, Mechanism mechanism, const std::vector<double>& baseline,
                   const DiagnosisOptions& options, const std::vector<std::vector<double>>& fitted) {
  const ModelVariant variant(set.specimen, {mechanism}, set.vertical_measured);
  const Yardstick yardstick = yardstick_of(set, options);
  const PopulationObjective training = [&](const std::vector<std::vector<double>>& points) {
    return objective_over(set, yardstick, variant, set.training, points, options);
  };
  return profile_mechanism(variant, {baseline}, fitted, training, profile_options_of(set, options));
}

std::vector<double> training_objective_without(const MeasuredSet& set, const std::vector<Mechanism>& mechanisms,
                                               const std::vector<std::vector<double>>& points, int left_out,
                                               const DiagnosisOptions& options) {
  const ModelVariant variant(set.specimen, mechanisms, set.vertical_measured);
  const Yardstick yardstick = yardstick_of(set, options);
  return leave_one_out(set, yardstick, variant, options)(points, left_out);
}

namespace {

struct SecondEffectSearch {
  std::vector<CandidateScore> ranking;     // each other mechanism on top of the cause, by held-out gain
  std::optional<ModelFit> refitted_cause;  // the cause's model refitted, when that fits better
};

// Each other mechanism fitted on top of the cause, from the cause's fit with the new mechanism
// off. A pair that fits better only because its search found a better region of the cause's
// own parameters must not pass for a second effect (on eccentric-mass data of seed 1001 the
// pair with a sensor delay reached J 17 against the cause's 100, its delay 1.4 ms, its
// damping ratio 0.032 where the cause's fit had stopped at 0.019 and the truth is 0.035): the
// cause's model is refitted from every pair's values of its parameters, as the baseline is
// from the candidates', and the pairs are scored against the better fit. The refit does not
// replace the cause's own score: judged against the baseline, a refit that fits the training
// tests better can predict the held-out ones worse (velocity-dependent friction of seed 101:
// J 60.1 to 48.8, held-out gain below 0.2), and a second look must not undo the first answer.
SecondEffectSearch search_second_effect(const MeasuredSet& set, const Yardstick& yardstick, Mechanism first,
                                        const ModelFit& cause, const DiagnosisOptions& options) {
  // The values of `to`'s parameters: `from`'s where the names agree, else `to`'s reference.
  const auto carried = [](const ModelFit& from, const ModelVariant& to) {
    std::vector<double> values = to.reference();
    for (std::size_t i = 0; i < from.parameters.size(); ++i) {
      for (std::size_t j = 0; j < to.parameters().size(); ++j) {
        if (to.parameters()[j].name == from.parameters[i].name) values[j] = from.fit.best[i];
      }
    }
    return values;
  };
  const ModelVariant cause_variant(set.specimen, {first}, set.vertical_measured);
  std::vector<std::pair<Mechanism, ModelFit>> pairs;  // the mechanism added, the pair's fit
  std::vector<std::vector<double>> cause_starts = {cause.fit.best};
  for (Mechanism m : all_mechanisms()) {
    if (m == first) continue;
    const ModelVariant variant(set.specimen, {first, m}, set.vertical_measured);
    say(options, "fitting " + variant.name());
    pairs.emplace_back(m, fit_variant(set, yardstick, variant, {carried(cause, variant)}, options));
    cause_starts.push_back(carried(pairs.back().second, cause_variant));
  }
  SecondEffectSearch search;
  say(options, "refitting " + cause_variant.name() + " from the pairs' values of its parameters");
  ModelFit refitted = fit_variant(set, yardstick, cause_variant, cause_starts, options);
  if (refitted.fit.objective < cause.fit.objective) search.refitted_cause = std::move(refitted);
  const ModelFit& against = search.refitted_cause ? *search.refitted_cause : cause;
  for (auto& [added, pair] : pairs) {
    const ModelVariant variant(set.specimen, {first, added}, set.vertical_measured);
    if (pair.fit.objective > against.fit.objective) pair = switched_off(against, variant);
    search.ranking.push_back(score(set, yardstick, added, std::move(pair), against, options));
  }
  std::stable_sort(search.ranking.begin(), search.ranking.end(),
                   [](const CandidateScore& a, const CandidateScore& b) { return a.heldout_gain > b.heldout_gain; });
  return search;
}

// Each mechanism's profile (profile.h) from the baseline as refined, after every fit. The
// profile's off point is the baseline searched again; where that fits better, the baseline is
// refitted from the off points, as from the candidates' (a mechanism must not gain by a better
// fit of the baseline alone). With refit_from_profile, a fit that ended above its profile's
// minimum by more than the profile's bound is repeated from that minimum.
void profile_candidates(const MeasuredSet& set, const Yardstick& yardstick, Diagnosis& d,
                        const DiagnosisOptions& options) {
  const ModelVariant baseline_variant(set.specimen, {}, set.vertical_measured);
  const std::size_t k = static_cast<std::size_t>(baseline_variant.baseline_size());
  const ProfileOptions profile_options = profile_options_of(set, options);
  std::vector<std::vector<double>> baseline_starts = {d.baseline.fit.best};
  // Every grid point's search starts from the best there of the baseline's values and those
  // each mechanism's fit settled at.
  std::vector<std::vector<double>> basins = {d.baseline.fit.best};
  for (const CandidateScore& c : d.ranking) {
    std::vector<double> b(c.model.fit.best.begin(), c.model.fit.best.begin() + k);
    if (std::find(basins.begin(), basins.end(), b) == basins.end()) basins.push_back(std::move(b));
  }
  double lowest_off = d.baseline.fit.objective;
  for (CandidateScore& c : d.ranking) {
    const ModelVariant variant(set.specimen, {c.mechanism}, set.vertical_measured);
    say(options, "profiling " + mechanism_name(c.mechanism) + " over its range, the baseline searched at each point");
    const PopulationObjective training = [&](const std::vector<std::vector<double>>& points) {
      return objective_over(set, yardstick, variant, set.training, points, options);
    };
    c.profile = profile_mechanism(variant, basins, {c.model.fit.best}, training, profile_options);
    const ProfilePoint& off = c.profile->grid[c.profile->off];
    if (off.objective < lowest_off) {
      lowest_off = off.objective;
      baseline_starts.emplace_back(off.best.begin(), off.best.begin() + k);
    }
  }
  if (lowest_off < d.baseline.fit.objective) {
    say(options, "refitting the baseline from the profiles' off points");
    ModelFit refined = fit_variant(set, yardstick, baseline_variant, baseline_starts, options);
    if (refined.fit.objective < d.baseline.fit.objective) d.baseline = std::move(refined);
  }
  for (CandidateScore& c : d.ranking) {
    if (!options.refit_from_profile) break;
    const ProfilePoint& lowest = c.profile->grid[c.profile->minimum];
    // Only where the profile found the fit's search short of its minimum by more than the
    // profile's own bound (chi2_1 at 95 %). Off by default: a lower training J is not always a
    // better prediction (velocity-dependent friction of seed 101 on caskdem's generator: refitted
    // from its profile's minimum, BIC -35 against -20 but a held-out gain of 0.03 against 0.42;
    // tests/diagnosis/test_hidden_effects.cpp), and the rates with it are those measured in
    // docs/diagnosis-accuracy.md.
    if (lowest.objective >= c.model.fit.objective - kProfileBound) continue;
    const ModelVariant variant(set.specimen, {c.mechanism}, set.vertical_measured);
    say(options, "refitting " + variant.name() + " from its profile's minimum (J " + std::to_string(lowest.objective) +
                     " against its fit's " + std::to_string(c.model.fit.objective) + ")");
    c.model = fit_variant(set, yardstick, variant, {lowest.best, c.model.fit.best}, options);
    add_point(*c.profile, variant, c.model.fit.best, c.model.fit.objective);
  }
}

// Steps 2 to 5 on the model form footprint->chosen (the given set's own where no form was
// compared).
Diagnosis diagnose_on_form(const MeasuredSet& given, std::optional<ModelFormChoice>& footprint,
                           const DiagnosisOptions& options) {
  Diagnosis d;
  d.minimum_gain = options.minimum_gain;
  const MeasuredSet& set = footprint ? footprint->sets[footprint->chosen] : given;
  const Yardstick yardstick = footprint ? footprint->yardsticks[footprint->chosen] : yardstick_of(set, options);
  d.baseline = footprint ? footprint->fits[footprint->chosen] : fit_baseline(set, yardstick, options);
  d.footprint_changed =
      footprint && footprint->tried[footprint->chosen].footprint != footprint->tried[footprint->stated].footprint;
  d.normal_law_changed = set.specimen.model.normal_law != given.specimen.model.normal_law;
  if (const std::optional<Footprint> f = footprint_of(set.specimen)) d.footprint = footprint_name(*f);
  d.normal_law = normal_law_name(set.specimen.model.normal_law);
  d.specimen = set.specimen;
  const ModelVariant baseline_variant(set.specimen, {}, set.vertical_measured);
  d.structure = residual_structure(set, yardstick.references, d.baseline, baseline_variant.model(),
                                   fitted_histories(set, d.baseline, options.isa));

  for (Mechanism m : all_mechanisms()) {
    const ModelVariant variant(set.specimen, {m}, set.vertical_measured);
    CandidateScore candidate;
    candidate.mechanism = m;
    say(options, "fitting " + variant.name());
    candidate.model = fit_variant(set, yardstick, variant, {variant.reference(&d.baseline.fit.best)}, options);
    d.ranking.push_back(std::move(candidate));
  }
  // The baseline again, from every candidate's baseline parameters: a candidate that fitted
  // better only because its search found a better region of the baseline's own parameters
  // must not pass for a cause.
  {
    std::vector<std::vector<double>> starts = {d.baseline.fit.best};
    for (const CandidateScore& c : d.ranking) {
      starts.emplace_back(c.model.fit.best.begin(), c.model.fit.best.begin() + baseline_variant.baseline_size());
    }
    say(options, "refitting the baseline from the candidates' baseline parameters");
    ModelFit refined = fit_variant(set, yardstick, baseline_variant, starts, options);
    if (refined.fit.objective < d.baseline.fit.objective) d.baseline = std::move(refined);
  }
  if (options.profile) profile_candidates(set, yardstick, d, options);
  if (footprint) {
    // One calibration per rule: the chosen rule's row is the baseline reported and ranked
    // against, refined or not, and every row is judged again at tolerances common to the rows
    // as they now stand. The choice stays: the mechanisms were fitted on that rule.
    footprint->fits[footprint->chosen] = d.baseline;
    d.footprints = model_form_scores(given, *footprint, options);
    d.footprints[footprint->chosen].chosen = true;
  }
  for (CandidateScore& c : d.ranking) {
    const ModelVariant variant(set.specimen, {c.mechanism}, set.vertical_measured);
    if (c.model.fit.objective > d.baseline.fit.objective) c.model = switched_off(d.baseline, variant);
    std::optional<Profile> profile = std::move(c.profile);
    c = score(set, yardstick, c.mechanism, std::move(c.model), d.baseline, options);
    c.profile = std::move(profile);
  }
  std::stable_sort(d.ranking.begin(), d.ranking.end(),
                   [](const CandidateScore& a, const CandidateScore& b) { return a.heldout_gain > b.heldout_gain; });
  const auto significant = [](const CandidateScore& c) { return c.significant; };
  auto cause = std::find_if(d.ranking.begin(), d.ranking.end(), significant);
  if (cause != d.ranking.end() && options.look_for_second_effect) {
    SecondEffectSearch search = search_second_effect(set, yardstick, cause->mechanism, cause->model, options);
    d.second_ranking = std::move(search.ranking);
    const auto second = std::find_if(d.second_ranking.begin(), d.second_ranking.end(), significant);
    if (second != d.second_ranking.end()) d.second_cause = mechanism_name(second->mechanism);
    d.cause_refit = std::move(search.refitted_cause);
  }
  if (options.jackknife) {
    say(options, "standard errors of the baseline" + std::string(cause != d.ranking.end() ? " and the cause" : "") +
                     ": refitting without each training test in turn (jackknife)");
    add_jackknife(set, yardstick, d.baseline, options);
    if (cause != d.ranking.end()) add_jackknife(set, yardstick, cause->model, options);
    if (footprint) d.footprints[footprint->chosen].baseline = d.baseline;  // its errors too
  }
  if (cause != d.ranking.end()) d.cause = mechanism_name(cause->mechanism);
  else if (d.footprint_changed) d.cause = "footprint";
  else if (d.normal_law_changed) d.cause = "normal_law";
  else if (!d.baseline.adequacy.adequate) d.cause = "unexplained";
  return d;
}

}  // namespace

Diagnosis diagnose(const MeasuredSet& given, const DiagnosisOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  say(options, "judging how predictable each test is (" + std::to_string(kPredictabilityRealisations) +
                   " simulations per test with fresh input noise)");
  // The model form first: the mechanisms are fitted on the footprint rule and normal law the
  // held-out tests prefer.
  std::optional<ModelFormChoice> footprint;
  if ((options.choose_footprint && footprint_of(given.specimen)) || options.compare_normal_laws) {
    footprint = choose_model_form(given, options, [&](const MeasuredSet& s, const Yardstick& y,
                                                      const std::vector<std::vector<double>>& also_from) {
      return fit_baseline(s, y, options, also_from);
    });
  }
  Diagnosis d = diagnose_on_form(given, footprint, options);
  // A form chosen over the stated one must still be preferred once its baseline is refitted
  // and the forms judged again: the refit can find a lower training J in another basin that
  // predicts the held-out tests worse (and it moves the common held-out tolerances). Else the
  // mechanisms are fitted again on the stated form, which stays (no second switch, which
  // could cycle).
  if (footprint && footprint->chosen != footprint->stated &&
      d.footprints[footprint->chosen].heldout_gain < options.minimum_gain) {
    const std::size_t withdrawn = footprint->chosen;
    const double gain_when_chosen = footprint->scores[withdrawn].heldout_gain;
    say(options, form_label(d.footprints[withdrawn], laws_compared(d.footprints)) + ": held-out gain " +
                     number_text(d.footprints[withdrawn].heldout_gain) +
                     " after its refit, below the minimum; fitting again on the stated form");
    footprint->chosen = footprint->stated;
    d = diagnose_on_form(given, footprint, options);
    d.footprints[withdrawn].withdrawn = true;
    d.footprints[withdrawn].gain_when_chosen = gain_when_chosen;
  }
  if (options.earlier) d.started_from = options.earlier->source.string();
  d.choices = {options.choose_footprint, options.compare_normal_laws, options.profile, options.refit_from_profile,
               options.look_for_second_effect, options.jackknife, options.minimum_gain, options.maximum_bic_delta,
               options.minimum_improved_fraction};
  d.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

}  // namespace caskdem::diagnosis
