// The 3D kernel (kernels/step3d.h, kernels/block3d.h): realisation-steps per second per
// instruction set, the flops a 3D realisation-step costs (counted on the counting number type)
// and the fraction of the core's peak, beside the planar kernel on the same cask and table;
// and end to end, 1,000 realisations of the 1/3 model under 20 s of a station's three
// components (El Centro 1940, compressed by sqrt 3) at spread intensities and incidences, in
// blocks of 64 lanes over two threads.

#include "bench/counted.h"  // before the kernels, so their templates see its overloads

#include <omp.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include <benchmark/benchmark.h>

#include "bench/bench_common.h"
#include "kernels/block3d.h"
#include "kernels/step3d.h"
#include "model/build3d.h"
#include "motion/component_set.h"
#include "motion/pair_intensity.h"

namespace caskdem::bench {
namespace {

constexpr int kSteps = kKernelSteps;
constexpr int kLanes = kKernelLanes;

struct Cask3D {
  Model3D model;
  RealisationParameters nominal;
};

Cask3D paper_cask3d() {
  const Case c = paper_model(FrictionLaw::exponential);
  const CaskSpec3D spec{0.5 * c.cask.cylinder.diameter, c.cask.cylinder.height, c.model.section.rounding, c.parameters.mass};
  const RealisationParameters nominal = nominal_parameters3d(spec, c.parameters);
  return {build_model3d(c.model, spec, nominal), nominal};
}

// A block whose lanes differ in friction, damping and incidence, as an ensemble's do.
LaneBlock3D make_block3d(const Cask3D& cask, int lanes) {
  LaneBlock3D block(lanes);
  for (int l = 0; l < lanes; ++l) {
    RealisationParameters p = cask.nominal;
    p.friction_static = 0.5 + 0.2 * l / lanes;
    p.friction_kinetic = 0.4 + 0.15 * l / lanes;
    p.damping_ratio = 0.01 + 0.05 * l / lanes;
    const LaneParameters<double> lane = lane_parameters3d(cask.model, p);
    const BodyState3D<double> body = rest_state3d(cask.model, lane);
    const ContactState3D<double> sliders[kContactSliders3D] = {};
    block.set_lane(l, lane, body, sliders, initial_response3d(lane, body), std::numbers::pi * l / lanes);
  }
  return block;
}

// Operations of one 3D realisation-step, averaged over the kernel benchmark's rocking.
lane::OperationCount count_operations3d(const Cask3D& cask) {
  const LaneParameters<double> p = lane_parameters3d(cask.model, cask.nominal);
  LaneParameters<lane::Counted> parameters;
  {
    LaneParameters<double> copy = p;
    std::vector<double> values;
    copy.for_each_field([&](double& v) { values.push_back(v); });
    int i = 0;
    parameters.for_each_field([&](lane::Counted& v) { v = lane::Counted(values[i++]); });
  }
  BodyState3D<double> rest = rest_state3d(cask.model, p);
  BodyState3D<lane::Counted> body;
  {
    std::vector<double> values;
    rest.for_each_field([&](double& v) { values.push_back(v); });
    int i = 0;
    body.for_each_field([&](lane::Counted& v) { v = lane::Counted(values[i++]); });
  }
  ContactState3D<lane::Counted> sliders[kContactSliders3D];
  for (auto& s : sliders) s.for_each_field([](lane::Counted& v) { v = lane::Counted(0.0); });
  Response3D<lane::Counted> response;
  response.for_each_field([](lane::Counted& v) { v = lane::Counted(0.0); });
  const std::vector<double> table = table_acceleration(cask.model.model.time_step, kSteps);
  lane::operation_count() = {};
  const lane::Counted dt(cask.model.model.time_step), none(0.0), c(std::cos(0.4)), s(std::sin(0.4));
  for (int n = 0; n < kSteps; ++n) {
    const lane::Counted a(table[n]);
    // As the block kernel reads the table: H1 turned by the incidence (H2 absent here).
    kernels::step3d<FrictionLaw::exponential>(cask.model.model, cask.model.contacts, parameters, c * a - s * none, none,
                                              s * a + c * none, lane::Counted(double(n)) * dt, body, sliders, response);
  }
  const lane::OperationCount total = lane::operation_count();
  return {total.flops / kSteps, total.other / kSteps};
}

void kernel3d(benchmark::State& state, InstructionSet isa) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  const Cask3D cask = paper_cask3d();
  const lane::OperationCount operations = count_operations3d(cask);
  const std::vector<double> table = table_acceleration(cask.model.model.time_step, kSteps);
  for (auto _ : state) {
    state.PauseTiming();
    LaneBlock3D block = make_block3d(cask, kLanes);
    state.ResumeTiming();
    advance_block3d(isa, cask.model.model, cask.model.contacts, block, table.data(), nullptr, nullptr, 0, kSteps);
    benchmark::DoNotOptimize(block.view().body);
  }
  const double lane_steps = double(kLanes) * kSteps * state.iterations();
  state.counters["lane_steps_per_s"] = benchmark::Counter(lane_steps, benchmark::Counter::kIsRate);
  state.counters["flops_per_lane_step"] = double(operations.flops);
  state.counters["other_ops_per_lane_step"] = double(operations.other);
  state.counters["fraction_of_core_peak"] =
      benchmark::Counter(lane_steps * operations.flops / core_peak(width_of(isa)), benchmark::Counter::kIsRate);
}

// The planar kernel on the same cask (two corners) and table, for the ratio.
void kernel2d(benchmark::State& state, InstructionSet isa) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  const Case c = paper_model(FrictionLaw::exponential);
  const Model model = build_model(c.model, c.parameters);
  const std::vector<double> table = table_acceleration(model.time_step, kSteps);
  for (auto _ : state) {
    state.PauseTiming();
    LaneBlock block = make_block(model, c.parameters, kLanes);
    state.ResumeTiming();
    advance_block(isa, model, block, table.data(), nullptr, 0, kSteps);
    benchmark::DoNotOptimize(block.view().body);
  }
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
}

// End to end: 1,000 realisations x 20 s of El Centro's three components (the 1/3 model, time
// compressed by sqrt 3), RotD50 PGA spread over 0.2 to 1.2 g and incidences over [0, 180), in
// lockstep blocks of 64 lanes shared by two OpenMP threads; realisation-seconds per second.
void ensemble3d(benchmark::State& state) {
  const Cask3D cask = paper_cask3d();
  const double dt = cask.model.model.time_step;
  const std::filesystem::path dir = std::filesystem::path(CASKDEM_SHARED_DIR) / "motions" / "three-component";
  const motion::ComponentSet set = motion::read_component_set(
      dir / "elcentro1940_RSN6_H1_180.AT2", dir / "elcentro1940_RSN6_H2_270.AT2", dir / "elcentro1940_RSN6_UP.AT2");
  const double rotd50 = motion::pair_intensity(set.h1, set.h2).pga_rotd50;
  const double duration = 20.0;
  const int steps = static_cast<int>(std::ceil(duration / dt));
  const auto component = [&](const motion::Record& r) {
    const auto m = motion::make_record_motion(motion::time_scaled(r, 1.0 / std::sqrt(3.0)));
    std::vector<double> table(steps);
    for (int n = 0; n < steps; ++n) table[n] = m->acceleration(n * dt);
    return table;
  };
  const std::vector<double> h1 = component(set.h1), h2 = component(set.h2), up = component(*set.vertical);
  constexpr int kRealisations = 1000, kBlock = 64;
  const int blocks = (kRealisations + kBlock - 1) / kBlock;
  std::int64_t tipped = 0;
  for (auto _ : state) {
    tipped = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(2) reduction(+ : tipped)
    for (int b = 0; b < blocks; ++b) {
      const int count = std::min(kBlock, kRealisations - b * kBlock);
      LaneBlock3D block(count);
      for (int l = 0; l < count; ++l) {
        const int i = b * kBlock + l;
        RealisationParameters p = cask.nominal;
        p.horizontal_scale = p.vertical_scale = (0.2 + 1.0 * (i % 50) / 49.0) * 9.80665 / rotd50;
        const LaneParameters<double> lane = lane_parameters3d(cask.model, p);
        const BodyState3D<double> body = rest_state3d(cask.model, lane);
        const ContactState3D<double> sliders[kContactSliders3D] = {};
        block.set_lane(l, lane, body, sliders, initial_response3d(lane, body), std::numbers::pi * (i / 50) / 20.0);
      }
      block.pad_from(0);
      // In chunks, as the ensemble runs blocks, so that a block whose lanes all stopped ends early.
      for (int first = 0; first < steps; first += 2048) {
        advance_block3d(InstructionSet::automatic, cask.model.model, cask.model.contacts, block, h1.data(), h2.data(),
                        up.data(), 0, std::min(2048, steps - first));
      }
      for (int l = 0; l < count; ++l) {
        Response3D<double> response;
        block.get_lane(l, nullptr, nullptr, &response);
        tipped += response.status == double(LaneStatus::tipped_over);
      }
    }
  }
  state.counters["realisations"] = kRealisations;
  state.counters["tipped_over"] = double(tipped);
  state.counters["realisation_seconds_per_s"] =
      benchmark::Counter(kRealisations * duration * state.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(kernel3d, scalar, InstructionSet::scalar)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel3d, sse2, InstructionSet::sse2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel3d, avx2, InstructionSet::avx2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel3d, avx512f, InstructionSet::avx512f)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel2d, avx2, InstructionSet::avx2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel2d, avx512f, InstructionSet::avx512f)->Unit(benchmark::kMillisecond);
BENCHMARK(ensemble3d)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("cpu_mhz_reported", std::to_string(caskdem::bench::reported_clock_mhz()));
  benchmark::AddCustomContext("best_instruction_set", caskdem::instruction_set_name(caskdem::best_instruction_set()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
