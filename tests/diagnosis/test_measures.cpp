// The error measures on signals whose measures are known in closed form: a sine of amplitude
// A over whole cycles (peak A, RMS A / sqrt 2, no asymmetry, two half-cycles per period), a
// sine offset by c (asymmetry 2c), a slide that settles (its residual value), a copy shifted
// in time (the lag, to a fraction of a sample), white noise (its level from second
// differences), and the scaled residuals, the sensor delay and the robust loss by their
// defining formulas (src/diagnosis/measures.h).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "diagnosis/measures.h"

namespace caskdem::diagnosis {
namespace {

constexpr double kStep = 0.005;       // s (200 Hz)
constexpr int kSamples = 2000;        // 10 s
constexpr double kFrequency = 1.0;    // Hz: ten whole cycles
constexpr double kAmplitude = 0.01;   // rad
constexpr double kStability = 0.2;    // rad, the cask's stability angle alpha

std::vector<double> times() {
  std::vector<double> t(kSamples);
  for (int k = 0; k < kSamples; ++k) t[k] = k * kStep;
  return t;
}

std::vector<double> sine(double amplitude, double delay = 0.0, double offset = 0.0) {
  std::vector<double> x;
  for (double t : times()) x.push_back(offset + amplitude * std::sin(2.0 * std::numbers::pi * kFrequency * (t - delay)));
  return x;
}

// A slide that grows to `distance` over 5 s and stays there.
std::vector<double> settling_slide(double distance) {
  std::vector<double> x;
  for (double t : times()) x.push_back(distance * std::min(t / 5.0, 1.0));
  return x;
}

MeasuredTest measured(std::vector<double> rotation, std::vector<double> slide) {
  MeasuredTest m;
  m.name = "synthetic";
  m.time_step = kStep;
  m.time = times();
  m.table_acceleration.assign(kSamples, 0.0);
  m.rotation = std::move(rotation);
  m.slide = std::move(slide);
  m.rotation_valid.assign(kSamples, 1);
  m.slide_valid.assign(kSamples, 1);
  return m;
}

TEST(Measures, SineOverWholeCycles) {
  const double threshold = 0.5 * kAmplitude;
  const Features f = features_of(times(), sine(kAmplitude), settling_slide(0.01), nullptr, nullptr, threshold);
  EXPECT_NEAR(f.peak_rotation, kAmplitude, 1e-12);  // a sample falls on every crest at 200 Hz
  EXPECT_NEAR(f.rotation_asymmetry, 0.0, 1e-12);
  // Over whole periods the mean of sin^2 of equally spaced samples is exactly 1/2.
  EXPECT_NEAR(f.rms_rotation, kAmplitude / std::sqrt(2.0), 1e-12);
  // |theta| first exceeds A/2 at t = 1/(12 f) and last at T - 1/(12 f), to a sample.
  const double duration = kSamples * kStep;
  EXPECT_NEAR(f.rocking_duration, duration - 1.0 / (6.0 * kFrequency), kStep);
  // 20 half-cycles above the threshold: 19 changes of side over that span, close to 2 f.
  EXPECT_NEAR(f.rocking_rate, 19.0 / (duration - 1.0 / (6.0 * kFrequency)), 0.01);
  EXPECT_NEAR(f.max_sliding, 0.01, 1e-15);
  EXPECT_NEAR(f.residual_sliding, 0.01, 1e-15);  // the mean of the last half second
}

TEST(Measures, OffsetSineIsAsymmetric) {
  const double offset = 0.002;
  const Features f =
      features_of(times(), sine(kAmplitude, 0.0, offset), settling_slide(0.0), nullptr, nullptr, 0.5 * kAmplitude);
  EXPECT_NEAR(f.peak_rotation, kAmplitude + offset, 1e-12);
  EXPECT_NEAR(f.rotation_asymmetry, 2.0 * offset, 1e-12);
}

TEST(Measures, InvalidSamplesAreSkipped) {
  std::vector<double> rotation = sine(kAmplitude), slide = settling_slide(0.01);
  std::vector<std::uint8_t> rotation_valid(kSamples, 1), slide_valid(kSamples, 1);
  rotation[700] = 10.0 * kAmplitude;  // a spike in a gap
  rotation_valid[700] = 0;
  slide[kSamples - 1] = 1.0;          // a clipped last sample
  slide_valid[kSamples - 1] = 0;
  const Features f = features_of(times(), rotation, slide, &rotation_valid, &slide_valid, 0.5 * kAmplitude);
  EXPECT_NEAR(f.peak_rotation, kAmplitude, 1e-12);
  EXPECT_NEAR(f.max_sliding, 0.01, 1e-15);
  EXPECT_NEAR(f.residual_sliding, 0.01, 1e-15);
}

TEST(Measures, NoiseLevelFromSecondDifferences) {
  // White noise of standard deviation sigma on a smooth sine. The second differences of the noise
  // have variance 6 sigma^2 and autocovariances -4 and 1 sigma^2 at lags 1 and 2, so the mean of
  // their squares over N samples has a relative standard deviation sqrt(2 (36 + 2 16 + 2 1) / N) / 6
  // = 4.4 % for N = 2000, and the estimate of sigma half that: 7 % is three standard deviations.
  // The sine's own second differences, A (2 pi f dt)^2 = 1e-5 rad, add 0.1 % in quadrature.
  const double sigma = 1e-4;
  std::mt19937_64 generator(20261122);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> rotation = sine(kAmplitude);
  for (double& x : rotation) x += normal(generator);
  const TestReference r = reference_of(measured(rotation, settling_slide(0.0)), kStability);
  RecordProperty("relative_error", std::to_string(r.rotation_noise / sigma - 1.0));
  EXPECT_NEAR(r.rotation_noise, sigma, 0.07 * sigma);
  // The rocking threshold is 1 % of alpha, which is above five noise levels here.
  EXPECT_DOUBLE_EQ(r.rocking_threshold, 0.01 * kStability);
}

TEST(Measures, ResidualsOfAnIdenticalSimulationVanish) {
  const MeasuredTest m = measured(sine(kAmplitude), settling_slide(0.01));
  const TestReference reference = reference_of(m, kStability);
  const std::vector<double> r = residuals(m, reference, {m.rotation, m.slide, false});
  ASSERT_EQ(r.size(), measure_names().size());
  for (std::size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(r[i], 0.0, 1e-12) << measure_names()[i];
}

TEST(Measures, ADeadChannelsMeasuresAreNotCompared) {
  // A rotation sensor dead throughout: a simulation that rocks is not wrong by its peak (the
  // measured one would read as 0), the rotation measures are left out and not counted, and the
  // sliding measures are compared as usual.
  MeasuredTest m = measured(sine(kAmplitude), settling_slide(0.01));
  m.rotation_valid.assign(kSamples, 0);
  const TestReference reference = reference_of(m, kStability);
  EXPECT_EQ(compared_count(reference), 3u);
  const std::vector<double> r = residuals(m, reference, {sine(kAmplitude), settling_slide(0.02), false});
  for (const char* name : {"peak_rotation", "rotation_asymmetry", "rms_rotation", "rocking_duration", "rocking_rate",
                           "rotation_history", "rotation_lag"})
    EXPECT_EQ(r[measure_index(name)], 0.0) << name;
  EXPECT_GT(r[measure_index("max_sliding")], 1.0);
  EXPECT_EQ(compared_count(reference_of(measured(sine(kAmplitude), settling_slide(0.01)), kStability)),
            measure_names().size());
}

TEST(Measures, IndexByNameAndAnUnknownNameIsRefused) {
  const auto& names = measure_names();
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(measure_index(names[i]), i);
  EXPECT_THROW(measure_index("peak_sliding"), std::invalid_argument);
}

TEST(Measures, ResidualsAreDifferencesOverTolerances) {
  const MeasuredTest m = measured(sine(kAmplitude), settling_slide(0.01));
  const TestReference reference = reference_of(m, kStability);
  const std::vector<double> r = residuals(m, reference, {sine(1.1 * kAmplitude), settling_slide(0.02), false});
  // Peak: 0.1 A over a tolerance of 5 % of the measured peak (above three noise levels and
  // 1e-3 alpha here).
  EXPECT_NEAR(r[measure_index("peak_rotation")], 2.0, 1e-9);
  // Sliding on the scale T(x) = ln(1 + x / s0), s0 = 2e-4 m for a noise-free slide, tolerance 0.05.
  const double expected = (std::log1p(0.02 / 2e-4) - std::log1p(0.01 / 2e-4)) / 0.05;
  EXPECT_NEAR(r[measure_index("max_sliding")], expected, 1e-9);
  EXPECT_NEAR(r[measure_index("residual_sliding")], expected, 1e-9);
}

TEST(Measures, LagOfAShiftedCopyToAFractionOfASample) {
  // The measurement is the simulation 2.46 samples late; the parabola through the peak of the
  // cross-correlation of a sine sampled 200 times a period is off by O((2 pi f dt)^2) samples.
  const double delay = 0.0123;
  const MeasuredTest m = measured(sine(kAmplitude, delay), settling_slide(0.0));
  const TestReference reference = reference_of(m, kStability);
  const std::vector<double> r = residuals(m, reference, {sine(kAmplitude), settling_slide(0.0), false});
  const std::size_t lag = measure_index("rotation_lag");
  RecordProperty("lag_error_samples", std::to_string((r[lag] * reference.tolerance[lag] - delay) / kStep));
  EXPECT_NEAR(r[lag] * reference.tolerance[lag], delay, 0.1 * kStep);
}

TEST(Measures, DelayShiftsALinearHistoryExactly) {
  SimulatedHistory h;
  for (double t : times()) {
    h.rotation.push_back(0.001 + 0.002 * t);
    h.slide.push_back(-0.003 * t);
  }
  const double delay = 0.0317;
  const SimulatedHistory d = delayed(h, times(), delay);
  for (int k = 10; k < kSamples; ++k) {
    const double t = k * kStep;
    EXPECT_NEAR(d.rotation[k], 0.001 + 0.002 * (t - delay), 1e-15);
    EXPECT_NEAR(d.slide[k], -0.003 * (t - delay), 1e-15);
  }
  // Before the delay has passed the first sample stands.
  EXPECT_DOUBLE_EQ(d.rotation[0], h.rotation[0]);
}

TEST(Measures, RobustLossIsQuadraticNearZeroAndLinearFarOut) {
  // 2 d^2 (sqrt(1 + (r/d)^2) - 1) = r^2 - r^4 / (4 d^2) + ... near zero, and
  // 2 d |r| - 2 d^2 + d^3 / |r| + O(1/r^3) far out (d = 3).
  const double d = kRobustScale;
  EXPECT_NEAR(robust_loss({0.01}), 1e-4, 1e-9);
  EXPECT_NEAR(robust_loss({300.0}), 2.0 * d * 300.0 - 2.0 * d * d + d * d * d / 300.0, 1e-4);
  EXPECT_NEAR(robust_loss({1.0, -1.0}), 2.0 * robust_loss({1.0}), 1e-15);
}

TEST(Measures, MarginalLossIsMinusTwiceTheLogOfTheMeanLikelihood) {
  // L = -2 ln((1/R) sum exp(-J_r / 2)): one input gives J; equal losses give J; otherwise L
  // lies between J_min and J_min + 2 ln R, the upper end reached when one input alone lands
  // near the measurement.
  EXPECT_DOUBLE_EQ(marginal_loss({7.5}), 7.5);
  EXPECT_NEAR(marginal_loss({3.0, 3.0, 3.0, 3.0}), 3.0, 1e-14);
  EXPECT_NEAR(marginal_loss({1.0, 2.0}), -2.0 * std::log(0.5 * (std::exp(-0.5) + std::exp(-1.0))), 1e-14);
  const double lone = marginal_loss({2.0, 2000.0, 4000.0, 1e6});
  EXPECT_NEAR(lone, 2.0 + 2.0 * std::log(4.0), 1e-12);  // no overflow or underflow far out
  EXPECT_LT(marginal_loss({2.0, 3.0, 50.0, 9.0}), lone);
}

TEST(Measures, InputRealisationsKeepTheMeasuredChannelFirstAndAddNoiseAtItsLevel) {
  // A smooth table channel plus white noise of known level: the copies after the first carry
  // fresh noise of that level, the same for the same seed and test, other noise for another
  // test index.
  MeasuredTest test = measured(sine(kAmplitude), settling_slide(0.0));
  const double sigma = 0.01;
  std::mt19937_64 generator(5);
  std::normal_distribution<double> noise(0.0, sigma);
  test.table_acceleration = sine(1.0);
  for (double& a : test.table_acceleration) a += noise(generator);
  const std::vector<MeasuredTest> inputs = input_realisations(test, 3, 4, 11);
  ASSERT_EQ(inputs.size(), 4u);
  EXPECT_EQ(inputs[0].table_acceleration, test.table_acceleration);
  for (std::size_t r = 1; r < inputs.size(); ++r) {
    double ss = 0.0;
    for (int k = 0; k < kSamples; ++k) {
      const double added = inputs[r].table_acceleration[k] - test.table_acceleration[k];
      ss += added * added;
    }
    // The level is estimated from the channel's second differences: within 10 % at 2000 samples.
    EXPECT_NEAR(std::sqrt(ss / kSamples), sigma, 0.1 * sigma);
    EXPECT_EQ(inputs[r].rotation, test.rotation);
  }
  EXPECT_EQ(input_realisations(test, 3, 4, 11)[2].table_acceleration, inputs[2].table_acceleration);
  EXPECT_NE(input_realisations(test, 4, 4, 11)[2].table_acceleration, inputs[2].table_acceleration);
  EXPECT_NE(inputs[1].table_acceleration, inputs[2].table_acceleration);
}

}  // namespace
}  // namespace caskdem::diagnosis
