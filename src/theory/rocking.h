#pragma once
// Rigid-block rocking theory (Housner 1963), the "theoretical solution" the DEM is
// compared with, and the closed forms the tests use as oracles. Notation as in
// ../shared/notes/rocking-theory.md, with caskdem's sign convention:
//
//   theta > 0 is counter-clockwise: the block pivots on its -x corner and leans toward -x.
//   A positive table acceleration a_g (along +x) pushes the block's inertia toward -x,
//   so it drives theta up:
//     I_O theta'' = -m g R sin(alpha sgn(theta) - theta) + m a_g R cos(alpha sgn(theta) - theta)
//   (the note writes the opposite sign for a_g; its results are symmetric in it).
//   At theta = 0 the block impacts and changes pivot: theta' -> e theta'.
//   From rest it starts to rock when |a_g| > g tan(alpha), on the side a_g drives it to.

#include <functional>
#include <vector>

namespace caskdem::theory {

// A rigid block in planar rocking about its two base pivots.
struct RigidBlock {
  double half_width = 0.0;                    // b: horizontal distance from the centre of mass to a pivot, m
  double centre_height = 0.0;                 // h: height of the centre of mass above the pivots, m
  double inertia_about_pivot_per_mass = 0.0;  // I_O / m, m^2
  double gravity = 9.80665;

  double size() const;                  // R = sqrt(b^2 + h^2)
  double slenderness() const;           // alpha = atan(b / h)
  double frequency_parameter() const;   // p = sqrt(g R / (I_O / m))

  static RigidBlock rectangle(double half_width, double half_height);  // I_O/m = (4/3) R^2
  static RigidBlock cylinder(double radius, double half_height);       // I_O/m = 5 r^2/4 + 4 h^2/3
};

// Housner's coefficient from angular momentum about the new pivot: e = 1 - 2 b^2 / (I_O/m).
double housner_restitution(const RigidBlock& block);

// Free rocking from rest at theta0 (0 < theta0 < alpha), no impact loss within the quarter cycles:
// the period of a full cycle (four quarter cycles). Both throw std::domain_error outside that range.
// The linearised form replaces sin(alpha - theta) by alpha - theta (Housner 1963): it is the
// small-alpha limit of the exact one; the difference goes as alpha^2 (linearised / exact - 1 =
// -7.3e-5 at alpha = 0.05, -7.3e-3 at alpha = 0.5, theta0 = alpha / 2; tests/theory/test_rocking_free.cpp).
double free_rocking_period_linearised(const RigidBlock& block, double theta0);  // (4/p) acosh(1/(1 - theta0/alpha))
double free_rocking_period_exact(const RigidBlock& block, double theta0);       // energy integral of the nonlinear equation

// Amplitude after one impact with restitution e, from energy before and after the impact:
// cos(alpha - theta_{n+1}) = cos(alpha) + e^2 [cos(alpha - theta_n) - cos(alpha)].
// Takes and returns magnitudes; throws std::domain_error unless 0 <= |theta_n| <= alpha and 0 <= e <= 1.
double amplitude_after_impact(const RigidBlock& block, double restitution, double theta_n);

struct RockingOptions {
  double restitution = -1.0;        // e; negative: Housner's value
  double duration = 0.0;            // s
  double initial_rotation = 0.0;    // rad
  double initial_rate = 0.0;        // rad/s
  double tip_over_angle = 1.5707963267948966;  // |theta| at which the block counts as overturned and the run stops
  double output_interval = 0.0;     // s; > 0 records (t, theta, omega) at that interval
  // s; > 0 caps the integrator's step and the step of the scan for the start of rocking from
  // rest, so that no feature of a_g shorter than it is stepped over; <= 0: 1e-3 s.
  double max_step = 0.0;
};

struct RockingResponse {
  double max_abs_rotation = 0.0;
  bool tipped_over = false;
  double tip_over_time = 0.0;
  int impacts = 0;
  std::vector<double> impact_times;
  std::vector<double> impact_rates_before;  // |theta'| just before each impact
  std::vector<double> uplift_times;          // each start of rocking from rest (|a_g| first above g tan alpha)
  std::vector<double> peak_times, peak_rotations;  // each local maximum of |theta| (theta' = 0), |theta| there
  std::vector<double> time, rotation, rate;  // when output_interval > 0
};

// Event-driven integration of the nonlinear equation above (adaptive Runge-Kutta with
// dense output; impacts and starts located to 1e-12 s), for any table acceleration.
// The block starts at rest on its base when initial_rotation and initial_rate are both 0. It
// returns to rest after an impact that leaves |theta'| below 1e-8 p (the next excursion would
// reach about 1e-16 / sin(alpha) rad): with e < 1 impacts otherwise accumulate without end.
// Limitations: a_g is only sampled by the integrator; its jumps and kinks (ends of pulses) are
// crossed by the step-size control at its tolerance (1e-12 per step), not located (tests: kinks
// cost < 1e-10 s of impact time). At rest, a_g is scanned every max_step, so an exceedance of
// g tan(alpha) shorter than that can be missed; while rocking, events are looked for at 8 points
// per step (steps <= max_step), so a turn of theta' and back within an eighth of a step can be
// missed (a short excursion from theta = 0 is not: the start of each segment is refined).
RockingResponse simulate_rocking(const RigidBlock& block, const std::function<double(double)>& table_acceleration,
                                 const RockingOptions& options);

// Overturning thresholds of pulses, beta = a_p / (g tan alpha), block at rest when the pulse
// starts (linearised closed forms; the nonlinear threshold differs by O(alpha^2), e.g. +0.92 % for
// the half-sine at alpha = 0.5, Omega = 4; tests/theory/test_rocking_pulses.cpp):
double rectangular_pulse_overturning_beta(const RigidBlock& block, double pulse_duration);  // 1 / (1 - exp(-p t1))
// Half-sine pulse of circular frequency w_p, Omega = w_p / p, overturning in the first excursion:
// beta [cos psi + exp(-(pi - psi)/Omega)] = Omega with sin psi = 1/beta. psi = w_p t_start is the
// phase at which the rising half of the pulse first reaches g tan alpha, so psi = asin(1/beta) in
// (0, pi/2]; the root beta > 1 is unique (the left side minus Omega increases with beta).
double half_sine_overturning_beta(double omega_ratio);

// The smallest beta in [beta_low, beta_high] at which the block overturns under a pulse
// found by bisection with simulate_rocking (the nonlinear equation, for comparison).
// The block starts at rest, Housner's restitution, the run lasts `duration`; tolerance is the
// final width of the bracket in beta, and the upper end (a beta that overturns) is returned.
// Returns beta_low if it already overturns; throws std::domain_error if beta_high does not.
// Bisection assumes one transition in the bracket; where safe bands exist (Zhang & Makris
// 2001) it finds a transition, not necessarily the smallest.
double overturning_beta_by_simulation(const RigidBlock& block,
                                      const std::function<double(double beta, double t)>& pulse_acceleration,
                                      double duration, double beta_low, double beta_high, double tolerance);

}  // namespace caskdem::theory
