// Validation 5, pulses: the smallest half-sine pulse that overturns the cask,
// beta = a_p / (g tan alpha), against the closed form of rocking theory
//   beta [cos(psi) + exp(-(pi - psi)/Omega)] = Omega,  sin(psi) = 1/beta,  Omega = w_p / p
// (overturning in the first excursion; ../shared/notes/rocking-theory.md), within 5 % for
// Omega = 1, 2, 4, with stiff contact and the DEM's restitution.

#include <cmath>
#include <cstdint>
#include <string>
#include <numbers>

#include <gtest/gtest.h>

#include "sim/rigid_equivalent.h"
#include "support/function_motion.h"
#include "support/paper_cases.h"
#include "theory/rocking.h"

namespace caskdem {
namespace {

TEST(Pulses, HalfSineOverturningThresholdFollowsTheClosedForm) {
  for (const testing::Scheme& scheme : testing::kSchemes) {
    Case c = testing::one_third_model();
    scheme.apply(c);
    const std::string name = scheme.name();
    c.model.stiffness.normal *= 10.0;
    c.model.stiffness.shear *= 10.0;
    c.model.friction_law = FrictionLaw::constant;
    c.parameters.friction_static = c.parameters.friction_kinetic = 2.0;
    const testing::Prepared p = testing::prepare(c);
    const theory::RigidBlock block = rigid_equivalent(p.model, c.parameters);
    const double p_frequency = block.frequency_parameter();
    const double uplift = block.gravity * std::tan(block.slenderness());

    for (double omega_ratio : {1.0, 2.0, 4.0}) {
      const double pulse_frequency = omega_ratio * p_frequency;
      const double pulse_duration = std::numbers::pi / pulse_frequency;
      auto overturns = [&](double beta) {
        testing::FunctionMotion pulse(
            [=](double t) { return t <= pulse_duration ? beta * uplift * std::sin(pulse_frequency * t) : 0.0; },
            pulse_duration);
        const RunResult run =
            simulate(p.model, p.lane, rest_state(p.model, p.lane), {&pulse, nullptr}, {pulse_duration + 8.0, 0.0});
        return run.summary.tipped_over;
      };
      const double closed_form = theory::half_sine_overturning_beta(omega_ratio);
      double low = 1.0, high = 2.0 * closed_form;
      ASSERT_FALSE(overturns(low));
      ASSERT_TRUE(overturns(high));
      while (high - low > 1e-3 * closed_form) {
        const double middle = 0.5 * (low + high);
        (overturns(middle) ? high : low) = middle;
      }
      const double dem = 0.5 * (low + high);
      const double error = dem / closed_form - 1.0;
      RecordProperty(name + " beta_error_Omega_" + std::to_string(omega_ratio), std::to_string(error));
      EXPECT_LT(std::abs(error), 0.05) << name << ", Omega = " << omega_ratio << ": DEM beta " << dem
                                       << ", closed form " << closed_form;
    }
  }
}

}  // namespace
}  // namespace caskdem
