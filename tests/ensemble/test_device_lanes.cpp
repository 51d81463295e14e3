// The GPU engine's host side, checked where no GPU is: queued lanes (kernels/queue_lanes.h) on
// the host in the GPU's place (open_host_lane_device), driven by the same host code as a GPU run
// (ensemble/device_runner.h), give every realisation the CPU engine's bits, planar and 3D, with
// every friction law, whatever the number of lanes, the ring's capacity (wrapping round, running
// dry) and the steps per launch; every realisation is reported once; an interrupted run keeps
// what finished and resumes on the device to the CPU's file. tests/ensemble/test_gpu.cpp runs
// the same comparisons on a GPU where one is present.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ensemble/device_runner.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/execute.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "kernels/lane_device.h"
#include "support/result_files.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

const std::string kData = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/";

// A realisation's outcome as bits, every field.
std::vector<std::uint64_t> bits_of(const RealisationOutcome& o) {
  const double fields[] = {double(o.status), o.max_abs_rotation, o.max_abs_slide,
                           o.residual_slide, o.max_uplift,       o.impacts,
                           o.end_time,       o.instability_time, o.spin,
                           o.max_slip,       o.residual_slip};
  std::vector<std::uint64_t> bits(std::size(fields));
  std::memcpy(bits.data(), fields, sizeof fields);
  return bits;
}

// Every realisation's outcome by index, checking that each is reported exactly once.
using Outcomes = std::map<std::int64_t, std::vector<std::uint64_t>>;
OutcomeSink collect(Outcomes& outcomes) {
  return [&outcomes](const std::vector<std::int64_t>& indices, const std::vector<RealisationOutcome>& done) {
    ASSERT_EQ(indices.size(), done.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
      EXPECT_TRUE(outcomes.emplace(indices[k], bits_of(done[k])).second) << "realisation " << indices[k] << " twice";
    }
  };
}

std::vector<std::int64_t> all_of(const EnsemblePlan& plan) {
  std::vector<std::int64_t> all(static_cast<std::size_t>(plan.size()));
  for (std::int64_t i = 0; i < plan.size(); ++i) all[static_cast<std::size_t>(i)] = i;
  return all;
}

// The CPU engine's outcomes: the scalar reference, one realisation after another.
Outcomes on_cpu(const EnsemblePlan& plan, const MotionTables& tables, const std::vector<std::int64_t>& indices) {
  Outcomes outcomes;
  RunOptions options;
  options.isa = InstructionSet::scalar;
  options.lanes = 1;
  run_realisations(plan, tables, indices, options, collect(outcomes));
  return outcomes;
}

Outcomes on_host_lanes(const EnsemblePlan& plan, const MotionTables& tables, const std::vector<std::int64_t>& indices,
                       const DeviceLanes::Tuning& tuning, LaneOccupancy* occupancy = nullptr) {
  const std::unique_ptr<LaneDevice> device = open_host_lane_device(tuning.lanes > 0 ? tuning.lanes : 8);
  DeviceLanes lanes(plan, tables, *device);
  lanes.set_tuning(tuning);
  Outcomes outcomes;
  RunOptions options;
  options.device = &lanes;
  run_realisations(plan, tables, indices, options, collect(outcomes), occupancy);
  return outcomes;
}

void expect_same(const Outcomes& device, const Outcomes& cpu, const std::string& what) {
  ASSERT_EQ(device.size(), cpu.size()) << what;
  int differ = 0;
  for (const auto& [index, bits] : cpu) {
    const auto found = device.find(index);
    ASSERT_NE(found, device.end()) << what << ": realisation " << index << " missing";
    if (found->second != bits && ++differ <= 3) ADD_FAILURE() << what << ": realisation " << index << " differs";
  }
  EXPECT_EQ(differ, 0) << what;
}

// How many realisations stopped early (tipped, left the floor) and how many ran their whole run:
// the lanes were refilled both ways.
void expect_mixed(const EnsemblePlan& plan, const Outcomes& outcomes) {
  int stopped = 0, ran = 0;
  for (const auto& [index, bits] : outcomes) {
    double status = 0.0;
    std::memcpy(&status, &bits[0], sizeof status);
    (status != 0.0 ? stopped : ran) += 1;
  }
  EXPECT_GT(stopped, 0) << plan.spec().name;
  EXPECT_GT(ran, 0) << plan.spec().name;
}

class DeviceLanesTest : public ::testing::TestWithParam<const char*> {};

// Lanes, ring and launch steps that make lanes refill inside a launch and across launches, the
// ring wrap round and run dry, and one lane hold everything.
TEST_P(DeviceLanesTest, HostLanesGiveTheCpuBitsHoweverTheWorkIsCut) {
  EnsembleSpec spec = load_ensemble(kData + GetParam());
  spec.realisations_per_stripe = spec.three_d() ? 6 : 12;
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  const MotionTables tables(plan);
  const std::vector<std::int64_t> all = all_of(plan);
  const Outcomes cpu = on_cpu(plan, tables, all);
  expect_mixed(plan, cpu);
  const DeviceLanes::Tuning cuts[] = {
      {5, 7, 1000},     // few lanes, a ring that wraps round many times, short launches
      {16, 16, 20000},  // a ring that runs dry within a launch
      {1, 3, 50000},    // one lane holds every realisation in turn
      {64, 0, 0},       // more lanes than realisations, launches adapted
  };
  for (const DeviceLanes::Tuning& cut : cuts) {
    expect_same(on_host_lanes(plan, tables, all, cut), cpu,
                std::string(GetParam()) + " with " + std::to_string(cut.lanes) + " lanes, ring " +
                    std::to_string(cut.ring) + ", " + std::to_string(cut.steps_per_launch) + " steps a launch");
  }
}

// Every friction law (the step's four instantiations, each its own GPU kernel) on both casks.
TEST_P(DeviceLanesTest, HostLanesGiveTheCpuBitsWithEveryFrictionLaw) {
  for (FrictionLaw law :
       {FrictionLaw::constant, FrictionLaw::static_kinetic, FrictionLaw::exponential, FrictionLaw::tabulated}) {
    EnsembleSpec spec = load_ensemble(kData + GetParam());
    spec.realisations_per_stripe = spec.three_d() ? 3 : 8;
    spec.base.model.friction_law = law;
    spec.uncertain.erase("restitution");  // the calibration's reach depends on the law
    if (law == FrictionLaw::tabulated) spec.base.model.friction_table = {{0.0, 0.55}, {0.02, 0.45}, {0.2, 0.35}};
    const EnsemblePlan plan(spec, InstructionSet::scalar);
    const MotionTables tables(plan);
    const std::vector<std::int64_t> all = all_of(plan);
    expect_same(on_host_lanes(plan, tables, all, {6, 9, 3000}), on_cpu(plan, tables, all),
                std::string(GetParam()) + ", friction law " + std::to_string(int(law)));
  }
}

// The whole-step slider (its velocity kicks are lane state the queue carries) on both casks.
TEST_P(DeviceLanesTest, HostLanesGiveTheCpuBitsWithTheWholeStepSlider) {
  EnsembleSpec spec = load_ensemble(kData + GetParam());
  spec.realisations_per_stripe = spec.three_d() ? 3 : 8;
  spec.base.model.whole_step_terms = kWholeStepSlider;
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  const MotionTables tables(plan);
  const std::vector<std::int64_t> all = all_of(plan);
  expect_same(on_host_lanes(plan, tables, all, {6, 9, 3000}), on_cpu(plan, tables, all),
              std::string(GetParam()) + ", whole-step slider");
}

// The Hunt-Crossley normal law with its damper (a model form: one uniform branch of the contact
// law), on queued host lanes and on every SIMD width this machine runs, both casks.
TEST_P(DeviceLanesTest, EveryPathGivesTheCpuBitsWithTheHuntCrossleyLaw) {
  EnsembleSpec spec = load_ensemble(kData + GetParam());
  spec.realisations_per_stripe = spec.three_d() ? 3 : 8;
  spec.base.model.normal_law = NormalLaw::hunt_crossley;
  spec.base.parameters.impact_damping = 2.0;  // s/m
  spec.uncertain.erase("restitution");       // the calibration's reach depends on the law
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  ASSERT_GT(plan.model().hertz_overlap, 0.0);
  const MotionTables tables(plan);
  const std::vector<std::int64_t> all = all_of(plan);
  const Outcomes cpu = on_cpu(plan, tables, all);
  expect_mixed(plan, cpu);
  expect_same(on_host_lanes(plan, tables, all, {6, 9, 3000}), cpu, std::string(GetParam()) + ", Hunt-Crossley");
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) continue;
    Outcomes wide;
    RunOptions options;
    options.isa = isa;
    options.lanes = 8;
    run_realisations(plan, tables, all, options, collect(wide));
    expect_same(wide, cpu, std::string(GetParam()) + ", Hunt-Crossley, " + instruction_set_name(isa));
  }
}

// A resumed run's pending realisations are not contiguous: any subset in any order.
TEST_P(DeviceLanesTest, AnySubsetGivesItsRealisationsTheirBits) {
  EnsembleSpec spec = load_ensemble(kData + GetParam());
  spec.realisations_per_stripe = spec.three_d() ? 6 : 12;
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  const MotionTables tables(plan);
  std::vector<std::int64_t> some;
  for (std::int64_t i = plan.size() - 1; i >= 0; i -= 3) some.push_back(i);
  expect_same(on_host_lanes(plan, tables, some, {4, 5, 4000}), on_cpu(plan, tables, some), GetParam());
}

INSTANTIATE_TEST_SUITE_P(PlanarAnd3D, DeviceLanesTest,
                         ::testing::Values("mixed-outcomes.toml", "mixed-outcomes-3d.toml"),
                         [](const auto& info) { return std::string(info.index == 0 ? "planar" : "spatial"); });

// With a ring that holds every realisation a lane finds one whenever one waits: lanes idle only
// in the tail, once nothing is left to start.
TEST(DeviceLanes, NoLaneIdlesWhileRealisationsWait) {
  EnsembleSpec spec = load_ensemble(kData + "mixed-outcomes.toml");
  spec.realisations_per_stripe = 12;
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  const MotionTables tables(plan);
  LaneOccupancy occupancy;
  on_host_lanes(plan, tables, all_of(plan), {8, plan.size(), 2000}, &occupancy);
  EXPECT_GT(occupancy.lane_steps, 0.0);
  EXPECT_GT(occupancy.stopped_lane_steps, 0.0) << "the last lanes drain alone";
  EXPECT_EQ(occupancy.stopped_while_waiting, 0.0);
}

// The sink may stop a run (as a failed checkpoint would): what it was given had finished, and
// the run stops at once with its error.
TEST(DeviceLanes, ASinkThatThrowsStopsTheRunWithWhatFinished) {
  EnsembleSpec spec = load_ensemble(kData + "mixed-outcomes.toml");
  spec.realisations_per_stripe = 12;
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  const MotionTables tables(plan);
  const std::vector<std::int64_t> all = all_of(plan);
  const Outcomes cpu = on_cpu(plan, tables, all);
  const std::unique_ptr<LaneDevice> device = open_host_lane_device(4);
  DeviceLanes lanes(plan, tables, *device);
  lanes.set_tuning({4, 6, 2000});
  Outcomes seen;
  int calls = 0;
  const OutcomeSink stop_at_third = [&](const std::vector<std::int64_t>& indices,
                                        const std::vector<RealisationOutcome>& outcomes) {
    collect(seen)(indices, outcomes);
    if (++calls == 3) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(lanes.run(all, stop_at_third), std::runtime_error);
  EXPECT_EQ(calls, 3);
  ASSERT_GT(seen.size(), 0u);
  ASSERT_LT(seen.size(), cpu.size());
  for (const auto& [index, bits] : seen) EXPECT_EQ(bits, cpu.at(index)) << "realisation " << index;
}

// The whole command's path: a result file made on the device (the host in its place) equals the
// CPU engine's, and a checkpoint with half of the realisations done resumes on the device to it.
class DeviceLanesFiles : public testing::TemporaryFiles {};

TEST_F(DeviceLanesFiles, ResultFileAndResumeEqualTheCpuEngine) {
  for (const char* name : {"resume.toml", "resume-3d.toml"}) {
    EnsembleSpec spec = load_ensemble(kData + name);
    spec.realisations_per_stripe = spec.three_d() ? 8 : 30;
    const EnsemblePlan plan(spec, InstructionSet::automatic);
    ExecuteOptions cpu;
    cpu.threads = 2;
    cpu.progress = false;
    cpu.output = dir_ / "cpu.h5";
    execute_ensemble(plan, cpu);

    const std::unique_ptr<LaneDevice> device = open_host_lane_device(16);
    ExecuteOptions gpu = cpu;
    gpu.device = device.get();
    gpu.output = dir_ / "device.h5";
    execute_ensemble(plan, gpu);
    testing::expect_same_results(cpu.output, gpu.output);
    EXPECT_EQ(hdf5::open_file(gpu.output).string_attribute("device"), device->name());
    EXPECT_EQ(hdf5::open_file(cpu.output).string_attribute("device"), "cpu");

    // A checkpoint holding every other realisation, written as a run interrupted there leaves it.
    double wall = 0.0;
    EnsembleResults half = read_ensemble_results(cpu.output, plan, &wall);
    for (std::int64_t i = 0; i < half.size; i += 2) half.completed[static_cast<std::size_t>(i)] = 0;
    ExecuteOptions resumed = gpu;
    resumed.output = dir_ / "resumed.h5";
    write_ensemble_file(resumed.output, plan, half, RunInformation{}, nullptr);
    resumed.resume = true;
    const ExecuteReport report = execute_ensemble(plan, resumed);
    EXPECT_EQ(report.realisations_run, (plan.size() + 1) / 2) << name;
    testing::expect_same_results(cpu.output, resumed.output);
  }
}

// A GPU asked for where the build or the machine has none: one clear refusal.
TEST(DeviceChoice, CudaWithoutAGpuIsRefusedWithItsReason) {
  std::string why;
  if (!cuda_devices(&why).empty()) GTEST_SKIP() << "this machine has a CUDA device";
  try {
    open_device(DeviceKind::cuda, 0, "--device cuda");
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--device cuda: no GPU to run on: " + why), std::string::npos) << e.what();
  }
  EXPECT_EQ(open_device(DeviceKind::automatic, 0, "--device auto"), nullptr) << "auto falls back to the CPU";
  EXPECT_EQ(open_device(DeviceKind::cpu, 0, "--device cpu"), nullptr);
  EXPECT_THROW(parse_device_kind("gpu"), std::invalid_argument);
}

}  // namespace
}  // namespace caskdem
