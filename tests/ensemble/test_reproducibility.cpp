// Reproducibility: a realisation's result does not depend on the thread count, the block it
// lands in, the block size or the instruction set. The results are hashed (FNV-1a over
// their bits) and compared, the way Box2D and Jolt test their determinism.

#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"

namespace caskdem {
namespace {

std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

std::uint64_t hash_of(const std::vector<RealisationOutcome>& outcomes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const RealisationOutcome& o : outcomes) {
    const double fields[] = {double(o.status), o.max_abs_rotation, o.max_abs_slide, o.residual_slide, o.max_uplift,
                             o.impacts,        o.end_time,         o.instability_time};
    hash = fnv1a(hash, fields, sizeof fields);
  }
  return hash;
}

// Lanes refilled as they stop (the default), or blocks of one motion in lockstep.
std::vector<RealisationOutcome> run(const EnsemblePlan& plan, const std::vector<std::int64_t>& indices, int lanes,
                                    InstructionSet isa, int threads, bool refill = true) {
  std::vector<RealisationOutcome> by_index(plan.size());
  const MotionTables tables(plan);
  RunOptions options;
  options.isa = isa;
  options.threads = threads;
  options.lanes = lanes;
  options.refill = refill;
  run_realisations(plan, tables, indices, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) by_index[done[k]] = outcomes[k];
                   });
  std::vector<RealisationOutcome> selected;
  for (std::int64_t i : indices) selected.push_back(by_index[i]);
  return selected;
}

class Reproducibility : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spec_ = new EnsembleSpec(load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml"));
    spec_->realisations_per_stripe = 24;  // 96 realisations: enough lanes of every kind, quick
    plan_ = new EnsemblePlan(*spec_, InstructionSet::scalar);
    for (std::int64_t i = 0; i < plan_->size(); ++i) all_.push_back(i);
    // The reference: one realisation at a time on the scalar path, nothing refilled.
    reference_ = hash_of(run(*plan_, all_, 1, InstructionSet::scalar, 1, false));
  }
  static void TearDownTestSuite() {
    delete plan_;
    delete spec_;
  }
  static EnsembleSpec* spec_;
  static EnsemblePlan* plan_;
  static std::vector<std::int64_t> all_;
  static std::uint64_t reference_;
};
EnsembleSpec* Reproducibility::spec_ = nullptr;
EnsemblePlan* Reproducibility::plan_ = nullptr;
std::vector<std::int64_t> Reproducibility::all_;
std::uint64_t Reproducibility::reference_ = 0;

TEST_F(Reproducibility, SameBitsOnEveryInstructionSet) {
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) {
      std::printf("%s is not available on this machine: not compared\n", instruction_set_name(isa).c_str());
      continue;
    }
    EXPECT_EQ(hash_of(run(*plan_, all_, 64, isa, 1)), reference_) << instruction_set_name(isa);
  }
}

TEST_F(Reproducibility, SameBitsOnOneTwoAndThreeThreads) {
  for (int threads : {1, 2, 3}) {
    EXPECT_EQ(hash_of(run(*plan_, all_, 16, InstructionSet::automatic, threads)), reference_) << threads << " threads";
  }
}

TEST_F(Reproducibility, SameBitsWhateverTheBlockSize) {
  for (int lanes : {1, 5, 8, 37, 96}) {
    EXPECT_EQ(hash_of(run(*plan_, all_, lanes, InstructionSet::automatic, 2)), reference_) << lanes << " lanes";
  }
}

// A lane that stops is refilled with a realisation that starts at step 0 on its own clock
// beside lanes far into their runs: the same bits as blocks that run in lockstep, on every
// instruction set, and with a whole-run table too large for its budget (lockstep, sampled
// chunk by chunk).
TEST_F(Reproducibility, RefilledLanesGiveTheLockstepBits) {
  for (InstructionSet isa : {InstructionSet::scalar, InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) continue;
    for (int lanes : {8, 24}) {
      EXPECT_EQ(hash_of(run(*plan_, all_, lanes, isa, 2, true)), reference_) << instruction_set_name(isa) << ", " << lanes;
      EXPECT_EQ(hash_of(run(*plan_, all_, lanes, isa, 2, false)), reference_) << instruction_set_name(isa) << ", " << lanes;
    }
  }
  std::vector<RealisationOutcome> by_index(plan_->size());
  const MotionTables too_large(*plan_, 0);
  EXPECT_FALSE(too_large.whole());
  RunOptions options;
  options.lanes = 16;
  options.threads = 2;
  run_realisations(*plan_, too_large, all_, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) by_index[done[k]] = outcomes[k];
                   });
  EXPECT_EQ(hash_of(by_index), reference_);
}

// Refilling is there to keep lanes busy: while realisations wait to start, no lane-step is
// spent on a lane that has stopped (in lockstep, a block's stopped lanes ride along until its
// last lane stops). What is left is the tail, when the last lanes drain alone.
TEST_F(Reproducibility, NoLaneRidesStoppedWhileRealisationsWait) {
  const MotionTables tables(*plan_);
  LaneOccupancy refilled, lockstep;
  RunOptions options;
  options.lanes = 8;
  const OutcomeSink ignore = [](const std::vector<std::int64_t>&, const std::vector<RealisationOutcome>&) {};
  run_realisations(*plan_, tables, all_, options, ignore, &refilled);
  options.refill = false;
  run_realisations(*plan_, tables, all_, options, ignore, &lockstep);
  std::printf("lane-steps on stopped lanes: %.1f %% in lockstep (%.1f %% while realisations waited), %.1f %% refilled "
              "(%.1f %%)\n", 100.0 * lockstep.stopped_fraction(), 100.0 * lockstep.stopped_while_waiting / lockstep.lane_steps,
              100.0 * refilled.stopped_fraction(), 100.0 * refilled.stopped_while_waiting / refilled.lane_steps);
  EXPECT_GT(lockstep.stopped_while_waiting, 0.0) << "the ensemble has lanes that stop early";
  EXPECT_EQ(refilled.stopped_while_waiting, 0.0);
}

// The suite above runs an ensemble's default, the whole-step slider. The source paper's scheme,
// the half-step slider, likewise: the same bits on every instruction set and thread count as
// its scalar reference, and not the whole-step slider's bits (the terms differ in the step).
TEST_F(Reproducibility, PaperSchemeSameBitsOnEveryInstructionSetAndThreadCount) {
  ASSERT_EQ(spec_->base.model.whole_step_terms, kWholeStepSlider) << "the suite above runs the default";
  EnsembleSpec spec = *spec_;
  spec.base.model.whole_step_terms = 0;
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  const std::uint64_t reference = hash_of(run(plan, all_, 1, InstructionSet::scalar, 1, false));
  EXPECT_NE(reference, reference_);
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) continue;
    EXPECT_EQ(hash_of(run(plan, all_, 24, isa, 2)), reference) << instruction_set_name(isa);
  }
  EXPECT_EQ(hash_of(run(plan, all_, 16, InstructionSet::automatic, 3, false)), reference) << "3 threads, lockstep";
}

TEST_F(Reproducibility, AnyRealisationRerunAloneGivesItsResult) {
  const std::vector<RealisationOutcome> together = run(*plan_, all_, 64, InstructionSet::automatic, 1);
  for (std::int64_t i : {std::int64_t(3), std::int64_t(41), std::int64_t(77)}) {
    const auto alone = run(*plan_, {i}, 64, InstructionSet::automatic, 1);
    EXPECT_EQ(hash_of(alone), hash_of({together[i]})) << "realisation " << i;
  }
}

}  // namespace
}  // namespace caskdem

namespace caskdem {
namespace {

// A distributed footprint (nine contacts across the base) is the same model description on
// every path: the same bits on every instruction set as the scalar reference.
TEST(ReproducibilityDistributed, SameBitsOnEveryInstructionSet) {
  EnsembleSpec spec = load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
  spec.realisations_per_stripe = 12;
  spec.base.cask.cylinder.rule = HalfWidthRule::radius;
  spec.base.cask.cylinder.footprint_points = kDefaultFootprintPoints;
  spec.base.model.section = cylinder_section(spec.base.cask.cylinder, spec.base.model.section.rounding);
  const EnsemblePlan plan(spec, InstructionSet::scalar);
  std::vector<std::int64_t> all;
  for (std::int64_t i = 0; i < plan.size(); ++i) all.push_back(i);
  const std::vector<RealisationOutcome> reference = run(plan, all, 16, InstructionSet::scalar, 1);
  int rocked = 0;
  for (const RealisationOutcome& o : reference) rocked += o.impacts > 0;
  EXPECT_GT(rocked, 0) << "the footprint's contacts were exercised";
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) continue;
    EXPECT_EQ(hash_of(run(plan, all, 16, isa, 2)), hash_of(reference)) << instruction_set_name(isa);
  }
}

}  // namespace
}  // namespace caskdem
