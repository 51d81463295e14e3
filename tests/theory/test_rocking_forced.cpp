// simulate_rocking under harmonic table motion (impacts, returns to rest and new uplifts
// included) against an independent fixed-step integration of the same equation written here:
// classical Runge-Kutta 4 at a fine step that lands on the kinks of a_g (a kink inside a fixed
// step costs Runge-Kutta its order: 2e-10 s of impact time at a 2e-5 s step, found by halving
// the step), impacts and uplifts found by bisection. simulate_rocking is not told of the kinks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "theory/rocking.h"

namespace caskdem::theory {
namespace {

struct ReferenceRocking {
  std::vector<double> impact_times, uplift_times;
  std::vector<double> sample_rotation;  // at multiples of the sample interval
};

ReferenceRocking reference_rocking(const RigidBlock& block, double restitution,
                                   const std::function<double(double)>& table, const std::vector<double>& kinks,
                                   double duration, double step, double sample_interval) {
  const double alpha = block.slenderness(), g = block.gravity;
  const double p_squared = g * block.size() / block.inertia_about_pivot_per_mass;
  const double uplift_acceleration = g * std::tan(alpha);
  struct Motion {
    double theta, rate;
  };
  auto angular_acceleration = [&](double t, double theta, int side) {
    const double lever = side * alpha - theta;
    return p_squared * (-std::sin(lever) + table(t) / g * std::cos(lever));
  };
  auto runge_kutta = [&](double t, Motion m, double h, int side) {
    const double k1 = angular_acceleration(t, m.theta, side);
    const double theta2 = m.theta + 0.5 * h * m.rate, rate2 = m.rate + 0.5 * h * k1;
    const double k2 = angular_acceleration(t + 0.5 * h, theta2, side);
    const double theta3 = m.theta + 0.5 * h * rate2, rate3 = m.rate + 0.5 * h * k2;
    const double k3 = angular_acceleration(t + 0.5 * h, theta3, side);
    const double theta4 = m.theta + h * rate3, rate4 = m.rate + h * k3;
    const double k4 = angular_acceleration(t + h, theta4, side);
    return Motion{m.theta + h / 6.0 * (m.rate + 2.0 * rate2 + 2.0 * rate3 + rate4),
                  m.rate + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)};
  };

  ReferenceRocking result;
  double t = 0.0;
  Motion motion{0.0, 0.0};
  int side = 0;  // 0: at rest
  std::size_t next_sample = 0;
  auto record_samples = [&](double until, auto state_at) {
    for (double ts = next_sample * sample_interval; ts <= until && ts <= duration; ts = ++next_sample * sample_interval)
      result.sample_rotation.push_back(state_at(ts));
  };
  auto next_kink = kinks.begin();
  while (t < duration) {
    while (next_kink != kinks.end() && *next_kink <= t) ++next_kink;
    const double h = std::min({step, duration - t, next_kink != kinks.end() ? *next_kink - t : step});
    if (side == 0) {
      if (std::abs(table(t + h)) <= uplift_acceleration) {
        record_samples(t + h, [](double) { return 0.0; });
        t += h;
        continue;
      }
      double low = t, high = t + h;
      while (high - low > 1e-15) {
        const double middle = 0.5 * (low + high);
        (std::abs(table(middle)) > uplift_acceleration ? high : low) = middle;
      }
      record_samples(high, [](double) { return 0.0; });
      t = high;
      side = table(t) > 0.0 ? 1 : -1;
      result.uplift_times.push_back(t);
      continue;
    }
    const Motion next = runge_kutta(t, motion, h, side);
    const double start = t;
    const Motion start_motion = motion;
    auto state_at = [&](double ts) { return runge_kutta(start, start_motion, ts - start, side).theta; };
    if (side * next.theta > 0.0) {
      record_samples(t + h, state_at);
      t += h;
      motion = next;
      continue;
    }
    double low = 0.0, high = h;
    for (int i = 0; i < 200 && high - low > 1e-16; ++i) {
      const double middle = 0.5 * (low + high);
      (side * runge_kutta(t, motion, middle, side).theta > 0.0 ? low : high) = middle;
    }
    record_samples(t + high, state_at);
    const double rate_after = restitution * runge_kutta(t, motion, high, side).rate;
    t += high;
    result.impact_times.push_back(t);
    const bool rests = std::abs(rate_after) < 1e-8 * std::sqrt(p_squared);
    side = rests ? 0 : -side;
    motion = {0.0, rests ? 0.0 : rate_after};
  }
  return result;
}

TEST(ForcedRocking, AgreesWithFixedStepIntegration) {
  // Bursts of whole cycles separated by quiet gaps (burst_cycles 0: continuous shaking); in
  // the gaps the block comes to rest through a converging sequence of impacts, and it is lifted
  // again by the next burst.
  struct Case {
    double alpha, amplitude_over_uplift, frequency_hz, duration, burst_cycles, gap, restitution;
  };
  for (const Case& c : {Case{0.2, 3.0, 3.0, 4.0, 0.0, 0.0, -1.0}, Case{0.15, 1.3, 5.0, 3.0, 0.0, 0.0, -1.0},
                        Case{0.15, 1.3, 3.0, 5.0, 3.0, 1.5, 0.7}}) {
    const RigidBlock block = RigidBlock::rectangle(0.5 * std::sin(c.alpha), 0.5 * std::cos(c.alpha));
    const double amplitude = c.amplitude_over_uplift * block.gravity * std::tan(c.alpha);
    const double frequency = 2.0 * std::numbers::pi * c.frequency_hz;
    const double burst = c.burst_cycles / c.frequency_hz;
    const std::function<double(double)> table = [=](double t) {
      const bool quiet = burst > 0.0 && std::fmod(t, burst + c.gap) >= burst;
      return quiet ? 0.0 : amplitude * std::sin(frequency * t);
    };
    std::vector<double> kinks;
    for (double start = 0.0; burst > 0.0 && start < c.duration; start += burst + c.gap)
      kinks.insert(kinks.end(), {start + burst, start + burst + c.gap});
    const double sample_interval = 0.01;
    RockingOptions options;
    options.duration = c.duration;
    options.output_interval = sample_interval;
    options.restitution = c.restitution;
    const RockingResponse response = simulate_rocking(block, table, options);
    const ReferenceRocking reference = reference_rocking(block, c.restitution < 0.0 ? housner_restitution(block) : c.restitution, table, kinks,
                                                         c.duration, 2e-5, sample_interval);

    ASSERT_FALSE(response.tipped_over);
    ASSERT_EQ(response.impact_times.size(), reference.impact_times.size());
    ASSERT_EQ(response.uplift_times.size(), reference.uplift_times.size());
    ASSERT_EQ(response.rotation.size(), reference.sample_rotation.size());
    double impact_error = 0.0, uplift_error = 0.0, rotation_error = 0.0;
    for (std::size_t i = 0; i < reference.impact_times.size(); ++i)
      impact_error = std::max(impact_error, std::abs(response.impact_times[i] - reference.impact_times[i]));
    for (std::size_t i = 0; i < reference.uplift_times.size(); ++i)
      uplift_error = std::max(uplift_error, std::abs(response.uplift_times[i] - reference.uplift_times[i]));
    for (std::size_t i = 0; i < reference.sample_rotation.size(); ++i)
      rotation_error = std::max(rotation_error, std::abs(response.rotation[i] - reference.sample_rotation[i]));
    std::printf("alpha %.2f A/(g tan alpha) %.1f f %.0f Hz: %d impacts, %zu uplifts, max |theta| %.4f; "
                "errors: impact time %.1e s, uplift time %.1e s, rotation %.1e rad\n",
                c.alpha, c.amplitude_over_uplift, c.frequency_hz, response.impacts, response.uplift_times.size(),
                response.max_abs_rotation, impact_error, uplift_error, rotation_error);
    EXPECT_LT(impact_error, 1e-9);
    EXPECT_LT(uplift_error, 1e-12);
    EXPECT_LT(rotation_error, 1e-9 * response.max_abs_rotation);
  }
}

}  // namespace
}  // namespace caskdem::theory
