#include "motion/pair_intensity.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace caskdem::motion {

namespace {
constexpr int kAngles = 180;  // 0, 1, ..., 179 degrees
}

std::vector<double> rotated_peaks(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::invalid_argument("a horizontal pair must have its components on one time base");
  std::vector<double> peaks(kAngles, 0.0);
  for (int k = 0; k < kAngles; ++k) {
    const double theta = k * std::numbers::pi / 180.0;
    const double c = std::cos(theta), s = std::sin(theta);
    double peak = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) peak = std::max(peak, std::abs(x[i] * c + y[i] * s));
    peaks[k] = peak;
  }
  return peaks;
}

double rotd(const std::vector<double>& peaks, double percentile) {
  if (peaks.empty() || !(percentile >= 0.0 && percentile <= 100.0)) {
    throw std::invalid_argument("RotD: expected peaks and a percentile from 0 to 100");
  }
  std::vector<double> sorted = peaks;
  std::sort(sorted.begin(), sorted.end());
  const double position = percentile / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

PairIntensity pair_intensity(const Record& h1, const Record& h2) {
  if (h1.acceleration.size() != h2.acceleration.size() || h1.time_step != h2.time_step) {
    throw std::invalid_argument("a horizontal pair must have its components on one time base");
  }
  PairIntensity p;
  p.pga_geometric_mean = std::sqrt(peak_ground_acceleration(h1) * peak_ground_acceleration(h2));
  p.pgv_geometric_mean = std::sqrt(peak_ground_velocity(h1) * peak_ground_velocity(h2));
  const std::vector<double> acceleration = rotated_peaks(h1.acceleration, h2.acceleration);
  p.pga_rotd50 = rotd(acceleration, 50.0);
  p.pga_rotd100 = rotd(acceleration, 100.0);
  p.pga_rotd100_angle = static_cast<double>(std::max_element(acceleration.begin(), acceleration.end()) - acceleration.begin());
  const std::vector<double> velocity = rotated_peaks(integrate_record(h1).velocity, integrate_record(h2).velocity);
  p.pgv_rotd50 = rotd(velocity, 50.0);
  p.pgv_rotd100 = rotd(velocity, 100.0);
  return p;
}

}  // namespace caskdem::motion
