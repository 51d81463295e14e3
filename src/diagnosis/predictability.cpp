// How predictable each measure of each test is, whatever the model: the spread of the measure
// over simulations that differ in a noise realisation added to the table channel, at the
// noise level the channel itself shows (second differences), and in the baseline parameters,
// each moved by a few percent (kParameterSpread). A chaotic test (many impacts near the
// uplift threshold) gets wide tolerances on its rotation measures; so does a knife-edge
// measure, such as the net drift of a cask sliding both ways under a sine, which changes by
// half when the kinetic friction changes by 2 %: no model whose parameters are known to a few
// percent can predict it, and judged by it the parameter space is a haystack of needles. A
// sliding test whose response follows its input keeps tight tolerances.
//
// A held-out test is judged by what a fitted model predicts, and a fit knows its parameters
// only to its standard errors: the prediction's own spread over draws of the fitted
// parameters (x_i + se_i z_i, z standard normal) widens that test's tolerances for that model,
// as a prediction interval adds the parameters' uncertainty to the measurement's (Seber &
// Wild, "Nonlinear Regression", 1989, on prediction intervals). A held-out sine that slides
// only when friction is below 0.32 is otherwise a miss of seven tolerances for a fit at 0.34
// whose training tests cannot tell 0.32 from 0.34 (tests/diagnosis/test_hidden_effects.cpp,
// the floor layer).

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "diagnosis/measures.h"
#include "diagnosis/mechanisms.h"
#include "diagnosis/test_simulation.h"
#include "ensemble/sampling.h"

namespace caskdem::diagnosis {

namespace {

// Philox streams (the counter's last word): the predictability realisations' draws, the
// noisy table inputs a test is judged with, and the draws of a fit's parameters.
constexpr std::uint32_t kPredictabilityStream = 0x9ed1, kInputStream = 0x1a7e, kFitSpreadStream = 0x5e7d;

double normal(std::uint64_t seed, std::uint64_t test, std::uint64_t realisation, std::uint64_t sample,
              std::uint32_t stream = kPredictabilityStream) {
  return philox_normal(seed, {static_cast<std::uint32_t>(sample), static_cast<std::uint32_t>(realisation),
                              static_cast<std::uint32_t>(test), stream});
}

// Fresh white noise of level `noise` on a table channel, drawn per (test, realisation, sample).
void add_table_noise(std::vector<double>& channel, double noise, std::uint64_t seed, std::size_t test,
                     std::size_t realisation, std::uint32_t stream) {
  for (std::size_t k = 0; k < channel.size(); ++k) channel[k] += noise * normal(seed, test, realisation, k, stream);
}

// Relative spread of the baseline parameters (friction, damping ratio, stiffness scale) over the
// realisations: what a calibration typically leaves open.
constexpr double kParameterSpread[] = {0.02, 0.1, 0.1};

}  // namespace

std::vector<MeasuredTest> input_realisations(const MeasuredTest& test, std::size_t test_index, int count,
                                             std::uint64_t seed) {
  std::vector<MeasuredTest> inputs(static_cast<std::size_t>(std::max(1, count)), test);
  const double noise = noise_level(test.table_acceleration);
  for (std::size_t r = 1; r < inputs.size(); ++r) {
    add_table_noise(inputs[r].table_acceleration, noise, seed, test_index, r, kInputStream);
  }
  return inputs;
}

namespace {

// Adds in quadrature to each tolerance the sample standard deviation of that measure's raw
// differences over simulations (values[m][r]).
void widen_by_sample_spread(TestReference& reference, const std::vector<std::vector<double>>& values) {
  for (std::size_t m = 0; m < values.size(); ++m) {
    const int count = static_cast<int>(values[m].size());
    double mean = 0.0;
    for (double v : values[m]) mean += v;
    mean /= count;
    double ss = 0.0;
    for (double v : values[m]) ss += (v - mean) * (v - mean);
    const double spread = count > 1 ? std::sqrt(ss / (count - 1)) : 0.0;
    reference.tolerance[m] = std::hypot(reference.tolerance[m], spread);
  }
}

// Widens one test's tolerances by the spread of its measures over the realisations.
void widen_by_spread(TestReference& reference, const MeasuredTest& test, std::size_t test_index,
                     const ModelVariant& variant, const std::vector<double>& x, int realisations, std::uint64_t seed) {
  const std::size_t measures = measure_names().size();
  const double noise = noise_level(test.table_acceleration);
  std::vector<std::vector<double>> values(measures);
  for (int r = 0; r < realisations; ++r) {
    // The same parameter draw for every test of a realisation (counter "test" 0xffff).
    std::vector<double> moved = x;
    for (int i = 0; i < 3; ++i) {
      const Parameter& p = variant.parameters()[i];
      moved[i] = std::clamp(x[i] * std::exp(kParameterSpread[i] * normal(seed, 0xffff, r, i)), p.low, p.high);
    }
    MeasuredTest perturbed = test;
    add_table_noise(perturbed.table_acceleration, noise, seed, test_index, r, kPredictabilityStream);
    const SimulatedHistory h = delayed(simulate_test(variant, perturbed, {moved}, InstructionSet::automatic)[0],
                                       perturbed.time, variant.sensor_delay(moved));
    // Residual times tolerance: the raw difference of each measure from the measured value.
    const std::vector<double> scaled = residuals(test, reference, h);
    for (std::size_t m = 0; m < measures; ++m) values[m].push_back(scaled[m] * reference.tolerance[m]);
  }
  widen_by_sample_spread(reference, values);
}

}  // namespace

void add_predictability(std::vector<TestReference>& references, const std::vector<MeasuredTest>& tests,
                        const ModelVariant& variant, const std::vector<double>& x, int realisations, std::uint64_t seed,
                        int threads) {
  std::exception_ptr failure;  // an exception may not leave an OpenMP region: rethrown after it
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (std::size_t t = 0; t < tests.size(); ++t) {
    try {
      widen_by_spread(references[t], tests[t], t, variant, x, realisations, seed);
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

void add_fit_spread(std::vector<TestReference>& references, const std::vector<MeasuredTest>& tests,
                    const std::vector<int>& which, const ModelVariant& variant, const std::vector<double>& x,
                    const std::vector<double>& standard_error, int draws, std::uint64_t seed, int threads) {
  if (standard_error.size() != x.size() || draws < 2) return;  // no uncertainty known: the point alone
  // The same draws for every test (counter "test" 0xfffe), all of them lanes of one run per test.
  std::vector<std::vector<double>> points(static_cast<std::size_t>(draws), x);
  for (int r = 0; r < draws; ++r) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Parameter& p = variant.parameters()[i];
      points[r][i] = std::clamp(x[i] + standard_error[i] * normal(seed, 0xfffe, r, i, kFitSpreadStream), p.low, p.high);
    }
  }
  const std::size_t measures = measure_names().size();
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (std::size_t k = 0; k < which.size(); ++k) {
    try {
      const int t = which[k];
      const std::vector<SimulatedHistory> h = simulate_test(variant, tests[t], points, InstructionSet::automatic);
      std::vector<std::vector<double>> values(measures);
      for (int r = 0; r < draws; ++r) {
        // Raw differences (residual times tolerance) at the tolerances before widening.
        const std::vector<double> scaled =
            residuals(tests[t], references[t], delayed(h[r], tests[t].time, variant.sensor_delay(points[r])));
        for (std::size_t m = 0; m < measures; ++m) values[m].push_back(scaled[m] * references[t].tolerance[m]);
      }
      widen_by_sample_spread(references[t], values);
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace caskdem::diagnosis
