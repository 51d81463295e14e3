// Synthetic accelerograms against their definition: the same seed gives the same record,
// the requested PGA is met, and the average periodogram of the stationary process over many
// seeds follows the Kanai-Tajimi / Clough-Penzien spectrum it was built from.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "motion/synthetic.h"

namespace caskdem::motion {
namespace {

TEST(Synthetic, SameSeedSameRecordAndRequestedPga) {
  SyntheticMotion s;
  s.seed = 42;
  s.pga = 3.0;
  const Record a = synthetic_record(s), b = synthetic_record(s);
  EXPECT_EQ(a.acceleration, b.acceleration);
  EXPECT_NEAR(peak_ground_acceleration(a), 3.0, 1e-12);
  s.seed = 43;
  EXPECT_NE(synthetic_record(s).acceleration, a.acceleration);
  EXPECT_NEAR(a.duration(), s.duration, s.time_step);
}

TEST(Synthetic, EnvelopeStartsAtRestAndDecays) {
  SyntheticMotion s;
  const Record r = synthetic_record(s);
  EXPECT_NEAR(r.acceleration.front(), 0.0, 1e-15);
  double late = 0.0, strong = 0.0;
  for (std::size_t n = 0; n < r.acceleration.size(); ++n) {
    const double t = n * r.time_step;
    if (t > s.rise_time && t < s.rise_time + s.strong_duration) strong = std::max(strong, std::abs(r.acceleration[n]));
    if (t > s.duration - 2.0) late = std::max(late, std::abs(r.acceleration[n]));
  }
  // After the strong phase the envelope is exp(-c (t - t2)): at the end, exp(-0.4 * 10) = 0.018.
  EXPECT_LT(late, 0.05 * strong);
}

TEST(Synthetic, AveragePeriodogramFollowsTheTargetSpectrum) {
  // Stationary process: a tiny rise time and a strong phase covering the record.
  SyntheticMotion s;
  s.duration = 20.0;
  s.time_step = 0.01;
  s.rise_time = 1e-6;
  s.strong_duration = 100.0;
  const int seeds = 40;
  // Power in frequency bands (Hz), periodogram against the spectrum's integral.
  const std::vector<std::pair<double, double>> bands = {{0.2, 1.0}, {1.0, 2.0}, {2.0, 3.0}, {3.0, 5.0}, {5.0, 10.0}};
  std::vector<double> measured(bands.size(), 0.0), expected(bands.size(), 0.0);
  for (int seed = 1; seed <= seeds; ++seed) {
    s.seed = seed;
    const Record r = synthetic_record(s);
    const auto n = r.acceleration.size();
    for (std::size_t b = 0; b < bands.size(); ++b) {
      // Discrete Fourier transform at the record's own frequencies k / (n dt) inside the band.
      for (std::size_t k = 1; k < n / 2; ++k) {
        const double f = double(k) / (double(n) * r.time_step);
        if (f < bands[b].first || f >= bands[b].second) continue;
        double re = 0.0, im = 0.0;
        for (std::size_t j = 0; j < n; ++j) {
          const double angle = 2.0 * std::numbers::pi * double(k) * double(j) / double(n);
          re += r.acceleration[j] * std::cos(angle);
          im -= r.acceleration[j] * std::sin(angle);
        }
        measured[b] += (re * re + im * im) / seeds;
      }
    }
  }
  for (std::size_t b = 0; b < bands.size(); ++b) {
    for (double f = bands[b].first; f < bands[b].second; f += 1e-3) {
      expected[b] += synthetic_spectral_shape(s, 2.0 * std::numbers::pi * (f + 0.5e-3)) * 1e-3;
    }
  }
  // Compare shapes (each record is scaled to its PGA, so absolute power is not the point):
  // each band's share of the total, within the scatter of 40 records.
  double measured_total = 0.0, expected_total = 0.0;
  for (std::size_t b = 0; b < bands.size(); ++b) {
    measured_total += measured[b];
    expected_total += expected[b];
  }
  for (std::size_t b = 0; b < bands.size(); ++b) {
    const double share = measured[b] / measured_total, target = expected[b] / expected_total;
    EXPECT_NEAR(share / target, 1.0, 0.15) << "band " << bands[b].first << "-" << bands[b].second << " Hz";
  }
}

TEST(Synthetic, RejectsParametersOutOfRange) {
  SyntheticMotion s;
  s.high_pass_frequency = 5.0;  // above the dominant frequency
  EXPECT_THROW(synthetic_record(s), std::invalid_argument);
  s = {};
  s.duration = -1.0;
  EXPECT_THROW(synthetic_record(s), std::invalid_argument);
}

}  // namespace
}  // namespace caskdem::motion
