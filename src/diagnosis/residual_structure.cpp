#include "diagnosis/residual_structure.h"

#include <cmath>
#include <cstdint>
#include <numeric>

namespace caskdem::diagnosis {

namespace {

double correlation(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 3) return 0.0;
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// Mean over t-statistic of a sample: how consistently it is off zero.
double t_statistic(const std::vector<double>& v) {
  const std::size_t n = v.size();
  if (n < 2) return 0.0;
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  const double sd = std::sqrt(ss / (n - 1));
  return sd > 0.0 ? mean / (sd / std::sqrt(double(n))) : (mean != 0.0 ? 1e3 : 0.0);
}

double peak_rate(const std::vector<double>& x, const std::vector<std::uint8_t>& valid, double dt) {
  double peak = 0.0;
  for (std::size_t k = 2; k + 2 < x.size(); ++k) {
    if (!valid[k - 2] || !valid[k + 2]) continue;
    // A five-point derivative smooths sensor noise.
    const double rate = (-x[k + 2] + 8.0 * x[k + 1] - 8.0 * x[k - 1] + x[k - 2]) / (12.0 * dt);
    peak = std::max(peak, std::abs(rate));
  }
  return peak;
}

// The lag (s) that best aligns the simulated rotation with the measured one (positive: the
// measurement is late), by cross-correlation over +-0.2 s.
double lag_of(const MeasuredTest& test, const SimulatedHistory& simulated) {
  const int steps = static_cast<int>(0.2 / test.time_step);
  double best = -1e300;
  int best_lag = 0;
  for (int lag = -steps; lag <= steps; ++lag) {
    double sum = 0.0;
    for (std::size_t k = 0; k < test.time.size(); ++k) {
      const auto j = static_cast<std::ptrdiff_t>(k) - lag;
      if (j < 0 || j >= static_cast<std::ptrdiff_t>(simulated.rotation.size()) || !test.rotation_valid[k]) continue;
      sum += test.rotation[k] * simulated.rotation[j];
    }
    if (sum > best) {
      best = sum;
      best_lag = lag;
    }
  }
  return best_lag * test.time_step;
}

}  // namespace

std::vector<StructureRow> residual_structure(const MeasuredSet& set, const std::vector<TestReference>& references,
                                             const ModelFit& baseline, const Model& model,
                                             const std::vector<SimulatedHistory>& histories) {
  const std::size_t asymmetry_index = measure_index("rotation_asymmetry"), rms_index = measure_index("rms_rotation"),
                    slide_index = measure_index("max_sliding"), rate_index = measure_index("rocking_rate"),
                    duration_index = measure_index("rocking_duration");
  std::vector<double> amplitude, sliding_speed, impact_speed, vertical, asymmetry, lag;
  std::vector<double> r_rms, r_slide, r_rate, r_duration;
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    const MeasuredTest& test = set.tests[t];
    amplitude.push_back(references[t].measured.peak_rotation / model.stability_angle);
    sliding_speed.push_back(peak_rate(test.slide, test.slide_valid, test.time_step));
    impact_speed.push_back(peak_rate(test.rotation, test.rotation_valid, test.time_step));
    double v = 0.0;
    if (test.has_vertical) {
      for (double a : test.vertical_table_acceleration) v += a * a;
      v = std::sqrt(v / test.vertical_table_acceleration.size()) / model.gravity;
    }
    vertical.push_back(v);
    const std::vector<double>& r = baseline.residuals[t];
    asymmetry.push_back(r[asymmetry_index]);
    r_rms.push_back(r[rms_index]);
    r_slide.push_back(r[slide_index]);
    r_rate.push_back(r[rate_index]);
    r_duration.push_back(r[duration_index]);
    lag.push_back(lag_of(test, histories[t]));
  }
  std::vector<StructureRow> rows = {
      {"amplitude (peak theta / alpha)", "rms_rotation", correlation(amplitude, r_rms), "correlation",
       "amplitude_dependent_restitution, out_of_plane_loss"},
      {"amplitude (peak theta / alpha)", "rocking_duration", correlation(amplitude, r_duration), "correlation",
       "amplitude_dependent_restitution, out_of_plane_loss, floor_compliance"},
      {"amplitude (peak theta / alpha)", "rocking_rate", correlation(amplitude, r_rate), "correlation",
       "base_imperfection, floor_compliance"},
      {"peak sliding speed", "max_sliding", correlation(sliding_speed, r_slide), "correlation",
       "velocity_dependent_friction"},
      {"peak angular (impact) speed", "rms_rotation", correlation(impact_speed, r_rms), "correlation",
       "amplitude_dependent_restitution"},
      {"rotation sign", "rotation_asymmetry", t_statistic(asymmetry), "t (mean / standard error)",
       "eccentric_mass, base_imperfection"},
      {"vertical table acceleration (rms / g)", "rms_rotation", correlation(vertical, r_rms), "correlation",
       "vertical_excitation"},
      {"time (lag of measured behind simulated rotation, s)", "rotation_history",
       std::accumulate(lag.begin(), lag.end(), 0.0) / lag.size(), "mean lag, s", "sensor_delay"},
  };
  return rows;
}


}  // namespace caskdem::diagnosis
