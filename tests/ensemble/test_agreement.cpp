// Agreement with the reference: every realisation of an ensemble run in SIMD lanes gives
// the deterministic code's result for the same parameters (the scalar instantiation of the
// same step; kernels/step.h), over a few hundred realisations that stand still, rock,
// slide and tip over.

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "sim/simulate.h"

namespace caskdem {
namespace {

TEST(Agreement, EveryLaneEqualsTheDeterministicRun) {
  const EnsembleSpec spec = load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  std::vector<std::int64_t> all(plan.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) all[i] = i;
  std::vector<RealisationOutcome> wide(plan.size());
  RunOptions options;
  options.lanes = 64;
  run_realisations(plan, MotionTables(plan), all, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) wide[done[k]] = outcomes[k];
                   });

  int standing = 0, rocking = 0, sliding = 0, tipped = 0;
  double worst_rotation = 0.0;
  for (std::int64_t i = 0; i < plan.size(); ++i) {
    const RealisationInput in = plan.realisation(i);
    const LaneParameters<double> lane = lane_parameters(plan.model(), in.parameters);
    const RunSummary reference = simulate(plan.model(), lane, rest_state(plan.model(), lane),
                                          {&plan.motion(in.motion), nullptr}, {plan.run_duration(in.motion), 0.0})
                                     .summary;
    const RealisationOutcome& w = wide[i];
    ASSERT_EQ(static_cast<int>(w.status), static_cast<int>(reference.status)) << "realisation " << i;
    const double rotation_error = std::abs(w.max_abs_rotation - reference.max_abs_rotation) /
                                  std::max(reference.max_abs_rotation, 1e-300);
    worst_rotation = std::max(worst_rotation, rotation_error);
    EXPECT_LE(rotation_error, 1e-9) << "realisation " << i;
    EXPECT_EQ(w.max_abs_slide, reference.max_abs_slide) << "realisation " << i;
    EXPECT_EQ(w.residual_slide, reference.residual_slide) << "realisation " << i;
    EXPECT_EQ(w.impacts, reference.impacts) << "realisation " << i;
    EXPECT_EQ(w.end_time, reference.end_time) << "realisation " << i;

    if (reference.tipped_over) ++tipped;
    else if (reference.max_abs_slide > 0.02) ++sliding;
    else if (reference.impacts > 0) ++rocking;
    else if (reference.max_rotation_ratio < 0.01 && reference.max_abs_slide < 1e-3) ++standing;
  }
  RecordProperty("worst_relative_rotation_difference", std::to_string(worst_rotation));
  RecordProperty("standing_rocking_sliding_tipped", std::to_string(standing) + "/" + std::to_string(rocking) + "/" +
                                                       std::to_string(sliding) + "/" + std::to_string(tipped));
  // The ensemble must exercise every kind of outcome, or the comparison proves little.
  EXPECT_GE(standing, 20);
  EXPECT_GE(rocking, 20);
  EXPECT_GE(sliding, 20);
  EXPECT_GE(tipped, 20);
}

}  // namespace
}  // namespace caskdem
