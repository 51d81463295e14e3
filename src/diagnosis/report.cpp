#include "diagnosis/report.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "caskdem/build_info.h"
#include "diagnosis/plan_report.h"
#include "io/hdf5_file.h"
#include "io/run_output.h"

namespace caskdem::diagnosis {

namespace {

nlohmann::json parameters_json(const ModelFit& m) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < m.parameters.size(); ++i) {
    const Parameter& parameter = m.parameters[i];
    nlohmann::json p;
    p["value"] = m.fit.best[i];
    const std::optional<double> error = standard_error_of(m.fit, m.parameters, i);
    if (error) p["standard_error"] = *error;
    else p["standard_error"] = nullptr;
    p["units"] = parameter.units;
    p["search_range"] = {parameter.low, parameter.high};
    p["at_search_bound"] = at_search_bound(parameter, m.fit.best[i]);
    j[parameter.name] = p;
  }
  return j;
}

nlohmann::json adequacy_json(const Adequacy& a) {
  nlohmann::json j;
  j["adequate"] = a.adequate;
  j["fits_within_noise"] = a.fits_within_noise;
  j["goodness_of_fit"] = {{"statistic", a.statistic},
                          {"residuals", a.residuals},
                          {"degrees_of_freedom", a.degrees_of_freedom},
                          {"p_value", a.p_value},
                          {"rms_residual", a.rms_residual},
                          {"level", kAdequacyLevel}};
  j["global_fits"] = a.global_fits;
  // Each family of measures tested alone, Holm's step-down over the families (adequacy.h).
  j["families"] = nlohmann::json::array();
  for (const FamilyFit& f : a.families) {
    nlohmann::json family = {
        {"family", f.family},
        {"statistic", f.statistic},
        {"residuals", f.residuals},
        {"p_value", f.p_value},
        {"holm_level", f.holm_level},
        {"misfits", f.misfits},
        {"mean_magnitude_residual",
         f.magnitude_residuals > 0 ? nlohmann::json(f.mean_magnitude_residual) : nlohmann::json(nullptr)}};
    for (const MeasureFamily& m : measure_families()) {
      if (m.name != f.family) continue;
      family["measures"] = m.measures;
      family["mechanisms_acting_on_it"] = m.mechanisms;
    }
    j["families"].push_back(family);
  }
  j["misfitting_families"] = a.misfitting_families;
  j["misfitting_tests"] = a.misfitting_tests;
  j["misfits"] = nlohmann::json::array();
  for (const Misfit& m : a.misfits) j["misfits"].push_back({{"test", m.test}, {"measure", m.measure}, {"residual", m.residual}});
  j["implausible"] = nlohmann::json::array();
  for (const ImplausibleValue& v : a.implausible) {
    j["implausible"].push_back({{"parameter", v.parameter},
                                {"value", v.value},
                                {"nominal", v.nominal},
                                {"why", v.why},
                                {"likelihood_ratio", v.likelihood_ratio}});
  }
  j["checks"] = a.checks;
  return j;
}

nlohmann::json fit_json(const ModelFit& m) {
  nlohmann::json j;
  j["model"] = m.name;
  j["parameters"] = parameters_json(m);
  j["training_objective"] = m.fit.objective;
  j["bic"] = m.bic;
  j["aic"] = m.aic;
  j["heldout_error"] = m.heldout_error;
  j["adequacy"] = adequacy_json(m.adequacy);
  // The errors whose prediction spread widened the held-out tests' tolerances (evaluate-measured
  // --from takes them, to judge this point as the diagnosis did).
  if (!m.heldout_standard_error.empty()) {
    for (std::size_t i = 0; i < m.parameters.size(); ++i) {
      j["heldout_standard_errors"][m.parameters[i].name] = m.heldout_standard_error[i];
    }
  }
  j["evaluations"] = m.fit.evaluations;
  j["populations"] = m.fit.populations;
  if (!m.fit.uncertainty_method.empty()) j["uncertainty_method"] = m.fit.uncertainty_method;
  if (!m.fit.uncertainty_note.empty()) j["uncertainty_note"] = m.fit.uncertainty_note;
  return j;
}

nlohmann::json candidate_json(const CandidateScore& c) {
  nlohmann::json j;
  j["mechanism"] = mechanism_name(c.mechanism);
  j["heldout_gain"] = c.heldout_gain;
  // The held-out errors the gain compares: both models judged at common tolerances, per test
  // and measure the larger of the two models' own (diagnose.h, step 4).
  j["heldout_error"] = c.heldout_error;
  j["reference_heldout_error"] = c.reference_heldout_error;
  j["at_off_value"] = c.at_off_value;
  j["heldout_gain_as_fitted"] = c.heldout_gain_as_fitted;
  j["information_criterion_delta"] = c.bic_delta;
  j["information_criterion"] = "BIC";
  j["aic_delta"] = c.aic_delta;
  j["heldout_tests_improved"] = c.heldout_tests_improved;
  j["significant"] = c.significant;
  j["parameters"] = parameters_json(c.model);
  nlohmann::json gain;
  for (std::size_t m = 0; m < measure_names().size(); ++m) gain[measure_names()[m]] = c.measure_gain[m];
  j["gain"] = gain;
  j["fit"] = fit_json(c.model);
  if (c.profile) {
    const Profile& p = *c.profile;
    nlohmann::json profile;
    profile["parameters"] = p.parameters;
    profile["units"] = p.units;
    profile["grid"] = nlohmann::json::array();
    for (const ProfilePoint& point : p.grid) {
      profile["grid"].push_back(
          {{"values", point.values}, {"training_objective", point.objective}, {"point", point.best}});
    }
    profile["minimum"] = p.minimum;
    profile["off"] = p.off;
    profile["likelihood_ratio"] = p.likelihood_ratio;
    profile["p_value"] = p.p_value;
    profile["interval_bound"] = kProfileBound;
    for (std::size_t i = 0; i < p.parameters.size(); ++i) {
      profile["interval"][p.parameters[i]] = {p.interval_low[i], p.interval_high[i]};
    }
    profile["evaluations"] = p.evaluations;
    profile["populations"] = p.populations;
    j["profile"] = profile;
  } else {
    j["profile"] = nullptr;
  }
  return j;
}

std::string number(double v, int precision = 3) {
  std::ostringstream out;
  out << std::setprecision(precision) << v;
  return out.str();
}

// "+- SE", or why there is none.
std::string uncertainty_text(const ModelFit& m, std::size_t i) {
  if (at_search_bound(m.parameters[i], m.fit.best[i])) return "at the search bound";
  const std::optional<double> error = standard_error_of(m.fit, m.parameters, i);
  return error ? "+- " + number(*error, 2) : "-";
}

std::string adequacy_markdown(const Adequacy& a) {
  std::ostringstream md;
  md << "\n## Is the baseline adequate?\n\n"
     << (a.adequate ? "Yes" : "No") << ". Goodness of fit over every test: J = " << number(a.statistic, 4) << " over "
     << a.residuals << " scaled residuals (RMS " << number(a.rms_residual, 3)
     << " tolerances), p = " << number(a.p_value, 3) << " against chi-square with " << a.degrees_of_freedom
     << " degrees of freedom" << (a.global_fits ? " (within noise" : " (beyond noise") << " at the "
     << number(kAdequacyLevel, 2) << " level).\n\n";
  if (!a.families.empty()) {
    md << "By what the measures measure, each family tested alone (Holm's step-down over the families at the same "
          "level; a misfit confined to a few measures is not averaged away over all of them):\n\n"
       << "| family | J | residuals | p | Holm level | misfits | mean magnitude residual (tolerances; < 0: "
          "under-predicted) | mechanisms acting on it |\n|---|---|---|---|---|---|---|---|\n";
    for (const FamilyFit& f : a.families) {
      std::string mechanisms;
      for (const MeasureFamily& m : measure_families()) {
        if (m.name != f.family) continue;
        for (const std::string& name : m.mechanisms) mechanisms += (mechanisms.empty() ? "" : ", ") + name;
      }
      md << "| " << f.family << " | " << number(f.statistic, 4) << " | " << f.residuals << " | " << number(f.p_value, 3)
         << " | " << number(f.holm_level, 2) << " | " << (f.misfits ? "**yes**" : "no") << " | "
         << (f.magnitude_residuals > 0 ? number(f.mean_magnitude_residual, 3) : std::string("-")) << " | " << mechanisms
         << " |\n";
    }
    md << "\n";
  }
  if (!a.misfitting_tests.empty()) {
    md << "Tests that misfit beyond noise:";
    for (const std::string& t : a.misfitting_tests) md << " " << t;
    md << ".\n\n";
  }
  if (!a.misfits.empty()) {
    md << "| test | measure | residual (tolerances) |\n|---|---|---|\n";
    for (const Misfit& m : a.misfits) md << "| " << m.test << " | " << m.measure << " | " << number(m.residual, 3) << " |\n";
    md << "\n";
  }
  for (const ImplausibleValue& v : a.implausible) {
    md << "- implausible: " << v.parameter << " = " << number(v.value, 4) << " (nominal " << number(v.nominal, 4)
       << "): " << v.why << "\n";
  }
  if (!a.checks.empty()) {
    md << "\nWhat to check:\n\n";
    for (const std::string& c : a.checks) md << "- " << c << "\n";
  }
  return md.str();
}

}  // namespace

std::string significance_text(const CandidateScore& c) {
  if (c.at_off_value) return "no (at its off value)";
  return c.significant ? "yes" : "no";
}

namespace {

const CandidateScore* find(const std::vector<CandidateScore>& list, const std::string& name) {
  for (const CandidateScore& c : list) {
    if (mechanism_name(c.mechanism) == name) return &c;
  }
  return nullptr;
}

void write_histories(const std::filesystem::path& file, const MeasuredSet& set, const std::vector<SimulatedHistory>& baseline,
                     const std::vector<SimulatedHistory>* extended, const std::string& extended_name) {
  hdf5::Group root = hdf5::create_file(file);
  root.attribute("extended_model", extended_name);
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    const MeasuredTest& test = set.tests[t];
    hdf5::Group g = root.group(test.name);
    g.attribute("heldout", std::int64_t(set.is_heldout(t)));
    g.write("time", test.time, "s");
    std::vector<double> rotation = test.rotation, slide = test.slide;
    // Masked samples are written as the last valid value before them: a plot shows a flat
    // stretch, never a NaN.
    for (std::size_t k = 0; k < rotation.size(); ++k) {
      if (!test.rotation_valid[k]) rotation[k] = k > 0 ? rotation[k - 1] : 0.0;
      if (!test.slide_valid[k]) slide[k] = k > 0 ? slide[k - 1] : 0.0;
    }
    g.write("measured_rotation", rotation, "rad");
    g.write("measured_slide", slide, "m");
    g.write("rotation_valid", test.rotation_valid, "1");
    g.write("slide_valid", test.slide_valid, "1");
    g.write("table_acceleration", test.table_acceleration, "m/s^2");
    g.write("baseline_rotation", baseline[t].rotation, "rad");
    g.write("baseline_slide", baseline[t].slide, "m");
    if (extended) {
      g.write("extended_rotation", (*extended)[t].rotation, "rad");
      g.write("extended_slide", (*extended)[t].slide, "m");
    }
  }
}

// The [diagnosis] settings the numbers came from, so that a run can be repeated.
nlohmann::json settings_json(const DiagnosisSettings& s) {
  return {{"starts", s.starts}, {"evaluations", s.evaluations}, {"exploration", s.exploration}, {"seed", s.seed},
          {"input_realisations", s.input_realisations}};
}

}  // namespace

void write_calibration(const std::filesystem::path& directory, const MeasuredSet& set, const ModelFit& baseline,
                       const std::string& started_from) {
  std::filesystem::create_directories(directory);
  nlohmann::json j = fit_json(baseline);
  j["caskdem_version"] = build_info::version;
  j["measured_data"] = set.directory.string();
  for (int t : set.training) j["training_tests"].push_back(set.tests[t].name);
  for (int t : set.heldout) j["heldout_tests"].push_back(set.tests[t].name);
  j["settings"] = settings_json(set.settings);
  j["started_from"] = started_from.empty() ? nlohmann::json(nullptr) : nlohmann::json(started_from);
  std::ofstream(directory / "calibration.json") << j.dump(2) << "\n";
}

void write_diagnosis(const std::filesystem::path& directory, const MeasuredSet& set, const Diagnosis& d,
                     InstructionSet isa, bool plots, const TestPlan* plan) {
  std::filesystem::create_directories(directory);
  nlohmann::json j;
  j["caskdem_version"] = build_info::version;
  j["measured_data"] = set.directory.string();
  j["cause"] = d.cause;
  j["second_cause"] = d.second_cause.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.second_cause);
  for (int t : set.training) j["tests"]["training"].push_back(set.tests[t].name);
  for (int t : set.heldout) j["tests"]["heldout"].push_back(set.tests[t].name);
  j["settings"] = settings_json(set.settings);
  // The earlier diagnosis whose fits joined the searches' starts, so that a run can be repeated.
  j["started_from"] = d.started_from.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.started_from);
  const Diagnosis::Choices& c = d.choices;
  j["options"] = {{"choose_footprint", c.choose_footprint},
                  {"compare_normal_laws", c.compare_normal_laws},
                  {"profile", c.profile},
                  {"refit_from_profile", c.refit_from_profile},
                  {"look_for_second_effect", c.look_for_second_effect},
                  {"jackknife", c.jackknife},
                  {"minimum_gain", c.minimum_gain},
                  {"maximum_bic_delta", c.maximum_bic_delta},
                  {"minimum_improved_fraction", c.minimum_improved_fraction}};
  j["data_issues"] = nlohmann::json::array();
  for (const MeasuredTest& t : set.tests) {
    for (const std::string& issue : t.issues) j["data_issues"].push_back(issue);
  }
  j["footprint"] = d.footprint.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.footprint);
  j["footprint_changed"] = d.footprint_changed;
  j["normal_law"] = d.normal_law;
  j["normal_law_changed"] = d.normal_law_changed;
  j["footprints"] = nlohmann::json::array();
  for (const FootprintScore& f : d.footprints) {
    j["footprints"].push_back({{"footprint", f.footprint.empty() ? nlohmann::json(nullptr) : nlohmann::json(f.footprint)},
                               {"normal_law", f.normal_law},
                               {"stated", f.stated},
                               {"chosen", f.chosen},
                               {"withdrawn", f.withdrawn},
                               {"gain_when_chosen", f.withdrawn ? nlohmann::json(f.gain_when_chosen) : nlohmann::json(nullptr)},
                               {"heldout_error", f.heldout_error},
                               {"heldout_gain", f.heldout_gain},
                               {"baseline", fit_json(f.baseline)}});
  }
  j["baseline"] = fit_json(d.baseline);
  j["ranking"] = nlohmann::json::array();
  for (const CandidateScore& c : d.ranking) j["ranking"].push_back(candidate_json(c));
  const CandidateScore* chosen = find(d.ranking, d.cause);
  if (chosen) {
    for (std::size_t m = 0; m < measure_names().size(); ++m) j["gain"][measure_names()[m]] = chosen->measure_gain[m];
  } else {
    j["gain"] = nlohmann::json::object();
  }
  j["second_ranking"] = nlohmann::json::array();
  for (const CandidateScore& c : d.second_ranking) j["second_ranking"].push_back(candidate_json(c));
  // Present when the search for a second effect found a better fit of the cause's own model:
  // the pairs of second_ranking are scored against it; the cause's score stays its own fit's.
  j["cause_refitted"] = d.cause_refit ? fit_json(*d.cause_refit) : nlohmann::json(nullptr);
  for (const StructureRow& r : d.structure) {
    j["residual_structure"].push_back({{"variable", r.variable}, {"residual", r.residual}, {"statistic", r.statistic},
                                       {"statistic_name", r.statistic_name}, {"points_to", r.points_to}});
  }
  j["baseline_residuals"] = nlohmann::json::object();
  for (std::size_t t = 0; t < set.tests.size(); ++t) j["baseline_residuals"][set.tests[t].name] = d.baseline.residuals[t];
  j["measures"] = measure_names();
  j["wall_time_s"] = d.wall_seconds;
  std::ofstream(directory / "diagnosis.json") << j.dump(2) << "\n";

  // Histories of the baseline and the chosen model, for the plots, on the footprint they were fitted on.
  MeasuredSet fitted = set;
  fitted.specimen = d.specimen;
  const std::vector<SimulatedHistory> baseline = fitted_histories(fitted, d.baseline, isa);
  std::vector<SimulatedHistory> extended;
  if (chosen) extended = fitted_histories(fitted, chosen->model, isa);
  write_histories(directory / "histories.h5", set, baseline, chosen ? &extended : nullptr,
                  chosen ? chosen->model.name : std::string());

  std::ofstream md(directory / "report.md");
  md << "# Diagnosis of " << set.directory.filename().string() << "\n\n";
  md << "**Cause: " << d.cause << "**";
  if (!d.second_cause.empty()) md << "; a second effect remains: **" << d.second_cause << "**";
  md << ".\n\n";
  if (d.cause == "none") {
    md << "No mechanism improves the prediction of the held-out tests significantly, and the calibrated baseline "
          "fits every test within what the noise and the tests' predictability allow, with plausible values: "
          "nothing to add to the model.\n\n";
  } else if (d.cause == "footprint") {
    md << "The calibrated baseline on the stated footprint predicts the held-out tests worse than on the `"
       << d.footprint << "` footprint, and no mechanism improves on that significantly: the stated footprint is the "
          "likely cause (below, \"Footprint\").\n\n";
  } else if (d.cause == "normal_law") {
    md << "The calibrated baseline with the stated normal law predicts the held-out tests worse than with the `"
       << d.normal_law << "` law, and no mechanism improves on that significantly: the contact's normal law is the "
          "likely cause (below, \"Model form\").\n\n";
  } else if (d.cause == "unexplained") {
    md << "No mechanism improves the prediction of the held-out tests significantly, but the calibrated baseline "
          "does not fit these data: the model misfits beyond noise, or reaches them only with implausible values, "
          "and no mechanism of the library explains it (below, \"Is the baseline adequate?\").\n\n";
  } else {
    md << "Fitted with `" << d.cause << "`, the model predicts the held-out tests (not used for fitting) with "
       << number(100.0 * chosen->heldout_gain, 3) << " % less error than the calibrated baseline, and its BIC on the "
       << "training tests is lower by " << number(-chosen->bic_delta, 3) << ".\n\n";
  }
  md << "Training tests: ";
  for (int t : set.training) md << set.tests[t].name << " ";
  md << "; held-out tests: ";
  for (int t : set.heldout) md << set.tests[t].name << " ";
  md << "\n\n";
  if (!d.started_from.empty()) {
    md << "Each fit's searches also started from the fit of the same model and footprint in `" << d.started_from
       << "`, an earlier diagnosis of this cask.\n\n";
  }
  if (d.choices.refit_from_profile) {
    md << "A fit whose profile found a training misfit lower by more than the profile's bound was searched again "
          "from the profile's minimum (`--refit-from-profile`).\n\n";
  }
  md << "## Data\n\n";
  bool any_issue = false;
  for (const MeasuredTest& t : set.tests) {
    for (const std::string& issue : t.issues) {
      md << "- " << issue << "\n";
      any_issue = true;
    }
  }
  if (!any_issue) md << "No imperfections found in the test files.\n";
  if (!d.footprints.empty()) {
    // With the normal laws compared a row is a form (a rule and a law), else a rule.
    const bool laws = laws_compared(d.footprints);
    const std::string row = laws ? "form" : "rule";
    md << "\n## " << (laws ? "Model form" : "Footprint") << "\n\nThe baseline calibrated on each footprint rule"
       << (laws ? " and each normal law (linear spring-dashpot, Hunt-Crossley)" : "")
       << ", the held-out tests judged at common tolerances; another " << row
       << " replaces the stated one when its held-out gain is at least " << number(d.minimum_gain, 3)
       << ", and still is once its baseline is refitted from the mechanisms' fits (where that fits the training tests "
          "better) and the rows judged again. The chosen "
       << row << "'s row is the calibrated baseline below.\n\n"
       << "| " << (laws ? "form" : "footprint") << " | held-out error | gain against the stated " << row
       << " | friction | damping ratio | stiffness scale | adequate | |\n|---|---|---|---|---|---|---|---|\n";
    for (const FootprintScore& f : d.footprints) {
      md << "| " << form_label(f, laws) << (f.stated ? " (stated)" : "") << " | " << number(f.heldout_error, 3) << " | "
         << number(f.heldout_gain, 3) << " | " << number(f.baseline.fit.best[0], 3) << " | "
         << number(f.baseline.fit.best[1], 3) << " | " << number(f.baseline.fit.best[2], 3) << " | "
         << (f.baseline.adequacy.adequate ? "yes" : "no") << " | "
         << (f.chosen ? "chosen" : f.withdrawn ? "withdrawn" : "") << " |\n";
    }
    for (const FootprintScore& f : d.footprints) {
      if (f.withdrawn) {
        md << "\nThe " << row << " `" << form_label(f, laws) << "` was chosen first (gain "
           << number(f.gain_when_chosen, 3) << " on its first calibration), but refitted from the mechanisms' fits "
           << "and judged again its gain is " << number(f.heldout_gain, 3) << ", below " << number(d.minimum_gain, 3)
           << ": the choice was withdrawn, and the mechanisms were fitted again on the stated " << row << ".\n";
      } else if (!f.chosen && !f.stated && f.heldout_gain >= d.minimum_gain) {
        md << "\nJudged again after the chosen " << row << "'s refit, `" << form_label(f, laws) << "` reaches a gain of "
           << number(f.heldout_gain, 3) << "; the choice is made on the first calibrations and stays (a second switch "
           << "could cycle), so treat the two " << row << "s as not told apart by these tests.\n";
      }
    }
  }
  md << "\n## Calibrated baseline";
  if (!d.footprint.empty()) md << " (footprint: " << d.footprint << ")";
  if (d.normal_law != "linear") md << " (normal law: " << d.normal_law << ")";
  md << "\n\n";
  if (!d.baseline.fit.uncertainty_method.empty()) {
    md << "Standard errors from the " << d.baseline.fit.uncertainty_method
       << (d.baseline.fit.uncertainty_method == "curvature"
               ? " of the objective (local: on rocking tests an order of magnitude too small; `--uncertainty jackknife`)"
               : " (the jackknife's fit repeated without each training test)")
       << ".\n\n";
  }
  md << "| parameter | value | standard error |\n|---|---|---|\n";
  for (std::size_t i = 0; i < d.baseline.parameters.size(); ++i) {
    md << "| " << d.baseline.parameters[i].name << " | " << number(d.baseline.fit.best[i], 4) << " "
       << d.baseline.parameters[i].units << " | " << uncertainty_text(d.baseline, i) << " |\n";
  }
  md << adequacy_markdown(d.baseline.adequacy);
  md << "\n## Where the baseline disagrees (residual structure)\n\n"
     << "| residual | against | statistic | suggests |\n|---|---|---|---|\n";
  for (const StructureRow& r : d.structure) {
    md << "| " << r.residual << " | " << r.variable << " | " << r.statistic_name << " " << number(r.statistic, 3) << " | "
       << r.points_to << " |\n";
  }
  md << "\n![residuals](residuals.png)\n\n## Mechanisms, ranked by held-out gain\n\n"
     << "| mechanism | held-out gain | BIC delta | held-out tests improved | significant | parameters | profile: "
        "likelihood ratio (p) | profile interval (J within 3.84 of its minimum) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const CandidateScore& c : d.ranking) {
    md << "| " << mechanism_name(c.mechanism) << " | " << number(c.heldout_gain, 3) << " | " << number(c.bic_delta, 3)
       << " | " << c.heldout_tests_improved << "/" << set.heldout.size() << " | " << significance_text(c) << " | ";
    for (std::size_t i = 3; i < c.model.parameters.size(); ++i) {  // the mechanism's own parameters
      md << c.model.parameters[i].name << " = " << number(c.model.fit.best[i], 3) << " "
         << c.model.parameters[i].units << " (" << uncertainty_text(c.model, i) << "); ";
    }
    md << "| ";
    if (c.profile) {
      md << number(c.profile->likelihood_ratio, 3) << " (" << number(c.profile->p_value, 2) << ") | ";
      for (std::size_t i = 0; i < c.profile->parameters.size(); ++i) {
        md << c.profile->parameters[i] << " " << number(c.profile->interval_low[i], 3) << " to "
           << number(c.profile->interval_high[i], 3) << " " << c.profile->units[i] << "; ";
      }
      md << "|\n";
    } else {
      md << "- | - |\n";
    }
  }
  md << "\n![ranking](ranking.png)\n\n";
  if (chosen) {
    md << "## Gain of " << d.cause << " on each error measure (held-out tests)\n\n| measure | gain |\n|---|---|\n";
    for (std::size_t m = 0; m < measure_names().size(); ++m) {
      md << "| " << measure_names()[m] << " | " << number(chosen->measure_gain[m], 3) << " |\n";
    }
    md << "\n";
  }
  if (!d.second_ranking.empty()) {
    md << "## A second effect on top of " << d.cause << "\n\n";
    if (d.cause_refit) {
      md << "Refitted from the pairs' values of its parameters, " << d.cause << " alone fits the training tests "
         << "better (J " << number(d.cause_refit->fit.objective, 4) << " against " << number(chosen->model.fit.objective, 4)
         << " at its own fit): each pair is scored against that refit, so that a pair does not gain by a better fit "
         << "of the cause's own parameters (`cause_refitted` in diagnosis.json).\n\n";
    }
    md << "| mechanism | held-out gain | BIC delta | significant |\n"
       << "|---|---|---|---|\n";
    for (const CandidateScore& c : d.second_ranking) {
      md << "| " << mechanism_name(c.mechanism) << " | " << number(c.heldout_gain, 3) << " | " << number(c.bic_delta, 3)
         << " | " << significance_text(c) << " |\n";
    }
    md << "\n";
  }
  md << "## Measured, baseline and extended histories\n\n![histories](histories.png)\n";
  if (plan) md << "\n" << plan_markdown(*plan);
  md.close();
  if (plan) write_plan(directory, *plan, plots);

  if (plots) {
    run_plot_script("plot_diagnosis.py", {(directory / "histories.h5").string(), (directory / "diagnosis.json").string(),
                                          directory.string()});
  }
}

}  // namespace caskdem::diagnosis
