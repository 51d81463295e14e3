// sliding_under_harmonic (piecewise closed form) against an independent fine time stepping of
// the same rigid-plastic model, the no-slip case and Den Hartog's (1931) non-stop steady state.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "theory/sliding.h"

namespace caskdem::theory {
namespace {

constexpr double kGravity = 9.80665;

struct ReferenceResult {
  double max_abs_displacement = 0.0;
  double final_displacement = 0.0;
  int slip_phases = 0;
};

// Classical Runge-Kutta 4 on (u, u') at a fixed fine step; the switches (slip starts where
// |a_g| = mu g, slip ends where u' = 0) are found by bisection, on the time for the start and on
// the length of a Runge-Kutta step from the last step's start for the end. Uses none of the
// closed forms.
ReferenceResult reference_sliding(double friction, double amplitude, double circular_frequency, double duration,
                                  double step) {
  const double friction_acceleration = friction * kGravity;
  auto table = [&](double t) { return amplitude * std::sin(circular_frequency * t); };
  struct Motion {
    double u, v;
  };
  auto runge_kutta = [&](double t, Motion m, double h, int direction) {
    auto acceleration = [&](double time) { return -table(time) - direction * friction_acceleration; };
    const double k1 = acceleration(t), k2 = acceleration(t + 0.5 * h), k4 = acceleration(t + h);
    // u'' depends on t only, so the u stages follow from the v stages.
    const double v2 = m.v + 0.5 * h * k1, v3 = m.v + 0.5 * h * k2, v4 = m.v + h * k2;
    return Motion{m.u + h / 6.0 * (m.v + 2.0 * v2 + 2.0 * v3 + v4), m.v + h / 6.0 * (k1 + 4.0 * k2 + k4)};
  };

  ReferenceResult result;
  double t = 0.0;
  Motion motion{0.0, 0.0};
  int direction = 0;  // 0: sticking
  while (t < duration) {
    const double h = std::min(step, duration - t);
    if (direction == 0) {
      if (std::abs(table(t + h)) <= friction_acceleration) {
        t += h;
        continue;
      }
      double low = t, high = t + h;
      for (int i = 0; i < 200 && high - low > 1e-15; ++i) {
        const double middle = 0.5 * (low + high);
        (std::abs(table(middle)) > friction_acceleration ? high : low) = middle;
      }
      t = high;
      direction = table(t) > 0.0 ? -1 : 1;
      ++result.slip_phases;
      continue;
    }
    const Motion next = runge_kutta(t, motion, h, direction);
    if (direction * next.v > 0.0) {
      t += h;
      motion = next;
    } else {
      double low = 0.0, high = h;
      for (int i = 0; i < 200 && high - low > 1e-16; ++i) {
        const double middle = 0.5 * (low + high);
        (direction * runge_kutta(t, motion, middle, direction).v > 0.0 ? low : high) = middle;
      }
      motion = {runge_kutta(t, motion, high, direction).u, 0.0};
      t += high;
      if (std::abs(table(t)) <= friction_acceleration) {
        direction = 0;
      } else {
        direction = table(t) > 0.0 ? -1 : 1;
        ++result.slip_phases;
      }
    }
    result.max_abs_displacement = std::max(result.max_abs_displacement, std::abs(motion.u));
  }
  result.final_displacement = motion.u;
  return result;
}

TEST(HarmonicSliding, AgreesWithIndependentTimeStepping) {
  struct Case {
    double friction, amplitude_over_g, frequency_hz, duration;
  };
  // The last case barely exceeds friction: slips of ~1e-4 s moving u by ~1e-13 m, where the
  // plain closed form lost 1e-5 relative to cancellation (sliding.cpp now avoids it).
  for (const Case& c : {Case{0.3, 0.5, 2.0, 5.0}, Case{0.3, 1.2, 1.0, 6.0}, Case{0.5, 0.6, 3.0, 4.0},
                        Case{0.2, 0.25, 0.7, 9.0}, Case{0.4, 0.4 * (1.0 + 3e-6), 4.6, 6.0}}) {
    const double amplitude = c.amplitude_over_g * kGravity;
    const double frequency = 2.0 * std::numbers::pi * c.frequency_hz;
    const SlidingResponse exact = sliding_under_harmonic(c.friction, kGravity, amplitude, frequency, c.duration, 0.01);
    const ReferenceResult reference = reference_sliding(c.friction, amplitude, frequency, c.duration, 1e-4);
    const double max_error = exact.max_abs_displacement / reference.max_abs_displacement - 1.0;
    const double final_error = (exact.final_displacement - reference.final_displacement) /
                               reference.max_abs_displacement;
    std::printf("mu %.1f A/g %.2f f %.1f Hz: %d slip phases, max|u| %.6e m (error %.2e), final u %.6e m (error %.2e)\n",
                c.friction, c.amplitude_over_g, c.frequency_hz, exact.slip_phases, exact.max_abs_displacement,
                max_error, exact.final_displacement, final_error);
    EXPECT_EQ(exact.slip_phases, reference.slip_phases);
    EXPECT_LT(std::abs(max_error), 1e-6);
    EXPECT_LT(std::abs(final_error), 1e-6);
    EXPECT_EQ(exact.time.size(), static_cast<std::size_t>(std::round(c.duration / 0.01)) + 1);
    EXPECT_EQ(exact.slip_start_times.size(), static_cast<std::size_t>(exact.slip_phases));
  }
}

TEST(HarmonicSliding, SticksWhenTheTableNeverExceedsFriction) {
  const SlidingResponse response = sliding_under_harmonic(0.4, kGravity, 0.39 * kGravity, 2.0 * std::numbers::pi,
                                                          5.0, 0.1);
  EXPECT_EQ(response.slip_phases, 0);
  EXPECT_EQ(response.max_abs_displacement, 0.0);
  EXPECT_EQ(response.final_displacement, 0.0);
  for (double u : response.displacement) EXPECT_EQ(u, 0.0);
}

TEST(HarmonicSliding, ReachesDenHartogsNonStopSteadyState) {
  // Without stops, u' changes sign every half cycle; over a half cycle from a reversal at t_s
  // with direction s the change of u' vanishes, so cos(w t_s) = -s pi mu g / (2 A), and the
  // displacement between reversals is -2 A sin(w t_s) / w^2: a peak-to-peak amplitude
  // 2 A / w^2 sqrt(1 - (pi mu g / (2 A))^2). Non-stop needs A / (mu g) > sqrt(1 + pi^2 / 4).
  const double friction = 0.25, amplitude = 3.0 * friction * kGravity, frequency = 2.0 * std::numbers::pi;
  const double duration = 40.0;
  const SlidingResponse response = sliding_under_harmonic(friction, kGravity, amplitude, frequency, duration, 1e-4);
  const double ratio = std::numbers::pi * friction * kGravity / (2.0 * amplitude);

  const double reversal = response.slip_start_times.back();
  const int direction = std::sin(frequency * reversal) > 0.0 ? -1 : 1;  // against a_g
  const double phase_error = std::cos(frequency * reversal) + direction * ratio;
  const double spacing_error = (reversal - response.slip_start_times[response.slip_start_times.size() - 2]) /
                                   (std::numbers::pi / frequency) - 1.0;

  // Peak to peak over the last two cycles, from the samples (u' = 0 at the extrema, so the
  // sampling error is of order a dt^2).
  double low = 1e300, high = -1e300;
  for (std::size_t i = 0; i < response.time.size(); ++i)
    if (response.time[i] > duration - 2.0) {
      low = std::min(low, response.displacement[i]);
      high = std::max(high, response.displacement[i]);
    }
  const double expected = 2.0 * amplitude / (frequency * frequency) * std::sqrt(1.0 - ratio * ratio);
  const double amplitude_error = (high - low) / expected - 1.0;
  std::printf("Den Hartog: phase error %.2e, half-cycle spacing error %.2e, peak-to-peak error %.2e\n", phase_error,
              spacing_error, amplitude_error);
  EXPECT_LT(std::abs(phase_error), 1e-9);
  EXPECT_LT(std::abs(spacing_error), 1e-9);
  EXPECT_LT(std::abs(amplitude_error), 1e-6);
}

}  // namespace
}  // namespace caskdem::theory
