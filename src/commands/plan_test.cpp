// caskdem plan-test DIR: the table tests that would tell a diagnosis's leading candidates
// apart (src/diagnosis/plan_test.h), from the diagnosis.json `caskdem diagnose DIR` wrote.
//
// The candidates are read back from the file: the baseline's fit; the cause's, if any; then the
// mechanisms whose profile gives them the data's support against the baseline (likelihood ratio
// at least 3.84) and whose fit leaves the off value, largest ratio first.

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "diagnosis/footprint.h"
#include "diagnosis/plan_report.h"
#include "io/output_paths.h"

namespace caskdem::commands {

namespace {

// A fit in diagnosis.json as a candidate: its values and the errors its held-out tests were
// judged with, in the model's parameter order.
diagnosis::PlanCandidate candidate_of(const nlohmann::json& fit, const std::string& name, const Case& specimen,
                                      bool vertical_measured, const std::filesystem::path& file) {
  const std::string model = fit.value("model", "");
  const std::vector<diagnosis::Mechanism> mechanisms =
      diagnosis::parse_mechanism_list(model, file.string() + ": model");
  const diagnosis::ModelVariant variant(specimen, mechanisms, vertical_measured);
  diagnosis::PlanCandidate c;
  c.name = name;
  c.mechanisms = mechanisms;
  const bool has_errors = fit.contains("heldout_standard_errors") && fit["heldout_standard_errors"].is_object();
  for (const diagnosis::Parameter& p : variant.parameters()) {
    const nlohmann::json* value = nullptr;
    if (fit.contains("parameters") && fit["parameters"].contains(p.name)) value = &fit["parameters"][p.name]["value"];
    if (!value || !value->is_number()) {
      throw InputError(located(file, 0, "the fit of \"" + model + "\" has no number parameters." + p.name + ".value"));
    }
    c.point.push_back(value->get<double>());
    if (has_errors) c.standard_error.push_back(fit["heldout_standard_errors"].value(p.name, 0.0));
  }
  return c;
}

std::vector<diagnosis::PlanCandidate> candidates_from(const std::filesystem::path& file, const Case& specimen,
                                                      bool vertical_measured, int count) {
  require_regular_file(file, "the diagnosis.json of `caskdem diagnose`");
  std::ifstream in(file);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(located(file, 0, std::string("not JSON: ") + e.what()));
  }
  if (!j.contains("baseline") || !j.contains("ranking") || !j["ranking"].is_array()) {
    throw InputError(located(file, 0,
                             "expected the diagnosis.json of `caskdem diagnose` (a \"baseline\" and a "
                             "\"ranking\")"));
  }
  std::vector<diagnosis::PlanCandidate> out = {
      candidate_of(j["baseline"], "baseline", specimen, vertical_measured, file)};
  const std::string cause = j.value("cause", "");
  std::vector<std::pair<double, const nlohmann::json*>> supported;
  for (const nlohmann::json& r : j["ranking"]) {
    const std::string name = r.value("mechanism", "");
    if (name == cause) {
      out.push_back(candidate_of(r["fit"], name, specimen, vertical_measured, file));
      continue;
    }
    if (r.value("at_off_value", true) || !r.contains("profile") || !r["profile"].is_object()) continue;
    const double ratio = r["profile"].value("likelihood_ratio", 0.0);
    if (ratio >= diagnosis::kProfileBound) supported.emplace_back(ratio, &r);
  }
  std::stable_sort(supported.begin(), supported.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [ratio, r] : supported) {
    if (static_cast<int>(out.size()) >= count) break;
    out.push_back(candidate_of((*r)["fit"], (*r).value("mechanism", ""), specimen, vertical_measured, file));
  }
  return out;
}

}  // namespace

void print_plan(const diagnosis::TestPlan& plan) {
  std::cout << "candidates     ";
  for (const diagnosis::PlanCandidate& c : plan.candidates) std::cout << " " << c.name;
  std::cout << "\ntable limits    " << plan.limits_source << "\n";
  if (plan.candidates.size() < 2) {
    std::cout << "proposed tests  none: only the baseline is left standing\n";
    return;
  }
  const std::size_t shown = std::min<std::size_t>(diagnosis::kProposedTests, plan.tests.size());
  for (std::size_t t = 0; t < shown; ++t) {
    const diagnosis::ProposedTest& p = plan.tests[t];
    std::cout << "proposed test " << t + 1 << " " << p.description << "\n                separation "
              << std::setprecision(3) << p.separation << " (closest pair " << p.closest_pair
              << "; above 10.8 one test decides between them)\n";
  }
}

void add_plan_test(CLI::App& app) {
  struct Options {
    std::string directory, from, out;
    int candidates = 4, threads = 0;
    bool quiet = false, no_plot = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd =
      app.add_subcommand("plan-test", "The shaking-table tests that would tell a diagnosis's leading candidates apart");
  cmd->add_option("directory", options->directory, "Measured-data directory (specimen.toml and CSV files)")->required();
  cmd->add_option("--from", options->from,
                  "The diagnosis.json to take the candidates from (default DIRECTORY/diagnosis/diagnosis.json)");
  cmd->add_option("--out", options->out, "Output directory (default DIRECTORY/plan)");
  cmd->add_option("--candidates", options->candidates, "Most candidates to tell apart, the baseline included")
      ->check(CLI::Range(2, 9))
      ->capture_default_str();
  cmd->add_option("--threads", options->threads, "OpenMP threads")->check(thread_count());
  cmd->add_flag("--quiet", options->quiet, "No progress lines");
  cmd->add_flag("--no-plot", options->no_plot, "Do not make plan.png");
  cmd->callback([options]() {
    const diagnosis::MeasuredSet set = diagnosis::read_measured_set(options->directory);
    print_data_issues(set);
    const std::filesystem::path from = options->from.empty()
                                           ? std::filesystem::path(options->directory) / "diagnosis" / "diagnosis.json"
                                           : std::filesystem::path(options->from);
    // The candidates were fitted on the footprint and normal law the diagnosis kept.
    Case specimen = set.specimen;
    {
      std::ifstream in(from);
      const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
      if (!j.is_discarded() && j.contains("footprint") && j["footprint"].is_string() &&
          diagnosis::footprint_of(specimen)) {
        for (diagnosis::Footprint f : diagnosis::all_footprints()) {
          if (diagnosis::footprint_name(f) == j["footprint"].get<std::string>())
            specimen = diagnosis::with_footprint(specimen, f);
        }
      }
      if (!j.is_discarded() && j.contains("normal_law") && j["normal_law"].is_string()) {
        try {
          specimen.model.normal_law = normal_law_of(j["normal_law"].get<std::string>());
        } catch (const std::invalid_argument& e) {
          throw InputError(located(from, 0, std::string("key normal_law: ") + e.what()));
        }
      }
    }
    const std::vector<diagnosis::PlanCandidate> candidates =
        candidates_from(from, specimen, set.vertical_measured, options->candidates);
    const std::filesystem::path out =
        options->out.empty() ? std::filesystem::path(options->directory) / "plan" : std::filesystem::path(options->out);
    prepare_output_directory(out);
    diagnosis::DiagnosisOptions run_options;
    run_options.threads = options->threads;
    if (!options->quiet) run_options.log = [](const std::string& line) { std::cerr << "plan-test: " << line << "\n"; };
    const diagnosis::TestPlan plan = diagnosis::plan_tests(set, specimen, candidates, run_options);
    print_plan(plan);
    diagnosis::write_plan(out, plan, !options->no_plot);
    std::cout << "wall time       " << std::setprecision(4) << plan.wall_seconds << " s\n";
    std::cout << "wrote           " << out.string() << "/ (plan.json, plan.md, plan-histories.h5"
              << (options->no_plot ? "" : ", plan.png")
              << (plan.tests.empty() ? "" : ", drive-1.csv ...: the proposed tests' table drives") << ")\n";
  });
}

}  // namespace caskdem::commands
