// Measured data in: caskdem calibrate-measured DIR, caskdem diagnose DIR, and
// caskdem synthesize-measured (synthetic data with hidden mechanisms, for trying it out).

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>

#include "commands/commands.h"
#include "commands/validators.h"
#include "diagnosis/plan_report.h"
#include "diagnosis/report.h"
#include "diagnosis/synthesize.h"
#include "io/output_paths.h"

namespace caskdem::commands {

namespace {

diagnosis::DiagnosisOptions options_for(int threads, bool quiet, const std::string& uncertainty) {
  diagnosis::DiagnosisOptions o;
  o.threads = threads;
  o.jackknife = uncertainty == "jackknife";
  if (!quiet) o.log = [](const std::string& line) { std::cerr << "diagnose: " << line << "\n"; };
  return o;
}

// --uncertainty: how the standard errors are made (docs/diagnosis-accuracy.md, "Are the uncertainties right?").
void add_uncertainty_option(CLI::App* cmd, std::string& uncertainty, const std::string& whose) {
  cmd->add_option("--uncertainty", uncertainty,
                  "Standard errors from 'jackknife' (the larger of the curvature's and a jackknife's, which refits "
                  "without each training test: one fit per test) or 'curvature' (of the objective at the optimum: "
                  "free, but an order of magnitude too small on rocking tests)" + whose)
      ->check(CLI::IsMember({"jackknife", "curvature"}))
      ->capture_default_str();
}

// --start-from: an earlier diagnosis of the cask whose fits start this one's (diagnosis/earlier_fits.h).
void add_start_from_option(CLI::App* cmd, std::string& start_from) {
  cmd->add_option("--start-from", start_from,
                  "An earlier diagnosis.json (or calibration.json) of this cask, e.g. before a test was added: each "
                  "of its fits joins the starts of the fit of the same model and footprint, which then ends no higher "
                  "than that fit's point on these tests, nor than without this option");
}

void print_adequacy(const diagnosis::Adequacy& a) {
  std::cout << "adequate        " << (a.adequate ? "yes" : "no") << ": J " << std::setprecision(4) << a.statistic
            << " over " << a.residuals << " residuals (RMS " << std::setprecision(3) << a.rms_residual
            << "), p = " << a.p_value
            << (a.global_fits ? " over every test (within noise)" : " over every test (beyond noise)") << "\n";
  for (const diagnosis::FamilyFit& f : a.families) {
    if (!f.misfits) continue;
    std::cout << "  misfitting family: " << f.family << ", J " << std::setprecision(4) << f.statistic << " over "
              << f.residuals << " residuals, p = " << std::setprecision(3) << f.p_value << " (Holm level "
              << f.holm_level << ")";
    if (f.magnitude_residuals > 0) {
      std::cout << "; " << (f.mean_magnitude_residual < 0.0 ? "under" : "over") << "-predicted by "
                << std::abs(f.mean_magnitude_residual) << " tolerances on average";
    }
    std::cout << "\n";
  }
  if (!a.misfitting_tests.empty()) {
    std::cout << "  misfitting tests:";
    for (const std::string& t : a.misfitting_tests) std::cout << " " << t;
    std::cout << "\n";
  }
  for (const diagnosis::ImplausibleValue& v : a.implausible) {
    std::cout << "  implausible: " << v.parameter << " = " << std::setprecision(4) << v.value << " (nominal " << v.nominal
              << "): " << v.why << "\n";
  }
  for (const std::string& c : a.checks) std::cout << "  check: " << c << "\n";
}

void print_fit(const diagnosis::ModelFit& m) {
  if (!m.fit.uncertainty_method.empty()) std::cout << "  standard errors from the " << m.fit.uncertainty_method << "\n";
  for (std::size_t i = 0; i < m.parameters.size(); ++i) {
    std::cout << "  " << std::left << std::setw(20) << m.parameters[i].name << std::setprecision(4) << m.fit.best[i];
    const std::optional<double> error = diagnosis::standard_error_of(m.fit, m.parameters, i);
    if (error) std::cout << " +- " << std::setprecision(2) << *error;
    std::cout << " " << m.parameters[i].units;
    if (diagnosis::at_search_bound(m.parameters[i], m.fit.best[i])) std::cout << " (at the search bound)";
    std::cout << "\n";
  }
}

}  // namespace

void add_diagnose(CLI::App& app) {
  {
    struct Options {
      std::string directory, out, start_from;
      int threads = 0;
      bool quiet = false;
      std::string uncertainty = "jackknife";
    };
    auto options = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("calibrate-measured",
                                       "Fit the baseline model (friction, damping, stiffness scale) to measured tests");
    cmd->add_option("directory", options->directory, "Measured-data directory (specimen.toml and CSV files)")->required();
    cmd->add_option("--out", options->out, "Output directory (default DIRECTORY/calibration)");
    cmd->add_option("--threads", options->threads, "OpenMP threads")->check(thread_count());
    cmd->add_flag("--quiet", options->quiet, "No progress lines");
    add_uncertainty_option(cmd, options->uncertainty, "");
    add_start_from_option(cmd, options->start_from);
    cmd->callback([options]() {
      const diagnosis::MeasuredSet set = diagnosis::read_measured_set(options->directory);
      print_data_issues(set);
      const std::filesystem::path out =
          options->out.empty() ? std::filesystem::path(options->directory) / "calibration" : std::filesystem::path(options->out);
      diagnosis::DiagnosisOptions run_options = options_for(options->threads, options->quiet, options->uncertainty);
      if (!options->start_from.empty()) run_options.earlier = diagnosis::read_earlier_fits(options->start_from, set);
      prepare_output_directory(out);
      const diagnosis::ModelFit fit = diagnosis::calibrate_baseline(set, run_options);
      if (!options->start_from.empty())
        std::cout << "started from    " << options->start_from << " (its fit among the starts)\n";
      std::cout << "baseline fitted on " << set.training.size() << " tests (" << fit.fit.evaluations
                << " evaluations in " << fit.fit.populations << " lockstep populations)\n";
      print_fit(fit);
      std::cout << "held-out error  " << fit.heldout_error << " (RMS of scaled residuals)\n";
      print_adequacy(fit.adequacy);
      diagnosis::write_calibration(out, set, fit, options->start_from);
      std::cout << "wrote           " << (out / "calibration.json").string() << "\n";
    });
  }
  {
    struct Options {
      std::string directory, out, start_from;
      int threads = 0;
      bool quiet = false, no_plot = false, no_second_effect = false, no_plan = false, normal_laws = false;
      bool refit_from_profile = false;
      std::string uncertainty = "jackknife";
    };
    auto options = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand(
        "diagnose", "What the model gets wrong on measured tests, its most likely physical cause, and the gain");
    cmd->add_option("directory", options->directory, "Measured-data directory (specimen.toml and CSV files)")->required();
    cmd->add_option("--out", options->out, "Output directory (default DIRECTORY/diagnosis)");
    cmd->add_option("--threads", options->threads, "OpenMP threads")->check(thread_count());
    cmd->add_flag("--quiet", options->quiet, "No progress lines");
    cmd->add_flag("--no-plot", options->no_plot, "Do not make the PNGs");
    cmd->add_flag("--no-plan", options->no_plan,
                  "Do not look for the table tests that would tell the leading candidates apart (plan-test)");
    cmd->add_flag("--normal-laws", options->normal_laws,
                  "Also calibrate on the other normal law (linear, Hunt-Crossley) and keep the one the held-out tests "
                  "prefer (twice the calibrations)");
    cmd->add_flag("--refit-from-profile", options->refit_from_profile,
                  "Search a mechanism's fit again from its profile's minimum where that is lower than the fit by more "
                  "than the profile's bound (chi2_1 at 95 %)");
    cmd->add_flag("--no-second-effect", options->no_second_effect,
                  "Do not fit the other mechanisms on top of the cause (faster; the cause is the same)");
    add_uncertainty_option(cmd, options->uncertainty, ", for the baseline and the cause");
    add_start_from_option(cmd, options->start_from);
    cmd->callback([options]() {
      const diagnosis::MeasuredSet set = diagnosis::read_measured_set(options->directory);
      print_data_issues(set);
      const std::filesystem::path out =
          options->out.empty() ? std::filesystem::path(options->directory) / "diagnosis" : std::filesystem::path(options->out);
      diagnosis::DiagnosisOptions run_options = options_for(options->threads, options->quiet, options->uncertainty);
      if (!options->start_from.empty()) run_options.earlier = diagnosis::read_earlier_fits(options->start_from, set);
      prepare_output_directory(out);
      run_options.look_for_second_effect = !options->no_second_effect;
      run_options.compare_normal_laws = options->normal_laws;
      run_options.refit_from_profile = options->refit_from_profile;
      const diagnosis::Diagnosis d = diagnosis::diagnose(set, run_options);
      std::optional<diagnosis::TestPlan> plan;
      if (!options->no_plan)
        plan = diagnosis::plan_tests(set, d.specimen, diagnosis::leading_candidates(d), run_options);
      std::cout << "cause           " << d.cause << "\n";
      if (!d.started_from.empty()) std::cout << "started from    " << d.started_from << " (its fits among the starts)\n";
      const bool laws = diagnosis::laws_compared(d.footprints);
      for (const diagnosis::FootprintScore& f : d.footprints) {
        std::cout << (laws ? "model form      " : "footprint       ") << std::left << std::setw(laws ? 30 : 12)
                  << diagnosis::form_label(f, laws) << " held-out error "
                  << std::setprecision(3) << f.heldout_error << ", gain " << f.heldout_gain
                  << (f.stated ? " (stated)" : "") << (f.chosen ? " chosen" : "");
        if (f.withdrawn) std::cout << " withdrawn after its refit (gain " << f.gain_when_chosen << " when chosen)";
        std::cout << "\n";
      }
      print_adequacy(d.baseline.adequacy);
      if (!d.second_cause.empty()) std::cout << "second effect   " << d.second_cause << "\n";
      std::cout << std::left << std::setw(34) << "mechanism" << std::setw(15) << "held-out gain" << std::setw(12)
                << "BIC delta" << std::setw(24) << "significant"
                << "profile likelihood ratio (p)\n";
      for (const diagnosis::CandidateScore& c : d.ranking) {
        std::cout << std::left << std::setw(34) << diagnosis::mechanism_name(c.mechanism) << std::setw(15)
                  << std::setprecision(3) << c.heldout_gain << std::setw(12) << c.bic_delta << std::setw(24)
                  << diagnosis::significance_text(c);
        if (c.profile)
          std::cout << c.profile->likelihood_ratio << " (" << std::setprecision(2) << c.profile->p_value << ")";
        std::cout << "\n";
      }
      if (plan) print_plan(*plan);
      diagnosis::write_diagnosis(out, set, d, InstructionSet::automatic, !options->no_plot, plan ? &*plan : nullptr);
      std::cout << "wall time       " << std::setprecision(4) << d.wall_seconds << " s\n";
      std::cout << "wrote           " << out.string() << "/ (diagnosis.json, report.md"
                << (options->no_plot ? "" : ", PNGs")
                << (plan && !plan->tests.empty() ? ", plan.json, drive-1.csv ...: the proposed tests' table drives" : "")
                << ")\n";
    });
  }
  {
    struct Options {
      std::string out, effects, drive;
      std::uint64_t seed = 1;
      int test = 0;
      diagnosis::SyntheticSpec noise;  // its noise levels only
    };
    auto options = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand(
        "synthesize-measured", "Write synthetic measured tests of the 1/3 model cask with hidden mechanisms");
    cmd->add_option("--out", options->out, "Directory to write")->required();
    cmd->add_option("--effect", options->effects, "Hidden mechanisms, comma separated (default: none)");
    cmd->add_option("--seed", options->seed, "Seed of the true values and the noise")->check(seed_number());
    // Each noise can be switched off alone, to see what it does to a diagnosis: with the table's
    // off, the true values reproduce every response channel to its own noise.
    auto* rotation_noise = cmd->add_option("--rotation-noise", options->noise.rotation_noise,
                                           "Standard deviation of the rotation channel's noise, rad")
                               ->check(number_within("a rotation noise in rad", 0.0, 0.1))
                               ->capture_default_str();
    auto* slide_noise = cmd->add_option("--slide-noise", options->noise.slide_noise,
                                        "Standard deviation of the sliding channel's noise, m")
                            ->check(number_within("a sliding noise in m", 0.0, 0.1))
                            ->capture_default_str();
    auto* table_noise = cmd->add_option("--table-noise", options->noise.table_noise,
                                        "Standard deviation of the table channels' noise (horizontal and vertical), m/s^2")
                            ->check(number_within("a table noise in m/s^2", 0.0, 10.0))
                            ->capture_default_str();
    // The loop closed: a proposed test (a plan's drive file) run on the same hidden specimen.
    auto* drive = cmd->add_option("--drive", options->drive,
                                  "Add one test to the set in --out (made with the same --effect and --seed): the "
                                  "table driven by this file, a plan's drive-1.csv");
    auto* test = cmd->add_option("--test", options->test, "The added test's number (with --drive)")
                     ->check(number_check(
                         "a test number, a whole number from 1 to 999",
                         [](double x) { return x >= 1.0 && x <= 999.0 && x == std::floor(x); }, "TEST"));
    drive->needs(test);
    test->needs(drive);
    // An added test has the set's noise levels (truth.json), whatever these say.
    for (CLI::Option* noise : {rotation_noise, slide_noise, table_noise}) drive->excludes(noise);
    cmd->callback([options]() {
      diagnosis::SyntheticSpec spec = options->noise;
      spec.seed = options->seed;
      spec.hidden = diagnosis::parse_mechanism_list(options->effects, "--effect");
      if (!options->drive.empty()) {
        diagnosis::add_synthetic_drive_test(options->out, spec, options->drive, options->test);
        std::cout << "wrote           " << options->out << "/test" << options->test << ".csv (the table driven by "
                  << options->drive << ")\n";
        return;
      }
      prepare_output_directory(options->out);
      const diagnosis::SyntheticTruth truth = diagnosis::write_synthetic_measured_set(options->out, spec);
      std::cout << "wrote           " << options->out << "/ (specimen.toml, test1.csv ... test8.csv, truth.json)\n";
      std::cout << "hidden          " << (truth.hidden.empty() ? std::string("none") : truth.hidden.front());
      for (std::size_t i = 1; i < truth.hidden.size(); ++i) std::cout << ", " << truth.hidden[i];
      std::cout << "\n";
    });
  }
}

}  // namespace caskdem::commands
