// The 3D kernel (kernels/step3d.h, kernels/block3d.h): realisation-steps per second per
// instruction set, the flops a 3D realisation-step costs (counted on the counting number type)
// and the fraction of the core's peak, beside the planar kernel on the same cask and table.
// End to end through the ensemble engine: bench/bench_ensemble.cpp.

#include "bench/counted.h"  // before the kernels, so their templates see its overloads

#include <cmath>
#include <filesystem>
#include <numbers>

#include <benchmark/benchmark.h>

#include "bench/bench_common.h"
#include "kernels/block3d.h"
#include "kernels/step3d.h"
#include "model/build3d.h"

namespace caskdem::bench {
namespace {

constexpr int kSteps = kKernelSteps;
constexpr int kLanes = kKernelLanes;

struct Cask3D {
  Model3D model;
  RealisationParameters nominal;
};

Cask3D paper_cask3d(NormalLaw law = NormalLaw::linear, std::int32_t whole_step_terms = 0) {
  Case c = paper_model(FrictionLaw::exponential);
  c.model.normal_law = law;
  c.model.whole_step_terms = whole_step_terms;
  if (law == NormalLaw::hunt_crossley) c.parameters.impact_damping = 2.0;  // s/m
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

// The timed work of a 3D kernel benchmark: a fresh block of kLanes lanes through kSteps steps.
void advance_blocks3d(benchmark::State& state, InstructionSet isa, const Cask3D& cask) {
  const std::vector<double> table = table_acceleration(cask.model.model.time_step, kSteps);
  for (auto _ : state) {
    state.PauseTiming();
    LaneBlock3D block = make_block3d(cask, kLanes);
    state.ResumeTiming();
    advance_block3d(isa, cask.model.model, cask.model.contacts, block, table.data(), nullptr, nullptr, 0, kSteps);
    benchmark::DoNotOptimize(block.view().body);
  }
}

void kernel3d(benchmark::State& state, InstructionSet isa) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  const Cask3D cask = paper_cask3d();
  const lane::OperationCount operations = count_operations3d(cask);
  advance_blocks3d(state, isa, cask);
  const double lane_steps = double(kLanes) * kSteps * state.iterations();
  state.counters["lane_steps_per_s"] = benchmark::Counter(lane_steps, benchmark::Counter::kIsRate);
  state.counters["flops_per_lane_step"] = double(operations.flops);
  state.counters["other_ops_per_lane_step"] = double(operations.other);
  state.counters["fraction_of_core_peak"] =
      benchmark::Counter(lane_steps * operations.flops / core_peak(width_of(isa)), benchmark::Counter::kIsRate);
}

// What the Hunt-Crossley normal law costs in 3D (kernels/contact_law.h): the rim's 16 nodes and
// the centre each take a square root, and the linear law's shortcut for the rim is off.
void normal_law3d(benchmark::State& state, InstructionSet isa, NormalLaw law) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  const Cask3D cask = paper_cask3d(law);
  advance_blocks3d(state, isa, cask);
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
}

// The whole-step slider (an ensemble's default; kernels/slider.h) against the paper's half-step
// one on the same work: what its whole-step velocities and its spring at a touch cost.
void slider3d(benchmark::State& state, InstructionSet isa, std::int32_t whole_step_terms) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError((instruction_set_name(isa) + " is not available on this machine").c_str());
    return;
  }
  const Cask3D cask = paper_cask3d(NormalLaw::linear, whole_step_terms);
  advance_blocks3d(state, isa, cask);
  state.counters["lane_steps_per_s"] = benchmark::Counter(double(kLanes) * kSteps * state.iterations(), benchmark::Counter::kIsRate);
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

}  // namespace

BENCHMARK_CAPTURE(kernel3d, scalar, InstructionSet::scalar)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel3d, sse2, InstructionSet::sse2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel3d, avx2, InstructionSet::avx2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel3d, avx512f, InstructionSet::avx512f)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law3d, avx2_linear, InstructionSet::avx2, NormalLaw::linear)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law3d, avx2_hunt_crossley, InstructionSet::avx2, NormalLaw::hunt_crossley)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law3d, avx512f_linear, InstructionSet::avx512f, NormalLaw::linear)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_law3d, avx512f_hunt_crossley, InstructionSet::avx512f, NormalLaw::hunt_crossley)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, scalar_half_step, InstructionSet::scalar, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, scalar_whole_step, InstructionSet::scalar, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, sse2_half_step, InstructionSet::sse2, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, sse2_whole_step, InstructionSet::sse2, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, avx2_half_step, InstructionSet::avx2, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, avx2_whole_step, InstructionSet::avx2, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, avx512f_half_step, InstructionSet::avx512f, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(slider3d, avx512f_whole_step, InstructionSet::avx512f, kWholeStepSlider)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel2d, avx2, InstructionSet::avx2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kernel2d, avx512f, InstructionSet::avx512f)->Unit(benchmark::kMillisecond);

}  // namespace caskdem::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("cpu_mhz_reported", std::to_string(caskdem::bench::reported_clock_mhz()));
  benchmark::AddCustomContext("best_instruction_set", caskdem::instruction_set_name(caskdem::best_instruction_set()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
