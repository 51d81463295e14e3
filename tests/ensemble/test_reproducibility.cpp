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

std::vector<RealisationOutcome> run(const EnsemblePlan& plan, const std::vector<std::int64_t>& indices, int lanes,
                                    InstructionSet isa, int threads) {
  std::vector<RealisationOutcome> by_index(plan.size());
  run_blocks(plan, make_blocks(plan, indices, lanes), isa, threads,
             [&](const WorkBlock& block, const std::vector<RealisationOutcome>& outcomes) {
               for (std::size_t l = 0; l < block.indices.size(); ++l) by_index[block.indices[l]] = outcomes[l];
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
    reference_ = hash_of(run(*plan_, all_, 64, InstructionSet::scalar, 1));
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
