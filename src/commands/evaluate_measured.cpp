// caskdem evaluate-measured DIR: the diagnosis's own judgement of one parameter set.
//
// A fit says where its search ended; this says how any point fares by the same measure: a
// published friction coefficient, a colleague's calibration, or the true values of a data set
// made by synthesize-measured. Values come from --at NAME=VALUE (SI, in the units the
// parameter list prints), else from a fit in a diagnosis.json or calibration.json, or the true
// values in synthesize-measured's truth.json (--from), else from the specimen's nominal values
// with every mechanism switched off. A fit from a file brings the standard errors its held-out
// tests were judged with (their tolerances widened by the prediction's spread over them), so at
// the fit's own point the numbers are the fit's; any other source judges the point alone.

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "core/text.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/footprint.h"

namespace caskdem::commands {

namespace {

std::string parameter_list(const std::vector<diagnosis::Parameter>& parameters) {
  std::string text;
  for (const diagnosis::Parameter& p : parameters) text.append(text.empty() ? "" : ", ").append(p.name);
  return text;
}

// The shortest text that reads back as exactly `value`, so that a bound copied from a
// message is accepted.
std::string exact(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

// Values must lie in the box the diagnosis searches: outside it the model is not meant to hold
// (a negative stiffness, a delay longer than the tests resolve).
void check_in_box(const diagnosis::Parameter& p, double value, const std::string& where) {
  if (!std::isfinite(value) || value < p.low || value > p.high) {
    throw InputError(where + ": " + p.name + " = " + exact(value) + " is outside the range the diagnosis searches, " +
                     exact(p.low) + " to " + exact(p.high) + (p.units.empty() ? "" : " " + p.units));
  }
}

// The fit of `model` in a diagnosis.json or calibration.json: any object whose "model" is that
// name and which has "parameters".
const nlohmann::json* find_fit(const nlohmann::json& j, const std::string& model) {
  if (j.is_object()) {
    if (j.contains("model") && j["model"] == model && j.contains("parameters") && j["parameters"].is_object()) return &j;
    for (const auto& item : j.items()) {
      if (const nlohmann::json* found = find_fit(item.value(), model)) return found;
    }
  } else if (j.is_array()) {
    for (const nlohmann::json& item : j) {
      if (const nlohmann::json* found = find_fit(item, model)) return found;
    }
  }
  return nullptr;
}

// Takes the model's values from a fit or a truth; a fit's held-out standard errors (those its
// held-out tests were judged with) go to `heldout_standard_error`, left empty where it has none.
void take_from_file(const std::filesystem::path& file, const diagnosis::ModelVariant& variant,
                    std::vector<double>& point, std::vector<std::string>& source,
                    std::vector<double>& heldout_standard_error) {
  require_regular_file(file, "a diagnosis.json, calibration.json or truth.json");
  std::ifstream in(file);
  if (!in) throw InputError(located(file, 0, "cannot be opened (expected a diagnosis.json, calibration.json or truth.json)"));
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // a syntax error, or a number beyond a double
    throw InputError(located(file, 0, std::string("not JSON: ") + e.what()));
  }
  // A truth.json of synthesize-measured holds the values the data were made with, each a
  // number; a fit holds each value in an object beside its standard error.
  const bool is_truth = j.is_object() && j.contains("hidden") && j.contains("parameters") && j["parameters"].is_object();
  const nlohmann::json* fit = is_truth ? &j : find_fit(j, variant.name());
  if (!fit) {
    throw InputError(located(file, 0, "no fit of the model \"" + variant.name() +
                                          "\" in it (expected a \"model\" of that name with \"parameters\")"));
  }
  const nlohmann::json& parameters = (*fit)["parameters"];
  const auto entry_of = [&](const std::string& name) -> const nlohmann::json* {
    if (!parameters.contains(name)) return nullptr;
    const nlohmann::json& entry = parameters[name];
    if (is_truth) return &entry;
    return entry.is_object() && entry.contains("value") ? &entry["value"] : nullptr;
  };
  for (std::size_t i = 0; i < variant.parameters().size(); ++i) {
    const diagnosis::Parameter& p = variant.parameters()[i];
    const nlohmann::json* value = entry_of(p.name);
    if (!value || !value->is_number()) {
      throw InputError(located(
          file, 0,
          is_truth ? "the truth has no number parameters." + p.name + " (it hides " + j["hidden"].dump() +
                         "; --model names the mechanisms to take)"
                   : "the fit of \"" + variant.name() + "\" has no number parameters." + p.name + ".value"));
    }
    point[i] = value->get<double>();
    check_in_box(p, point[i], file.string());
    source[i] = file.filename().string();
  }
  if (is_truth || !fit->contains("heldout_standard_errors")) return;
  const nlohmann::json& errors = (*fit)["heldout_standard_errors"];
  heldout_standard_error.assign(point.size(), 0.0);
  for (std::size_t i = 0; i < variant.parameters().size(); ++i) {
    const std::string& name = variant.parameters()[i].name;
    if (!errors.is_object() || !errors.contains(name) || !errors[name].is_number() ||
        !std::isfinite(errors[name].get<double>()) || errors[name].get<double>() < 0.0) {
      throw InputError(located(file, 0, "the fit of \"" + variant.name() + "\" has no heldout_standard_errors." + name +
                                            " (expected a number >= 0 for every parameter)"));
    }
    heldout_standard_error[i] = errors[name].get<double>();
  }
}

// The footprint rule and the normal law a diagnosis.json kept ("" for any other file, or none).
struct FormKept {
  std::string footprint, normal_law;
};
FormKept form_kept_in(const std::string& file) {
  if (file.empty() || !std::filesystem::is_regular_file(file)) return {};
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return {};
  auto text = [&j](const char* key) { return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; };
  return {text("footprint"), text("normal_law")};
}

void take_assignment(const std::string& assignment, const diagnosis::ModelVariant& variant, std::vector<double>& point,
                     std::vector<std::string>& source) {
  const std::vector<diagnosis::Parameter>& parameters = variant.parameters();
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) {
    throw InputError("--at " + assignment + ": expected NAME=VALUE, NAME one of: " + parameter_list(parameters));
  }
  const std::string name(trim(std::string_view(assignment).substr(0, equals)));
  const int i = variant.index_of(name);
  if (i < 0) {
    throw InputError("--at " + assignment + ": \"" + name + "\" is not a parameter of " + variant.name() +
                     "; expected one of: " + parameter_list(parameters));
  }
  const std::optional<double> value = parse_double(trim(std::string_view(assignment).substr(equals + 1)));
  if (!value) throw InputError("--at " + assignment + ": expected a number (SI units)");
  check_in_box(parameters[i], *value, "--at " + assignment);
  if (source[i] == "--at") throw InputError("--at " + assignment + ": " + name + " is given twice; expected each once");
  point[i] = *value;
  source[i] = "--at";
}

nlohmann::json evaluation_json(const diagnosis::MeasuredSet& set, const diagnosis::PointEvaluation& e,
                               const std::vector<std::string>& source) {
  nlohmann::json j;
  j["measured_data"] = set.directory.string();
  j["model"] = e.model;
  for (std::size_t i = 0; i < e.parameters.size(); ++i) {
    j["parameters"][e.parameters[i].name] = {{"value", e.point[i]}, {"units", e.parameters[i].units}, {"from", source[i]}};
  }
  j["tests"] = nlohmann::json::array();
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    nlohmann::json test;
    test["name"] = set.tests[t].name;
    test["role"] = set.is_heldout(t) ? "heldout" : "training";
    test["loss"] = e.loss[t];
    for (std::size_t m = 0; m < diagnosis::measure_names().size(); ++m) {
      test["residuals"][diagnosis::measure_names()[m]] = e.residuals[t][m];
    }
    j["tests"].push_back(test);
  }
  j["training_objective"] = e.training_objective;
  j["training_residual_count"] = e.training_residual_count;
  j["heldout_error"] = e.heldout_error;
  j["bic"] = e.bic;
  return j;
}

}  // namespace

void print_data_issues(const diagnosis::MeasuredSet& set) {
  for (const diagnosis::MeasuredTest& t : set.tests) {
    for (const std::string& issue : t.issues) std::cout << "data            " << issue << "\n";
  }
}

void add_evaluate_measured(CLI::App& app) {
  struct Options {
    std::string directory, model = "baseline", from, json, footprint;
    std::vector<std::string> at;
    int threads = 0;
    bool residuals = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate-measured", "How one parameter set fares on measured tests, judged as the diagnosis judges its fits");
  cmd->add_option("directory", options->directory, "Measured-data directory (specimen.toml and CSV files)")->required();
  cmd->add_option("--model", options->model,
                  "baseline (default), a mechanism, or several joined by ',' or '+' (e.g. floor_compliance)");
  cmd->add_option("--at", options->at, "NAME=VALUE in SI units; repeat or separate with ','")->delimiter(',');
  cmd->add_option("--from", options->from, "Take the model's values from a fit in a diagnosis.json or calibration.json, or from a truth.json of synthesize-measured");
  cmd->add_option("--footprint", options->footprint,
                  "Judge on this footprint rule: gyration, radius or distributed (default: the one a diagnosis.json "
                  "given with --from kept, else the specimen's)")
      ->check(CLI::IsMember({"gyration", "radius", "distributed"}));
  cmd->add_option("--json", options->json, "Also write the evaluation (per-test residuals) to this JSON file");
  cmd->add_option("--threads", options->threads, "OpenMP threads")->check(thread_count());
  cmd->add_flag("--residuals", options->residuals, "Print every test's scaled residual per measure");
  cmd->callback([options]() {
    diagnosis::MeasuredSet set = diagnosis::read_measured_set(options->directory);
    print_data_issues(set);
    // A diagnosis's fits belong to the footprint rule it kept, which need not be the stated one.
    const FormKept kept = form_kept_in(options->from);
    const std::string footprint = !options->footprint.empty() ? options->footprint : kept.footprint;
    if (!footprint.empty()) {
      for (diagnosis::Footprint f : diagnosis::all_footprints()) {
        if (diagnosis::footprint_name(f) != footprint) continue;
        if (!diagnosis::footprint_of(set.specimen)) {
          throw InputError("--footprint " + footprint + ": only a cylindrical specimen has footprint rules");
        }
        set.specimen = diagnosis::with_footprint(set.specimen, f);
      }
    }
    // And to the normal law it kept (diagnose --normal-laws).
    try {
      if (!kept.normal_law.empty()) set.specimen.model.normal_law = normal_law_of(kept.normal_law);
    } catch (const std::invalid_argument& e) {
      throw InputError(located(options->from, 0, std::string("key normal_law: ") + e.what()));
    }
    const std::vector<diagnosis::Mechanism> mechanisms = diagnosis::parse_mechanism_list(options->model, "--model");
    const diagnosis::ModelVariant variant(set.specimen, mechanisms, set.vertical_measured);
    std::vector<double> point = variant.reference();
    std::vector<std::string> source(point.size(), "nominal");
    for (std::size_t i = 0; i < point.size(); ++i) {
      if (variant.parameters()[i].mechanism) source[i] = "switched off";
    }
    std::vector<double> heldout_standard_error;
    if (!options->from.empty()) take_from_file(options->from, variant, point, source, heldout_standard_error);
    for (const std::string& assignment : options->at) take_assignment(assignment, variant, point, source);

    diagnosis::DiagnosisOptions run_options;
    run_options.threads = options->threads;
    const diagnosis::PointEvaluation e = diagnosis::evaluate_point(set, mechanisms, point, heldout_standard_error, run_options);

    std::cout << "model           " << e.model << "\n";
    for (std::size_t i = 0; i < e.parameters.size(); ++i) {
      std::cout << "  " << std::left << std::setw(20) << e.parameters[i].name << std::setw(14) << std::setprecision(6)
                << e.point[i] << std::setw(6) << e.parameters[i].units << "(" << source[i] << ")\n";
    }
    const std::vector<std::string>& measures = diagnosis::measure_names();
    std::cout << std::left << std::setw(12) << "test" << std::setw(10) << "role" << "loss\n";
    for (std::size_t t = 0; t < set.tests.size(); ++t) {
      std::cout << std::left << std::setw(12) << set.tests[t].name << std::setw(10)
                << (set.is_heldout(t) ? "held-out" : "training")
                << std::setprecision(4) << e.loss[t] << "\n";
      if (options->residuals) {
        for (std::size_t m = 0; m < measures.size(); ++m) {
          std::cout << "    " << std::left << std::setw(20) << measures[m] << std::setprecision(3) << e.residuals[t][m] << "\n";
        }
      }
    }
    std::cout << "training J      " << std::setprecision(5) << e.training_objective << " (" << e.training_residual_count
              << " scaled residuals; what the fits minimise)\n";
    std::cout << "held-out error  " << e.heldout_error << " (RMS of scaled residuals; "
              << (heldout_standard_error.empty() ? "judged at the point alone"
                                                 : "tolerances widened by the prediction's spread over the fit's standard errors")
              << ")\n";
    std::cout << "BIC             " << e.bic << "\n";
    if (!options->json.empty()) {
      std::ofstream out(options->json);
      if (!out) throw InputError(located(options->json, 0, "cannot be written"));
      out << evaluation_json(set, e, source).dump(2) << "\n";
      std::cout << "wrote           " << options->json << "\n";
    }
  });
}

}  // namespace caskdem::commands
