// End to end: an ensemble file in, the fragility file out, on every core. The default is
// the yardstick, 10,000 realisations of the 1/3 model cask under a 20 s record at an
// ensemble's default step (ensembles/benchmark-1-3-elcentro-20s.toml);
// CASKDEM_BENCH_ENSEMBLE names another file. One iteration per instruction set (the best this
// machine has, then AVX2 for the ratio between them). The *_paper_scheme runs take the same
// file at the source paper's scheme (the half-step slider at f_s = 0.01, the ensembles' default
// before the whole-step slider's), for the ratio of the two steps in one run. The cask in 3D
// has its own yardstick, 1,000 realisations under 20 s of a station's three components
// (ensembles/benchmark-1-3-elcentro-20s-3d.toml), refilled and in lockstep.

#include <omp.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "ensemble/execute.h"
#include "kernels/block.h"

namespace caskdem::bench {
namespace {

void end_to_end(benchmark::State& state, InstructionSet instruction_set, bool refill, const char* default_file,
                bool paper_scheme = false) {
  if (!instruction_set_available(instruction_set)) {
    state.SkipWithError((instruction_set_name(instruction_set) + " is not available on this machine").c_str());
    return;
  }
  const char* chosen = std::getenv("CASKDEM_BENCH_ENSEMBLE");
  const std::string file = chosen ? chosen : std::string(CASKDEM_SOURCE_DIR) + "/ensembles/" + default_file;
  EnsembleSpec spec = load_ensemble(file);
  if (paper_scheme) {
    spec.base.model.safety_factor = 0.01;
    spec.base.model.whole_step_terms = 0;
  }
  double lane_steps = 0.0;
  LaneOccupancy occupancy;
  for (auto _ : state) {
    const EnsemblePlan plan(spec, instruction_set);
    ExecuteOptions options;
    options.threads = static_cast<int>(state.range(0));
    options.isa = instruction_set;
    options.progress = false;
    options.refill = refill;
    options.output = std::filesystem::temp_directory_path() / "caskdem-bench-ensemble.h5";
    const ExecuteReport report = execute_ensemble(plan, options);
    benchmark::DoNotOptimize(report.limit_states.data());
    occupancy.lane_steps += report.occupancy.lane_steps;
    occupancy.stopped_lane_steps += report.occupancy.stopped_lane_steps;
    for (int m = 0; m < plan.motion_count(); ++m) {
      lane_steps += double(plan.size()) / plan.motion_count() * std::ceil(plan.run_duration(m) / plan.model().time_step);
    }
  }
  state.counters["realisations"] = double(spec.realisation_count());
  state.counters["realisation_seconds_per_s"] =
      benchmark::Counter(lane_steps * EnsemblePlan(spec, instruction_set).model().time_step, benchmark::Counter::kIsRate);
  state.counters["realisations_per_s"] = benchmark::Counter(double(spec.realisation_count()) * state.iterations(), benchmark::Counter::kIsRate);
  // Scheduled work: lanes that tip over stop early, so the kernel does less than this.
  state.counters["scheduled_lane_steps_per_s"] = benchmark::Counter(lane_steps, benchmark::Counter::kIsRate);
  // Of the lane-steps computed, the share on lanes that had stopped (ensemble/runner.h).
  state.counters["stopped_lane_fraction"] = occupancy.stopped_fraction();
  state.counters["time_step_s"] = EnsemblePlan(spec, instruction_set).model().time_step;
}

}  // namespace

constexpr const char* kPlanar = "benchmark-1-3-elcentro-20s.toml";
constexpr const char* k3D = "benchmark-1-3-elcentro-20s-3d.toml";
BENCHMARK_CAPTURE(end_to_end, best, InstructionSet::automatic, true, kPlanar)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
// Lanes in lockstep blocks, as before refilling: what refilling saves.
BENCHMARK_CAPTURE(end_to_end, best_lockstep, InstructionSet::automatic, false, kPlanar)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(end_to_end, avx2, InstructionSet::avx2, true, kPlanar)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(end_to_end, best_paper_scheme, InstructionSet::automatic, true, kPlanar, true)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(end_to_end, best_3d, InstructionSet::automatic, true, k3D)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(end_to_end, avx2_3d, InstructionSet::avx2, true, k3D)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(end_to_end, best_lockstep_3d, InstructionSet::automatic, false, k3D)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(end_to_end, best_paper_scheme_3d, InstructionSet::automatic, true, k3D, true)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("best_instruction_set", caskdem::instruction_set_name(caskdem::best_instruction_set()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
