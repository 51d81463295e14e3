// Response spectra against closed forms of the single-degree-of-freedom oscillator (steady
// harmonic response, step load, rectangular and half-sine pulses; Chopra, Dynamics of
// Structures, 4th ed., sections 3.2, 4.3, 4.7 and 4.8), against an independent RK4
// integration, against the PGA in the rigid limit, and for linearity, AvgSa and bad arguments.
//
// Peaks are looked at every T/100 or finer (response_spectrum.cpp), so a peak between two
// looks can be missed by up to 1 - cos(pi/100) = 4.9e-4 of the oscillating part: that is the
// floor of the tolerances below unless a test says otherwise.

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "motion/record.h"
#include "motion/response_spectrum.h"

namespace caskdem::motion {
namespace {

using std::numbers::pi;

Record sampled(double dt, double duration, auto a_of_t) {
  Record record;
  record.source = "test";
  record.time_step = dt;
  const auto n = static_cast<std::size_t>(std::llround(duration / dt)) + 1;
  for (std::size_t k = 0; k < n; ++k) record.acceleration.push_back(a_of_t(static_cast<double>(k) * dt));
  return record;
}

Record elcentro() { return read_record(std::filesystem::path(CASKDEM_SHARED_DIR) / "motions" / "elcentro1940_ns_RSN6.AT2"); }

double relative_error(double value, double exact) { return (value - exact) / exact; }

std::string text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2e", x);
  return buffer;
}

// u'' + 2 zeta w u' + w^2 u = -a(t) by classical RK4 on the continuous a(t), step h; max|u|
// at the steps. Independent of the recurrence: used to check a closed form before trusting it.
double rk4_peak(double w, double zeta, double duration, double h, auto a_of_t) {
  const auto f = [&](double t, double u, double v, double& du, double& dv) {
    du = v;
    dv = -w * w * u - 2.0 * zeta * w * v - a_of_t(t);
  };
  double u = 0.0, v = 0.0, peak = 0.0;
  const auto steps = static_cast<long>(std::ceil(duration / h));
  for (long i = 0; i < steps; ++i) {
    const double t = static_cast<double>(i) * h;
    double du1, dv1, du2, dv2, du3, dv3, du4, dv4;
    f(t, u, v, du1, dv1);
    f(t + h / 2, u + h / 2 * du1, v + h / 2 * dv1, du2, dv2);
    f(t + h / 2, u + h / 2 * du2, v + h / 2 * dv2, du3, dv3);
    f(t + h, u + h * du3, v + h * dv3, du4, dv4);
    u += h / 6 * (du1 + 2 * du2 + 2 * du3 + du4);
    v += h / 6 * (dv1 + 2 * dv2 + 2 * dv3 + dv4);
    peak = std::max(peak, std::abs(u));
  }
  return peak;
}

// Each coefficient of A and B against RK4 over the one step (4000 substeps, error below 1e-12
// of the coefficient's scale), on both of B's evaluations (series for w h < 0.03, closed form
// above) and at steps up to 1.6 periods long: the recurrence is exact at any step.
TEST(ResponseSpectrum, RecurrenceMatchesAnIndependentIntegrationOfOneStep) {
  const double w = 5.0;
  double largest = 0.0;
  for (const double zeta : {0.0, 0.05, 0.5, 0.95}) {
    for (const double wh : {0.003, 0.02, 0.04, 0.5, 2.0, 10.0}) {
      const double h = wh / w;
      const auto step = [&](double u0, double v0, double a0, double a1) {
        const auto a_of_t = [&](double t) { return a0 + (a1 - a0) * t / h; };
        const int n = 4000;
        const double dt = h / n;
        const auto f = [&](double t, double u, double v) { return -w * w * u - 2.0 * zeta * w * v - a_of_t(t); };
        double u = u0, v = v0;
        for (int i = 0; i < n; ++i) {
          const double t = i * dt;
          const double du1 = v, dv1 = f(t, u, v);
          const double du2 = v + dt / 2 * dv1, dv2 = f(t + dt / 2, u + dt / 2 * du1, v + dt / 2 * dv1);
          const double du3 = v + dt / 2 * dv2, dv3 = f(t + dt / 2, u + dt / 2 * du2, v + dt / 2 * dv2);
          const double du4 = v + dt * dv3, dv4 = f(t + dt, u + dt * du3, v + dt * dv3);
          u += dt / 6 * (du1 + 2 * du2 + 2 * du3 + du4);
          v += dt / 6 * (dv1 + 2 * dv2 + 2 * dv3 + dv4);
        }
        return std::pair{u, v};
      };
      const StepRecurrence k = nigam_jennings_step(w, zeta, h);
      // Scales of u and v over the step from a unit state or load, so that small coefficients
      // (B ~ h^2 for w h << 1) are held to the same relative precision as large ones.
      const double u_per_v = h / (1.0 + wh), u_per_a = h * h / (1.0 + wh * wh), v_per_a = h / (1.0 + wh);
      const auto [a11, a21] = step(1.0, 0.0, 0.0, 0.0);
      const auto [a12, a22] = step(0.0, 1.0, 0.0, 0.0);
      const auto [b11, b21] = step(0.0, 0.0, 1.0, 0.0);
      const auto [b12, b22] = step(0.0, 0.0, 0.0, 1.0);
      const std::string where = "zeta " + std::to_string(zeta) + ", w h " + std::to_string(wh);
      const auto expect = [&](double coefficient, double integrated, double scale) {
        const double difference = std::abs(coefficient - integrated) / scale;
        largest = std::max(largest, difference);
        EXPECT_LT(difference, 1e-10) << where;
      };
      expect(k.a11, a11, 1.0);
      expect(k.a21, a21, 1.0 / u_per_v);
      expect(k.a12, a12, u_per_v);
      expect(k.a22, a22, 1.0);
      expect(k.b11, b11, u_per_a);
      expect(k.b12, b12, u_per_a);
      expect(k.b21, b21, v_per_a);
      expect(k.b22, b22, v_per_a);
    }
  }
  RecordProperty("largest_scaled_difference", text(largest));
}

// Steady state of a_g = A sin(w_g t): max|u| = (A/w^2) / sqrt((1 - r^2)^2 + (2 zeta r)^2),
// r = w_g/w (Chopra eq. 3.2.11 with p0/k = A/w^2). Started or stopped abruptly, the harmonic
// leaves a free vibration as large as r times the steady response (3x the steady peak at
// r = 2), which would be the maximum; sin^2 envelopes over 20 periods of both the input and
// the oscillator, in and out, excite almost none, and 20/(zeta w) of full amplitude between
// them lets the resonant case reach its steady amplitude within exp(-20).
double sine_envelope(double t, double ramp, double hold) {
  if (t < ramp) return std::pow(std::sin(0.5 * pi * t / ramp), 2);
  if (t < ramp + hold) return 1.0;
  return std::pow(std::cos(0.5 * pi * std::min(t - ramp - hold, ramp) / ramp), 2);
}

TEST(ResponseSpectrum, SteadyHarmonicResponseAwayFromAndAtResonance) {
  const double period = 1.0, zeta = 0.05, amplitude = 2.0, w = 2.0 * pi / period;
  for (const double r : {0.5, 1.0, 2.0}) {
    const double wg = r * w, input_period = 2.0 * pi / wg;
    const double ramp = 20.0 * std::max(period, input_period), hold = 20.0 / (zeta * w);
    const Record record = sampled(std::min(period, input_period) / 200.0, 2.0 * ramp + hold, [&](double t) {
      return amplitude * sine_envelope(t, ramp, hold) * std::sin(wg * t);
    });
    const double exact = amplitude / (w * w) / std::hypot(1.0 - r * r, 2.0 * zeta * r);
    const SpectralPoint point = spectral_response(record, period, zeta);
    const double error = relative_error(point.peak_displacement, exact);
    RecordProperty("relative_error_r_" + std::to_string(r), text(error));
    // Linear interpolation of the samples lowers the input's amplitude by (w_g dt)^2/12 =
    // 8e-5 at 200 samples per period; the sampled peak misses at most 4.9e-4.
    EXPECT_NEAR(error, 0.0, 1e-3) << "r = " << r;
    EXPECT_DOUBLE_EQ(point.pseudo_acceleration, w * w * point.peak_displacement);
  }
}

// The free vibration after the record counts. Undamped, r = 2, the steady response is
// u = U sin(w_g t), U = A / (3 w^2); stopped where u = 0 and u' = U w_g, it swings on with
// amplitude U w_g / w = 2 U, twice the largest |u| during the record.
TEST(ResponseSpectrum, ThePeakAfterTheRecordEndsIsCounted) {
  const double period = 1.0, amplitude = 2.0, w = 2.0 * pi / period, wg = 2.0 * w, ramp = 20.0;
  const Record record = sampled(period / 400.0, ramp + 10.0, [&](double t) {
    return amplitude * sine_envelope(t, ramp, 1e9) * std::sin(wg * t);
  });
  const double steady = amplitude / (3.0 * w * w);
  const double error = relative_error(spectral_response(record, period, 0.0).peak_displacement, 2.0 * steady);
  RecordProperty("relative_error", text(error));
  EXPECT_NEAR(error, 0.0, 1e-3);
}

// A constant a0 from rest: u = -(a0/w^2)(1 - exp(-zeta w t)(cos wd t + r sin wd t)), whose
// first peak, at t = pi/wd, is (a0/w^2)(1 + exp(-zeta pi / sqrt(1 - zeta^2))) (Chopra
// section 4.3). Returning to rest at the end of the record starts a free vibration no
// larger than a0/w^2, so the first peak is the maximum. This exercises every damped term of
// B; undamped, the peak falls on a look (T/2 = 50 substeps) and is met to rounding.
TEST(ResponseSpectrum, StepLoadOvershootsByTheDampedFactor) {
  const double period = 0.8, a0 = 3.0, w = 2.0 * pi / period;
  const Record record = sampled(period / 50.0, 20.0 * period, [&](double) { return a0; });
  for (const double zeta : {0.0, 0.05, 0.2, 0.5, 0.9}) {
    const double exact = a0 / (w * w) * (1.0 + std::exp(-zeta * pi / std::sqrt(1.0 - zeta * zeta)));
    const double error = relative_error(spectral_response(record, period, zeta).peak_displacement, exact);
    RecordProperty("relative_error_zeta_" + std::to_string(zeta), text(error));
    EXPECT_NEAR(error, 0.0, zeta == 0.0 ? 1e-9 : 5e-4) << "zeta = " << zeta;
  }
}

// Rectangular pulse A for td, undamped: max|u| = (A/w^2) 2 sin(pi td/T) for td/T < 1/2 (in
// the free vibration after it) and 2 A/w^2 for td/T >= 1/2 (Chopra section 4.7). The leading
// edge is exact (the record starts at A from rest); the trailing one is a ramp over one
// sample, a pulse longer by dt/2 in effect: dt = td/2000 makes that 2.5e-4 of td, which moves
// 2 sin(pi td/T) by at most pi (dt/2)/T / tan(pi td/T), below 3e-4 for td/T >= 0.1.
TEST(ResponseSpectrum, RectangularPulseUndamped) {
  const double amplitude = 1.5, period = 0.5, w = 2.0 * pi / period;
  for (const double ratio : {0.1, 0.25, 0.4, 0.5, 0.75, 1.5}) {
    const double td = ratio * period, dt = td / 2000.0;
    const Record record = sampled(dt, td + 2.0 * period, [&](double t) { return t <= td + dt / 4 ? amplitude : 0.0; });
    const double exact = amplitude / (w * w) * (ratio < 0.5 ? 2.0 * std::sin(pi * ratio) : 2.0);
    const double error = relative_error(spectral_response(record, period, 0.0).peak_displacement, exact);
    RecordProperty("relative_error_td_T_" + std::to_string(ratio), text(error));
    EXPECT_NEAR(error, 0.0, 1e-3) << "td/T = " << ratio;
  }
}

// Half-cycle sine pulse A sin(pi t/td) for td, undamped, td/T < 1/2: the maximum is in the
// free vibration after the pulse, amplitude (A/w^2) 4 (td/T) cos(pi td/T) / (1 - 4 (td/T)^2)
// (Chopra eq. 4.8.4 and the amplitude below it, with u_st = A/w^2). The formula is first
// checked against RK4 on the continuous pulse, so a slip in it cannot pass as agreement.
TEST(ResponseSpectrum, HalfSinePulseUndampedMatchesChopraAndRk4) {
  const double amplitude = 1.0, period = 0.4, w = 2.0 * pi / period;
  for (const double ratio : {0.1, 0.2, 0.3, 0.4}) {
    const double td = ratio * period;
    const auto pulse = [&](double t) { return t <= td ? amplitude * std::sin(pi * t / td) : 0.0; };
    const double exact = amplitude / (w * w) * 4.0 * ratio * std::cos(pi * ratio) / (1.0 - 4.0 * ratio * ratio);
    const double rk4 = rk4_peak(w, 0.0, td + 2.0 * period, period / 4000.0, pulse);
    RecordProperty("rk4_relative_error_td_T_" + std::to_string(ratio), text(relative_error(rk4, exact)));
    EXPECT_NEAR(relative_error(rk4, exact), 0.0, 1e-6) << "closed form vs RK4, td/T = " << ratio;

    // 2000 samples over the pulse: linear interpolation changes its area by (pi/2000)^2/12.
    const Record record = sampled(td / 2000.0, td + 2.0 * period, pulse);
    const double error = relative_error(spectral_response(record, period, 0.0).peak_displacement, exact);
    RecordProperty("relative_error_td_T_" + std::to_string(ratio), text(error));
    EXPECT_NEAR(error, 0.0, 5e-4) << "td/T = " << ratio;
  }
}

// A stiff oscillator moves with the ground, u -> -a_g/w^2, so Sa -> PGA. At T = dt = 0.01 s
// it still responds a little dynamically to the record's content near 100 Hz.
TEST(ResponseSpectrum, ShortPeriodsTendToThePga) {
  const Record record = elcentro();
  const double pga = peak_ground_acceleration(record);
  const double error_10ms = relative_error(spectral_acceleration(record, 0.01), pga);
  const double error_20ms = relative_error(spectral_acceleration(record, 0.02), pga);
  const double error_1ms = relative_error(spectral_acceleration(record, 0.001), pga);
  RecordProperty("relative_error_1ms", text(error_1ms));
  RecordProperty("relative_error_10ms", text(error_10ms));
  RecordProperty("relative_error_20ms", text(error_20ms));
  EXPECT_NEAR(error_1ms, 0.0, 1e-3);
  EXPECT_NEAR(error_10ms, 0.0, 0.01);
  EXPECT_NEAR(error_20ms, 0.0, 0.02);
  // Not flat everywhere: a spectrum that returned the PGA would pass the lines above.
  EXPECT_GT(spectral_acceleration(record, 0.3), 1.5 * pga);
}

// Every operation is linear in the record: doubling is exact in floating point, tripling
// (and reversing the sign) within rounding.
TEST(ResponseSpectrum, LinearInTheRecord) {
  const Record record = elcentro();
  for (const double period : {0.05, 0.5, 2.0}) {
    const double sa = spectral_acceleration(record, period);
    EXPECT_EQ(spectral_acceleration(scaled(record, 2.0), period), 2.0 * sa);
    EXPECT_NEAR(spectral_acceleration(scaled(record, -3.0), period) / (3.0 * sa), 1.0, 1e-12);
  }
}

TEST(ResponseSpectrum, AverageIsTheGeometricMeanOfTheLogSpacedPeriods) {
  const Record record = elcentro();
  const std::vector<double> periods = average_spectral_acceleration_periods(0.2, 3.0, 10);
  ASSERT_EQ(periods.size(), 10u);
  EXPECT_EQ(periods.front(), 0.2);
  EXPECT_EQ(periods.back(), 3.0);
  for (std::size_t j = 1; j < periods.size(); ++j)
    EXPECT_NEAR(periods[j] / periods[j - 1], std::pow(15.0, 1.0 / 9.0), 1e-12);
  double product = 1.0;
  for (const double sa : spectral_accelerations(record, periods, 0.05)) product *= sa;
  const double avg = average_spectral_acceleration(record, 0.2, 3.0, 0.05, 10);
  EXPECT_NEAR(avg / std::pow(product, 0.1), 1.0, 1e-12);
  EXPECT_NEAR(average_spectral_acceleration(record, 0.5, 0.5), spectral_acceleration(record, 0.5), 1e-12);
}

TEST(ResponseSpectrum, BadArgumentsAreRefused) {
  const Record record = sampled(0.01, 1.0, [](double t) { return std::sin(10.0 * t); });
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  for (const double period : {0.0, -1.0, nan, inf, 0.99e-4, 1000.1})
    EXPECT_THROW(spectral_acceleration(record, period), std::invalid_argument) << period;
  EXPECT_NO_THROW(spectral_acceleration(record, kShortestSpectralPeriod));
  EXPECT_NO_THROW(spectral_acceleration(record, kLongestSpectralPeriod));
  for (const double zeta : {-0.01, 1.0, 1.5, nan})
    EXPECT_THROW(spectral_acceleration(record, 1.0, zeta), std::invalid_argument) << zeta;
  EXPECT_NO_THROW(spectral_acceleration(record, 1.0, 0.999));
  EXPECT_THROW(average_spectral_acceleration(record, 2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(average_spectral_acceleration(record, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(average_spectral_acceleration(record, 0.5, nan), std::invalid_argument);
  EXPECT_THROW(average_spectral_acceleration(record, 0.5, 1.0, 0.05, 1), std::invalid_argument);
  EXPECT_THROW(spectral_acceleration(Record{}, 1.0), std::invalid_argument);
  Record no_step = record;
  no_step.time_step = 0.0;
  EXPECT_THROW(spectral_acceleration(no_step, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace caskdem::motion
