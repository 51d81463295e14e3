// Solution verification of an ensemble's answer, not of one trajectory: the fragility
// (median, beta, each stripe's probability) and, given a hazard curve, the annual frequency,
// computed at several time-step safety factors f_s on the same realisations (common random
// numbers: the plan draws the same parameters and motions whatever the step), each set
// against the finest with a paired bootstrap.
//
// The criterion (docs/time-step.md): an f_s is acceptable for an ensemble when every answer
// differs from the finest f_s's by less than a quarter of the width of that answer's 95 %
// band: the bootstrap band of the median, of beta and of the annual frequency, the
// Clopper-Pearson interval of each stripe's probability. With common random numbers the
// difference is measured far more precisely than either answer (its own paired 95 % interval
// is printed beside it), so the criterion tests the step, not the sampling.
//
//   timestep_convergence ENSEMBLE --fs 0.005,0.01,0.02,0.05,0.1 [--stiffness 1,0.25]
//       [--slider whole-step] [--per-stripe N] [--hazard FILE --similarity N] [--replicates 200]
//       [--csv ROWS.csv]
//   timestep_convergence ENSEMBLE --variants 0.005:1,0.01:0.25:whole-step,...
//       (f_s:contact stiffness scale[:slider])
//
// Every f_s with every contact-stiffness scale (model/build.h), or the listed variants, with
// the ensemble's slider scheme or the one --slider names (kernels/slider.h). The first variant
// is the reference. --per-stripe replaces the file's realisations per stripe (the same plan,
// more draws). Rows are appended to --csv when given.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench/paired_bootstrap.h"
#include "core/error.h"
#include "model/build.h"
#include "ensemble/analysis.h"
#include "ensemble/execute.h"
#include "ensemble/fragility.h"
#include "risk/annual_frequency.h"
#include "risk/hazard_curve.h"

namespace caskdem {
namespace {

struct Variant {
  double safety_factor = 0.01;
  double stiffness_scale = 1.0;  // contact-frequency scaling (1: the model as given)
  std::int32_t whole_step_terms = 0;  // the slider scheme (model/build.h, slider_names)
};

std::string slider_of(const Variant& v) { return slider_name_of(v.whole_step_terms); }

struct Answers {
  bool fitted = false;
  double median = 0.0, beta = 0.0, annual_frequency = 0.0;
  std::vector<double> stripe_probability;
};

struct Run {
  Variant variant;
  double time_step = 0.0;
  double wall_seconds = 0.0;
  std::vector<std::vector<std::uint8_t>> exceeds;  // [limit state][realisation]
  std::vector<int> stripe, motion;
  std::vector<std::uint8_t> counted;  // completed and finite
};

std::vector<double> number_list(const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) values.push_back(std::stod(item));
  return values;
}

Run run_variant(const EnsembleSpec& base_spec, const Variant& variant) {
  EnsembleSpec spec = base_spec;
  spec.base.model.safety_factor = variant.safety_factor;
  spec.base.model.contact_stiffness_scale = variant.stiffness_scale;
  spec.base.model.whole_step_terms = variant.whole_step_terms;
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  ExecuteOptions options;
  options.progress = false;
  options.output = std::filesystem::temp_directory_path() / ("caskdem-fs-" + std::to_string(::getpid()) + ".h5");
  const auto start = std::chrono::steady_clock::now();
  execute_ensemble(plan, options);
  Run run;
  run.variant = variant;
  run.time_step = plan.model().time_step;
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double wall = 0.0;
  const EnsembleResults results = read_ensemble_results(options.output, plan, &wall);
  std::filesystem::remove(options.output);
  for (const LimitState& l : spec.limit_states) {
    std::vector<std::uint8_t> e(results.size);
    for (std::int64_t i = 0; i < results.size; ++i) e[i] = exceeds(l, results, i) ? 1 : 0;
    run.exceeds.push_back(std::move(e));
  }
  for (std::int64_t i = 0; i < results.size; ++i) {
    run.stripe.push_back(results.stripe[i]);
    run.motion.push_back(results.motion[i]);
    run.counted.push_back(results.completed[i] && static_cast<LaneStatus>(results.status[i]) != LaneStatus::non_finite);
  }
  return run;
}

// The answers of one limit state from the realisations in `sample` (indices, repeats allowed).
Answers answers(const Run& run, int limit_state, const std::vector<std::int64_t>& sample, const EnsembleSpec& spec,
                const std::optional<risk::HazardCurve>& hazard, double to_prototype) {
  const std::size_t stripes = spec.levels.size();
  std::vector<std::int64_t> trials(stripes, 0), counts(stripes, 0);
  for (std::int64_t i : sample) {
    if (!run.counted[i]) continue;
    ++trials[run.stripe[i]];
    counts[run.stripe[i]] += run.exceeds[limit_state][i];
  }
  Answers a;
  for (std::size_t j = 0; j < stripes; ++j) a.stripe_probability.push_back(trials[j] ? double(counts[j]) / trials[j] : 0.0);
  const fragility::LognormalFit fit = fragility::fit_lognormal(spec.levels, trials, counts);
  a.fitted = fit.fitted;
  a.median = fit.median;
  a.beta = fit.log_std;
  if (fit.fitted && hazard) a.annual_frequency = risk::convolve(*hazard, fit.median * to_prototype, fit.log_std).annual_frequency;
  return a;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double position = q * double(v.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, v.size() - 1);
  return v[below] + (position - double(below)) * (v[above] - v[below]);
}

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

std::string general(double v) {
  if (!std::isfinite(v)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

int program(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: timestep_convergence ENSEMBLE --fs LIST [--stiffness LIST] [--hazard FILE --similarity N]"
                 " [--replicates B] [--csv FILE]\n";
    return 2;
  }
  const std::filesystem::path file = argv[1];
  std::vector<double> safety_factors = {0.005, 0.01, 0.02, 0.05, 0.1};
  std::vector<double> stiffness = {1.0};
  std::optional<risk::HazardCurve> hazard;
  double similarity = 1.0;
  int replicates = 200;
  std::string csv;
  std::vector<Variant> listed;
  std::optional<std::int32_t> slider;
  std::optional<std::int64_t> per_stripe;
  for (int a = 2; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--fs") safety_factors = number_list(value);
    else if (key == "--stiffness") stiffness = number_list(value);
    else if (key == "--variants") {
      std::stringstream in(value);
      std::string item;
      while (std::getline(in, item, ',')) {
        std::stringstream fields(item);
        std::string f, k, s;
        std::getline(fields, f, ':');
        std::getline(fields, k, ':');
        std::getline(fields, s, ':');
        listed.push_back({std::stod(f), k.empty() ? 1.0 : std::stod(k), s.empty() ? -1 : whole_step_terms_of(s)});
      }
    }
    else if (key == "--slider") slider = whole_step_terms_of(value);
    else if (key == "--per-stripe") per_stripe = std::stoll(value);
    else if (key == "--hazard") hazard = risk::read_hazard_curve(value);
    else if (key == "--similarity") similarity = std::stod(value);
    else if (key == "--replicates") replicates = std::stoi(value);
    else if (key == "--csv") csv = value;
    else {
      std::cerr << "unknown option " << key << "\n";
      return 2;
    }
  }
  EnsembleSpec spec = load_ensemble(file);
  const std::int64_t shipped_per_stripe = spec.realisations_per_stripe;
  if (per_stripe) spec.realisations_per_stripe = *per_stripe;
  const std::int32_t default_slider = slider ? *slider : spec.base.model.whole_step_terms;
  // A 1/N model's velocities are the prototype's over sqrt(N) (caskdem risk --similarity).
  const double to_prototype = spec.measure == IntensityMeasure::pgv ? std::sqrt(similarity) : 1.0;

  std::vector<Variant> variants;
  for (double k : stiffness) {
    for (double f : safety_factors) variants.push_back({f, k, default_slider});
  }
  if (!listed.empty()) {
    variants = listed;
    for (Variant& v : variants) {
      if (v.whole_step_terms < 0) v.whole_step_terms = default_slider;
    }
  }
  std::vector<Run> runs;
  std::vector<Variant> ran;
  for (const Variant& v : variants) {
    std::cerr << file.stem().string() << ": f_s " << v.safety_factor << ", stiffness x" << v.stiffness_scale << ", "
              << slider_of(v) << " slider ..." << std::flush;
    // A step the model refuses (unstable, or a restitution it cannot reach) is reported, not fatal.
    try {
      runs.push_back(run_variant(spec, v));
      ran.push_back(v);
      std::cerr << " " << fixed(runs.back().wall_seconds, 1) << " s\n";
    } catch (const std::exception& e) {
      std::cerr << " cannot run\n";
      std::cout << "\n" << file.filename().string() << ": f_s " << v.safety_factor << ", stiffness x" << v.stiffness_scale
                << " cannot run: " << e.what() << "\n";
    }
  }
  if (runs.empty()) return 2;
  variants = ran;

  // Paired bootstrap: one draw of the resampling unit serves every variant. Several motions:
  // the motions are resampled (record-to-record variability, as the ensemble's own band);
  // one motion: each stripe's realisations.
  const std::int64_t size = spec.realisation_count();
  const int motions = static_cast<int>(spec.motions.size());
  std::vector<std::vector<std::int64_t>> by_motion(motions), by_stripe(spec.levels.size());
  for (std::int64_t i = 0; i < size; ++i) {
    by_motion[runs[0].motion[i]].push_back(i);
    by_stripe[runs[0].stripe[i]].push_back(i);
  }
  std::vector<std::int64_t> everything(size);
  for (std::int64_t i = 0; i < size; ++i) everything[i] = i;
  std::mt19937_64 random(20261126);
  std::vector<std::vector<std::int64_t>> samples;
  for (int b = 0; b < replicates; ++b)
    samples.push_back(motions > 1 ? bench::resample_motions(by_motion, random) : bench::resample_stripes(by_stripe, random));

  std::ofstream rows;
  if (!csv.empty()) {
    const bool fresh = !std::filesystem::exists(csv);
    rows.open(csv, std::ios::app);
    if (fresh) {
      rows << "ensemble,limit_state,safety_factor,stiffness_scale,time_step_s,wall_s,median,beta,annual_frequency,"
              "d_median_rel,d_median_lo,d_median_hi,median_band_rel,d_beta,d_beta_lo,d_beta_hi,beta_band,"
              "d_frequency_rel,frequency_band_rel,worst_stripe,d_stripe,stripe_band,worst_ratio,acceptable,slider,"
              "realisations,per_stripe,shipped_per_stripe,motions\n";
    }
  }

  std::cout << "\n## " << file.filename().string() << " (" << size << " realisations, " << replicates
            << " paired bootstrap replicates; reference f_s " << variants[0].safety_factor << ", stiffness x"
            << variants[0].stiffness_scale << ", " << slider_of(variants[0]) << " slider)\n\n"
            << "| limit state | f_s | stiffness | slider | median | d median (paired 95 %) | band/4 | beta | d beta (paired 95 %) |"
               " band/4 | worst stripe d p | CP/4 | d annual freq. | band/4 | acceptable |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t l = 0; l < spec.limit_states.size(); ++l) {
    const int ls = static_cast<int>(l);
    const Answers reference = answers(runs[0], ls, everything, spec, hazard, to_prototype);
    std::vector<Answers> reference_boot;
    for (const auto& s : samples) reference_boot.push_back(answers(runs[0], ls, s, spec, hazard, to_prototype));
    std::vector<double> median_boot, beta_boot, frequency_boot;
    for (const Answers& a : reference_boot) {
      if (!a.fitted) continue;
      median_boot.push_back(a.median);
      beta_boot.push_back(a.beta);
      frequency_boot.push_back(a.annual_frequency);
    }
    const double median_band = (quantile(median_boot, 0.975) - quantile(median_boot, 0.025)) / reference.median;
    const double beta_band = quantile(beta_boot, 0.975) - quantile(beta_boot, 0.025);
    const double frequency_band =
        hazard ? (quantile(frequency_boot, 0.975) - quantile(frequency_boot, 0.025)) / reference.annual_frequency : NAN;

    for (std::size_t v = 0; v < runs.size(); ++v) {
      const Answers here = answers(runs[v], ls, everything, spec, hazard, to_prototype);
      std::vector<double> d_median, d_beta;
      for (std::size_t b = 0; b < samples.size(); ++b) {
        const Answers a = answers(runs[v], ls, samples[b], spec, hazard, to_prototype);
        if (!a.fitted || !reference_boot[b].fitted) continue;
        d_median.push_back(a.median / reference_boot[b].median - 1.0);
        d_beta.push_back(a.beta - reference_boot[b].beta);
      }
      const bool fitted = here.fitted && reference.fitted;
      const double dm = fitted ? here.median / reference.median - 1.0 : NAN;
      const double db = fitted ? here.beta - reference.beta : NAN;
      const double df = fitted && hazard ? here.annual_frequency / reference.annual_frequency - 1.0 : NAN;
      // Each stripe against a quarter of the reference's Clopper-Pearson interval.
      double worst_stripe_ratio = 0.0, worst_d = 0.0, worst_band = 0.0;
      int worst = -1;
      for (std::size_t j = 0; j < spec.levels.size(); ++j) {
        std::int64_t n = 0, z = 0;
        for (std::int64_t i : by_stripe[j]) {
          if (!runs[0].counted[i]) continue;
          ++n;
          z += runs[0].exceeds[ls][i];
        }
        double lower = 0.0, upper = 1.0;
        fragility::clopper_pearson(z, n, spec.confidence, lower, upper);
        const double d = here.stripe_probability[j] - reference.stripe_probability[j];
        const double ratio = std::abs(d) / ((upper - lower) / 4.0);
        if (ratio > worst_stripe_ratio || worst < 0) {
          worst_stripe_ratio = ratio;
          worst = static_cast<int>(j);
          worst_d = d;
          worst_band = upper - lower;
        }
      }
      // The criterion reads the fitted answers (median, beta, annual frequency); a stripe's count
      // moves by whole realisations and is shown against its interval for reading only.
      double worst_ratio = 0.0;
      if (fitted) {
        worst_ratio = std::max(std::abs(dm) / (median_band / 4.0), std::abs(db) / (beta_band / 4.0));
        if (hazard) worst_ratio = std::max(worst_ratio, std::abs(df) / (frequency_band / 4.0));
      } else if (reference.fitted) {
        worst_ratio = INFINITY;  // a curve the reference fits and this step does not: not the same answer
      }
      const bool acceptable = worst_ratio < 1.0;
      const auto pct = [](double x) { return fixed(100.0 * x, 2) + " %"; };
      std::cout << "| " << spec.limit_states[l].name << " | " << general(variants[v].safety_factor) << " | x"
                << general(variants[v].stiffness_scale) << " | " << slider_of(variants[v]) << " | "
                << general(here.median) << " | " << pct(dm) << " ("
                << pct(quantile(d_median, 0.025)) << " to " << pct(quantile(d_median, 0.975)) << ") | "
                << pct(median_band / 4.0) << " | " << fixed(here.beta, 3) << " | " << fixed(db, 3) << " ("
                << fixed(quantile(d_beta, 0.025), 3) << " to " << fixed(quantile(d_beta, 0.975), 3) << ") | "
                << fixed(beta_band / 4.0, 3) << " | " << fixed(worst_d, 3) << " (stripe " << worst + 1 << ") | "
                << fixed(worst_band / 4.0, 3) << " | " << (hazard ? pct(df) : "-") << " | "
                << (hazard ? pct(frequency_band / 4.0) : "-") << " | " << (v == 0 ? "reference" : acceptable ? "yes" : "no")
                << " |\n";
      if (rows.is_open()) {
        rows << file.stem().string() << ',' << spec.limit_states[l].name << ',' << variants[v].safety_factor << ','
             << variants[v].stiffness_scale << ',' << runs[v].time_step << ',' << runs[v].wall_seconds << ','
             << here.median << ',' << here.beta << ',' << here.annual_frequency << ',' << dm << ','
             << quantile(d_median, 0.025) << ',' << quantile(d_median, 0.975) << ',' << median_band << ',' << db << ','
             << quantile(d_beta, 0.025) << ',' << quantile(d_beta, 0.975) << ',' << beta_band << ',' << df << ','
             << frequency_band << ',' << worst + 1 << ',' << worst_d << ',' << worst_band << ',' << worst_ratio << ','
             << (v == 0 ? "reference" : acceptable ? "yes" : "no") << ',' << slider_of(variants[v]) << ',' << size << ','
             << spec.realisations_per_stripe << ',' << shipped_per_stripe << ',' << motions << '\n';
      }
    }
  }
  std::cout << "\nwall time per variant:";
  for (const Run& r : runs) {
    std::cout << " f_s " << r.variant.safety_factor << " x" << r.variant.stiffness_scale << " " << slider_of(r.variant)
              << ": " << fixed(r.wall_seconds, 1) << " s;";
  }
  std::cout << "\n";
  return 0;
}

}  // namespace
}  // namespace caskdem

int main(int argc, char** argv) {
  try {
    return caskdem::program(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "timestep_convergence: " << e.what() << "\n";
    return 2;
  }
}
