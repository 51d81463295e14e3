#include "diagnosis/report.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "caskdem/build_info.h"
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

nlohmann::json fit_json(const ModelFit& m) {
  nlohmann::json j;
  j["model"] = m.name;
  j["parameters"] = parameters_json(m);
  j["training_objective"] = m.fit.objective;
  j["bic"] = m.bic;
  j["aic"] = m.aic;
  j["heldout_error"] = m.heldout_error;
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
    g.write("rotation_valid", test.rotation_valid);
    g.write("slide_valid", test.slide_valid);
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

void write_calibration(const std::filesystem::path& directory, const MeasuredSet& set, const ModelFit& baseline) {
  std::filesystem::create_directories(directory);
  nlohmann::json j = fit_json(baseline);
  j["caskdem_version"] = build_info::version;
  j["measured_data"] = set.directory.string();
  for (int t : set.training) j["training_tests"].push_back(set.tests[t].name);
  for (int t : set.heldout) j["heldout_tests"].push_back(set.tests[t].name);
  j["settings"] = settings_json(set.settings);
  std::ofstream(directory / "calibration.json") << j.dump(2) << "\n";
}

void write_diagnosis(const std::filesystem::path& directory, const MeasuredSet& set, const Diagnosis& d,
                     InstructionSet isa, bool plots) {
  std::filesystem::create_directories(directory);
  nlohmann::json j;
  j["caskdem_version"] = build_info::version;
  j["measured_data"] = set.directory.string();
  j["cause"] = d.cause;
  j["second_cause"] = d.second_cause.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.second_cause);
  for (int t : set.training) j["tests"]["training"].push_back(set.tests[t].name);
  for (int t : set.heldout) j["tests"]["heldout"].push_back(set.tests[t].name);
  j["settings"] = settings_json(set.settings);
  j["data_issues"] = nlohmann::json::array();
  for (const MeasuredTest& t : set.tests) {
    for (const std::string& issue : t.issues) j["data_issues"].push_back(issue);
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

  // Histories of the baseline and the chosen model, for the plots.
  const std::vector<SimulatedHistory> baseline = fitted_histories(set, d.baseline, isa);
  std::vector<SimulatedHistory> extended;
  if (chosen) extended = fitted_histories(set, chosen->model, isa);
  write_histories(directory / "histories.h5", set, baseline, chosen ? &extended : nullptr,
                  chosen ? chosen->model.name : std::string());

  std::ofstream md(directory / "report.md");
  md << "# Diagnosis of " << set.directory.filename().string() << "\n\n";
  md << "**Cause: " << d.cause << "**";
  if (!d.second_cause.empty()) md << "; a second effect remains: **" << d.second_cause << "**";
  md << ".\n\n";
  if (d.cause == "none") {
    md << "No mechanism improves the prediction of the held-out tests significantly: the baseline model "
          "disagrees with these data no more than their noise explains.\n\n";
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
  md << "## Data\n\n";
  bool any_issue = false;
  for (const MeasuredTest& t : set.tests) {
    for (const std::string& issue : t.issues) {
      md << "- " << issue << "\n";
      any_issue = true;
    }
  }
  if (!any_issue) md << "No imperfections found in the test files.\n";
  md << "\n## Calibrated baseline\n\n";
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
  md << "\n## Where the baseline disagrees (residual structure)\n\n"
     << "| residual | against | statistic | suggests |\n|---|---|---|---|\n";
  for (const StructureRow& r : d.structure) {
    md << "| " << r.residual << " | " << r.variable << " | " << r.statistic_name << " " << number(r.statistic, 3) << " | "
       << r.points_to << " |\n";
  }
  md << "\n![residuals](residuals.png)\n\n## Mechanisms, ranked by held-out gain\n\n"
     << "| mechanism | held-out gain | BIC delta | held-out tests improved | significant | parameters |\n"
     << "|---|---|---|---|---|---|\n";
  for (const CandidateScore& c : d.ranking) {
    md << "| " << mechanism_name(c.mechanism) << " | " << number(c.heldout_gain, 3) << " | " << number(c.bic_delta, 3)
       << " | " << c.heldout_tests_improved << "/" << set.heldout.size() << " | " << (c.significant ? "yes" : "no") << " | ";
    for (std::size_t i = 3; i < c.model.parameters.size(); ++i) {  // the mechanism's own parameters
      md << c.model.parameters[i].name << " = " << number(c.model.fit.best[i], 3) << " "
         << c.model.parameters[i].units << " (" << uncertainty_text(c.model, i) << "); ";
    }
    md << "|\n";
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
         << " | " << (c.significant ? "yes" : "no") << " |\n";
    }
    md << "\n";
  }
  md << "## Measured, baseline and extended histories\n\n![histories](histories.png)\n";
  md.close();

  if (plots) {
    run_plot_script("plot_diagnosis.py", {(directory / "histories.h5").string(), (directory / "diagnosis.json").string(),
                                          directory.string()});
  }
}

}  // namespace caskdem::diagnosis
