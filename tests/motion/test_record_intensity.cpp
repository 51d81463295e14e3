// integrate_record against exact integrals (with the trapezoid rule's error bound or its
// exact error term), the baseline correction, and scaling to PGA, PGV and time.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/units.h"
#include "motion/record.h"

namespace caskdem::motion {
namespace {

using std::numbers::pi;

Record sampled(double dt, std::size_t n, auto a_of_t) {
  Record record;
  record.source = "test";
  record.time_step = dt;
  for (std::size_t k = 0; k < n; ++k) record.acceleration.push_back(a_of_t(static_cast<double>(k) * dt));
  return record;
}

Record elcentro() { return read_record(std::filesystem::path(CASKDEM_SHARED_DIR) / "motions" / "elcentro1940_ns_RSN6.AT2"); }

// a = A sin(w t) over 1.25 periods (so v(T) != 0 and the correction matters). The exact
// corrected motion is v_c = (A/w)(1 - cos w t) - t V / T, V = (A/w)(1 - cos w T), and
// u_c = (A/w)(t - sin(w t)/w) - V t^2 / (2T). The composite trapezoid error over [0, t] is at
// most t h^2 max|f''| / 12: for v, E_v = T h^2 A w^2 / 12; the correction subtracts
// (t/T) times v's error at T, so |v error| <= 2 E_v; u integrates that (<= 2 T E_v) plus its
// own rule error, T h^2 max|v_c''| / 12 = T h^2 A w / 12.
struct SineErrors {
  double velocity, displacement;  // max |error| over the samples
  double velocity_bound, displacement_bound;
};

SineErrors sine_errors(double h) {
  const double amplitude = 2.0, frequency = 1.3, w = units::hz_to_rad_per_s(frequency);
  const auto n = static_cast<std::size_t>(std::lround(1.25 / frequency / h)) + 1;
  const Record record = sampled(h, n, [&](double t) { return amplitude * std::sin(w * t); });
  const GroundMotion ground = integrate_record(record);
  const double T = record.duration();
  const double V = amplitude / w * (1.0 - std::cos(w * T));
  SineErrors e{0.0, 0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * h;
    const double v = amplitude / w * (1.0 - std::cos(w * t)) - t * V / T;
    const double u = amplitude / w * (t - std::sin(w * t) / w) - V * t * t / (2.0 * T);
    e.velocity = std::max(e.velocity, std::abs(ground.velocity[k] - v));
    e.displacement = std::max(e.displacement, std::abs(ground.displacement[k] - u));
  }
  const double ev = T * h * h * amplitude * w * w / 12.0;
  e.velocity_bound = 2.0 * ev;
  e.displacement_bound = 2.0 * T * ev + T * h * h * amplitude * w / 12.0;
  return e;
}

TEST(IntegrateRecord, SampledSineWithinTheTrapezoidBoundAndSecondOrder) {
  const SineErrors coarse = sine_errors(0.01);
  const SineErrors fine = sine_errors(0.005);
  EXPECT_LE(coarse.velocity, coarse.velocity_bound);
  EXPECT_LE(coarse.displacement, coarse.displacement_bound);
  EXPECT_LE(fine.velocity, fine.velocity_bound);
  EXPECT_LE(fine.displacement, fine.displacement_bound);
  // Halving the step divides a second-order error by 4 (the grids end at the same T).
  EXPECT_NEAR(coarse.velocity / fine.velocity, 4.0, 0.2);
  EXPECT_NEAR(coarse.displacement / fine.displacement, 4.0, 0.2);
}

TEST(IntegrateRecord, LinearAccelerationHasTheTrapezoidRulesExactErrorTerm) {
  // a = c t: the trapezoid rule integrates it exactly, v = c t^2 / 2, corrected
  // v_c = c t^2/2 - t c T/2. v_c'' = c is constant, so the rule's error on u is exactly
  // t h^2 c / 12: u = c t^3/6 - c T t^2/4 + c t h^2/12. Only rounding remains.
  const double c = 3.0, h = 0.02;
  const std::size_t n = 251;
  const Record record = sampled(h, n, [&](double t) { return c * t; });
  const GroundMotion ground = integrate_record(record);
  const double T = record.duration();
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * h;
    EXPECT_NEAR(ground.velocity[k], c * t * t / 2.0 - t * c * T / 2.0, 1e-12) << k;
    EXPECT_NEAR(ground.displacement[k], c * t * t * t / 6.0 - c * T * t * t / 4.0 + c * t * h * h / 12.0, 1e-12) << k;
  }
}

TEST(IntegrateRecord, BaselineCorrectionEndsARealRecordAtRest) {
  const Record record = elcentro();
  const GroundMotion ground = integrate_record(record);
  ASSERT_EQ(ground.velocity.size(), record.acceleration.size());
  ASSERT_EQ(ground.displacement.size(), record.acceleration.size());
  EXPECT_EQ(ground.velocity.front(), 0.0);
  EXPECT_EQ(ground.displacement.front(), 0.0);
  EXPECT_EQ(ground.velocity.back(), 0.0);  // v_N - (N/N) v_N is exactly zero
  // A sine over 1.25 periods ends with v(T) = A/w (1 - cos w T) = A/w uncorrected.
  const double amplitude = 2.0, w = 2.0 * pi, h = 0.01;
  const Record sine = sampled(h, 126, [&](double t) { return amplitude * std::sin(w * t); });
  const GroundMotion corrected = integrate_record(sine);
  EXPECT_EQ(corrected.velocity.back(), 0.0);
  // ...so the correction had a velocity to remove (trapezoid sum within its error bound).
  double uncorrected = 0.0;
  for (std::size_t k = 1; k < sine.acceleration.size(); ++k)
    uncorrected += 0.5 * h * (sine.acceleration[k - 1] + sine.acceleration[k]);
  EXPECT_NEAR(uncorrected, amplitude / w, 1.25 * h * h * amplitude * w * w / 12.0);
}

TEST(IntegrateRecord, ShortRecords) {
  EXPECT_TRUE(integrate_record(Record{}).velocity.empty());
  const GroundMotion one = integrate_record(Record{"one", 0.01, {5.0}});
  EXPECT_EQ(one.velocity, std::vector<double>{0.0});
  EXPECT_EQ(one.displacement, std::vector<double>{0.0});
}

TEST(Intensity, PgvOfAFullSineCycle) {
  // a = A sin(w t) over one period, 200 samples a period: v = (A/w)(1 - cos w t) peaks at
  // 2A/w at half period, a sample. Over a whole period the trapezoid sum of a is zero to
  // rounding, so the correction is negligible; the error is within E_v = T h^2 A w^2 / 12.
  const double amplitude = 1.5, period = 0.8, w = 2.0 * pi / period, h = period / 200.0;
  const Record record = sampled(h, 201, [&](double t) { return amplitude * std::sin(w * t); });
  EXPECT_NEAR(peak_ground_velocity(record), 2.0 * amplitude / w, period * h * h * amplitude * w * w / 12.0);
  EXPECT_NEAR(peak_ground_acceleration(record), amplitude, 1e-12);
}

TEST(Scaling, HitsPgaAndPgvTargets) {
  const Record record = elcentro();
  const double target_pga = units::g_to_si(0.5);
  const Record to_pga = scaled_to_pga(record, target_pga);
  EXPECT_NEAR(peak_ground_acceleration(to_pga), target_pga, 1e-12 * target_pga);
  EXPECT_EQ(to_pga.time_step, record.time_step);

  const double target_pgv = 0.30;  // m/s
  const Record to_pgv = scaled_to_pgv(record, target_pgv);
  EXPECT_NEAR(peak_ground_velocity(to_pgv), target_pgv, 1e-12 * target_pgv);

  const Record doubled = scaled(record, -2.0);
  for (std::size_t k = 0; k < record.acceleration.size(); ++k)
    ASSERT_EQ(doubled.acceleration[k], -2.0 * record.acceleration[k]);
}

TEST(Scaling, ZeroRecordsAndBadTargetsAreRejected) {
  const Record zeros{"zeros", 0.01, std::vector<double>(100, 0.0)};
  EXPECT_THROW(scaled_to_pga(zeros, 1.0), std::invalid_argument);
  EXPECT_THROW(scaled_to_pgv(zeros, 1.0), std::invalid_argument);
  EXPECT_THROW(scaled_to_pga(Record{}, 1.0), std::invalid_argument);
  const Record record = elcentro();
  EXPECT_THROW(scaled_to_pga(record, -1.0), std::invalid_argument);
  EXPECT_THROW(scaled_to_pga(record, std::nan("")), std::invalid_argument);
  EXPECT_THROW(time_scaled(record, 0.0), std::invalid_argument);
  EXPECT_THROW(scaled(record, INFINITY), std::invalid_argument);
}

// Scaling never makes a record no ground motion can be: the largest allowed factor brings
// the PGA to the bound (1000 m/s^2, as the readers use), a larger one is refused, and so are
// targets whose factor would overflow or break the bound. Nothing comes back non-finite.
TEST(Scaling, ByTheLargestAllowedFactor) {
  const Record record = elcentro();
  const double largest = 1000.0 / peak_ground_acceleration(record);
  for (const double factor : {largest, -largest}) {
    const Record top = scaled(record, factor);
    EXPECT_NEAR(peak_ground_acceleration(top), 1000.0, 1e-12);
    EXPECT_TRUE(std::isfinite(peak_ground_velocity(top)));
  }
  EXPECT_THROW(scaled(record, 1.000001 * largest), std::invalid_argument);
  EXPECT_THROW(scaled(record, 1e306), std::invalid_argument);
  EXPECT_NO_THROW(scaled_to_pga(record, 1000.0));
  EXPECT_THROW(scaled_to_pga(record, 1000.001), std::invalid_argument);
  EXPECT_THROW(scaled_to_pgv(record, 1e3), std::invalid_argument);

  // A record of (almost) no motion: its factor to a target would overflow.
  const Record tiny{"tiny", 0.01, {0.0, 5e-324, -5e-324, 0.0}};
  EXPECT_THROW(scaled_to_pga(tiny, 1.0), std::invalid_argument);
  EXPECT_THROW(scaled_to_pgv(tiny, 1.0), std::invalid_argument);
  // A constant acceleration has (to rounding) no baseline-corrected velocity.
  const Record constant{"constant", 0.01, std::vector<double>(1000, 1.0)};
  EXPECT_THROW(scaled_to_pgv(constant, 0.5), std::invalid_argument);
}

TEST(Scaling, TimeScalingNeverGivesANonFiniteOrZeroStep) {
  const Record slow{"slow", 1e300, {0.0, 1.0, 0.0}};
  EXPECT_THROW(time_scaled(slow, 1e10), std::invalid_argument);
  const Record fast{"fast", 1e-300, {0.0, 1.0, 0.0}};
  EXPECT_THROW(time_scaled(fast, 1e-30), std::invalid_argument);
}

TEST(Scaling, TimeScalingKeepsAccelerationAndScalesVelocity) {
  // Similarity law for a 4-times smaller model: time by 1/sqrt(4). a is unchanged, and
  // v = integral of a dt scales with the time factor.
  const Record record = elcentro();
  const double factor = 1.0 / std::sqrt(4.0);
  const Record model = time_scaled(record, factor);
  EXPECT_EQ(model.time_step, record.time_step * factor);
  EXPECT_EQ(model.acceleration, record.acceleration);
  EXPECT_NEAR(model.duration(), record.duration() * factor, 1e-12);
  EXPECT_NEAR(peak_ground_velocity(model), factor * peak_ground_velocity(record), 1e-12);
}

}  // namespace
}  // namespace caskdem::motion
