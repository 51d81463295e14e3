// Response spectra by the exact piecewise-linear recurrence of Nigam and Jennings (1969,
// "Calculation of response spectra from strong-motion earthquake records", BSSA 59(2),
// 909-922). For u'' + 2 zeta w u' + w^2 u = -a_g(t), zeta < 1, and a_g linear over a step h,
//
//   [u_{i+1}; v_{i+1}] = A [u_i; v_i] + B [a_i; a_{i+1}],
//
// A and B as written in response_spectrum.h. They follow from splitting the response over the
// step into the particular solution for a linear load, u_p(tau) = -(a(tau) - 2 zeta a'/w) / w^2
// with a' = (a_{i+1} - a_i) / h, and the free vibration that starts from the remaining
// initial conditions (u_i - u_p(0), v_i - u_p'(0)), whose transfer over h is A.
//
// Why the steps are divided: the recurrence is exact at any step, also for T/h < 10 (the
// record is piecewise linear, so nothing is interpolated), but it gives u only at the step's
// ends and the peak of an oscillation at the period T can fall between them, missing up to
// 1 - cos(pi h / T) of it (19 % at h = T/5). Each record step is therefore cut into equal
// substeps of at most T / kPointsPerPeriod, the load still linear on each, so the miss is
// below 1 - cos(pi/100) = 4.9e-4. The number of substeps is capped at kMostSubsteps: for
// T well below the time step the oscillator follows the ground almost rigidly and its peak
// is at a sample, where the piecewise-linear load has its extremes.
//
// Why B has a second evaluation: its closed form subtracts terms 1/(w h)^3 larger than B
// itself (t2 against B11 ~ h^2/3), losing eps/(w h)^3 of it or more with damping: measured
// against the series below, 8e-11 at w h = 0.03 and 1e-6 at 1e-3 (T = 6000 h, a long period
// of a finely sampled record), zeta = 0.95. Below kSeriesBelow, B comes from the Taylor
// series of the same exact integrals. With x = [u; v], x' = M x + b a(t),
// M = [0 1; -w^2 -2 zeta w], b = [0; -1], and a linear over the step,
//   B[:, 1] = sum_k (k+1) M^k h^(k+1) / (k+2)! b,   B[:, 2] = sum_k M^k h^(k+1) / (k+2)! b
// (from x(h) = e^(M h) x(0) + int_0^h e^(M s) b a(h - s) ds); the terms fall as
// (3 w h)^k / (k+2)!, so ten of them reach rounding for w h < 0.03 (the two agree to 4e-14
// at w h = 0.1 undamped). A's closed form does not cancel and serves for every step.

#include "motion/response_spectrum.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/text.h"

namespace caskdem::motion {
namespace {

constexpr double kPointsPerPeriod = 100.0;
constexpr double kMostSubsteps = 1000.0;
constexpr double kSeriesBelow = 0.03;  // w h
constexpr int kSeriesTerms = 10;

void check_record(const Record& record) {
  if (record.acceleration.empty()) throw std::invalid_argument("a record with no samples has no response spectrum");
  if (!std::isfinite(record.time_step) || record.time_step <= 0.0)
    throw std::invalid_argument("the record's time step must be finite and above zero, not " +
                                number_text(record.time_step) + " s");
}

void check_period(double period) {
  if (!std::isfinite(period) || period <= 0.0)
    throw std::invalid_argument("the period must be finite and above zero, not " + number_text(period) + " s");
  if (period < kShortestSpectralPeriod)
    throw std::invalid_argument("the period of " + number_text(period) + " s is below " +
                                number_text(kShortestSpectralPeriod) + " s, the shortest a spectrum is computed at");
  if (period > kLongestSpectralPeriod)
    throw std::invalid_argument("the period of " + number_text(period) + " s is above " +
                                number_text(kLongestSpectralPeriod) + " s, the longest a spectrum is computed at");
}

void check_damping(double damping_ratio) {
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0))
    throw std::invalid_argument("the damping ratio must be from 0 to below 1 (a fraction of critical), not " +
                                number_text(damping_ratio));
}

}  // namespace

StepRecurrence nigam_jennings_step(double w, double zeta, double h) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double wd = w * root;
  const double e = std::exp(-zeta * w * h);
  const double s = std::sin(wd * h);
  const double c = std::cos(wd * h);
  const double r = zeta / root;
  const double w2 = w * w;
  const double t1 = (2.0 * zeta * zeta - 1.0) / (w2 * h);
  const double t2 = 2.0 * zeta / (w2 * w * h);
  const double velocity_phase = c - r * s;
  const double velocity_rate = wd * s + zeta * w * c;
  StepRecurrence k{};
  k.a11 = e * (c + r * s);
  k.a12 = e * s / wd;
  k.a21 = -e * w * s / root;
  k.a22 = e * velocity_phase;
  if (w * h < kSeriesBelow) {
    double p_u = 0.0, p_v = -h;  // M^k h^(k+1) b, from k = 0
    double factorial = 2.0;      // (k+2)!
    k.b11 = k.b12 = k.b21 = k.b22 = 0.0;
    for (int j = 0; j < kSeriesTerms; ++j) {
      k.b11 += (j + 1) * p_u / factorial;
      k.b21 += (j + 1) * p_v / factorial;
      k.b12 += p_u / factorial;
      k.b22 += p_v / factorial;
      const double next_u = h * p_v;
      p_v = h * (-w2 * p_u - 2.0 * zeta * w * p_v);
      p_u = next_u;
      factorial *= j + 3;
    }
    return k;
  }
  k.b11 = e * ((t1 + zeta / w) * s / wd + (t2 + 1.0 / w2) * c) - t2;
  k.b12 = -e * (t1 * s / wd + t2 * c) - 1.0 / w2 + t2;
  k.b21 = e * ((t1 + zeta / w) * velocity_phase - (t2 + 1.0 / w2) * velocity_rate) + 1.0 / (w2 * h);
  k.b22 = -e * (t1 * velocity_phase - t2 * velocity_rate) - 1.0 / (w2 * h);
  return k;
}

SpectralPoint spectral_response(const Record& record, double period, double damping_ratio) {
  check_record(record);
  check_period(period);
  check_damping(damping_ratio);
  const double w = 2.0 * std::numbers::pi / period;
  const double dt = record.time_step;
  const double substeps = std::clamp(std::ceil(kPointsPerPeriod * dt / period), 1.0, kMostSubsteps);
  const int n_sub = static_cast<int>(substeps);
  const StepRecurrence k = nigam_jennings_step(w, damping_ratio, dt / substeps);

  double u = 0.0, v = 0.0, peak = 0.0;
  const auto advance = [&](double a_begin, double a_end) {
    double a0 = a_begin;
    for (int j = 1; j <= n_sub; ++j) {
      // Points on the same line as the record step, so the load stays the record's.
      const double a1 = j == n_sub ? a_end : a_begin + (a_end - a_begin) * (static_cast<double>(j) / substeps);
      const double u1 = k.a11 * u + k.a12 * v + k.b11 * a0 + k.b12 * a1;
      const double v1 = k.a21 * u + k.a22 * v + k.b21 * a0 + k.b22 * a1;
      u = u1;
      v = v1;
      peak = std::max(peak, std::abs(u));
      a0 = a1;
    }
  };
  const std::vector<double>& a = record.acceleration;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) advance(a[i], a[i + 1]);
  advance(a.back(), 0.0);

  // A damped free vibration's |u| peaks within half a damped period T_d; near critical
  // damping T_d grows without bound, but by 10 T the envelope exp(-zeta w t) is below
  // exp(-62) and no later peak can matter.
  const double damped_period = period / std::sqrt(1.0 - damping_ratio * damping_ratio);
  const double free_steps = std::ceil(std::min(damped_period, 10.0 * period) / dt);
  for (double j = 0.0; j < free_steps; j += 1.0) advance(0.0, 0.0);

  SpectralPoint point;
  point.period = period;
  point.damping_ratio = damping_ratio;
  point.peak_displacement = peak;
  point.pseudo_acceleration = w * w * peak;
  return point;
}

double spectral_acceleration(const Record& record, double period, double damping_ratio) {
  return spectral_response(record, period, damping_ratio).pseudo_acceleration;
}

std::vector<double> spectral_accelerations(const Record& record, const std::vector<double>& periods,
                                           double damping_ratio) {
  std::vector<double> sa;
  sa.reserve(periods.size());
  for (const double period : periods) sa.push_back(spectral_acceleration(record, period, damping_ratio));
  return sa;
}

std::vector<double> average_spectral_acceleration_periods(double period_low, double period_high, int points) {
  if (!std::isfinite(period_low) || !std::isfinite(period_high) || period_low <= 0.0 || period_low > period_high)
    throw std::invalid_argument("the period range must have 0 < low <= high, both finite; got " +
                                number_text(period_low) + " s to " + number_text(period_high) + " s");
  if (points < 2)
    throw std::invalid_argument("the average spectral acceleration needs at least 2 periods, not " +
                                std::to_string(points));
  std::vector<double> periods(static_cast<std::size_t>(points));
  const double log_ratio = std::log(period_high / period_low);
  for (int j = 0; j < points; ++j)
    periods[static_cast<std::size_t>(j)] = period_low * std::exp(log_ratio * j / (points - 1));
  periods.front() = period_low;
  periods.back() = period_high;
  return periods;
}

double average_spectral_acceleration(const Record& record, double period_low, double period_high,
                                     double damping_ratio, int points) {
  const std::vector<double> sa =
      spectral_accelerations(record, average_spectral_acceleration_periods(period_low, period_high, points),
                             damping_ratio);
  // The mean of logarithms, not a product, so that ten small Sa cannot underflow.
  double sum_log = 0.0;
  for (const double x : sa) sum_log += std::log(x);
  return std::exp(sum_log / static_cast<double>(sa.size()));
}

}  // namespace caskdem::motion
