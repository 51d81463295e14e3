#include "motion/synthetic.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Random123/philox.h>
#include <Random123/u01fixedpt.h>

namespace caskdem::motion {

namespace {

double envelope(const SyntheticMotion& s, double t) {
  if (t < s.rise_time) return (t / s.rise_time) * (t / s.rise_time);
  if (t < s.rise_time + s.strong_duration) return 1.0;
  return std::exp(-s.decay * (t - s.rise_time - s.strong_duration));
}

// Uniform phase in [0, 2 pi) for component k of the record keyed by seed.
double phase(std::uint64_t seed, std::uint64_t k) {
  using Philox = r123::Philox4x32;
  const Philox::key_type key = {{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  const Philox::ctr_type counter = {{static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k >> 32), 0x5eed, 0}};
  const Philox::ctr_type out = Philox()(counter, key);
  return 2.0 * std::numbers::pi * u01fixedpt_closed_open_64_double((std::uint64_t(out[0]) << 32) | out[1]);
}

}  // namespace

double synthetic_spectral_shape(const SyntheticMotion& s, double w) {
  const double wg = 2.0 * std::numbers::pi * s.dominant_frequency;
  const double wf = 2.0 * std::numbers::pi * s.high_pass_frequency;
  const double w2 = w * w;
  const double kanai_tajimi = (wg * wg * wg * wg + 4.0 * s.ground_damping * s.ground_damping * wg * wg * w2) /
                              ((wg * wg - w2) * (wg * wg - w2) + 4.0 * s.ground_damping * s.ground_damping * wg * wg * w2);
  const double clough_penzien =
      w2 * w2 / ((wf * wf - w2) * (wf * wf - w2) + 4.0 * s.high_pass_damping * s.high_pass_damping * wf * wf * w2);
  return kanai_tajimi * clough_penzien;
}

Record synthetic_record(const SyntheticMotion& s) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("synthetic motion: " + what);
  };
  require(s.duration > 0.0 && s.time_step > 0.0 && s.time_step < s.duration, "duration and time step must be positive");
  require(s.dominant_frequency > 0.0 && s.ground_damping > 0.0, "the ground filter needs a positive frequency and damping");
  require(s.high_pass_frequency > 0.0 && s.high_pass_frequency < s.dominant_frequency && s.high_pass_damping > 0.0,
          "the high-pass frequency must be positive and below the dominant frequency");
  require(s.rise_time > 0.0 && s.strong_duration >= 0.0 && s.decay > 0.0, "the envelope times must be positive");
  require(s.pga > 0.0, "the PGA must be positive");

  // Frequencies up to 25 Hz (or Nyquist), spaced finely enough not to repeat within the record.
  const double nyquist = std::numbers::pi / s.time_step;
  const double highest = std::min(2.0 * std::numbers::pi * 25.0, nyquist);
  const double spacing = std::min(2.0 * std::numbers::pi / (2.0 * s.duration), highest / 400.0);
  const int components = static_cast<int>(highest / spacing);
  std::vector<double> amplitude(components), frequency(components), angle(components);
  for (int k = 0; k < components; ++k) {
    frequency[k] = (k + 0.5) * spacing;
    amplitude[k] = std::sqrt(2.0 * synthetic_spectral_shape(s, frequency[k]) * spacing);
    angle[k] = phase(s.seed, k);
  }
  Record record;
  record.source = "synthetic (seed " + std::to_string(s.seed) + ")";
  record.time_step = s.time_step;
  const auto samples = static_cast<std::size_t>(std::floor(s.duration / s.time_step)) + 1;
  record.acceleration.resize(samples);
  for (std::size_t n = 0; n < samples; ++n) {
    const double t = static_cast<double>(n) * s.time_step;
    double sum = 0.0;
    for (int k = 0; k < components; ++k) sum += amplitude[k] * std::cos(frequency[k] * t + angle[k]);
    record.acceleration[n] = envelope(s, t) * sum;
  }
  return scaled_to_pga(record, s.pga);
}

}  // namespace caskdem::motion
