#pragma once
// Synthetic accelerograms: broadband ground motions that need no file, for examples and
// built-in ensembles. A stationary Gaussian process with the Kanai-Tajimi spectrum of a
// soil layer, high-passed by the Clough-Penzien filter so the ground ends at rest, is
// sampled by the spectral representation method (Shinozuka & Deodatis 1991,
// Appl. Mech. Rev. 44(4)) and shaped by a Jennings envelope (Jennings, Housner & Tsai 1968):
//
//   S(w) = S0 (wg^4 + 4 zg^2 wg^2 w^2) / ((wg^2 - w^2)^2 + 4 zg^2 wg^2 w^2)      Kanai-Tajimi
//              * w^4 / ((wf^2 - w^2)^2 + 4 zf^2 wf^2 w^2)                         Clough-Penzien
//   a(t) = e(t) sum_k sqrt(2 S(w_k) dw) cos(w_k t + phi_k),   w_k = (k + 1/2) dw
//   e(t) = (t / t1)^2 before t1, 1 until t2, exp(-c (t - t2)) after
//
// The phases phi_k are uniform, drawn from Philox keyed by the seed: one seed, one record,
// on every machine. The record is then scaled to the requested PGA.

#include <cstdint>

#include "motion/record.h"

namespace caskdem::motion {

struct SyntheticMotion {
  std::uint64_t seed = 1;
  double duration = 20.0;             // s
  double time_step = 0.005;           // s
  double dominant_frequency = 2.5;    // wg / 2 pi, Hz (a firm soil: 2.5 Hz)
  double ground_damping = 0.6;        // zg
  double high_pass_frequency = 0.25;  // wf / 2 pi, Hz
  double high_pass_damping = 0.6;     // zf
  double rise_time = 2.0;             // t1, s
  double strong_duration = 6.0;       // t2 - t1, s
  double decay = 0.4;                 // c, 1/s
  double pga = 1.0;                   // m/s^2 of the result
};

// Throws std::invalid_argument when a parameter is out of range.
Record synthetic_record(const SyntheticMotion& spec);

// The one-sided spectral density S(w) above with S0 = 1 (for tests and documentation).
double synthetic_spectral_shape(const SyntheticMotion& spec, double circular_frequency);

}  // namespace caskdem::motion
