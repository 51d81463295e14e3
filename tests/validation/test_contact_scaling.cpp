// Contact-stiffness scaling (ModelSpec::contact_stiffness_scale, model/build.h) does what it
// says and no more: springs s times softer, so the cask settles s^-1 times deeper (statics of
// linear springs, in the simulation itself), the contact frequency and the step change by
// sqrt(s) and 1/sqrt(s), and the damping ratio at the softened contact's frequency is the one
// the case gives. What it does to a fragility is measured, not asserted: docs/time-step.md.

#include <cmath>

#include <gtest/gtest.h>

#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

struct Scaled {
  Model model;
  ModelFacts facts;
  double settled_penetration = 0.0;  // m, simulated, after 1 s at rest
};

Scaled scaled(double s) {
  Case c = testing::one_third_model();
  c.model.contact_stiffness_scale = s;
  const testing::Prepared p = testing::prepare(c);
  Scaled out{p.model, model_facts(p.model, c.model, c.parameters)};
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  BodyState<double> touching = rest_state(p.model, p.lane);
  touching.y = c.parameters.centre_of_mass.y;  // set down with zero penetration, then released
  const RunResult run = simulate(p.model, p.lane, touching, {&still, nullptr}, {1.0, 1e-3});
  out.settled_penetration = c.parameters.centre_of_mass.y - run.history.centre_y.back();
  return out;
}

TEST(ContactStiffnessScaling, SofterSpringsSettleDeeperAndTakeLongerStepsAtTheSameDampingRatio) {
  const Scaled stiff = scaled(1.0);
  for (double s : {0.5, 0.25, 0.04}) {
    const Scaled soft = scaled(s);
    EXPECT_NEAR(soft.facts.total_normal_stiffness / stiff.facts.total_normal_stiffness, s, 1e-12 * s);
    EXPECT_NEAR(soft.facts.total_shear_stiffness / stiff.facts.total_shear_stiffness, s, 1e-12 * s);
    EXPECT_NEAR(soft.model.time_step / stiff.model.time_step, 1.0 / std::sqrt(s), 1e-12);
    EXPECT_NEAR(soft.facts.natural_frequency / stiff.facts.natural_frequency, std::sqrt(s), 1e-12);
    // The damping ratio at the contact's own frequency: beta w / 2 with beta = 2 h / (w_given sqrt(s)).
    const double ratio_stiff = stiff.facts.damping_beta * 2.0 * std::acos(-1.0) * 135.0 / 2.0;
    const double ratio_soft = soft.facts.damping_beta * 2.0 * std::acos(-1.0) * 135.0 * std::sqrt(s) / 2.0;
    EXPECT_NEAR(ratio_stiff, 0.056, 1e-12);
    EXPECT_NEAR(ratio_soft, 0.056, 1e-12) << "s = " << s;
    // m g / (s K): the simulated springs are the scaled ones.
    EXPECT_NEAR(soft.settled_penetration / stiff.settled_penetration, 1.0 / s, 1e-3 / s) << "s = " << s;
    EXPECT_NEAR(soft.settled_penetration, soft.facts.static_penetration, 1e-3 * soft.facts.static_penetration);
  }
}

TEST(ContactStiffnessScaling, AScaleOutsideZeroToOneIsRefused) {
  Case c = testing::one_third_model();
  for (double s : {0.0, -0.5, 1.5}) {
    c.model.contact_stiffness_scale = s;
    EXPECT_THROW(build_model(c.model, c.parameters), std::invalid_argument) << s;
  }
}

}  // namespace
}  // namespace caskdem
