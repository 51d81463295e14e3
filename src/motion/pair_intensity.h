#pragma once
// Intensity measures of a horizontal pair that do not depend on how the sensors were turned.
//
// Geometric mean: sqrt(PGA_1 PGA_2) (and of PGV), the as-recorded pair's.
// RotDnn (Boore 2010, "Orientation-independent, nongeometric-mean measures of seismic
// intensity from two horizontal components of motion", BSSA 100(4), 1830-1835): the pair
// rotated to each angle theta in [0, 180) degrees,
//   a_theta(t) = a_1(t) cos theta + a_2(t) sin theta,
// the peak max_t |a_theta(t)| taken at each angle, and the nn-th percentile of those peaks
// over the angles: RotD50 the median, RotD100 the largest (the peak in the strongest
// direction). Angles step by 1 degree as in Boore's definition; the median of the 180 peaks
// is the mean of the 90th and 91st in order. PGV the same on the velocities, which rotate as
// the accelerations do (integration and its baseline correction are linear).

#include <vector>

#include "motion/record.h"

namespace caskdem::motion {

struct PairIntensity {
  double pga_geometric_mean = 0.0;  // m/s^2
  double pgv_geometric_mean = 0.0;  // m/s
  double pga_rotd50 = 0.0, pga_rotd100 = 0.0;  // m/s^2
  double pgv_rotd50 = 0.0, pgv_rotd100 = 0.0;  // m/s
  double pga_rotd100_angle = 0.0;   // degrees from H1 towards H2, of the strongest direction
};

// Peaks max_t |x cos theta + y sin theta| at theta = 0, 1, ..., 179 degrees. Throws
// std::invalid_argument unless x and y have the same length.
std::vector<double> rotated_peaks(const std::vector<double>& x, const std::vector<double>& y);
// The percentile (0 to 100) of the peaks over the angles, interpolated between ranks at
// percentile / 100 x (count - 1): of 180 peaks, RotD50 is the mean of the 90th and 91st.
double rotd(const std::vector<double>& peaks, double percentile);

// Of a pair on one time base (motion/component_set.h); throws std::invalid_argument otherwise.
PairIntensity pair_intensity(const Record& h1, const Record& h2);

}  // namespace caskdem::motion
