// The GPU engine against the same machine's CPU cores (bench/device-check.sh runs it on a lent
// machine; results in bench/results/ with the card's name). Every case runs the benchmark
// ensemble's cask under 20 s of El Centro (ensembles/benchmark-1-3-elcentro-20s.toml, ten
// stripes from 0.2 to 2 g) with more or fewer realisations a stripe:
//
//   device_kernel     the queued lanes alone (no file), every lane of the card busy: the kernel's
//                     realisation-steps/s, and its flops over the card's FP64 rate
//   device_ensemble   end to end on the GPU: plan, lanes, result file and fragility written
//   cpu_ensemble      the same on every CPU core (the SIMD engine), for the ratio a user sees
//
// for 10^4 (the CPU's yardstick), 10^5 and 10^6 realisations, and the 3D benchmark (1,000
// realisations, ensembles/benchmark-1-3-elcentro-20s-3d.toml) on both. A GPU case without a GPU
// says so and is skipped. One iteration each: they take seconds to a minute.

#include <omp.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "ensemble/device_runner.h"
#include "ensemble/execute.h"
#include "kernels/block.h"
#include "kernels/lane_device.h"

namespace caskdem::bench {
namespace {

constexpr const char* kPlanar = "benchmark-1-3-elcentro-20s.toml";
constexpr const char* k3D = "benchmark-1-3-elcentro-20s-3d.toml";
// Flops of one realisation-step of the planar kernel with the exponential law, counted from the
// step's source (bench/bench_kernel.cpp, flops_per_lane_step; docs/performance.md).
constexpr double kFlopsPerStep = 170.0;

EnsembleSpec benchmark_spec(const char* file, std::int64_t realisations) {
  EnsembleSpec spec = load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/ensembles/" + file);
  if (realisations > 0) spec.realisations_per_stripe = realisations / static_cast<std::int64_t>(spec.levels.size());
  return spec;
}

// The first usable GPU, or null after marking the benchmark skipped with the reason.
std::unique_ptr<LaneDevice> gpu_or_skip(benchmark::State& state) {
  std::string why;
  const std::vector<CudaDeviceInfo> devices = cuda_devices(&why);
  if (devices.empty()) {
    state.SkipWithError(("no GPU: " + why).c_str());
    return nullptr;
  }
  return open_cuda_device(devices.front().ordinal);
}

double fp64_peak() {
  std::string why;
  const std::vector<CudaDeviceInfo> devices = cuda_devices(&why);
  return devices.empty() ? 0.0 : devices.front().fp64_peak();
}

// The work the plan schedules: every realisation's whole run (those that stop early do less).
double scheduled_steps(const EnsemblePlan& plan) {
  double steps = 0.0;
  for (int m = 0; m < plan.motion_count(); ++m) {
    steps += double(plan.size()) / plan.motion_count() * std::ceil(plan.run_duration(m) / plan.model().time_step);
  }
  return steps;
}

void device_kernel(benchmark::State& state, const char* file) {
  const std::unique_ptr<LaneDevice> gpu = gpu_or_skip(state);
  if (!gpu) return;
  // Four realisations per lane of the full card, so that the lanes stay busy until the tail.
  const EnsemblePlan probe(benchmark_spec(file, 0), InstructionSet::automatic);
  const std::int64_t lanes = gpu->lane_capacity(probe.three_d() ? 3 : 2, probe.model().friction_law);
  const EnsembleSpec spec = benchmark_spec(file, 4 * lanes);
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  const MotionTables tables(plan, MotionTables::kDeviceBudgetBytes);
  std::vector<std::int64_t> all(static_cast<std::size_t>(plan.size()));
  for (std::int64_t i = 0; i < plan.size(); ++i) all[static_cast<std::size_t>(i)] = i;
  DeviceLanes device_lanes(plan, tables, *gpu);
  const OutcomeSink ignore = [](const std::vector<std::int64_t>&, const std::vector<RealisationOutcome>&) {};
  for (auto _ : state) device_lanes.run(all, ignore);
  const DeviceLanes::Statistics& s = device_lanes.statistics();
  state.counters["lanes"] = double(lanes);
  state.counters["realisations"] = double(plan.size());
  state.counters["launches"] = s.launches;
  state.counters["realisation_steps_per_s"] = s.busy_steps / s.launch_seconds;
  state.counters["busy_lane_fraction"] = s.busy_steps / s.lane_steps;
  if (!plan.three_d()) state.counters["fp64_fraction"] = s.busy_steps / s.launch_seconds * kFlopsPerStep / fp64_peak();
}

void ensemble(benchmark::State& state, const char* file, std::int64_t realisations, bool on_gpu) {
  std::unique_ptr<LaneDevice> gpu;
  if (on_gpu && !(gpu = gpu_or_skip(state))) return;
  const EnsembleSpec spec = benchmark_spec(file, realisations);
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  ExecuteReport report;
  for (auto _ : state) {
    ExecuteOptions options;
    options.threads = omp_get_max_threads();
    options.progress = false;
    options.device = gpu.get();
    options.output = std::filesystem::temp_directory_path() / "caskdem-bench-device.h5";
    report = execute_ensemble(plan, options);
    benchmark::DoNotOptimize(report.limit_states.data());
  }
  state.counters["realisations"] = double(plan.size());
  state.counters["threads"] = on_gpu ? 0.0 : double(omp_get_max_threads());
  state.counters["realisation_seconds_per_s"] = benchmark::Counter(
      scheduled_steps(plan) * plan.model().time_step * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["idle_lane_fraction"] = report.occupancy.stopped_fraction();
  bool fitted = false;
  for (const LimitStateSummary& s : report.limit_states) fitted = fitted || s.fit.fitted;
  state.counters["fragility_written"] = fitted ? 1.0 : 0.0;
}

}  // namespace

#define CASKDEM_ONCE ->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond)
BENCHMARK_CAPTURE(device_kernel, planar, kPlanar) CASKDEM_ONCE;
BENCHMARK_CAPTURE(device_kernel, spatial, k3D) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, device_10k, kPlanar, 10000, true) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, cpu_10k, kPlanar, 10000, false) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, device_3d_1k, k3D, 1000, true) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, cpu_3d_1k, k3D, 1000, false) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, device_100k, kPlanar, 100000, true) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, cpu_100k, kPlanar, 100000, false) CASKDEM_ONCE;
BENCHMARK_CAPTURE(ensemble, device_1m, kPlanar, 1000000, true) CASKDEM_ONCE;
#undef CASKDEM_ONCE

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::string why;
  const std::vector<caskdem::CudaDeviceInfo> devices = caskdem::cuda_devices(&why);
  benchmark::AddCustomContext("gpu", devices.empty() ? "none: " + why : devices.front().name);
  if (!devices.empty()) {
    benchmark::AddCustomContext("gpu_fp64_peak_tflops", std::to_string(devices.front().fp64_peak() / 1e12));
    benchmark::AddCustomContext("gpu_clock_mhz", std::to_string(devices.front().clock_hz / 1e6));
  }
  benchmark::AddCustomContext("cpu_threads", std::to_string(omp_get_max_threads()));
  benchmark::AddCustomContext("best_instruction_set", caskdem::instruction_set_name(caskdem::best_instruction_set()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
