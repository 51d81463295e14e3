#pragma once
// The table motions of the test programme: sines of 10 mm displacement amplitude with a
// one-cycle ramp in and out, and recorded earthquakes compressed in time by sqrt(3) (1/3-scale
// similitude: lengths 1/3, accelerations 1, times 1/sqrt(3)).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace independent {

// A uniformly sampled acceleration history, linear between samples, zero outside.
struct Accelerogram {
  double time_step = 0.0;
  std::vector<double> acceleration;  // m/s^2
  double operator()(double t) const;
  double duration() const;
  double peak() const;
};

// Reads a PEER .AT2 file (4 header lines, the 4th naming NPTS and DT; values in g). Throws
// std::runtime_error naming the file on anything else.
Accelerogram read_at2(const std::filesystem::path& file);

// The part of a record from `start` to `end` (prototype seconds), tapered over its last
// `taper` seconds (a cosine), compressed in time by `time_factor` and scaled to peak `pga`.
Accelerogram model_scale_window(const Accelerogram& record, double start, double end, double taper, double time_factor,
                                double pga);

// Table acceleration of a sine test: displacement amplitude A at frequency f, `cycles` at
// full amplitude between a one-cycle sin^2 ramp in and out; -A (2 pi f)^2 envelope sin(2 pi f t + phase).
std::function<double(double)> ramped_sine(double amplitude, double frequency, double cycles, double phase = 0.0);
double ramped_sine_duration(double frequency, double cycles);

}  // namespace independent
