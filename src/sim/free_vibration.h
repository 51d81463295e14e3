#pragma once
// Free-vibration analysis and damping calibration, as in the source paper.
//
// The cask is released at rest from a tilt theta0 = r alpha about its pivot corner and rocks
// freely. Its rocking restitution coefficient (the paper's eq. 1) is the ratio of successive
// peak angular velocities, each taken in one rocking half-cycle just before its impact:
//   e = mean over k = 1..R of |omega|_peak(k) / |omega|_peak(k-1).
// `calibrate` finds the damping ratio h whose free vibration gives a target e, by bracketed
// root finding (TOMS 748, Alefeld, Potra & Shi 1995; Boost.Math) on log h.
//
// What e a geometry can reach is bounded: with growing h the heel's spring-dashpot becomes
// a perfectly plastic rigid impact and e falls to Housner's 1 - 2 b^2 m / I_O; with h -> 0 the
// springs exchange energy elastically and e rises to the undamped limit (near 1 for slender
// casks, lower for stocky ones). A target outside the range is refused with the range.

#include <vector>

#include "casefile/case_file.h"
#include "kernels/model.h"
#include "model/build.h"

namespace caskdem {

struct FreeVibrationResult {
  double restitution = 0.0;  // mean of the successive peak ratios; 0 when too few impacts
  bool enough_impacts = false;
  std::vector<double> peaks;  // |omega| peaks of the half-cycles, rad/s
  double initial_tilt = 0.0;  // rad
  double duration = 0.0;      // s simulated
};

// The mean of the first `ratios` successive ratios of half-cycle peaks (0 if too few peaks).
double restitution_from_peaks(const std::vector<double>& peaks, int ratios);

// Long enough for ratios + 1 impacts of free rocking from theta0 (Housner's half-cycles, with margin).
double free_vibration_duration(const Model& model, const RealisationParameters& parameters, const FreeVibrationSpec& spec);

FreeVibrationResult free_vibration(const Model& model, const RealisationParameters& parameters, const FreeVibrationSpec& spec);

struct CalibrationResult {
  double damping_ratio = 0.0;
  double restitution = 0.0;     // reached
  double target = 0.0;
  int evaluations = 0;
  double lowest_restitution = 0.0;   // at the largest damping ratio tried
  double highest_restitution = 0.0;  // at the smallest
  double smallest_damping = 0.0;
  double largest_damping = 0.0;      // stability limit of the explicit scheme, or 1
};

// Throws InputError (naming the case file) when the target is out of reach.
CalibrationResult calibrate_damping(const Case& c, double target);

// The largest damping ratio the explicit scheme stays stable with, at this time step.
double largest_stable_damping_ratio(const Model& model, const ModelSpec& spec, const RealisationParameters& parameters);

}  // namespace caskdem
