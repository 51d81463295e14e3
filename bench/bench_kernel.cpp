// Kernel throughput in realisation-steps per second: per instruction set and friction law,
// on one thread and two, against the scalar deterministic code on the same work; the flops a
// realisation-step costs (counted by running the step on a counting number type) and the
// fraction of the machine's peak.

#include "bench/counted.h"  // before the kernels, so their templates see its overloads

#include <omp.h>

#include <benchmark/benchmark.h>

#include "bench/bench_common.h"
#include "kernels/step.h"
#include "sim/simulate.h"

namespace caskdem::bench {
namespace {

constexpr int kSteps = kKernelSteps;
constexpr int kLanes = kKernelLanes;

// Operations of one realisation-step, averaged over a rocking history.
lane::OperationCount count_operations(FrictionLaw law) {
  const Case c = paper_model(law);
  const Model model = build_model(c.model, c.parameters);
  const LaneParameters<double> p = lane_parameters(model, c.parameters);
  LaneParameters<lane::Counted> parameters;
  {
    LaneParameters<double> copy = p;
    double values[LaneParameters<double>::field_count];
    int i = 0;
    copy.for_each_field([&](double& v) { values[i++] = v; });
    i = 0;
    parameters.for_each_field([&](lane::Counted& v) { v = lane::Counted(values[i++]); });
  }
  const BodyState<double> rest = rest_state(model, p);
  BodyState<double> rest_copy = rest;
  double rest_values[BodyState<double>::field_count];
  int field = 0;
  rest_copy.for_each_field([&](double& v) { rest_values[field++] = v; });
  BodyState<lane::Counted> body;
  field = 0;
  body.for_each_field([&](lane::Counted& v) { v = lane::Counted(rest_values[field++]); });
  CornerState<lane::Counted> corners[kMaxCorners];
  Response<lane::Counted> response;
  response.for_each_field([](lane::Counted& v) { v = lane::Counted(0.0); });
  response.instability_time = lane::Counted(-1.0);
  const std::vector<double> table = table_acceleration(model.time_step, kSteps);
  lane::operation_count() = {};
  // As the block kernel runs it (kernels/block_kernel.h): each lane's time from its own clock.
  auto run = [&](auto law_tag) {
    lane::Counted clock(0.0);
    const lane::Counted dt(model.time_step), one(1.0), no_vertical(0.0);
    for (int n = 0; n < kSteps; ++n) {
      kernels::step<decltype(law_tag)::value>(model, parameters, lane::Counted(table[n]), no_vertical, clock * dt, body,
                                              corners, response);
      clock = clock + one;
    }
  };
  switch (law) {
    case FrictionLaw::constant: run(std::integral_constant<FrictionLaw, FrictionLaw::constant>{}); break;
    case FrictionLaw::static_kinetic: run(std::integral_constant<FrictionLaw, FrictionLaw::static_kinetic>{}); break;
    case FrictionLaw::exponential: run(std::integral_constant<FrictionLaw, FrictionLaw::exponential>{}); break;
    case FrictionLaw::tabulated: run(std::integral_constant<FrictionLaw, FrictionLaw::tabulated>{}); break;
  }
  lane::OperationCount total = lane::operation_count();
  return {total.flops / kSteps, total.other / kSteps};
}

// The timed work of the kernel benchmarks: a fresh block of kLanes advanced kSteps under the
// shipped sine, once per iteration.
void advance_blocks(benchmark::State& state, InstructionSet isa, const Model& model, const RealisationParameters& nominal) {
  const std::vector<double> table = table_acceleration(model.time_step, kSteps);
  const std::vector<double> still(kSteps, 0.0);
  for (auto _ : state) {
    state.PauseTiming();
    LaneBlock block = make_block(model, nominal, kLanes);
    state.ResumeTiming();
    advance_block(isa, model, block, table.data(), still.data(), 0, kSteps);
    benchmark::DoNotOptimize(block.view().body);
  }
}

void kernel(benchmark::State& state, InstructionSet isa, FrictionLaw law) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  const Case c = paper_model(law);
  const Model model = build_model(c.model, c.parameters);
  const lane::OperationCount operations = count_operations(law);
  advance_blocks(state, isa, model, c.parameters);
  const double lane_steps = double(kLanes) * kSteps * state.iterations();
  state.counters["lane_steps_per_s"] = benchmark::Counter(lane_steps, benchmark::Counter::kIsRate);
  state.counters["flops_per_lane_step"] = double(operations.flops);
  state.counters["other_ops_per_lane_step"] = double(operations.other);
  state.counters["fraction_of_core_peak"] =
      benchmark::Counter(lane_steps * operations.flops / core_peak(width_of(isa)), benchmark::Counter::kIsRate);
}

// What a distributed footprint costs (model/section.h): the same work with the 1/3 model's
// base as two corners at the gyration half-width (points = 0) or N contacts across the diameter.
void footprint(benchmark::State& state, InstructionSet isa, int points) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  Case c = paper_model(FrictionLaw::exponential);
  if (points > 0) {
    c.cask.cylinder.rule = HalfWidthRule::radius;
    c.cask.cylinder.footprint_points = points;
    c.model.section = cylinder_section(c.cask.cylinder, c.model.section.rounding);
  }
  const Model model = build_model(c.model, c.parameters);
  advance_blocks(state, isa, model, c.parameters);
  state.counters["contacts"] = double(model.corner_count);
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
}

// What the Hunt-Crossley normal law costs (kernels/contact_law.h): the same work with the linear
// spring-dashpot or the Hertz spring (a square root per contact) and Hunt & Crossley's damper.
void normal_law(benchmark::State& state, InstructionSet isa, NormalLaw law) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  Case c = paper_model(FrictionLaw::exponential);
  c.model.normal_law = law;
  if (law == NormalLaw::hunt_crossley) c.parameters.impact_damping = 2.0;  // s/m
  const Model model = build_model(c.model, c.parameters);
  advance_blocks(state, isa, model, c.parameters);
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
}

// The whole-step slider (an ensemble's default; kernels/slider.h) against the paper's half-step
// one on the same work: what its whole-step velocities and its spring at a touch cost.
void slider(benchmark::State& state, InstructionSet isa, std::int32_t whole_step_terms) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  Case c = paper_model(FrictionLaw::exponential);
  c.model.whole_step_terms = whole_step_terms;
  const Model model = build_model(c.model, c.parameters);
  advance_blocks(state, isa, model, c.parameters);
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
}

// The scalar deterministic code (the reference path, with its time-history bookkeeping off)
// on the same work: one realisation after another.
void deterministic(benchmark::State& state, FrictionLaw law) {
  const Case c = paper_model(law);
  const Model model = build_model(c.model, c.parameters);
  const LaneParameters<double> lane = lane_parameters(model, c.parameters);
  const std::vector<double> table = table_acceleration(model.time_step, kSteps);
  for (auto _ : state) {
    BodyState<double> body = rest_state(model, lane);
    CornerState<double> corners[kMaxCorners] = {};
    Response<double> response = initial_response(lane, body);
    for (int n = 0; n < kSteps; ++n) {
      kernels::step<FrictionLaw::exponential>(model, lane, table[n], 0.0, double(n) * model.time_step, body, corners,
                                              response);
    }
    benchmark::DoNotOptimize(response);
  }
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kSteps) * state.iterations(), benchmark::Counter::kIsRate);
}

// Threads: each benchmark thread advances its own block, as the ensemble's OpenMP threads do.
void threads(benchmark::State& state) {
  const Case c = paper_model(FrictionLaw::exponential);
  const Model model = build_model(c.model, c.parameters);
  const std::vector<double> table = table_acceleration(model.time_step, kSteps);
  const std::vector<double> still(kSteps, 0.0);
  for (auto _ : state) {
    state.PauseTiming();
    LaneBlock block = make_block(model, c.parameters, kLanes);
    state.ResumeTiming();
    advance_block(InstructionSet::automatic, model, block, table.data(), still.data(), 0, kSteps);
    benchmark::DoNotOptimize(block.view().body);
  }
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(kernel, scalar_exponential, InstructionSet::scalar, FrictionLaw::exponential)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, sse2_exponential, InstructionSet::sse2, FrictionLaw::exponential)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, avx2_exponential, InstructionSet::avx2, FrictionLaw::exponential)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, avx512f_exponential, InstructionSet::avx512f, FrictionLaw::exponential)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, scalar_constant, InstructionSet::scalar, FrictionLaw::constant)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, sse2_constant, InstructionSet::sse2, FrictionLaw::constant)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, avx2_constant, InstructionSet::avx2, FrictionLaw::constant)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel, avx512f_constant, InstructionSet::avx512f, FrictionLaw::constant)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(footprint, avx2_two_corners, InstructionSet::avx2, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(footprint, avx2_distributed_9, InstructionSet::avx2, 9)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(footprint, avx512f_two_corners, InstructionSet::avx512f, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(footprint, avx512f_distributed_9, InstructionSet::avx512f, 9)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, scalar_linear, InstructionSet::scalar, NormalLaw::linear)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, scalar_hunt_crossley, InstructionSet::scalar, NormalLaw::hunt_crossley)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, sse2_linear, InstructionSet::sse2, NormalLaw::linear)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, sse2_hunt_crossley, InstructionSet::sse2, NormalLaw::hunt_crossley)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, avx2_linear, InstructionSet::avx2, NormalLaw::linear)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, avx2_hunt_crossley, InstructionSet::avx2, NormalLaw::hunt_crossley)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, avx512f_linear, InstructionSet::avx512f, NormalLaw::linear)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law, avx512f_hunt_crossley, InstructionSet::avx512f, NormalLaw::hunt_crossley)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, scalar_half_step, InstructionSet::scalar, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, scalar_whole_step, InstructionSet::scalar, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, sse2_half_step, InstructionSet::sse2, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, sse2_whole_step, InstructionSet::sse2, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, avx2_half_step, InstructionSet::avx2, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, avx2_whole_step, InstructionSet::avx2, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, avx512f_half_step, InstructionSet::avx512f, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider, avx512f_whole_step, InstructionSet::avx512f, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(deterministic, exponential, FrictionLaw::exponential)->Unit(benchmark::kMillisecond);
BENCHMARK(threads)->Threads(1)->Threads(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("cpu_mhz_reported", std::to_string(caskdem::bench::reported_clock_mhz()));
  benchmark::AddCustomContext("best_instruction_set", caskdem::instruction_set_name(caskdem::best_instruction_set()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
