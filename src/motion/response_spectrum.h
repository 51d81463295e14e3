#pragma once
// Elastic response spectra of a record: the pseudo-spectral acceleration Sa(T, zeta) and the
// average spectral acceleration over a period range.
//
// The oscillator is u'' + 2 zeta w u' + w^2 u = -a_g(t), w = 2 pi / T, u relative to the
// ground. Between samples the record is taken as linear in time (as integrate_record's
// trapezoid rule takes it), and over such a step the response has an exact closed form
// (Nigam and Jennings 1969, "Calculation of response spectra from strong-motion earthquake
// records", BSSA 59(2), 909-922): for zeta < 1 and a step h from t_i to t_{i+1},
//
//   [u_{i+1}]       [u_i]       [a_i    ]
//   [v_{i+1}] = A * [v_i] + B * [a_{i+1}]
//
// with wd = w sqrt(1 - zeta^2), e = exp(-zeta w h), s = sin(wd h), c = cos(wd h),
// r = zeta / sqrt(1 - zeta^2), t1 = (2 zeta^2 - 1) / (w^2 h), t2 = 2 zeta / (w^3 h):
//
//   A11 = e (c + r s)                 A12 = e s / wd
//   A21 = -e w s / sqrt(1 - zeta^2)   A22 = e (c - r s)
//   B11 = e [(t1 + zeta/w) s/wd + (t2 + 1/w^2) c] - t2
//   B12 = -e [t1 s/wd + t2 c] - 1/w^2 + t2
//   B21 = e [(t1 + zeta/w)(c - r s) - (t2 + 1/w^2)(wd s + zeta w c)] + 1/(w^2 h)
//   B22 = -e [t1 (c - r s) - t2 (wd s + zeta w c)] - 1/(w^2 h)
//
// The recurrence is exact for the piecewise-linear record at any step, however long against
// T (even T/h < 10), which is its virtue over a time-stepping integrator: there is no
// stability limit and no truncation error. What a step can miss is a peak of u between the
// points where u is looked at; response_spectrum.cpp says how steps are divided for that,
// and how B is evaluated for w h << 1, where its closed form cancels.
//
// Sa = w^2 max|u| over the record and one damped period (at most 10 T) of free vibration
// after it (the ground returning linearly to rest over one time step): the peak of a long-period
// oscillator often comes after the shaking, and a damped free vibration reaches its largest
// |u| within half a damped period. As T -> 0 the oscillator follows the ground rigidly,
// u -> -a_g / w^2, so Sa tends to the PGA.
//
// SI inside: m/s^2, s; damping as a fraction of critical (0.05, not 5 %).

#include <vector>

#include "motion/record.h"

namespace caskdem::motion {

// The periods accepted. No structure has a period under 0.1 ms (Sa is the PGA well before
// it), and over 1000 s the free vibration after the record alone takes 1000 s / dt steps.
inline constexpr double kShortestSpectralPeriod = 1.0e-4;  // s
inline constexpr double kLongestSpectralPeriod = 1.0e3;    // s

struct SpectralPoint {
  double period = 0.0;               // s
  double damping_ratio = 0.0;        // fraction of critical
  double pseudo_acceleration = 0.0;  // w^2 max|u|, m/s^2
  double peak_displacement = 0.0;    // max|u|, m
};

// Each throws std::invalid_argument for a record with no samples or without a positive,
// finite time step, a period that is not finite or outside the range above, and a damping
// ratio that is not in [0, 1).
SpectralPoint spectral_response(const Record& record, double period, double damping_ratio = 0.05);
double spectral_acceleration(const Record& record, double period, double damping_ratio = 0.05);  // pseudo Sa, m/s^2
std::vector<double> spectral_accelerations(const Record& record, const std::vector<double>& periods,
                                           double damping_ratio = 0.05);

// A and B above for one step h at circular frequency w (rad/s), [a11 a12; a21 a22] and
// [b11 b12; b21 b22], u in m, v in m/s, a in m/s^2. Exposed so that its tests can check each
// coefficient against an independent integration. It checks nothing: spectral_response does.
struct StepRecurrence {
  double a11, a12, a21, a22;
  double b11, b12, b21, b22;
};
StepRecurrence nigam_jennings_step(double w, double damping_ratio, double h);

// The periods average_spectral_acceleration uses: `points` periods from period_low to
// period_high, equally spaced in log T (the ends exact). Throws std::invalid_argument unless
// 0 < period_low <= period_high are finite and points >= 2.
inline constexpr int kAverageSpectralAccelerationPoints = 10;
std::vector<double> average_spectral_acceleration_periods(double period_low, double period_high,
                                                          int points = kAverageSpectralAccelerationPoints);

// AvgSa (Baker and Cornell 2006, "Spectral shape, epsilon and record selection", EESD 35;
// Eads, Miranda and Lignos 2015, "Average spectral acceleration as an intensity measure for
// collapse risk assessment", EESD 44): the geometric mean of Sa at the periods above. The
// geometric mean, because Sa is close to lognormal and ln AvgSa is then the mean of ln Sa.
double average_spectral_acceleration(const Record& record, double period_low, double period_high,
                                     double damping_ratio = 0.05, int points = kAverageSpectralAccelerationPoints);

}  // namespace caskdem::motion
