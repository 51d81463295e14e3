// The site-risk convolution (risk/annual_frequency.h) against the number of hazard points:
// each segment's integral is in closed form, so the time is linear in the points; a hazard
// table of 10^6 points, as a fine engine export or a resampled curve may hold, in well under a
// second. site_risk convolves three times (the mean, the median member and, with beta_U, the two
// fractiles) and checks the curve's coverage.

#include <cmath>

#include <benchmark/benchmark.h>

#include "risk/annual_frequency.h"

namespace caskdem::bench {
namespace {

// H = 1e-2 (v / 1 cm/s)^-2.5 + a bend, from 1 to 1000 cm/s, log-spaced.
risk::HazardCurve curve(int points) {
  risk::HazardCurve c;
  c.source = "synthetic";
  c.measure = {risk::IntensityMeasure::Kind::pgv, 0.0};
  for (int i = 0; i < points; ++i) {
    const double x = std::log(1000.0) * i / (points - 1);
    c.intensity.push_back(0.01 * std::exp(x));
    c.annual_frequency.push_back(1e-2 * std::exp(-2.5 * x - 0.05 * x * x));
  }
  return c;
}

void site_risk(benchmark::State& state) {
  const risk::HazardCurve hazard = curve(static_cast<int>(state.range(0)));
  const risk::LognormalFragility fragility{0.6, 0.35, 0.25};
  double mean = 0.0;
  for (auto _ : state) {
    const risk::SiteRisk r = risk::site_risk(hazard, fragility);
    mean = r.mean;
    benchmark::DoNotOptimize(mean);
  }
  state.counters["points"] = double(state.range(0));
  state.counters["mean_annual_frequency"] = mean;
  state.SetComplexityN(state.range(0));
}

}  // namespace

BENCHMARK(site_risk)->RangeMultiplier(10)->Range(100, 1000000)->Unit(benchmark::kMillisecond)->Complexity();

}  // namespace caskdem::bench

BENCHMARK_MAIN();
