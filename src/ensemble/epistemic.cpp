#include "ensemble/epistemic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "ensemble/sampling.h"

namespace caskdem::fragility {

namespace {

constexpr int kBiasReplicates = 40;

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// The bias of a fitted beta at this design: the mean of beta refitted to counts drawn from the
// fit itself (a parametric bootstrap; Bernoulli draws from Philox, so it is reproducible),
// minus the fit's beta. Replicates that cannot be fitted are left out.
double beta_bias(const LognormalFit& fit, const std::vector<double>& levels, const std::vector<std::int64_t>& trials,
                 std::uint64_t seed, std::uint64_t point) {
  double sum = 0.0;
  int fitted = 0;
  std::vector<std::int64_t> counts(levels.size());
  for (int b = 0; b < kBiasReplicates; ++b) {
    for (std::size_t k = 0; k < levels.size(); ++k) {
      const double p = normal_cdf(std::log(levels[k] / fit.median) / fit.log_std);
      counts[k] = 0;
      for (std::int64_t t = 0; t < trials[k]; ++t)
        counts[k] += philox_uniform(seed, point, static_cast<std::uint64_t>(b) * levels.size() + k, t) < p;
    }
    const LognormalFit refit = fit_lognormal(levels, trials, counts);
    if (!refit.fitted) continue;
    sum += refit.log_std;
    ++fitted;
  }
  return fitted > 0 ? sum / fitted - fit.log_std : 0.0;
}

double mean_of(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double variance_of(const std::vector<double>& x) {
  const double m = mean_of(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return s / static_cast<double>(x.size() - 1);
}

}  // namespace

double NestedFit::beta_c() const { return std::sqrt(beta_r * beta_r + beta_u * beta_u); }

double log_median_variance(const LognormalFit& fit, const std::vector<double>& levels,
                           const std::vector<std::int64_t>& trials) {
  double sw = 0.0, swz = 0.0, swz2 = 0.0;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    if (trials[k] <= 0) continue;
    const double z = std::log(levels[k] / fit.median) / fit.log_std;
    const double p = 0.5 * std::erfc(-z / std::sqrt(2.0));
    const double pq = p * (1.0 - p);
    if (!(pq > 1e-300)) continue;  // a stripe far outside the curve carries no information
    const double density = std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
    const double w = static_cast<double>(trials[k]) * density * density / pq;
    sw += w;
    swz += w * z;
    swz2 += w * z * z;
  }
  const double determinant = sw * swz2 - swz * swz;
  if (!(determinant > 0.0)) return std::numeric_limits<double>::infinity();
  return fit.log_std * fit.log_std * swz2 / determinant;
}

NestedFit fit_nested(const std::vector<double>& levels, const std::vector<std::vector<std::int64_t>>& trials,
                     const std::vector<std::vector<std::int64_t>>& counts, double confidence, std::uint64_t seed) {
  if (trials.size() != counts.size()) throw std::invalid_argument("one list of counts per outer point is expected");
  if (!(confidence > 0.0 && confidence < 1.0)) throw std::invalid_argument("a confidence in (0, 1) is expected");
  NestedFit nested;
  nested.outer_points = static_cast<int>(trials.size());
  nested.confidence = confidence;
  if (nested.outer_points < 3) {
    nested.reason = "fewer than 3 outer points";
    return nested;
  }
  std::vector<double> log_median, beta, variance;
  int unfitted = 0;
  for (std::size_t j = 0; j < trials.size(); ++j) {
    const LognormalFit fit = fit_lognormal(levels, trials[j], counts[j]);
    // An unfitted point holds zeros, not the optimum its fit rejected (docs/output.md).
    nested.outer_median.push_back(fit.fitted ? fit.median : 0.0);
    nested.outer_log_std.push_back(fit.fitted ? fit.log_std : 0.0);
    if (!fit.fitted) {
      ++unfitted;
      continue;
    }
    log_median.push_back(std::log(fit.median));
    beta.push_back(fit.log_std);
    variance.push_back(log_median_variance(fit, levels, trials[j]));
  }
  if (unfitted > 0) {
    nested.reason = std::to_string(unfitted) + " of " + std::to_string(nested.outer_points) +
                    " outer points could not be fitted (their stripes do not span their capacity)";
    return nested;
  }
  // beta_R: the outer points' betas, each less the bias of its fit at this design.
  std::vector<double> beta_corrected;
  for (std::size_t j = 0; j < beta.size(); ++j) {
    LognormalFit fit;
    fit.fitted = true;
    fit.median = std::exp(log_median[j]);
    fit.log_std = beta[j];
    beta_corrected.push_back(beta[j] - beta_bias(fit, levels, trials[j], seed, j));
  }
  const double m = static_cast<double>(log_median.size());
  const double noise2 = mean_of(variance);
  const double spread2 = variance_of(log_median);
  if (!std::isfinite(noise2)) {
    nested.reason = "an outer point's stripes carry no information on its median";
    return nested;
  }
  nested.fitted = true;
  nested.median = std::exp(mean_of(log_median));
  nested.beta_r = mean_of(beta_corrected);
  nested.beta_u = std::sqrt(std::max(0.0, spread2 - noise2));
  nested.log_median_spread = std::sqrt(spread2);
  nested.fit_noise = std::sqrt(noise2);

  // Intervals for normal samples of M: Student's t for the means (ln A_m, beta_R), chi-square
  // for the variance of the ln A_j, from which the fits' noise is taken as for beta_U.
  const double tail = 0.5 * (1.0 - confidence);
  const boost::math::students_t t(m - 1.0);
  const boost::math::chi_squared chi2(m - 1.0);
  const double tq = boost::math::quantile(boost::math::complement(t, tail));
  const double median_half = tq * std::sqrt(spread2 / m), beta_half = tq * std::sqrt(variance_of(beta_corrected) / m);
  nested.median_low = nested.median * std::exp(-median_half);
  nested.median_high = nested.median * std::exp(median_half);
  nested.beta_r_low = nested.beta_r - beta_half;
  nested.beta_r_high = nested.beta_r + beta_half;
  const double upper2 = (m - 1.0) * spread2 / boost::math::quantile(chi2, tail) - noise2;
  const double lower2 = (m - 1.0) * spread2 / boost::math::quantile(boost::math::complement(chi2, tail)) - noise2;
  nested.beta_u_low = std::sqrt(std::max(0.0, lower2));
  nested.beta_u_high = std::sqrt(std::max(0.0, upper2));
  return nested;
}

}  // namespace caskdem::fragility
