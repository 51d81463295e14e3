// The sliding displacement is measured in the floor's frame, so it cannot drift from
// integrating a record: a table acceleration with a constant offset (the typical defect of
// an uncorrected record: its velocity and displacement grow without bound) leaves a cask
// that friction holds exactly where it stood, while the table itself travels metres.

#include <cmath>

#include <gtest/gtest.h>

#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

TEST(RelativeFrame, OffsetRecordMakesNoSlidingDrift) {
  Case c = testing::one_third_model();
  c.model.friction_law = FrictionLaw::constant;
  c.parameters.friction_static = c.parameters.friction_kinetic = 0.6;
  const testing::Prepared p = testing::prepare(c);
  const double offset = 0.05 * p.model.gravity;  // well below both mu g and g tan(alpha)
  const double duration = 20.0;
  testing::FunctionMotion offset_record([=](double t) { return offset + 0.02 * p.model.gravity * std::sin(9.0 * t); },
                                        duration);
  const RunResult run = simulate(p.model, p.lane, rest_state(p.model, p.lane), {&offset_record, nullptr},
                                 {duration, 1e-2});
  // Integrated twice, the offset alone moves the table 0.5 a t^2 = 98 m in 20 s.
  ASSERT_GT(0.5 * offset * duration * duration, 90.0);
  // The cask carries only the elastic shear deflection of its springs, m a / K_s.
  const double elastic = c.parameters.mass * (offset + 0.02 * p.model.gravity) /
                         (p.model.corner_shear_stiffness[0] + p.model.corner_shear_stiffness[1]);
  EXPECT_LT(run.summary.max_abs_slide, 1.5 * elastic);
  EXPECT_LT(run.summary.max_abs_slide, 1e-5);
  EXPECT_EQ(run.summary.impacts, 0);
}

}  // namespace
}  // namespace caskdem
