#include "diagnosis/measures.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace caskdem::diagnosis {

double noise_level(const std::vector<double>& x, const std::vector<std::uint8_t>* valid) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 1; k + 1 < x.size(); ++k) {
    if (valid && (!(*valid)[k - 1] || !(*valid)[k] || !(*valid)[k + 1])) continue;
    const double d = x[k + 1] - 2.0 * x[k] + x[k - 1];
    sum += d * d;
    ++count;
  }
  return count > 0 ? std::sqrt(sum / count / 6.0) : 0.0;
}

namespace {

double rms(const std::vector<double>& x, const std::vector<std::uint8_t>* valid) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (valid && !(*valid)[k]) continue;
    sum += x[k] * x[k];
    ++count;
  }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b, const std::vector<std::uint8_t>& valid) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    if (!valid[k]) continue;
    sum += (a[k] - b[k]) * (a[k] - b[k]);
    ++count;
  }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

// The shift (s) of the simulated rotation that best matches the measured one, positive when the
// measurement is late: the peak of their cross-correlation over +-0.15 s, refined by a parabola
// through the peak and its neighbours (a fraction of a sample).
double lag(const std::vector<double>& time, const std::vector<double>& measured, const std::vector<std::uint8_t>& valid,
           const std::vector<double>& simulated) {
  const double dt = time.size() > 1 ? time[1] - time[0] : 1.0;
  const int steps = static_cast<int>(0.15 / dt);
  const auto n = static_cast<std::ptrdiff_t>(measured.size());
  std::vector<double> c(2 * steps + 1, 0.0);
  for (int s = -steps; s <= steps; ++s) {
    double sum = 0.0;
    for (std::ptrdiff_t k = 0; k < n; ++k) {
      const std::ptrdiff_t j = k - s;
      if (j < 0 || j >= n || !valid[k]) continue;
      sum += measured[k] * simulated[j];
    }
    c[s + steps] = sum;
  }
  const auto peak = std::max_element(c.begin(), c.end()) - c.begin();
  double offset = 0.0;
  if (peak > 0 && peak + 1 < static_cast<std::ptrdiff_t>(c.size())) {
    const double curvature = c[peak - 1] - 2.0 * c[peak] + c[peak + 1];
    if (curvature < 0.0) offset = 0.5 * (c[peak - 1] - c[peak + 1]) / curvature;
  }
  return (static_cast<double>(peak - steps) + offset) * dt;
}

double sliding_scale(double x, double floor) { return std::copysign(std::log1p(std::abs(x) / floor), x); }

}  // namespace

const std::vector<std::string>& measure_names() {
  static const std::vector<std::string> names = {"peak_rotation",    "rotation_asymmetry", "rms_rotation",
                                                 "rocking_duration", "rocking_rate",       "rotation_history",
                                                 "max_sliding",      "residual_sliding",   "sliding_history",
                                                 "rotation_lag"};
  return names;
}

std::size_t measure_index(const std::string& name) {
  const auto& names = measure_names();
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) throw std::invalid_argument("no error measure is named '" + name + "'");
  return static_cast<std::size_t>(found - names.begin());
}

Features features_of(const std::vector<double>& time, const std::vector<double>& rotation,
                     const std::vector<double>& slide, const std::vector<std::uint8_t>* rotation_valid,
                     const std::vector<std::uint8_t>* slide_valid, double threshold) {
  Features f;
  double positive = 0.0, negative = 0.0, sum = 0.0;
  int count = 0, side = 0, half_cycles = 0;
  double first = -1.0, last = -1.0;
  for (std::size_t k = 0; k < rotation.size(); ++k) {
    if (rotation_valid && !(*rotation_valid)[k]) continue;
    const double theta = rotation[k];
    positive = std::max(positive, theta);
    negative = std::max(negative, -theta);
    sum += theta * theta;
    ++count;
    if (std::abs(theta) > threshold) {
      if (first < 0.0) first = time[k];
      last = time[k];
      const int now = theta > 0.0 ? 1 : -1;
      if (side != 0 && now != side) ++half_cycles;
      side = now;
    }
  }
  f.peak_rotation = std::max(positive, negative);
  f.rotation_asymmetry = positive - negative;
  f.rms_rotation = count > 0 ? std::sqrt(sum / count) : 0.0;
  f.rocking_duration = first >= 0.0 ? last - first : 0.0;
  f.rocking_rate = f.rocking_duration > 0.0 ? half_cycles / f.rocking_duration : 0.0;
  // The residual sliding is the mean of the last half second, less sensitive to noise.
  double tail = 0.0;
  int tail_count = 0;
  const double end = time.empty() ? 0.0 : time.back();
  for (std::size_t k = 0; k < slide.size(); ++k) {
    if (slide_valid && !(*slide_valid)[k]) continue;
    f.max_sliding = std::max(f.max_sliding, std::abs(slide[k]));
    if (time[k] >= end - 0.5) {
      tail += slide[k];
      ++tail_count;
    }
  }
  f.residual_sliding = tail_count > 0 ? tail / tail_count : 0.0;
  return f;
}

TestReference reference_of(const MeasuredTest& test, double stability_angle) {
  TestReference r;
  r.rotation_noise = noise_level(test.rotation, &test.rotation_valid);
  r.slide_noise = noise_level(test.slide, &test.slide_valid);
  // Rocking: beyond 1 % of alpha and well above the noise.
  r.rocking_threshold = std::max(0.01 * stability_angle, 5.0 * r.rotation_noise);
  r.measured = features_of(test.time, test.rotation, test.slide, &test.rotation_valid, &test.slide_valid,
                           r.rocking_threshold);
  const Features& m = r.measured;
  const double rotation = std::max({0.05 * m.peak_rotation, 3.0 * r.rotation_noise, 1e-3 * stability_angle});
  r.slide_floor = std::max(3.0 * r.slide_noise, 2e-4);
  const double rotation_rms = rms(test.rotation, &test.rotation_valid);
  const double slide_rms = rms(test.slide, &test.slide_valid);
  r.tolerance = {
      rotation,                                                   // peak_rotation
      rotation,                                                   // rotation_asymmetry
      std::max(0.05 * m.rms_rotation, r.rotation_noise),          // rms_rotation (noise adds in quadrature)
      std::max(0.05 * m.rocking_duration, 0.2),                   // rocking_duration, s
      std::max(0.1 * m.rocking_rate, 0.2),                        // rocking_rate, 1/s
      0.3 * std::max(rotation_rms, 3.0 * r.rotation_noise),       // rotation_history
      0.05,                                                       // max_sliding, on T: 5 % above the noise
      0.05,                                                       // residual_sliding, on T
      0.3 * std::max({slide_rms, 3.0 * r.slide_noise, 2e-4}),     // sliding_history
      std::max(2.0 * test.time_step, 0.01),                        // rotation_lag, s
  };
  for (double& t : r.tolerance) t = std::max(t, 1e-12);
  const std::uint8_t rotation_used = any_valid(test.rotation_valid), slide_used = any_valid(test.slide_valid);
  r.compared = {rotation_used, rotation_used, rotation_used, rotation_used, rotation_used,
                rotation_used, slide_used,    slide_used,    slide_used,    rotation_used};
  return r;
}

std::size_t compared_count(const TestReference& reference) {
  return static_cast<std::size_t>(std::count(reference.compared.begin(), reference.compared.end(), 1));
}

SimulatedHistory delayed(const SimulatedHistory& h, const std::vector<double>& time, double delay) {
  if (delay == 0.0) return h;
  SimulatedHistory out = h;
  const double dt = time.size() > 1 ? time[1] - time[0] : 1.0;
  const auto n = static_cast<std::ptrdiff_t>(time.size());
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const double position = std::clamp((time[k] - delay) / dt, 0.0, double(n - 1));
    const auto i = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(position), n - 2);
    const double w = position - double(i);
    out.rotation[k] = (1.0 - w) * h.rotation[i] + w * h.rotation[i + 1];
    out.slide[k] = (1.0 - w) * h.slide[i] + w * h.slide[i + 1];
  }
  return out;
}

std::vector<double> residuals(const MeasuredTest& test, const TestReference& reference, const SimulatedHistory& simulated) {
  const Features s = features_of(test.time, simulated.rotation, simulated.slide, nullptr, nullptr,
                                 reference.rocking_threshold);
  const Features& m = reference.measured;
  const std::vector<double> differences = {
      s.peak_rotation - m.peak_rotation,
      s.rotation_asymmetry - m.rotation_asymmetry,
      s.rms_rotation - m.rms_rotation,
      s.rocking_duration - m.rocking_duration,
      s.rocking_rate - m.rocking_rate,
      rms_difference(simulated.rotation, test.rotation, test.rotation_valid),
      sliding_scale(s.max_sliding, reference.slide_floor) - sliding_scale(m.max_sliding, reference.slide_floor),
      sliding_scale(s.residual_sliding, reference.slide_floor) - sliding_scale(m.residual_sliding, reference.slide_floor),
      rms_difference(simulated.slide, test.slide, test.slide_valid),
      // The measured rotation's lag behind the simulated one; a rotation that never leaves the
      // noise has no phase to compare.
      reference.measured.peak_rotation > reference.rocking_threshold
          ? lag(test.time, test.rotation, test.rotation_valid, simulated.rotation)
          : 0.0,
  };
  std::vector<double> scaled(differences.size());
  for (std::size_t i = 0; i < differences.size(); ++i)
    scaled[i] = reference.compared[i] ? differences[i] / reference.tolerance[i] : 0.0;
  return scaled;
}

double robust_loss(const std::vector<double>& residuals) {
  double sum = 0.0;
  for (double r : residuals) {
    const double q = r / kRobustScale;
    sum += 2.0 * kRobustScale * kRobustScale * (std::sqrt(1.0 + q * q) - 1.0);
  }
  return sum;
}

double marginal_loss(const std::vector<double>& losses) {
  const double best = *std::min_element(losses.begin(), losses.end());
  if (!std::isfinite(best)) return best;
  double sum = 0.0;
  for (double j : losses) sum += std::exp(-0.5 * (j - best));  // fixed order: the realisations'
  return best - 2.0 * std::log(sum / double(losses.size()));
}

}  // namespace caskdem::diagnosis
