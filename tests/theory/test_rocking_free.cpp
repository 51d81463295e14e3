// Free rocking, impacts and the start of rocking from rest: simulate_rocking (ODE integration)
// against the energy integral, conservation of energy, the energy balance at an impact
// (Housner 1963; Yim, Chopra & Penzien 1980) and the uplift condition |a_g| = g tan(alpha).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "theory/rocking.h"

namespace caskdem::theory {
namespace {

// A rectangle of size R = 1 m and slenderness alpha.
RigidBlock rectangle_with_slenderness(double alpha) {
  return RigidBlock::rectangle(std::sin(alpha), std::cos(alpha));
}

// Mechanical energy over m g R: cos(alpha - |theta|) + theta'^2 / (2 p^2).
double energy_over_mgR(const RigidBlock& block, double theta, double rate) {
  const double p = block.frequency_parameter();
  return std::cos(block.slenderness() - std::abs(theta)) + rate * rate / (2.0 * p * p);
}

const std::function<double(double)> kNoShaking = [](double) { return 0.0; };

TEST(RigidBlockParameters, AgreeWithTheNoteAndWithIntegrationOverTheSolid) {
  const RigidBlock rectangle = RigidBlock::rectangle(0.3, 1.1);
  EXPECT_NEAR(rectangle.size(), std::hypot(0.3, 1.1), 1e-15);
  EXPECT_NEAR(rectangle.slenderness(), std::atan(0.3 / 1.1), 1e-15);
  EXPECT_NEAR(std::pow(rectangle.frequency_parameter(), 2), 3.0 * rectangle.gravity / (4.0 * rectangle.size()), 1e-12);

  // Solid cylinder, radius r, height 2h, axis vertical, turning about the horizontal line through
  // a rim point of its base perpendicular to the rocking plane: I_O/m = mean of (x + r)^2 + z^2
  // over the solid, by the midpoint rule on a polar grid (exact in the angle for x^2).
  const double radius = 1.0, half_height = 2.5;
  const int radial_cells = 2000, angular_cells = 8, height_cells = 2000;
  double radial_mean = 0.0;  // mean of (x + r)^2 over the disc, area-weighted
  for (int i = 0; i < radial_cells; ++i) {
    const double rho = (i + 0.5) * radius / radial_cells;
    for (int j = 0; j < angular_cells; ++j) {
      const double x = rho * std::cos((j + 0.5) * 2.0 * std::numbers::pi / angular_cells);
      radial_mean += (x + radius) * (x + radius) * rho;
    }
  }
  radial_mean /= angular_cells * (0.5 * radius * radius) * radial_cells / radius;
  double height_mean = 0.0;
  for (int k = 0; k < height_cells; ++k) height_mean += std::pow((k + 0.5) * 2.0 * half_height / height_cells, 2);
  height_mean /= height_cells;
  const RigidBlock cylinder = RigidBlock::cylinder(radius, half_height);
  EXPECT_NEAR(cylinder.inertia_about_pivot_per_mass / (radial_mean + height_mean), 1.0, 1e-6);
  EXPECT_NEAR(housner_restitution(cylinder), 1.0 - 2.0 / (radial_mean + height_mean), 1e-6);
}

TEST(HousnerRestitution, RectangleIsOneMinusOneAndAHalfSineSquared) {
  for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
    const double expected = 1.0 - 1.5 * std::pow(std::sin(alpha), 2);
    EXPECT_NEAR(housner_restitution(rectangle_with_slenderness(alpha)), expected, 1e-15) << "alpha " << alpha;
  }
}

TEST(FreeRocking, PeriodOfSimulationEqualsEnergyIntegralAndEnergyIsConserved) {
  for (double alpha : {0.05, 0.25, 0.5}) {
    for (double fraction : {0.2, 0.5, 0.9}) {
      const RigidBlock block = rectangle_with_slenderness(alpha);
      const double theta0 = fraction * alpha;
      const double period = free_rocking_period_exact(block, theta0);
      RockingOptions options;
      options.restitution = 1.0;
      options.initial_rotation = theta0;
      options.duration = 3.1 * period;
      options.output_interval = period / 400.0;
      const RockingResponse response = simulate_rocking(block, kNoShaking, options);

      // Impacts at T/4 + k T/2.
      ASSERT_EQ(response.impacts, 6);
      const double measured_period = 2.0 * (response.impact_times.back() - response.impact_times.front()) / 5.0;
      const double period_error = measured_period / period - 1.0;
      const double quarter_error = 4.0 * response.impact_times.front() / period - 1.0;
      EXPECT_LT(std::abs(period_error), 1e-9) << "alpha " << alpha << " theta0/alpha " << fraction;
      EXPECT_LT(std::abs(quarter_error), 1e-9) << "alpha " << alpha << " theta0/alpha " << fraction;

      const double initial_energy = energy_over_mgR(block, theta0, 0.0);
      double energy_error = 0.0;
      for (std::size_t i = 0; i < response.time.size(); ++i)
        energy_error = std::max(energy_error,
                                std::abs(energy_over_mgR(block, response.rotation[i], response.rate[i]) - initial_energy));
      EXPECT_LT(energy_error, 1e-10) << "alpha " << alpha << " theta0/alpha " << fraction;
      EXPECT_NEAR(response.max_abs_rotation, theta0, 1e-12);
      std::printf("alpha %.2f theta0/alpha %.1f: period error %.2e, first quarter %.2e, energy drift %.2e\n", alpha,
                  fraction, period_error, quarter_error, energy_error);
    }
  }
}

TEST(FreeRocking, LinearisedPeriodIsTheSmallSlendernessLimit) {
  // theta0 = alpha / 2. The linearisation replaces sin(alpha - theta) by alpha - theta, an error
  // of order alpha^2 / 6 relative.
  const double small = 0.05, large = 0.5;
  const RigidBlock small_block = rectangle_with_slenderness(small);
  const RigidBlock large_block = rectangle_with_slenderness(large);
  const double small_difference =
      free_rocking_period_linearised(small_block, small / 2) / free_rocking_period_exact(small_block, small / 2) - 1.0;
  const double large_difference =
      free_rocking_period_linearised(large_block, large / 2) / free_rocking_period_exact(large_block, large / 2) - 1.0;
  std::printf("linearised / exact - 1 at theta0 = alpha/2: alpha 0.05: %.3e, alpha 0.5: %.3e\n", small_difference,
              large_difference);
  EXPECT_LT(std::abs(small_difference), 5e-3);
  EXPECT_GT(std::abs(large_difference), 10.0 * std::abs(small_difference));
  // The difference shrinks like alpha^2.
  const double ratio = large_difference / small_difference;
  EXPECT_NEAR(ratio, 100.0, 10.0);
}

TEST(ImpactLoss, AmplitudesAndRatesFollowTheEnergyBalance) {
  for (double restitution : {0.6, -1.0}) {
    const double alpha = 0.25;
    const RigidBlock block = rectangle_with_slenderness(alpha);
    const double e = restitution < 0.0 ? housner_restitution(block) : restitution;
    RockingOptions options;
    options.restitution = restitution;
    options.initial_rotation = -0.8 * alpha;  // the other side, to use both pivots first
    options.duration = 4.0 * free_rocking_period_exact(block, 0.8 * alpha);
    const RockingResponse response = simulate_rocking(block, kNoShaking, options);

    // Release, impact, peak, impact, peak...: peak k follows impact k. Each peak is compared with
    // the closed form applied to the peak before it, down to 1e-12 rad: the integrator's absolute
    // tolerance (1e-12 per step) limits the relative accuracy of smaller excursions (3e-8 at
    // 2e-14 rad, 2e-6 at 2e-15 rad). The chain from the release is compared over 20 impacts
    // (its error accumulates, to 3e-8 after 130 impacts).
    std::size_t compared = 0;
    double previous = 0.8 * alpha;
    double chain = previous;
    double amplitude_error = 0.0, chain_error = 0.0;
    while (compared < response.peak_rotations.size() && compared + 1 < response.impact_times.size()) {
      const double expected = amplitude_after_impact(block, e, previous);
      if (expected < 1e-12) break;
      const std::size_t k = compared++;
      EXPECT_GT(response.peak_times[k], response.impact_times[k]);
      EXPECT_LT(response.peak_times[k], response.impact_times[k + 1]);
      amplitude_error = std::max(amplitude_error, std::abs(response.peak_rotations[k] / expected - 1.0));
      chain = amplitude_after_impact(block, e, chain);
      if (k < 20) chain_error = std::max(chain_error, std::abs(response.peak_rotations[k] / chain - 1.0));
      previous = response.peak_rotations[k];
    }
    EXPECT_GE(compared, 10u);
    // The flight between impacts is symmetric without shaking, so |theta'| before the next impact
    // is |theta'| after this one: e times |theta'| before it.
    double rate_error = 0.0;
    for (std::size_t k = 0; k < compared; ++k)
      rate_error = std::max(rate_error,
                            std::abs(response.impact_rates_before[k + 1] / (e * response.impact_rates_before[k]) - 1.0));
    std::printf("e %.4f: %zu peaks compared, amplitude error %.2e (chain of 20: %.2e), rate ratio error %.2e\n", e,
                compared, amplitude_error, chain_error, rate_error);
    EXPECT_LT(amplitude_error, 1e-8);
    EXPECT_LT(chain_error, 1e-8);
    EXPECT_LT(rate_error, 1e-8);
  }
}

TEST(ImpactLoss, BlockComesToRestAfterFinitelyManyImpacts) {
  const RigidBlock block = rectangle_with_slenderness(0.25);
  RockingOptions options;
  options.restitution = 0.5;
  options.initial_rotation = 0.1;
  options.duration = 20.0;
  options.output_interval = 0.5;
  const RockingResponse response = simulate_rocking(block, kNoShaking, options);
  // |theta'| falls by e per impact from about p alpha to the rest threshold 1e-8 p.
  EXPECT_GT(response.impacts, 20);
  EXPECT_LT(response.impacts, 40);
  EXPECT_EQ(response.rotation.back(), 0.0);
  EXPECT_EQ(response.rate.back(), 0.0);
  EXPECT_LT(response.impact_times.back(), 5.0);

  options.restitution = 0.0;  // plastic impact: the first one stops it
  EXPECT_EQ(simulate_rocking(block, kNoShaking, options).impacts, 1);
}

TEST(Uplift, StartsWhenTheRampReachesGTanAlphaOnTheDrivenSide) {
  const double alpha = 0.2;
  const RigidBlock block = rectangle_with_slenderness(alpha);
  const double threshold = block.gravity * std::tan(alpha);
  const double ramp_rate = threshold / 2.0;  // m/s^3: the threshold is reached at 2 s
  const double uplift_time = 2.0;
  for (int direction : {+1, -1}) {
    const std::function<double(double)> ramp = [=](double t) { return direction * ramp_rate * t; };
    RockingOptions options;
    options.duration = 2.3;
    options.output_interval = 0.01;
    const RockingResponse response = simulate_rocking(block, ramp, options);
    ASSERT_EQ(response.uplift_times.size(), 1u);
    EXPECT_NEAR(response.uplift_times[0], uplift_time, 1e-12);
    // Just after the start, theta'' = p^2 cos(alpha) (a_g - g tan alpha) / g to first order:
    // theta = s p^2 cos(alpha) k dt^3 / (6 g), independent of the located start time.
    const double p = block.frequency_parameter();
    for (std::size_t i = 0; i < response.time.size(); ++i) {
      const double after = response.time[i] - uplift_time;
      if (after <= 1e-9) {
        EXPECT_LE(std::abs(response.rotation[i]), 1e-30) << "t " << response.time[i];
      } else if (after < 0.021) {
        const double leading = direction * p * p * std::cos(alpha) * ramp_rate * std::pow(after, 3) / (6.0 * block.gravity);
        EXPECT_NEAR(response.rotation[i] / leading, 1.0, 1e-3) << "t " << response.time[i];
      } else {
        EXPECT_GT(direction * response.rotation[i], 0.0) << "t " << response.time[i];
      }
    }
  }
}

TEST(TipOver, ReleasedBeyondAlphaOverturns) {
  const double alpha = 0.25;
  const RigidBlock block = rectangle_with_slenderness(alpha);
  RockingOptions options;
  options.initial_rotation = 1.001 * alpha;
  options.duration = 10.0;
  const RockingResponse response = simulate_rocking(block, kNoShaking, options);
  EXPECT_TRUE(response.tipped_over);
  EXPECT_EQ(response.impacts, 0);
  EXPECT_DOUBLE_EQ(response.max_abs_rotation, options.tip_over_angle);

  options.initial_rotation = 0.999 * alpha;
  EXPECT_FALSE(simulate_rocking(block, kNoShaking, options).tipped_over);
}

}  // namespace
}  // namespace caskdem::theory
