// Table motions against what they must satisfy: a sine's acceleration and velocity are
// derivatives of its displacement (central differences, with their truncation bounds), it
// starts and ends at rest and holds amplitude A; pulses change the velocity by the integral
// of their acceleration (integrated here with Simpson's rule, not the code's formulas).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/units.h"
#include "motion/table_motion.h"

namespace caskdem::motion {
namespace {

using std::numbers::pi;
constexpr double eps = std::numeric_limits<double>::epsilon();

struct SineCase {
  double amplitude, frequency, cycles, ramp_cycles;
};

// Central differences with step h: |(u(t+h) - u(t-h))/2h - u'| <= h^2 max|u'''| / 6 and
// |(u(t+h) - 2u + u(t-h))/h^2 - u''| <= h^2 max|u''''| / 12, plus rounding of about
// eps |u| / h and 4 eps |u| / h^2. For u = A r sin(w t) with |r^(j)| <= p^j / 2 (p = pi/tau),
// Leibniz's rule bounds |u^(n)| <= A (w + p)^n. Points within 2h of a ramp's end, where r''
// jumps, are skipped.
void check_derivatives(const SineCase& c) {
  const auto motion = make_sine(c.amplitude, c.frequency, c.cycles, c.ramp_cycles);
  const double w = units::hz_to_rad_per_s(c.frequency);
  const double duration = c.cycles / c.frequency, ramp = c.ramp_cycles / c.frequency;
  const double p = ramp > 0.0 ? pi / ramp : 0.0;
  const double A = std::abs(c.amplitude), h = 1e-4;
  const double tol_v = h * h / 6.0 * A * std::pow(w + p, 3) + 4.0 * eps * A / h;
  const double tol_a = h * h / 12.0 * A * std::pow(w + p, 4) + 8.0 * eps * A / (h * h);
  const double tol_av = h * h / 6.0 * A * std::pow(w + p, 4) + 4.0 * eps * A * w / h;
  const std::vector<double> kinks = {0.0, ramp, duration - ramp, duration};
  int checked = 0, in_ramp = 0;
  for (double t = 0.0; t <= duration; t += duration / 997.0) {
    if (std::any_of(kinks.begin(), kinks.end(), [&](double k) { return std::abs(t - k) < 2.0 * h; })) continue;
    const double u0 = motion->displacement(t - h), u1 = motion->displacement(t), u2 = motion->displacement(t + h);
    EXPECT_NEAR(motion->velocity(t), (u2 - u0) / (2.0 * h), tol_v) << "t = " << t;
    EXPECT_NEAR(motion->acceleration(t), (u2 - 2.0 * u1 + u0) / (h * h), tol_a) << "t = " << t;
    EXPECT_NEAR(motion->acceleration(t), (motion->velocity(t + h) - motion->velocity(t - h)) / (2.0 * h), tol_av)
        << "t = " << t;
    ++checked;
    if (t < ramp || t > duration - ramp) ++in_ramp;
  }
  EXPECT_GT(checked, 900);
  if (ramp > 0.0) {
    EXPECT_GT(in_ramp, 100);
  }
  // The tolerance is tight: well under the acceleration amplitude A w^2.
  EXPECT_LT(tol_a, 1e-5 * A * w * w);
}

TEST(SineMotion, DerivativesOfTheDisplacementIncludingTheRamps) {
  check_derivatives({units::cm_to_m(1.0), 2.0, 10.0, 2.0});
  check_derivatives({units::cm_to_m(1.5), 3.5, 12.0, 1.25});  // ramps end mid-cycle: a jumps there
  check_derivatives({units::cm_to_m(0.5), 5.0, 8.0, 4.0});    // all ramp, no hold
  check_derivatives({units::cm_to_m(0.5), 5.0, 8.0, 0.0});    // no envelope
}

TEST(SineMotion, StartsAndEndsAtRestWithRamps) {
  const double A = units::cm_to_m(1.0), f = 2.0;
  const auto motion = make_sine(A, f, 10.0, 2.0);
  const double D = 5.0, w = units::hz_to_rad_per_s(f);
  EXPECT_DOUBLE_EQ(motion->duration(), D);
  EXPECT_EQ(motion->displacement(0.0), 0.0);
  EXPECT_EQ(motion->velocity(0.0), 0.0);
  EXPECT_EQ(motion->acceleration(0.0), 0.0);
  // At the end r = r' = 0 to rounding of cos(p s) near s = 0; sin(w D) = sin(20 pi) ~ 1e-15.
  EXPECT_NEAR(motion->displacement(D), 0.0, 1e-15);
  EXPECT_NEAR(motion->velocity(D), 0.0, 1e-14);
  EXPECT_NEAR(motion->acceleration(D), 0.0, 1e-12);
  for (const double t : {-1.0, -1e-9, D + 1e-9, D + 3.0}) {
    EXPECT_EQ(motion->displacement(t), 0.0);
    EXPECT_EQ(motion->velocity(t), 0.0);
    EXPECT_EQ(motion->acceleration(t), 0.0);
  }
  // Continuity into rest: near the ends u ~ t^2 and v ~ t, so they are tiny just inside.
  EXPECT_LT(std::abs(motion->velocity(1e-6)), 1e-6 * A * w);
  EXPECT_LT(std::abs(motion->velocity(D - 1e-6)), 1e-6 * A * w);
}

TEST(SineMotion, HoldsAmplitudeABetweenTheRamps) {
  const double A = units::cm_to_m(1.5), f = 2.0, w = units::hz_to_rad_per_s(f);
  const auto motion = make_sine(A, f, 10.0, 2.0);
  // Quarter-cycle points of the hold part (1 s to 4 s): sin(w t) = +-1.
  for (int k = 2; k < 8; ++k) {
    const double crest = (k + 0.25) / f, trough = (k + 0.75) / f;
    EXPECT_NEAR(motion->displacement(crest), A, 1e-14);
    EXPECT_NEAR(motion->displacement(trough), -A, 1e-14);
    EXPECT_NEAR(motion->acceleration(crest), -A * w * w, 1e-12);
    EXPECT_NEAR(motion->velocity(k / f), A * w, 1e-13);
  }
  // The ramps add envelope-derivative terms, so the peak acceleration can exceed the hold's
  // A w^2 slightly: A w^2 <= peak <= A (w^2 + 2 w |r'| + |r''|) <= A (w^2 + w p + p^2 / 2),
  // p = pi / tau. On a grid that hits the crests the lower bound is attained in the hold.
  const double p = pi / (2.0 / f), dt = 1.0 / (f * 200.0);
  double peak = 0.0;
  for (int n = 0; n <= 2000; ++n) peak = std::max(peak, std::abs(motion->acceleration(n * dt)));
  EXPECT_EQ(peak_acceleration(*motion, dt), peak);
  EXPECT_GE(peak, A * w * w * (1.0 - 1e-15));
  EXPECT_LE(peak, A * (w * w + w * p + p * p / 2.0));
  EXPECT_GE(peak_velocity(*motion, dt), A * w * (1.0 - 1e-15));
  EXPECT_LE(peak_velocity(*motion, dt), A * (w + p / 2.0));
  // Without ramps the peaks are exactly the sine's.
  const auto plain = make_sine(A, f, 10.0, 0.0);
  EXPECT_NEAR(peak_acceleration(*plain, dt), A * w * w, 1e-12);
  EXPECT_NEAR(peak_velocity(*plain, dt), A * w, 1e-14);
}

TEST(SineMotion, NoEnvelopeIsAPlainSine) {
  const double A = units::cm_to_m(1.0), f = 1.5, w = units::hz_to_rad_per_s(f);
  const auto motion = make_sine(A, f, 3.0, 0.0);
  for (double t = 0.0; t <= 2.0; t += 0.0137) {
    EXPECT_NEAR(motion->displacement(t), A * std::sin(w * t), 1e-16);
    EXPECT_NEAR(motion->velocity(t), A * w * std::cos(w * t), 1e-15);
    EXPECT_NEAR(motion->acceleration(t), -A * w * w * std::sin(w * t), 1e-14);
  }
  EXPECT_EQ(motion->acceleration(2.01), 0.0);
}

TEST(SineMotion, BadParametersAreRejected) {
  EXPECT_THROW(make_sine(0.01, 0.0, 10.0, 2.0), std::invalid_argument);
  EXPECT_THROW(make_sine(0.01, 2.0, -1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(make_sine(0.01, 2.0, 3.0, 2.0), std::invalid_argument);  // ramps longer than the motion
  EXPECT_THROW(make_sine(NAN, 2.0, 3.0, 1.0), std::invalid_argument);
  EXPECT_THROW(make_pulse(PulseShape::half_sine, 1.0, 0.0), std::invalid_argument);
}

// Simpson's rule on [a, b] with n (even) intervals: error (b - a) h^4 max|f''''| / 180.
double simpson(auto f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
}

TEST(Pulses, VelocityChangesAreTheIntegralsOfTheirAccelerations) {
  const double ap = 3.0, d = 0.12;
  struct Case {
    PulseShape shape;
    double velocity_change;  // closed form
  };
  const Case cases[] = {{PulseShape::half_sine, 2.0 * ap / (pi / d)},
                        {PulseShape::one_sine, 0.0},
                        {PulseShape::rectangular, ap * d}};
  for (const Case& c : cases) {
    const auto motion = make_pulse(c.shape, ap, d);
    EXPECT_EQ(motion->duration(), d);
    const auto a = [&](double t) { return motion->acceleration(t); };
    const auto v = [&](double t) { return motion->velocity(t); };
    // a is smooth on [0, d]; with h = d / 2000 Simpson's error is below 1e-12 m/s.
    const double change = simpson(a, 0.0, d, 2000);
    EXPECT_NEAR(change, c.velocity_change, 1e-12);
    EXPECT_NEAR(motion->velocity(d), c.velocity_change, 1e-14);
    for (const double t : {0.3 * d, 0.77 * d}) {
      EXPECT_NEAR(motion->velocity(t), simpson(a, 0.0, t, 2000), 1e-12);
      EXPECT_NEAR(motion->displacement(t), simpson(v, 0.0, t, 2000), 1e-12);
    }
    // After the pulse: no acceleration, the velocity it left, the displacement growing linearly.
    EXPECT_EQ(motion->acceleration(d * 1.5), 0.0);
    EXPECT_NEAR(motion->velocity(d * 3.0), c.velocity_change, 1e-14);
    EXPECT_NEAR(motion->displacement(d * 3.0) - motion->displacement(d * 2.0), c.velocity_change * d, 1e-14);
    EXPECT_NEAR(motion->displacement(d * 1.5), simpson(v, 0.0, d * 1.5, 3000), 1e-12);
    EXPECT_EQ(motion->acceleration(-0.01), 0.0);
    EXPECT_EQ(motion->velocity(-0.01), 0.0);
  }
  EXPECT_NEAR(peak_acceleration(*make_pulse(PulseShape::half_sine, ap, d), d / 100.0), ap, 1e-12);
}

TEST(Sampling, SampleAccelerationIsAccelerationAtNTimesDt) {
  const auto motion = make_sine(units::cm_to_m(1.0), 3.0, 20.0, 2.0);
  const double dt = 1.0 / 7000.0;  // not a binary fraction: accumulated time would drift
  for (const std::int64_t first : {std::int64_t{0}, std::int64_t{12345}, std::int64_t{41990}}) {
    std::vector<double> out(64, -1.0);
    sample_acceleration(*motion, dt, first, 64, out.data());
    for (int i = 0; i < 64; ++i) ASSERT_EQ(out[i], motion->acceleration(static_cast<double>(first + i) * dt)) << first + i;
  }
  // Beyond the motion's end the samples are zero.
  std::vector<double> after(4, -1.0);
  sample_acceleration(*motion, dt, 7000 * 7, 4, after.data());
  EXPECT_EQ(after, std::vector<double>(4, 0.0));
}

TEST(RecordMotion, InterpolatesSamplesAndStopsAfterTheEnd) {
  Record record{"test", 0.01, {0.0, 1.0, -2.0, 4.0, 0.5}};
  const GroundMotion ground = integrate_record(record);
  const auto motion = make_record_motion(record);
  EXPECT_DOUBLE_EQ(motion->duration(), 0.04);
  for (std::int64_t n = 0; n < 5; ++n) EXPECT_EQ(motion->acceleration(static_cast<double>(n) * 0.01), record.acceleration[n]);
  EXPECT_DOUBLE_EQ(motion->acceleration(0.015), -0.5);
  EXPECT_DOUBLE_EQ(motion->acceleration(0.0275), -2.0 + 0.75 * 6.0);
  EXPECT_DOUBLE_EQ(motion->velocity(0.025), 0.5 * (ground.velocity[2] + ground.velocity[3]));
  EXPECT_DOUBLE_EQ(motion->displacement(0.035), 0.5 * (ground.displacement[3] + ground.displacement[4]));
  EXPECT_EQ(motion->acceleration(0.0400001), 0.0);
  EXPECT_EQ(motion->acceleration(1.0), 0.0);
  EXPECT_EQ(motion->acceleration(-0.001), 0.0);
  EXPECT_EQ(motion->velocity(1.0), 0.0);  // baseline-corrected: ends at rest
  EXPECT_EQ(motion->displacement(1.0), ground.displacement.back());
  EXPECT_EQ(motion->acceleration(NAN), 0.0);

  EXPECT_EQ(peak_acceleration(*motion, 0.001), 4.0);  // the record's own samples
  EXPECT_EQ(peak_velocity(*motion, 0.001), peak_ground_velocity(record));

  std::vector<double> out(7);
  sample_acceleration(*motion, 0.01, 0, 7, out.data());
  EXPECT_EQ(out, (std::vector<double>{0.0, 1.0, -2.0, 4.0, 0.5, 0.0, 0.0}));

  EXPECT_THROW(make_record_motion(Record{}), std::invalid_argument);
}

TEST(StillMotion, IsZero) {
  const auto motion = make_still();
  EXPECT_EQ(motion->duration(), 0.0);
  for (const double t : {0.0, 1.0, 100.0}) {
    EXPECT_EQ(motion->acceleration(t), 0.0);
    EXPECT_EQ(motion->velocity(t), 0.0);
    EXPECT_EQ(motion->displacement(t), 0.0);
  }
  EXPECT_EQ(peak_acceleration(*motion, 0.01), 0.0);
}

TEST(ParsePulseShape, Names) {
  EXPECT_EQ(parse_pulse_shape("half_sine"), PulseShape::half_sine);
  EXPECT_EQ(parse_pulse_shape("one_sine"), PulseShape::one_sine);
  EXPECT_EQ(parse_pulse_shape("rectangular"), PulseShape::rectangular);
  EXPECT_EQ(parse_pulse_shape("square"), std::nullopt);
}

}  // namespace
}  // namespace caskdem::motion
