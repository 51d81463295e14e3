#pragma once
// Rigid-plastic sliding of a block on a floor with Coulomb friction (no rocking), the exact
// solution the DEM's sliding is compared with.
//
// Relative displacement u of the block on the floor (positive along +x), table acceleration
// a_g(t). While sliding with velocity sign s: u'' = -a_g(t) - s mu g. A block at rest
// relative to the floor sticks while |a_g| <= mu g and starts to slide, against the table's
// acceleration, when |a_g| exceeds mu g; a sliding block sticks again when u' returns to 0 and
// |a_g| <= mu g, otherwise it reverses. ("Two-way" sliding: both directions; Newmark 1965,
// Den Hartog 1931 for the harmonic steady state.)

#include <vector>

namespace caskdem::theory {

struct SlidingResponse {
  std::vector<double> time, displacement, velocity;  // sampled at output_interval
  double max_abs_displacement = 0.0;
  double final_displacement = 0.0;
  int slip_phases = 0;
  std::vector<double> slip_start_times;  // start of each slip phase (from sticking or a reversal)
};

// Exact piecewise-analytic solution for a harmonic table acceleration a_g(t) = amplitude sin(w t),
// block at rest at t = 0: within a slip phase u and u' are closed-form; the phase ends where
// u' = 0 (found by bracketing and root finding on the closed form, to 1e-13 s); sticking
// phases end where |a_g| = mu g.
SlidingResponse sliding_under_harmonic(double friction, double gravity, double amplitude, double circular_frequency,
                                       double duration, double output_interval);

}  // namespace caskdem::theory
