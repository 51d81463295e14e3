// Validation 3, free rocking. Released at rest from theta0, a block on stiff contact with
// little damping
//  - reaches its first impact after a quarter of Housner's period,
//    T = (4/p) acosh(1 / (1 - theta0/alpha)) (Housner 1963), within 3 % for theta0/alpha
//    in 0.3 .. 0.9;
//  - loses amplitude at each impact as the exact energy relation for its own restitution e
//    says: cos(alpha - theta_{n+1}) = cos(alpha) + e^2 [cos(alpha - theta_n) - cos(alpha)].
// The theory's block is the DEM section's rigid equivalent (pivots at the corner arcs).

#include <cmath>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "sim/rigid_equivalent.h"
#include "support/function_motion.h"
#include "support/paper_cases.h"
#include "theory/rocking.h"

namespace caskdem {
namespace {

Case stiff_lightly_damped() {
  Case c = testing::one_third_model();
  c.model.stiffness.normal *= 10.0;  // stiff contact: the DEM tends to Housner's rigid block
  c.model.stiffness.shear *= 10.0;
  c.model.friction_law = FrictionLaw::constant;
  c.parameters.friction_static = c.parameters.friction_kinetic = 2.0;  // rocking, not sliding
  c.parameters.damping_ratio = 0.01;
  return c;
}

struct FreeRocking {
  double first_impact_time = 0.0;
  std::vector<double> amplitudes;  // max |theta| of each half-cycle
  std::vector<double> peaks;       // max |omega| before each impact
};

FreeRocking release(const Case& c, double tilt_ratio, double duration) {
  const testing::Prepared p = testing::prepare(c);
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const double theta0 = tilt_ratio * p.model.stability_angle;
  const RunResult run = simulate(p.model, p.lane, tilted_state(p.model, p.lane, theta0), {&still, nullptr},
                                 {duration, p.model.time_step});
  FreeRocking r;
  r.peaks = run.summary.half_cycle_peaks;
  const TimeHistory& h = run.history;
  for (std::size_t i = 1; i < h.time.size(); ++i) {
    if (h.rotation[i] <= 0.0 && h.rotation[i - 1] > 0.0) {  // first crossing, linearly interpolated
      r.first_impact_time = h.time[i - 1] + (h.time[i] - h.time[i - 1]) * h.rotation[i - 1] / (h.rotation[i - 1] - h.rotation[i]);
      break;
    }
  }
  // Half-cycle amplitudes: the largest |theta| between sign changes.
  double current = 0.0;
  int side = 1;
  for (std::size_t i = 0; i < h.time.size(); ++i) {
    const double theta = h.rotation[i];
    if (theta * side < -p.model.rocking_threshold_angle) {
      r.amplitudes.push_back(current);
      current = 0.0;
      side = -side;
    }
    current = std::max(current, std::abs(theta));
  }
  return r;
}

TEST(FreeRocking, QuarterPeriodFollowsHousner) {
  for (const testing::Scheme& scheme : testing::kSchemes) {
    Case c = stiff_lightly_damped();
    scheme.apply(c);
    const testing::Prepared p = testing::prepare(c);
    const theory::RigidBlock block = rigid_equivalent(p.model, c.parameters);
    const std::string name = scheme.name();
    for (double ratio : {0.3, 0.5, 0.7, 0.9}) {
      const double expected = theory::free_rocking_period_linearised(block, ratio * block.slenderness());
      const FreeRocking r = release(c, ratio, 0.5 * expected);
      ASSERT_GT(r.first_impact_time, 0.0) << "no impact for theta0/alpha = " << ratio;
      const double measured = 4.0 * r.first_impact_time;
      const double error = measured / expected - 1.0;
      RecordProperty(name + " period_error_" + std::to_string(ratio), std::to_string(error));
      EXPECT_LT(std::abs(error), 0.03) << name << ", theta0/alpha = " << ratio << ": DEM " << measured << " s, Housner "
                                       << expected << " s";
    }
  }
}

TEST(FreeRocking, AmplitudeDecayFollowsTheExactRelationForItsOwnRestitution) {
  for (const testing::Scheme& scheme : testing::kSchemes) {
    Case c = stiff_lightly_damped();
    scheme.apply(c);
    const std::string name = scheme.name();
    const testing::Prepared p = testing::prepare(c);
    const theory::RigidBlock block = rigid_equivalent(p.model, c.parameters);
    const FreeRocking r = release(c, 0.7, 8.0);
    ASSERT_GE(r.peaks.size(), 5u);
    ASSERT_GE(r.amplitudes.size(), 5u);
    double worst = 0.0;
    for (std::size_t n = 0; n + 1 < 5; ++n) {
      const double restitution = r.peaks[n + 1] / r.peaks[n];  // this impact's own coefficient
      const double predicted = theory::amplitude_after_impact(block, restitution, r.amplitudes[n]);
      const double error = r.amplitudes[n + 1] / predicted - 1.0;
      worst = std::max(worst, std::abs(error));
      EXPECT_LT(std::abs(error), 0.02) << name << ", impact " << n + 1 << ": amplitude " << r.amplitudes[n + 1]
                                       << " rad, predicted " << predicted << " rad";
    }
    RecordProperty(name + " worst_amplitude_error", std::to_string(worst));
  }
}

}  // namespace
}  // namespace caskdem
