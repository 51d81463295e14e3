// The peer: caskdem against MuJoCo (Debian's libmujoco-dev) on the same cask under the same
// record, each at the step where its own answer converges, in realisation-seconds of
// simulated time per wall-second per core.
//
// The cask: the source paper's 1/3 model (12.6 t, the section of cases/model-1-3-sine.toml),
// friction 0.6 (caskdem's constant law), under Kobe Takatori 090 compressed in time by sqrt(3)
// (the 1/3 model's similarity) and scaled to PGA 0.4, 0.5 and 0.6 g, where it rocks without
// tipping over in both codes (a tipped cask's max rotation is the tip-over angle at any step,
// which says nothing about convergence). In MuJoCo it is a box
// of the same section (2b x H) and mass on a plane, planar (slide x, slide z, hinge y), in the
// table's frame like caskdem: the table acceleration enters as the force -m a(t) at the
// centre of mass. MuJoCo's contact is its own (soft constraints, default solref), so the two
// answers are not compared with each other: each code is run at several steps and the
// largest step from which every finer step's max rotation is within 1 % of its own finest's,
// at every intensity, is the converged one. Speed: MuJoCo one realisation per core (mj_step in a loop, as its users run
// it); caskdem its ensemble engine on one thread (64 lanes of the three intensities). Both
// counters are in one run, so the ratio between them means something on a noisy machine.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include "casefile/case_file.h"
#include "core/units.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "model/build.h"
#include "sim/simulate.h"
#include "bench/peer_cask.h"

namespace caskdem::bench {
namespace {

const std::vector<double> kPgaG = {0.4, 0.5, 0.6};
constexpr double kFriction = kPeerFriction;
constexpr double kTolerance = 0.01;  // max rotation within 1 % of the finest step's

// ---- caskdem ---------------------------------------------------------------------------
double caskdem_max_rotation(double safety_factor, double pga_g) {
  const Peer& p = peer();
  Case c = p.cask;
  c.model.safety_factor = safety_factor;
  const Model model = build_model(c.model, c.parameters);
  LaneParameters<double> lane = lane_parameters(model, c.parameters);
  lane.horizontal_scale = units::g_to_si(pga_g) / p.pga;
  return simulate(model, lane, rest_state(model, lane), {p.motion.get(), nullptr}, {p.duration, 0.0}).summary.max_abs_rotation;
}

// ---- convergence: each code's largest step within 1 % of its own finest ----------------
struct Converged {
  double step = 0.0;  // f_s for caskdem, dt for MuJoCo
  std::vector<double> max_rotation;  // at that step, per intensity
  double worst_difference = 0.0;     // relative to the finest, over the intensities
};

template <class Run>
Converged converge(const std::vector<double>& steps, Run run, const char* name) {  // steps finest first
  std::vector<std::vector<double>> rotation;
  for (double s : steps) {
    std::vector<double> r;
    for (double pga : kPgaG) r.push_back(run(s, pga));
    rotation.push_back(r);
  }
  // The largest step from which every finer one is within the tolerance too: a rocking
  // history can land near the finest one's by chance at a coarse step.
  Converged best{steps[0], rotation[0], 0.0};
  bool converged = true;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    double worst = 0.0;
    for (std::size_t i = 0; i < kPgaG.size(); ++i) worst = std::max(worst, std::abs(rotation[k][i] / rotation[0][i] - 1.0));
    std::printf("%s step %-8g max rotation", name, steps[k]);
    for (double r : rotation[k]) std::printf(" %.5f", r);
    std::printf(" rad  worst difference %.3f %%\n", 100.0 * worst);
    converged = converged && worst <= kTolerance;
    if (converged) best = {steps[k], rotation[k], worst};
  }
  return best;
}

const Converged& caskdem_converged() {
  static const Converged c =
      converge({0.0025, 0.005, 0.01, 0.02, 0.04, 0.08}, [](double fs, double pga) { return caskdem_max_rotation(fs, pga); }, "caskdem f_s");
  return c;
}

const Converged& mujoco_converged() {
  static const Converged c = converge(
      {6.25e-5, 1.25e-4, 2.5e-4, 5e-4, 1e-3, 2e-3, 4e-3},
      [](double dt, double pga) { return mujoco_run(mujoco_model(dt, kFriction)->model, units::g_to_si(pga) / peer().pga).max_rotation; }, "MuJoCo dt   ");
  return c;
}

// ---- the timed work ---------------------------------------------------------------------
// step <= 0: the converged step of the study above; otherwise that step (f_s for caskdem).
void mujoco_speed(benchmark::State& state, double step) {
  const Converged& c = mujoco_converged();
  const double dt = step > 0.0 ? step : c.step;
  const auto model = mujoco_model(dt, kFriction);
  double simulated = 0.0;
  for (auto _ : state) {
    for (double pga : kPgaG) simulated += mujoco_run(model->model, units::g_to_si(pga) / peer().pga).simulated;
  }
  state.counters["time_step_s"] = dt;
  state.counters["realisation_seconds_per_wall_second"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}

void caskdem_speed(benchmark::State& state, double step) {
  const Converged& c = caskdem_converged();
  const Peer& p = peer();
  // The ensemble engine on one thread: 64 realisations of each intensity.
  EnsembleSpec spec = load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/ensembles/benchmark-1-3-elcentro-20s.toml");
  spec.base.model = p.cask.model;
  spec.base.model.safety_factor = step > 0.0 ? step : c.step;
  spec.base.parameters = p.cask.parameters;
  spec.base.duration = p.duration;
  spec.motions = {kobe()};
  spec.motion_names = {"kobe"};
  spec.uncertain.clear();
  spec.levels.clear();
  for (double g : kPgaG) spec.levels.push_back(units::g_to_si(g));
  spec.realisations_per_stripe = 64;
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  const MotionTables tables(plan);
  std::vector<std::int64_t> all(plan.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) all[i] = i;
  RunOptions options;
  options.threads = 1;
  double simulated = 0.0;
  for (auto _ : state) {
    run_realisations(plan, tables, all, options,
                     [&](const std::vector<std::int64_t>&, const std::vector<RealisationOutcome>& outcomes) {
                       for (const RealisationOutcome& o : outcomes) simulated += o.end_time;
                     });
  }
  state.counters["safety_factor"] = spec.base.model.safety_factor;
  state.counters["time_step_s"] = plan.model().time_step;
  state.counters["realisation_seconds_per_wall_second"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}

}  // namespace

// Each code at its converged step (MuJoCo at its finest when no coarser one converges), then
// each at the step it is commonly run at: MuJoCo 2 ms, caskdem the paper's f_s = 0.01.
BENCHMARK_CAPTURE(mujoco_speed, converged, 0.0)->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0);
BENCHMARK_CAPTURE(caskdem_speed, converged, 0.0)->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0);
BENCHMARK_CAPTURE(mujoco_speed, dt_2ms, 2e-3)->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0);
BENCHMARK_CAPTURE(caskdem_speed, fs_0_01, 0.01)->Unit(benchmark::kSecond)->UseRealTime()->MinTime(5.0);

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("mujoco_version", std::to_string(mj_version()));
  // The convergence studies first, printed, so the timed runs use converged steps.
  const auto& c = caskdem::bench::caskdem_converged();
  const auto& m = caskdem::bench::mujoco_converged();
  benchmark::AddCustomContext("caskdem_converged_safety_factor", std::to_string(c.step));
  benchmark::AddCustomContext("caskdem_converged_worst_difference", std::to_string(c.worst_difference));
  benchmark::AddCustomContext("mujoco_converged_time_step", std::to_string(m.step));
  benchmark::AddCustomContext("mujoco_converged_worst_difference", std::to_string(m.worst_difference));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
