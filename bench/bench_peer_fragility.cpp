// The peer on the statistic a user reads: caskdem against MuJoCo (bench/peer_cask.h) as
// ensembles on the same cask and sampling plan, each at the largest step whose fragility stays
// within a quarter of its own band of its finest step's, timed in one run.
//
// The plan: the 1/3 model under the six records of ensembles/model-1-3-records.toml (compressed
// by sqrt 3, each run for its duration and the file's settle time) scaled to twelve stripes of
// PGA, 0.2 to 2 g, friction uniform 0.4 to 0.8 (Latin hypercube, caskdem's sampler; MuJoCo runs
// each of the same realisations with its record, friction and scale factor), PEER_PER_STRIPE
// realisations a stripe (24 by default, 288 in all: a quick look; the committed results use 96,
// 1,152 in all, where the quarter-band criterion is no longer moved by single realisations).
// Several records give the curves the record-to-record spread a site's fragility has; under one
// record the tip-over curve is nearly a step in PGA, and one realisation crossing the threshold
// moves it by more than a quarter of its band. Two limit states: tip-over and rocking beyond
// alpha / 2 (each code's own alpha: caskdem's rounded section, MuJoCo's box). Each is fitted
// with a lognormal (the ensemble's fit, ensemble/fragility.h), its 95 % band from 200 bootstrap
// replicates (Band, below), the same draws at every step.
//
// Convergence: caskdem at f_s 0.0025 .. 0.08 with the source paper's half-step slider and with
// the whole-step one (0.05 among them, an ensemble's default), MuJoCo at dt 0.125 ms .. 4 ms with
// its default integrator (semi-implicit Euler) and at 0.5 .. 4 ms with its RK4, which is judged
// against the Euler integrator's finest step (the same model and contact, so the same limit). A
// step converges when every finer step's median and beta of both limit states differ from the
// reference's (the finest step's) by less than a quarter of that answer's band at the reference.
// Two bands judge the steps (Band, below): the record-to-record band an ensemble of several
// motions reports, and the narrower band of the realisations with the six records fixed; each
// code is timed at the step each band's criterion converged at.
// Speed at the converged steps: realisation-seconds of simulated time per wall-second per core;
// MuJoCo one realisation after another on one core (its users' way), caskdem's ensemble engine on
// one thread. Both are timed in this run. The convergence tables are printed first (PEER_TABLE=FILE
// writes them to FILE as well).

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/paired_bootstrap.h"
#include "bench/peer_cask.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/fragility.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"

namespace caskdem::bench {
namespace {

constexpr int kReplicates = 200;
const int kPerStripe = std::getenv("PEER_PER_STRIPE") ? std::atoi(std::getenv("PEER_PER_STRIPE")) : 24;
const std::vector<double> kLevelsG = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 1.0, 1.2, 1.4, 1.7, 2.0};

EnsembleSpec peer_spec(std::int32_t slider, double safety_factor) {
  const Peer& p = peer();
  // The six records of the 1/3 model's records ensemble, compressed by sqrt 3, each run for its
  // duration and the file's settle time.
  EnsembleSpec spec = load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/ensembles/model-1-3-records.toml");
  spec.base.model = p.cask.model;
  spec.base.model.safety_factor = safety_factor;
  spec.base.model.whole_step_terms = slider;
  spec.base.parameters = p.cask.parameters;
  spec.uncertain.clear();
  Distribution friction;
  friction.kind = Distribution::Kind::uniform;
  friction.first = 0.4;
  friction.second = 0.8;
  spec.uncertain["friction_static"] = friction;
  spec.measure = IntensityMeasure::pga;
  spec.levels.clear();
  for (double g : kLevelsG) spec.levels.push_back(units::g_to_si(g));
  spec.realisations_per_stripe = kPerStripe;
  return spec;
}

// One code's realisations at one step: tipped over, rocked beyond alpha / 2, and simulated time.
struct Outcomes {
  std::vector<std::uint8_t> tipped, rocked;
  double simulated = 0.0;  // realisation-seconds
};

Outcomes caskdem_outcomes(std::int32_t slider, double safety_factor, int threads) {
  const EnsemblePlan plan(peer_spec(slider, safety_factor), InstructionSet::automatic);
  const MotionTables tables(plan);
  std::vector<std::int64_t> all(plan.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) all[i] = i;
  Outcomes o;
  o.tipped.assign(plan.size(), 0);
  o.rocked.assign(plan.size(), 0);
  RunOptions options;
  options.threads = threads;
  run_realisations(plan, tables, all, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) {
                       o.tipped[done[k]] = outcomes[k].status == LaneStatus::tipped_over;
                       o.rocked[done[k]] = outcomes[k].max_abs_rotation > 0.5 * plan.stability_angle();
                       o.simulated += outcomes[k].end_time;
                     }
                   });
  return o;
}

Outcomes mujoco_outcomes(double time_step, int threads, const char* integrator = "Euler") {
  const EnsemblePlan plan(peer_spec(0, 0.01), InstructionSet::automatic);  // the draws, not the step
  const Peer& p = peer();
  const double alpha = std::atan(p.half_width / (0.5 * p.height));
  Outcomes o;
  o.tipped.assign(plan.size(), 0);
  o.rocked.assign(plan.size(), 0);
  std::vector<double> simulated(threads, 0.0);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&, t] {
      const auto model = mujoco_model(time_step, kPeerFriction, integrator);  // one model a core, its friction set per realisation
      for (std::int64_t i = t; i < plan.size(); i += threads) {
        const RealisationInput r = plan.realisation(i);
        set_mujoco_friction(model->model, r.parameters.friction_static);
        const MujocoRun run =
            mujoco_run(model->model, r.scale_factor, &plan.motion(r.motion), plan.run_duration(r.motion));
        o.tipped[i] = run.max_rotation >= 0.5 * std::numbers::pi;
        o.rocked[i] = run.max_rotation > 0.5 * alpha;
        simulated[t] += run.simulated;
      }
    });
  }
  for (std::thread& w : workers) w.join();
  for (double s : simulated) o.simulated += s;
  return o;
}

// A limit state's fit on the realisations `sample` (indices into the plan, repeats allowed).
fragility::LognormalFit fit(const std::vector<std::uint8_t>& exceeded, const std::vector<std::int64_t>& sample,
                            const EnsemblePlan& plan) {
  const std::size_t stripes = plan.spec().levels.size();
  std::vector<std::int64_t> trials(stripes, 0), counts(stripes, 0);
  for (std::int64_t i : sample) {
    const int s = plan.realisation(i).stripe;
    ++trials[s];
    counts[s] += exceeded[i];
  }
  return fragility::fit_lognormal(plan.spec().levels, trials, counts);
}

struct Answer {
  double median = 0.0, beta = 0.0;
  bool fitted = false;
};

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[static_cast<std::size_t>(std::lround(q * (v.size() - 1)))];
}

// The convergence tables go to stdout and, when PEER_TABLE names a file, to that file too.
void say(const char* format, ...) __attribute__((format(printf, 1, 2)));
void say(const char* format, ...) {
  static std::FILE* table = std::getenv("PEER_TABLE") ? std::fopen(std::getenv("PEER_TABLE"), "w") : nullptr;
  std::va_list args;
  va_start(args, format);
  std::va_list copy;
  va_copy(copy, args);
  std::vprintf(format, args);
  if (table) {
    std::vfprintf(table, format, copy);
    std::fflush(table);
  }
  va_end(copy);
  va_end(args);
}

// Which band a step is judged by. Both resample the plan's realisations 200 times, the same
// draws at every step: `stripes` resamples each stripe's realisations (the six records fixed,
// the band of the realisations drawn under them), `motions` resamples the six records, each with
// all its realisations (the record-to-record band, the one an ensemble of several motions
// reports and the default-step study judges by: docs/time-step.md). The first is the narrower.
enum Band { stripes = 0, motions = 1 };
constexpr const char* kBandName[] = {"stripes resampled", "motions resampled"};

// The largest step from which every finer step's answers are within a quarter band of the
// reference's (runs[0], labelled `reference`: the finest step of this code, or of the same model
// under another integrator), under each band, printed as a table. steps[0] is the reference's
// step; a code none of whose own steps converges gets step 0.
struct Converged {
  double step = 0.0;
  double worst = 0.0;  // the largest |difference| / (band / 4) at that step
};

std::array<Converged, 2> converge(const char* name, const char* reference, const std::vector<double>& steps,
                                  const std::vector<Outcomes>& runs, bool reference_is_own_step) {
  const EnsemblePlan plan(peer_spec(0, 0.01), InstructionSet::automatic);
  std::vector<std::vector<std::int64_t>> by_stripe(plan.spec().levels.size()), by_motion(plan.spec().motions.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) {
    by_stripe[plan.realisation(i).stripe].push_back(i);
    by_motion[plan.realisation(i).motion].push_back(i);
  }
  std::mt19937_64 random(2026);
  std::array<std::vector<std::vector<std::int64_t>>, 2> samples;
  for (int k = 0; k < kReplicates; ++k) samples[stripes].push_back(resample_stripes(by_stripe, random));
  for (int k = 0; k < kReplicates; ++k) samples[motions].push_back(resample_motions(by_motion, random));
  std::vector<std::int64_t> all(plan.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) all[i] = i;
  std::array<Converged, 2> best;
  best.fill({reference_is_own_step ? steps[0] : 0.0, 0.0});
  bool converged[2] = {true, true};
  double bands[2][2][2] = {};  // [band][limit state][median, beta]: a quarter of the reference's band
  Answer finest[2];
  for (std::size_t k = 0; k < steps.size(); ++k) {
    double worst[2] = {0.0, 0.0};
    say("%s %-8g%s", k == 0 ? reference : name, steps[k], k == 0 ? " (reference)" : "");
    for (int l = 0; l < 2; ++l) {
      const auto& exceeded = l == 0 ? runs[k].tipped : runs[k].rocked;
      const fragility::LognormalFit f = fit(exceeded, all, plan);
      const Answer a{f.median, f.log_std, f.fitted};
      if (k == 0) {
        for (int b = 0; b < 2; ++b) {
          std::vector<double> medians, betas;
          for (const auto& sample : samples[b]) {
            const fragility::LognormalFit r = fit(exceeded, sample, plan);
            if (!r.fitted) continue;
            medians.push_back(r.median / a.median);
            betas.push_back(r.log_std);
          }
          bands[b][l][0] = (quantile(medians, 0.975) - quantile(medians, 0.025)) / 4.0;
          bands[b][l][1] = (quantile(betas, 0.975) - quantile(betas, 0.025)) / 4.0;
        }
        finest[l] = a;
      }
      // A curve the reference cannot fit has no band to judge by: left out (printed as such).
      const double dm = a.fitted ? a.median / finest[l].median - 1.0 : INFINITY;
      const double db = a.fitted ? a.beta - finest[l].beta : INFINITY;
      for (int b = 0; b < 2; ++b) {
        if (finest[l].fitted)
          worst[b] = std::max({worst[b], std::abs(dm) / bands[b][l][0], std::abs(db) / bands[b][l][1]});
      }
      if (!finest[l].fitted && k == 0) say("  (%s not fitted at the reference: left out)", l == 0 ? "tip-over" : "rocking > alpha/2");
      say("  %s median %.4f g (%+.2f %%, band/4 %.2f %% / %.2f %%) beta %.3f (%+.3f, band/4 %.3f / %.3f)",
          l == 0 ? "tip-over" : "rocking > alpha/2", units::si_to_g(a.median), 100.0 * dm, 100.0 * bands[stripes][l][0],
          100.0 * bands[motions][l][0], a.beta, db, bands[stripes][l][1], bands[motions][l][1]);
    }
    say("  worst %.2f / %.2f x band/4 (%s / %s)\n", worst[stripes], worst[motions], kBandName[stripes],
        kBandName[motions]);
    if (k == 0) continue;
    for (int b = 0; b < 2; ++b) {
      converged[b] = converged[b] && worst[b] < 1.0;
      if (converged[b]) best[b] = {steps[k], worst[b]};
    }
  }
  return best;
}

struct Study {
  std::array<Converged, 2> half_step, whole_step, mujoco, mujoco_rk4;
};

const Study& study() {
  static const Study s = [] {
    Study r;
    say("%d realisations (%d a stripe), MuJoCo %d; each row's band/4 under stripes resampled / motions resampled\n",
        static_cast<int>(kLevelsG.size()) * kPerStripe, kPerStripe, mj_version());
    const std::vector<double> fs = {0.0025, 0.005, 0.01, 0.02, 0.04, 0.05, 0.08};
    for (std::int32_t slider : {std::int32_t(0), std::int32_t(kWholeStepSlider)}) {
      std::vector<Outcomes> runs;
      for (double f : fs) runs.push_back(caskdem_outcomes(slider, f, 2));
      const std::string name = "caskdem " + slider_name_of(slider) + " f_s";
      (slider ? r.whole_step : r.half_step) = converge(name.c_str(), name.c_str(), fs, runs, true);
    }
    const std::vector<double> dt = {1.25e-4, 2.5e-4, 5e-4, 1e-3, 2e-3, 4e-3};
    std::vector<Outcomes> runs;
    for (double d : dt) runs.push_back(mujoco_outcomes(d, 2));
    r.mujoco = converge("MuJoCo Euler dt", "MuJoCo Euler dt", dt, runs, true);
    // RK4 (four evaluations a step) from 0.5 ms, against the Euler integrator's finest step: the
    // same model, so the same limit.
    const std::vector<double> dt_rk4 = {dt[0], 5e-4, 1e-3, 2e-3, 4e-3};
    std::vector<Outcomes> rk4 = {runs[0]};
    for (std::size_t k = 1; k < dt_rk4.size(); ++k) rk4.push_back(mujoco_outcomes(dt_rk4[k], 2, "RK4"));
    r.mujoco_rk4 = converge("MuJoCo RK4 dt", "MuJoCo Euler dt", dt_rk4, rk4, false);
    for (int b = 0; b < 2; ++b) {
      say("converged, %s: caskdem half-step f_s %g, whole-step f_s %g; MuJoCo Euler dt %g s, RK4 dt %g s\n",
          kBandName[b], r.half_step[b].step, r.whole_step[b].step, r.mujoco[b].step, r.mujoco_rk4[b].step);
    }
    return r;
  }();
  return s;
}

void mujoco_fragility_speed(benchmark::State& state, const char* integrator, Band band) {
  const bool rk4 = std::string(integrator) == "RK4";
  const double dt = (rk4 ? study().mujoco_rk4 : study().mujoco)[band].step;
  if (dt == 0.0) {
    state.SkipWithError("no step of this integrator converged");
    return;
  }
  // RK4 takes four evaluations a step: at no more than four times the Euler integrator's step
  // it cannot be the faster, and is not timed.
  if (rk4 && dt <= 4.0 * study().mujoco[band].step) {
    state.SkipWithError("RK4's converged step is within four times Euler's: slower than Euler, not timed");
    return;
  }
  double simulated = 0.0;
  for (auto _ : state) simulated += mujoco_outcomes(dt, 1, integrator).simulated;
  state.counters["time_step_s"] = dt;
  state.counters["realisation_seconds_per_wall_second"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}

void caskdem_fragility_speed(benchmark::State& state, std::int32_t slider, Band band) {
  const double fs = (slider ? study().whole_step : study().half_step)[band].step;
  double simulated = 0.0;
  for (auto _ : state) simulated += caskdem_outcomes(slider, fs, 1).simulated;
  state.counters["safety_factor"] = fs;
  state.counters["realisation_seconds_per_wall_second"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}

}  // namespace

// Each code at the step each band's criterion converged at: the band in the name.
#define CASKDEM_PEER_BENCHMARKS(band)                                                                          \
  BENCHMARK_CAPTURE(mujoco_fragility_speed, euler_##band, "Euler", band)                                       \
      ->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0);                                                 \
  BENCHMARK_CAPTURE(mujoco_fragility_speed, rk4_##band, "RK4", band)->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0); \
  BENCHMARK_CAPTURE(caskdem_fragility_speed, half_step_##band, 0, band)                                        \
      ->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0);                                                 \
  BENCHMARK_CAPTURE(caskdem_fragility_speed, whole_step_##band, kWholeStepSlider, band)                        \
      ->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0)
CASKDEM_PEER_BENCHMARKS(stripes);
CASKDEM_PEER_BENCHMARKS(motions);

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("mujoco_version", std::to_string(mj_version()));
  const auto& s = caskdem::bench::study();  // printed, before the timed runs
  benchmark::AddCustomContext("realisations",
                              std::to_string(caskdem::bench::kLevelsG.size() * caskdem::bench::kPerStripe));
  for (int b = 0; b < 2; ++b) {
    const std::string band = b == caskdem::bench::stripes ? "stripes" : "motions";
    benchmark::AddCustomContext("caskdem_half_step_converged_safety_factor_" + band, std::to_string(s.half_step[b].step));
    benchmark::AddCustomContext("caskdem_whole_step_converged_safety_factor_" + band, std::to_string(s.whole_step[b].step));
    benchmark::AddCustomContext("mujoco_converged_time_step_" + band, std::to_string(s.mujoco[b].step));
    benchmark::AddCustomContext("mujoco_rk4_converged_time_step_" + band, std::to_string(s.mujoco_rk4[b].step));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
