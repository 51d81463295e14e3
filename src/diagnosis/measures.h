#pragma once
// How far a simulated test is from the measured one: one scaled residual per error measure,
//   peak_rotation       max |theta|
//   rotation_asymmetry  max theta - max(-theta): rocking further to one side
//   rms_rotation        root mean square of theta
//   rocking_duration    from the first to the last time |theta| exceeds the rocking threshold
//   rocking_rate        rocking half-cycles per second of rocking (frequency content)
//   rotation_history    RMS of the history difference
//   max_sliding         max |sliding|
//   residual_sliding    the sliding at the end
//   sliding_history     RMS of the history difference
//   rotation_lag        the time shift that best aligns the simulated rotation with the measured
//                       one (cross-correlation over +-0.15 s): a phase error
// Sliding magnitudes (max_sliding, residual_sliding) are compared on the scale
// T(x) = sign(x) ln(1 + |x| / s0), s0 the sliding noise floor: a relative error above the noise,
// an absolute one below it. Sliding grows steeply with falling friction, so in metres a model
// that slides ten times too far costs far more than one that does not slide at all, and fits
// settle on "never slide"; on T both misses cost alike and the objective changes smoothly.
// Each residual is (simulated - measured) / tolerance. The tolerance adds in quadrature
//  - what the measurement allows: 5 % of the measured value, and the channel's noise,
//    estimated from second differences of the signal (sigma = std(x[k+1] - 2 x[k] + x[k-1]) /
//    sqrt(6) for white noise on a smooth signal);
//  - what the test allows a model to predict at all: rocking is chaotic, and a table channel
//    known only to its noise level leaves some measures of some tests undetermined. The
//    spread of each measure over simulations whose input is the measured table channel plus
//    fresh noise at its estimated level, with the baseline parameters moved by a few percent
//    (src/diagnosis/predictability.cpp), is that part; without it a fit
//    chases the noise's accidents and the true parameters score worse than wrong ones.

#include <string>
#include <vector>

#include "diagnosis/measured_test.h"
#include "diagnosis/mechanisms.h"
#include "diagnosis/test_simulation.h"

namespace caskdem::diagnosis {

const std::vector<std::string>& measure_names();

// The position of a measure in measure_names(); throws std::invalid_argument for an unknown name.
std::size_t measure_index(const std::string& name);

struct Features {
  double peak_rotation = 0.0, rotation_asymmetry = 0.0, rms_rotation = 0.0, rocking_duration = 0.0,
         rocking_rate = 0.0, max_sliding = 0.0, residual_sliding = 0.0;
};

// What a test's measurement fixes once: its features, noise levels and tolerances.
struct TestReference {
  Features measured;
  double slide_floor = 0.0;  // s0 of the sliding scale T, m
  double rotation_noise = 0.0;  // rad
  double slide_noise = 0.0;     // m
  double rocking_threshold = 0.0;  // rad
  std::vector<double> tolerance;   // per measure
  // Per measure, 1 where it is compared: a channel with no usable sample (missing or dead
  // throughout) leaves its measures out, with a residual of 0 that is not counted.
  std::vector<std::uint8_t> compared;
};

// How many of a test's measures are compared (the residuals an objective or error counts).
std::size_t compared_count(const TestReference& reference);


// White-noise level of a sampled signal from its second differences, std(x[k+1] - 2 x[k] +
// x[k-1]) / sqrt(6), over the samples whose neighbours are valid (all when `valid` is null).
double noise_level(const std::vector<double>& x, const std::vector<std::uint8_t>* valid = nullptr);

TestReference reference_of(const MeasuredTest& test, double stability_angle);

// Adds to each test's tolerances the spread of its measures over `realisations` simulations
// at parameters x whose table input carries fresh noise at the level estimated from the
// channel (src/diagnosis/predictability.cpp).
void add_predictability(std::vector<TestReference>& references, const std::vector<MeasuredTest>& tests,
                        const ModelVariant& variant, const std::vector<double>& x, int realisations, std::uint64_t seed,
                        int threads = 0);  // threads: 0 for OpenMP's default

// Adds to the tolerances of the tests `which` the spread of their measures over `draws`
// simulations of the model at its fitted point x moved by its standard errors (x_i + se_i z_i,
// clamped to the parameter's range; src/diagnosis/predictability.cpp): what the fit leaves its
// prediction of those tests open to. Without standard errors (none, or not one per parameter)
// the tolerances stay.
void add_fit_spread(std::vector<TestReference>& references, const std::vector<MeasuredTest>& tests,
                    const std::vector<int>& which, const ModelVariant& variant, const std::vector<double>& x,
                    const std::vector<double>& standard_error, int draws, std::uint64_t seed, int threads = 0);

// The table inputs a test is judged with: the measured channel first, then `count - 1` copies
// with fresh noise at the level estimated from the channel (the same draws at every point a
// fit tries, so that its objective is a function of the parameters alone).
std::vector<MeasuredTest> input_realisations(const MeasuredTest& test, std::size_t test_index, int count,
                                             std::uint64_t seed);

// Features of a history sampled at the test's times; samples where `valid` is 0 are skipped.
Features features_of(const std::vector<double>& time, const std::vector<double>& rotation,
                     const std::vector<double>& slide, const std::vector<std::uint8_t>* rotation_valid,
                     const std::vector<std::uint8_t>* slide_valid, double rocking_threshold);

// The simulated history seen through a sensor delay: the response channels lag the table by
// `delay`, so the sample at t shows the response at t - delay.
SimulatedHistory delayed(const SimulatedHistory& history, const std::vector<double>& time, double delay);

// Scaled residuals, one per measure (simulated minus measured, over the tolerance; 0 for a
// measure that is not compared).
std::vector<double> residuals(const MeasuredTest& test, const TestReference& reference, const SimulatedHistory& simulated);

// The fits' loss: pseudo-Huber on the scaled residuals, sum 2 d^2 (sqrt(1 + (r/d)^2) - 1), d = 3
// (Charbonnier et al. 1997; Hartley & Zisserman, "Multiple View Geometry", A6.8): r^2 within a
// few tolerances, growing like 2 d |r| beyond. A chaotic or near-threshold test can miss by
// hundreds of tolerances; with squares such misses dominate the objective and make the
// parameter space a haystack whose only broad basin is the wrong one.
double robust_loss(const std::vector<double>& residuals);
inline constexpr double kRobustScale = 3.0;

// The loss of a test simulated with R table inputs (input_realisations: the measured channel
// and R - 1 noisy copies) with losses J_r: read as -2 ln of a likelihood, exp(-J/2), averaged
// over the inputs the measured channel is consistent with,
//   L = -2 ln( (1/R) sum_r exp(-J_r / 2) ) = J_min - 2 ln( (1/R) sum_r exp(-(J_r - J_min)/2) ),
// between J_min and J_min + 2 ln R: a model is charged for how seldom its response lands near
// the measured one, not for how far one input's response lands from it. A chaotic test whose
// response jumps between branches under the table channel's noise then stops deciding a fit
// by which branch the measured channel's own noise happens to select (Monte Carlo
// marginalisation of the unknown true input; Diggle & Gratton 1984, simulated likelihood).
// R = 1 gives J itself.
double marginal_loss(const std::vector<double>& losses);

}  // namespace caskdem::diagnosis
