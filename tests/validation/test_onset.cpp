// Validation 2, onset of rocking and of sliding under a slowly growing table acceleration:
//   rocking starts when |a| reaches g tan(alpha) (friction holding), Housner 1963;
//   sliding starts when |a| reaches mu g, if mu < tan(alpha) (Shenton 1996).

#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

constexpr double kRampRate = 0.05 * 9.80665;  // m/s^3: slow against the cask's ~200 Hz contact modes

struct Onset {
  double acceleration = 0.0;
  bool found = false;
};

// Runs the ramp a(t) = rate t and returns a(t) at the first sample where `happened` holds.
template <class Predicate>
Onset ramp_until(const Case& c, double duration, Predicate happened) {
  const testing::Prepared p = testing::prepare(c);
  testing::FunctionMotion ramp([](double t) { return kRampRate * t; }, duration);
  const RunResult run = simulate(p.model, p.lane, rest_state(p.model, p.lane), {&ramp, nullptr},
                                 {duration, p.model.time_step});
  const TimeHistory& h = run.history;
  for (std::size_t i = 0; i < h.time.size(); ++i) {
    if (happened(h, i)) return {h.table_acceleration[i], true};
  }
  return {};
}

TEST(Onset, RockingStartsAtGTanAlpha) {
  for (const testing::Scheme& scheme : testing::kSchemes) {
    Case c = testing::one_third_model();
    scheme.apply(c);
    c.model.friction_law = FrictionLaw::constant;
    c.parameters.friction_static = c.parameters.friction_kinetic = 2.0;  // friction holds
    const testing::Prepared p = testing::prepare(c);
    const double expected = p.model.gravity * std::tan(p.model.stability_angle);
    // Uplift: the heel corner's normal force falls to zero.
    const Onset onset = ramp_until(c, 1.3 * expected / kRampRate, [](const TimeHistory& h, std::size_t i) {
      return h.normal_force[0][i] == 0.0 || h.normal_force[1][i] == 0.0;
    });
    ASSERT_TRUE(onset.found);
    const double error = onset.acceleration / expected - 1.0;
    RecordProperty(scheme.name() + " relative_error", std::to_string(error));
    EXPECT_LT(std::abs(error), 0.02) << scheme.name() << ": uplift at " << onset.acceleration
                                     << " m/s^2, g tan(alpha) = " << expected;
  }
}

TEST(Onset, SlidingStartsAtMuGWhenMuBelowTanAlpha) {
  Case c = testing::one_third_model();
  for (const testing::Scheme& scheme : testing::kSchemes)
    for (double mu : {0.10, 0.15}) {
      scheme.apply(c);
      c.model.friction_law = FrictionLaw::constant;
      c.parameters.friction_static = c.parameters.friction_kinetic = mu;
      const testing::Prepared p = testing::prepare(c);
      ASSERT_LT(mu, std::tan(p.model.stability_angle));
      const double expected = mu * p.model.gravity;
      // Sliding: every corner's shear force has reached its Coulomb limit.
      const Onset onset = ramp_until(c, 1.5 * expected / kRampRate, [mu](const TimeHistory& h, std::size_t i) {
        for (std::size_t k = 0; k < h.normal_force.size(); ++k) {
          if (std::abs(h.shear_force[k][i]) < mu * h.normal_force[k][i] * (1.0 - 1e-12)) return false;
        }
        return true;
      });
      ASSERT_TRUE(onset.found) << "mu = " << mu;
      const double error = onset.acceleration / expected - 1.0;
      RecordProperty(scheme.name() + " relative_error_mu_" + std::to_string(mu), std::to_string(error));
      EXPECT_LT(std::abs(error), 0.02) << scheme.name() << ", mu = " << mu << ": sliding at "
                                       << onset.acceleration << " m/s^2";
    }
}

}  // namespace
}  // namespace caskdem
