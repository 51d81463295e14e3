// Fragility statistics of a multiple-stripe analysis (Baker 2015, Earthquake Spectra 31(1)).
//
// Model. P(exceed | IM = x) = Phi(s), s = (ln x - u) / beta, u = ln(median), beta = log_std.
//
// Likelihood. Stripe j has n_j runs at level x_j, z_j of them exceeding; the runs are taken as
// independent Bernoulli trials, so
//   l(u, beta) = sum_j [ln C(n_j, z_j) + z_j ln Phi(s_j) + (n_j - z_j) ln Phi(-s_j)]
// (1 - Phi(s) = Phi(-s) is computed as such, never as a difference). The optimiser works on
//   l_rel = sum_j [z_j ln(Phi(s_j) / p_j) + (n_j - z_j) ln(Phi(-s_j) / (1 - p_j))],  p_j = z_j / n_j,
// which differs from l by a constant (the saturated log-likelihood), is <= 0, and near a good fit
// is ~ -chi-square / 2 whatever n is. Terms with a zero coefficient are skipped (0 * ln 0). Near
// the fit each stripe's term is evaluated without cancellation (see stripe_log_likelihood).
//
// Gradient. With lambda(s) = phi(s) / Phi(s) (the inverse Mills ratio),
//   g_j = dl/ds_j = z_j lambda(s_j) - (n_j - z_j) lambda(-s_j) = -n_j phi(s_j) (Phi(s_j) - p_j) / (Phi (1 - Phi)),
// and ds_j/du = -1/beta, ds_j/dv = -s_j with v = ln beta give
//   dl/du = -sum_j g_j / beta,   dl/dv = -sum_j g_j s_j.
// NLopt's LD_LBFGS maximises over (u, v) (v keeps beta > 0 without a constraint) with this
// gradient: a gradient method finds the zero of the gradient to near machine precision, whereas
// a derivative-free one sees only l, flat to O(dx^2) at the optimum, i.e. x to ~sqrt(eps).
// The coordinates handed to NLopt are scaled by the square roots of the diagonal of the Fisher
// information at the start (see ScaledProblem), so that a unit step is about one standard error
// whatever the number of runs.
//
// Uniqueness and start. In (a, b) = (-u / beta, 1 / beta), s = a + b ln x is linear and ln Phi is
// concave, so l is concave in (a, b) (probit regression). (u, v) -> (a, b) is a smooth bijection
// onto b > 0 with an invertible Jacobian, so every stationary point in (u, v) is the global
// maximum and any start converges to the same fit. The start (Berkson's minimum chi-square probit
// fit, a weighted least squares) only saves iterations.
//
// Convergence. NLopt's exit code is not the test (L-BFGS often reports FAILURE when asked for
// more than its line search can resolve); the fit is accepted when the score statistic
// g^T I^-1 g, the squared distance to the optimum in standard errors, is below 1e-8. A run that
// stops short is restarted (rescaled) from where it stopped, at most three times.
//
// Identifiability. Sort and merge the stripes by level and drop those without runs. As beta -> 0
// the curve becomes a step at some level c: the likelihood stays finite only if all stripes
// below c have z = 0, all above have z = n, and at most the one stripe at c is partial, and then
// it reaches the saturated maximum, so the MLE is beta -> 0 (no finite fit). That happens exactly
// when the last stripe with z < n comes no later than the first stripe with z > 0, which is
// checked before optimising (it includes "no exceedances", "all exceed" and "one stripe only").
// Otherwise two stripes i < k with z_i > 0 and z_k < n forbid any step, and the optimum is
// either finite or runs to beta -> infinity (data that do not increase with IM); the latter, and
// any optimum with beta outside [1e-3, 5] or a median pressed against its search bound, is
// reported as not fitted.
//
// Tails. ln Phi(s) = log1p(-erfc(s / sqrt 2) / 2) for s > 0, ln(erfc(-s / sqrt 2) / 2) for
// -30 < s <= 0 (erfc(21.2) ~ 1e-197 is still a normal double), and below -30 the Laplace
// asymptotic series ln phi(s) - ln(-s) + ln(1 - 1/s^2 + 3/s^4 - 15/s^6 + 105/s^8) (next term
// 945 / s^10 < 2e-12), so l and its gradient stay finite and smooth for any (u, v).
//
// Intervals. Clopper-Pearson: lower = B^-1(alpha/2; z, n - z + 1), upper = B^-1(1 - alpha/2;
// z + 1, n - z) with beta quantiles from Boost, lower = 0 for z = 0 and upper = 1 for z = n.
//
// Bootstrap. Record-to-record variability dominates, so with >= 2 motions a replicate draws the
// motions with replacement and sums their per-stripe counts and trials; with one motion it
// resamples each stripe's realisations, i.e. draws z*_j ~ Binomial(n_j, z_j / n_j). Random numbers:
// Philox4x32-10 keyed by the seed; the counter holds the replicate index (and the stripe, for
// realisations) and r123::MicroURNG counts the draws in its last word, so every replicate has its
// own stream and the band does not depend on the order in which replicates are computed.
// Quantiles at each IM are order statistics of the successful replicates, linearly interpolated.
//
// Misfit. Pearson chi-square sum_j (z_j - n_j P_j)^2 / (n_j P_j (1 - P_j)) over stripes with
// runs, compared with chi-square(max(1, stripes - 2)) (two fitted parameters).

#include "ensemble/fragility.h"

// philox.h first: MicroURNG.hpp uses the R123_ macros that philox.h's features header defines.
#include <Random123/philox.h>

#include <Random123/MicroURNG.hpp>
#include <nlopt.h>

#include <algorithm>
#include <array>
#include <boost/math/distributions/beta.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/special_functions/log1p.hpp>
#include <boost/random/binomial_distribution.hpp>
#include <boost/random/uniform_int_distribution.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace caskdem::fragility {
namespace {

constexpr double kMinLogStd = 1e-3;  // the contract's range of an acceptable beta
constexpr double kMaxLogStd = 5.0;
// The optimiser's box is wider than the acceptable range, so that an optimum outside the range
// is seen as such (and not as a fit pressed against the limit).
constexpr double kSearchMinLogStd = 1e-4;
constexpr double kSearchMaxLogStd = 50.0;
// ln(median) may lie this far beyond the logs of the lowest and highest levels (e^30 ~ 1e13).
constexpr double kMedianSearchMargin = 30.0;
constexpr double kAsymptoticTailStart = -30.0;
// A fit is converged when it lies within 1e-4 standard errors of the optimum (score < 1e-8).
// Statistically that is nothing; numerically it is what L-BFGS's line search can resolve: l_rel
// carries a rounding error of ~1e-16 sqrt(n) per stripe (from delta = Phi - p), so with 1e9 runs
// per stripe it stalls at scores of ~1e-12 to 1e-10.
constexpr double kConvergedScore = 1e-8;
constexpr int kOptimiserRestarts = 3;

// ln Phi(s), finite for every finite s (see "Tails" above).
double log_normal_cdf(double s) {
  if (s > 0.0) return std::log1p(-0.5 * std::erfc(s / std::numbers::sqrt2));
  if (s > kAsymptoticTailStart) return std::log(0.5 * std::erfc(-s / std::numbers::sqrt2));
  const double inverse_square = 1.0 / (s * s);
  const double series =
      1.0 - inverse_square * (1.0 - 3.0 * inverse_square * (1.0 - 5.0 * inverse_square * (1.0 - 7.0 * inverse_square)));
  const double log_density = -0.5 * s * s - 0.5 * std::log(2.0 * std::numbers::pi);
  return log_density - std::log(-s) + std::log(series);
}

// phi(s) / Phi(s), computed in logs so that it stays finite (~ -s) deep in the lower tail.
double inverse_mills_ratio(double s) {
  const double log_density = -0.5 * s * s - 0.5 * std::log(2.0 * std::numbers::pi);
  return std::exp(log_density - log_normal_cdf(s));
}

// Phi(s) and 1 - Phi(s), each from erfc so that neither loses digits near 0.
double normal_cdf(double s) { return 0.5 * std::erfc(-s / std::numbers::sqrt2); }
double normal_survival(double s) { return 0.5 * std::erfc(s / std::numbers::sqrt2); }

// Stripes with runs, sorted by level, equal levels merged: what the likelihood sees.
struct PooledStripes {
  std::vector<double> log_level;
  std::vector<double> trials;
  std::vector<double> counts;
};

PooledStripes pool_stripes(const std::vector<double>& levels, const std::vector<std::int64_t>& trials,
                           const std::vector<std::int64_t>& counts) {
  if (trials.size() != levels.size() || counts.size() != levels.size())
    throw std::invalid_argument("fragility: levels, trials and counts differ in size");
  std::vector<std::size_t> order;
  for (std::size_t j = 0; j < levels.size(); ++j) {
    if (!(levels[j] > 0.0) || !std::isfinite(levels[j]))
      throw std::invalid_argument("fragility: IM levels must be finite and > 0");
    if (trials[j] < 0 || counts[j] < 0 || counts[j] > trials[j])
      throw std::invalid_argument("fragility: need 0 <= count <= trials for every stripe");
    if (trials[j] > 0) order.push_back(j);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return levels[a] < levels[b]; });
  PooledStripes pooled;
  double previous_level = -1.0;
  for (std::size_t j : order) {
    if (levels[j] == previous_level) {
      pooled.trials.back() += static_cast<double>(trials[j]);
      pooled.counts.back() += static_cast<double>(counts[j]);
      continue;
    }
    previous_level = levels[j];
    pooled.log_level.push_back(std::log(levels[j]));
    pooled.trials.push_back(static_cast<double>(trials[j]));
    pooled.counts.push_back(static_cast<double>(counts[j]));
  }
  return pooled;
}

// Stripe j's term of l_rel, z ln(Phi / p) + (n - z) ln((1 - Phi) / (1 - p)), and its derivative
// in s. Near a good fit Phi = p + delta with |delta| << p, and the two logs are large and cancel
// to first order, leaving -n delta^2 / (2 p (1 - p)); summed as logs, n ~ 1e9 runs would bury that
// under ~n * 1e-16 of rounding and stall the optimiser. With a = delta / p, b = -delta / (1 - p)
// and p a + (1 - p) b = 0 the term is exactly z log1pmx(a) + (n - z) log1pmx(b) (log1pmx(x) =
// log1p(x) - x, both terms <= 0: no cancellation) and its derivative -n phi delta / (Phi (1 - Phi)).
// delta is Phi - p for p <= 1/2 and (1 - p) - (1 - Phi) otherwise, so that it comes from the
// smaller of Phi, 1 - Phi, which erfc gives to full relative precision. Far from the fit (or
// with z = 0 or z = n, where nothing cancels) the plain logs are used.
double stripe_log_likelihood(double n, double z, double s, double& d_s) {
  const double survivors = n - z;
  if (z > 0.0 && survivors > 0.0) {
    const double p = z / n, p_survive = survivors / n;
    const double cdf = normal_cdf(s), survival = normal_survival(s);
    const double delta = p <= 0.5 ? cdf - p : p_survive - survival;
    const double a = delta / p, b = -delta / p_survive;
    if (std::abs(a) < 0.5 && std::abs(b) < 0.5) {
      const double density = std::exp(-0.5 * s * s) / std::sqrt(2.0 * std::numbers::pi);
      d_s = -n * density * delta / (cdf * survival);
      return z * boost::math::log1pmx(a) + survivors * boost::math::log1pmx(b);
    }
  }
  double value = 0.0;
  d_s = 0.0;
  if (z > 0.0) {
    value += z * (log_normal_cdf(s) - std::log(z / n));
    d_s += z * inverse_mills_ratio(s);
  }
  if (survivors > 0.0) {
    value += survivors * (log_normal_cdf(-s) - std::log(survivors / n));
    d_s -= survivors * inverse_mills_ratio(-s);
  }
  return value;
}

// l_rel of the derivation and its gradient in (u, v), unscaled (ScaledProblem scales for NLopt).
struct LikelihoodProblem {
  const PooledStripes* stripes = nullptr;

  double relative_log_likelihood(double log_median, double log_log_std, double* gradient) const {
    const double log_std = std::exp(log_log_std);
    double value = 0.0, d_log_median = 0.0, d_log_log_std = 0.0;
    for (std::size_t j = 0; j < stripes->trials.size(); ++j) {
      const double s = (stripes->log_level[j] - log_median) / log_std;
      double d_s = 0.0;  // dl/ds_j
      value += stripe_log_likelihood(stripes->trials[j], stripes->counts[j], s, d_s);
      d_log_median -= d_s / log_std;
      d_log_log_std -= d_s * s;
    }
    if (gradient != nullptr) {
      gradient[0] = d_log_median;
      gradient[1] = d_log_log_std;
    }
    return value;
  }
};

// Saturated part of l: sum_j [ln C(n_j, z_j) + z_j ln p_j + (n_j - z_j) ln(1 - p_j)].
double saturated_log_likelihood(const PooledStripes& stripes) {
  double total = 0.0;
  for (std::size_t j = 0; j < stripes.trials.size(); ++j) {
    const double n = stripes.trials[j], z = stripes.counts[j];
    total += std::lgamma(n + 1.0) - std::lgamma(z + 1.0) - std::lgamma(n - z + 1.0);
    if (z > 0.0) total += z * std::log(z / n);
    if (n - z > 0.0) total += (n - z) * std::log((n - z) / n);
  }
  return total;
}

// Expected (Fisher) information of (u, v), with ds/du = -1/beta and ds/dv = -s:
//   I = sum_j n_j phi_j^2 / (Phi_j (1 - Phi_j)) [1/beta^2, s_j/beta; s_j/beta, s_j^2],
// the weight formed in logs so that it stays finite (-> 0) in the tails.
struct Information {
  double uu = 0.0, uv = 0.0, vv = 0.0;
};

Information fisher_information(const PooledStripes& stripes, double log_median, double log_log_std) {
  const double log_std = std::exp(log_log_std);
  Information information;
  for (std::size_t j = 0; j < stripes.trials.size(); ++j) {
    const double s = (stripes.log_level[j] - log_median) / log_std;
    const double log_density = -0.5 * s * s - 0.5 * std::log(2.0 * std::numbers::pi);
    const double weight = stripes.trials[j] * std::exp(2.0 * log_density - log_normal_cdf(s) - log_normal_cdf(-s));
    information.uu += weight / (log_std * log_std);
    information.uv += weight * s / log_std;
    information.vv += weight * s * s;
  }
  return information;
}

// Score statistic g^T I^-1 g at (u, v), g the gradient of l: the squared distance to the optimum
// in standard errors (the length of a Fisher-scoring step in the metric of the information), so
// it measures convergence in the data's own units whatever n is.
double score_statistic(const LikelihoodProblem& problem, double log_median, double log_log_std) {
  std::array<double, 2> gradient{};
  problem.relative_log_likelihood(log_median, log_log_std, gradient.data());
  const Information information = fisher_information(*problem.stripes, log_median, log_log_std);
  const double determinant = information.uu * information.vv - information.uv * information.uv;
  if (!(determinant > 0.0)) return std::numeric_limits<double>::infinity();
  return (information.vv * gradient[0] * gradient[0] - 2.0 * information.uv * gradient[0] * gradient[1] +
          information.uu * gradient[1] * gradient[1]) /
         determinant;
}

// What NLopt sees: l_rel in scaled coordinates y_i = scale_i (x_i - origin_i), x = (u, v), with
// scale_i = sqrt(I_ii) at the start. L-BFGS takes its first step along the raw gradient and stops
// on a fixed gradient norm (1e-8); in x the gradient grows with n (a first step of 1e11 for 1e12
// runs per stripe, straight into the bounds) and differs between u and v by 1/beta^2 against s^2.
// In y the curvature is ~1 in both directions, so the first step is about a Fisher-scoring step
// and the gradient norm is about the distance to the optimum in standard errors.
struct ScaledProblem {
  const LikelihoodProblem* problem = nullptr;
  std::array<double, 2> origin{};
  std::array<double, 2> scale{1.0, 1.0};

  std::array<double, 2> unscale(const double* y) const {
    return {origin[0] + y[0] / scale[0], origin[1] + y[1] / scale[1]};
  }
};

double nlopt_objective(unsigned /*dimension*/, const double* y, double* gradient, void* data) {
  const auto& scaled = *static_cast<const ScaledProblem*>(data);
  const std::array<double, 2> x = scaled.unscale(y);
  const double value = scaled.problem->relative_log_likelihood(x[0], x[1], gradient);
  if (gradient != nullptr) {
    gradient[0] /= scaled.scale[0];
    gradient[1] /= scaled.scale[1];
  }
  return value;
}

// Start: Berkson's minimum chi-square probit fit, weighted least squares of
// y_j = Phi^-1(p_j) = (L_j - u) / beta on L_j = ln x_j with p_j = (z_j + 1/2) / (n_j + 1) and
// weights n_j phi(y_j)^2 / (p_j (1 - p_j)) (the inverse variance of y_j), which is close to the
// MLE and gives stripes at 0 or n (clamped probits) little weight. Slope 1/beta, intercept
// -u/beta; falls back to beta = 1 at the mean level when the slope is not positive.
std::array<double, 2> starting_point(const PooledStripes& stripes) {
  const boost::math::normal standard_normal;
  const std::size_t count = stripes.trials.size();
  std::vector<double> probits(count), weights(count);
  double weight_sum = 0.0, mean_level = 0.0, mean_probit = 0.0;
  for (std::size_t j = 0; j < count; ++j) {
    const double p = (stripes.counts[j] + 0.5) / (stripes.trials[j] + 1.0);
    probits[j] = boost::math::quantile(standard_normal, p);
    weights[j] = stripes.trials[j] * std::pow(boost::math::pdf(standard_normal, probits[j]), 2) / (p * (1.0 - p));
    weight_sum += weights[j];
    mean_level += weights[j] * stripes.log_level[j];
    mean_probit += weights[j] * probits[j];
  }
  mean_level /= weight_sum;
  mean_probit /= weight_sum;
  double covariance = 0.0, level_variance = 0.0;
  for (std::size_t j = 0; j < count; ++j) {
    const double dl = stripes.log_level[j] - mean_level;
    covariance += weights[j] * dl * (probits[j] - mean_probit);
    level_variance += weights[j] * dl * dl;
  }
  if (!(level_variance > 0.0) || !(covariance > 0.0)) return {mean_level, 0.0};
  const double slope = covariance / level_variance;
  const double log_std = std::clamp(1.0 / slope, 2.0 * kMinLogStd, kMaxLogStd);
  return {mean_level - mean_probit * log_std, std::log(log_std)};
}

using NloptHandle = std::unique_ptr<std::remove_pointer_t<nlopt_opt>, decltype(&nlopt_destroy)>;

// One L-BFGS run in the scaled coordinates about x (updated to the end point; objective = l_rel
// there).
nlopt_result maximise_scaled(const LikelihoodProblem& problem, const std::array<double, 2>& lower_bounds,
                             const std::array<double, 2>& upper_bounds, std::array<double, 2>& x, double& objective) {
  ScaledProblem scaled{&problem, x, {1.0, 1.0}};
  const Information information = fisher_information(*problem.stripes, x[0], x[1]);
  if (std::isfinite(information.uu) && information.uu > 1e-12) scaled.scale[0] = std::sqrt(information.uu);
  if (std::isfinite(information.vv) && information.vv > 1e-12) scaled.scale[1] = std::sqrt(information.vv);
  std::array<double, 2> y = {0.0, 0.0}, y_lower{}, y_upper{};
  for (int i = 0; i < 2; ++i) {
    y_lower[i] = (lower_bounds[i] - x[i]) * scaled.scale[i];
    y_upper[i] = (upper_bounds[i] - x[i]) * scaled.scale[i];
  }
  NloptHandle optimiser(nlopt_create(NLOPT_LD_LBFGS, 2), &nlopt_destroy);
  if (!optimiser) throw std::runtime_error("fit_lognormal: nlopt_create failed");
  nlopt_set_max_objective(optimiser.get(), &nlopt_objective, &scaled);
  nlopt_set_lower_bounds(optimiser.get(), y_lower.data());
  nlopt_set_upper_bounds(optimiser.get(), y_upper.data());
  // y is in standard errors (at the start): stop when a step moves the fit by < 1e-10 of one
  nlopt_set_xtol_abs1(optimiser.get(), 1e-10);
  nlopt_set_maxeval(optimiser.get(), 2000);
  const nlopt_result result = nlopt_optimize(optimiser.get(), y.data(), &objective);
  x = scaled.unscale(y.data());
  // NLopt can leave the point a hair outside the box after unscaling
  for (int i = 0; i < 2; ++i) x[i] = std::clamp(x[i], lower_bounds[i], upper_bounds[i]);
  return result;
}

std::string describe_separation(const PooledStripes& stripes, std::size_t last_not_all, std::size_t first_some,
                                const LevelText& level_text) {
  const auto level = [&](std::size_t k) {
    const double im = std::exp(stripes.log_level[k]);
    if (level_text) return level_text(im);
    std::ostringstream out;
    out << "IM " << im;
    return out.str();
  };
  std::ostringstream reason;
  if (stripes.trials.size() == 1) {
    reason << "only one stripe has runs (" << level(0)
           << "): one fraction cannot fix both median and log_std (not identifiable)";
  } else if (last_not_all == first_some) {
    reason << "only one stripe (" << level(first_some)
           << ") lies between no exceedance below and all exceeding above, so log_std -> 0 (not identifiable)";
  } else {
    reason << "the stripes are perfectly separated (none exceed up to " << level(last_not_all) << ", all exceed from "
           << level(first_some) << "), so the maximum likelihood is a step, log_std -> 0 (not identifiable)";
  }
  return reason.str();
}

// The binomial draws of a bootstrap replicate come from boost::random on a Philox stream.
using PhiloxStream = r123::MicroURNG<r123::Philox4x32>;
constexpr std::uint32_t kMotionStream = 1;
constexpr std::uint32_t kRealisationStream = 2;

PhiloxStream philox_stream(std::uint64_t seed, std::uint32_t replicate, std::uint32_t stripe, std::uint32_t stream) {
  const r123::Philox4x32::ukey_type key = {{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  // The last counter word must be zero: MicroURNG counts the draws there.
  const r123::Philox4x32::ctr_type counter = {{replicate, stripe, stream, 0u}};
  return PhiloxStream(counter, key);
}

void check_confidence(double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) throw std::invalid_argument("fragility: confidence must be in (0, 1)");
}

void check_shape(const StripeData& data) {
  if (data.trials.size() != data.counts.size())
    throw std::invalid_argument("fragility: trials and counts have different numbers of motions");
  for (std::size_t m = 0; m < data.trials.size(); ++m) {
    if (data.trials[m].size() != data.levels.size() || data.counts[m].size() != data.levels.size())
      throw std::invalid_argument("fragility: a motion's trials or counts do not have one entry per stripe");
    for (std::size_t j = 0; j < data.levels.size(); ++j)
      if (data.trials[m][j] < 0 || data.counts[m][j] < 0 || data.counts[m][j] > data.trials[m][j])
        throw std::invalid_argument("fragility: need 0 <= count <= trials for every motion and stripe");
  }
}

// Linear interpolation between order statistics of sorted values (Hyndman-Fan type 7).
double sorted_quantile(const std::vector<double>& sorted, double probability) {
  const double position = probability * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

}  // namespace

void clopper_pearson(std::int64_t count, std::int64_t trials, double confidence, double& lower, double& upper) {
  check_confidence(confidence);
  if (trials < 0 || count < 0 || count > trials)
    throw std::invalid_argument("clopper_pearson: need 0 <= count <= trials");
  if (trials == 0) {  // no information
    lower = 0.0;
    upper = 1.0;
    return;
  }
  const double tail = 0.5 * (1.0 - confidence);
  const auto z = static_cast<double>(count), n = static_cast<double>(trials);
  lower = count == 0 ? 0.0 : boost::math::quantile(boost::math::beta_distribution<double>(z, n - z + 1.0), tail);
  upper = count == trials ? 1.0
                          : boost::math::quantile(boost::math::beta_distribution<double>(z + 1.0, n - z), 1.0 - tail);
}

std::vector<StripeProbability> stripe_probabilities(const StripeData& data, double confidence) {
  check_confidence(confidence);
  check_shape(data);
  std::vector<StripeProbability> stripes(data.levels.size());
  for (std::size_t j = 0; j < data.levels.size(); ++j) {
    StripeProbability& stripe = stripes[j];
    stripe.level = data.levels[j];
    for (std::size_t m = 0; m < data.trials.size(); ++m) {
      stripe.trials += data.trials[m][j];
      stripe.count += data.counts[m][j];
    }
    stripe.probability =
        stripe.trials > 0 ? static_cast<double>(stripe.count) / static_cast<double>(stripe.trials) : 0.0;
    clopper_pearson(stripe.count, stripe.trials, confidence, stripe.lower, stripe.upper);
  }
  return stripes;
}

LognormalFit fit_lognormal(const std::vector<double>& levels, const std::vector<std::int64_t>& trials,
                           const std::vector<std::int64_t>& counts, const LevelText& level_text) {
  LognormalFit fit;
  const PooledStripes stripes = pool_stripes(levels, trials, counts);
  const std::size_t stripe_count = stripes.trials.size();
  if (stripe_count == 0) {
    fit.reason = "no stripe has any runs";
    return fit;
  }
  // first stripe with an exceedance, last stripe with a non-exceedance (see "Identifiability")
  std::size_t first_some = stripe_count, last_not_all = stripe_count;
  for (std::size_t j = 0; j < stripe_count; ++j) {
    if (first_some == stripe_count && stripes.counts[j] > 0.0) first_some = j;
    if (stripes.counts[j] < stripes.trials[j]) last_not_all = j;
  }
  if (first_some == stripe_count) {
    fit.reason = "no exceedances in any stripe";
    return fit;
  }
  if (last_not_all == stripe_count) {
    fit.reason = "every run of every stripe exceeds";
    return fit;
  }
  if (last_not_all <= first_some) {
    fit.reason = describe_separation(stripes, last_not_all, first_some, level_text);
    return fit;
  }

  LikelihoodProblem problem{&stripes};
  const std::array<double, 2> lower_bounds = {stripes.log_level.front() - kMedianSearchMargin,
                                              std::log(kSearchMinLogStd)};
  const std::array<double, 2> upper_bounds = {stripes.log_level.back() + kMedianSearchMargin,
                                              std::log(kSearchMaxLogStd)};
  std::array<double, 2> x = starting_point(stripes);
  for (int i = 0; i < 2; ++i) x[i] = std::clamp(x[i], lower_bounds[i], upper_bounds[i]);
  double objective = 0.0, score = std::numeric_limits<double>::infinity();
  nlopt_result result = NLOPT_FAILURE;
  // The scaling is the information at the start; from a poor start it can be far from that at
  // the optimum, so an unconverged run is restarted, rescaled, from where it stopped.
  for (int attempt = 0; attempt < kOptimiserRestarts && !(score < kConvergedScore); ++attempt) {
    result = maximise_scaled(problem, lower_bounds, upper_bounds, x, objective);
    if (result == NLOPT_INVALID_ARGS || result == NLOPT_OUT_OF_MEMORY || result == NLOPT_FORCED_STOP) break;
    score = score_statistic(problem, x[0], x[1]);
  }
  if (result == NLOPT_INVALID_ARGS || result == NLOPT_OUT_OF_MEMORY || result == NLOPT_FORCED_STOP) {
    fit.reason = "NLopt failed (code " + std::to_string(static_cast<int>(result)) + ")";
    return fit;
  }
  objective = problem.relative_log_likelihood(x[0], x[1], nullptr);  // at the (clamped) end point
  const double log_std = std::exp(x[1]);
  if (!std::isfinite(objective) || !std::isfinite(x[0]) || !std::isfinite(log_std)) {
    fit.reason = "the likelihood optimum is not finite";
    return fit;
  }
  fit.median = std::exp(x[0]);
  fit.log_std = log_std;
  fit.log_likelihood = saturated_log_likelihood(stripes) + objective;
  if (log_std < kMinLogStd || log_std > kMaxLogStd) {
    std::ostringstream reason;
    reason << "the optimum log_std " << log_std << " is outside [" << kMinLogStd << ", " << kMaxLogStd << "]";
    if (log_std > kMaxLogStd) reason << " (the exceedance fraction does not increase with IM)";
    fit.reason = reason.str();
    return fit;
  }
  const double median_margin = 1e-6;  // in ln(median)
  if (x[0] < lower_bounds[0] + median_margin || x[0] > upper_bounds[0] - median_margin) {
    std::ostringstream reason;
    reason << "the median runs to its search bound (a factor e^" << kMedianSearchMargin
           << " beyond the stripes): not identifiable";
    fit.reason = reason.str();
    return fit;
  }
  // Inside the box, L-BFGS often ends with FAILURE or ROUNDOFF_LIMITED once the tolerance asks
  // for more than its line search can resolve, at a point that is nonetheless the optimum; so
  // convergence is judged by the score statistic, not the exit code (after the bound checks: at a
  // bound the gradient need not vanish).
  if (!(score < kConvergedScore)) {
    std::ostringstream reason;
    reason << "the optimiser did not converge (NLopt code " << static_cast<int>(result) << ", score statistic "
           << score << ")";
    fit.reason = reason.str();
    return fit;
  }
  fit.fitted = true;
  return fit;
}

double fragility_probability(const LognormalFit& fit, double im) {
  // Not a curve: 0 rather than NaN, so that a caller that forgets to check `fitted` gets no NaN.
  if (!fit.fitted || !(fit.median > 0.0) || !(fit.log_std > 0.0) || !(im > 0.0)) return 0.0;
  return normal_cdf(std::log(im / fit.median) / fit.log_std);
}

Band bootstrap_band(const StripeData& data, const std::vector<double>& im_grid, int replicates, double confidence,
                    std::uint64_t seed) {
  check_confidence(confidence);
  check_shape(data);
  if (replicates < 0) throw std::invalid_argument("bootstrap_band: replicates must be >= 0");
  Band band;
  band.im = im_grid;
  const std::size_t stripe_count = data.levels.size();
  // Motions without a single run (not yet simulated, or all runs dropped) carry no data; drawing
  // them would only make the replicates' sizes vary, so only motions with runs are resampled.
  std::vector<std::size_t> motions;
  for (std::size_t m = 0; m < data.trials.size(); ++m)
    if (std::any_of(data.trials[m].begin(), data.trials[m].end(), [](std::int64_t n) { return n > 0; }))
      motions.push_back(m);
  const std::size_t motion_count = motions.size();
  band.resampled = motion_count >= 2 ? "records" : (motion_count == 1 ? "realisations" : "");

  // curves[i][r]: successful replicate r at im_grid[i]
  std::vector<std::vector<double>> curves(im_grid.size());
  std::vector<std::int64_t> trials(stripe_count), counts(stripe_count);
  for (int replicate = 0; replicate < replicates && motion_count > 0; ++replicate) {
    const auto replicate_index = static_cast<std::uint32_t>(replicate);
    if (motion_count >= 2) {
      std::fill(trials.begin(), trials.end(), 0);
      std::fill(counts.begin(), counts.end(), 0);
      PhiloxStream stream = philox_stream(seed, replicate_index, 0u, kMotionStream);
      boost::random::uniform_int_distribution<std::size_t> pick_motion(0, motion_count - 1);
      for (std::size_t draw = 0; draw < motion_count; ++draw) {
        const std::size_t motion = motions[pick_motion(stream)];
        for (std::size_t j = 0; j < stripe_count; ++j) {
          trials[j] += data.trials[motion][j];
          counts[j] += data.counts[motion][j];
        }
      }
    } else {
      const std::size_t motion = motions.front();
      for (std::size_t j = 0; j < stripe_count; ++j) {
        trials[j] = data.trials[motion][j];
        counts[j] = 0;
        if (trials[j] == 0) continue;
        PhiloxStream stream = philox_stream(seed, replicate_index, static_cast<std::uint32_t>(j), kRealisationStream);
        const double fraction = static_cast<double>(data.counts[motion][j]) / static_cast<double>(trials[j]);
        boost::random::binomial_distribution<std::int64_t, double> resample(trials[j], fraction);
        counts[j] = resample(stream);
      }
    }
    const LognormalFit fit = fit_lognormal(data.levels, trials, counts);
    if (!fit.fitted) {
      ++band.failed_replicates;
      continue;
    }
    ++band.replicates;
    for (std::size_t i = 0; i < im_grid.size(); ++i) curves[i].push_back(fragility_probability(fit, im_grid[i]));
  }

  band.lower.assign(im_grid.size(), 0.0);  // no successful replicate: the uninformative band [0, 1]
  band.upper.assign(im_grid.size(), 1.0);
  if (band.replicates == 0) return band;
  for (std::size_t i = 0; i < im_grid.size(); ++i) {
    std::sort(curves[i].begin(), curves[i].end());
    band.lower[i] = sorted_quantile(curves[i], 0.5 * (1.0 - confidence));
    band.upper[i] = sorted_quantile(curves[i], 0.5 * (1.0 + confidence));
  }
  return band;
}

Misfit misfit(const LognormalFit& fit, const std::vector<StripeProbability>& stripes) {
  Misfit result;
  if (!fit.fitted) return result;  // degrees_of_freedom = 0 marks "not evaluated"
  int informative = 0;
  for (const StripeProbability& stripe : stripes) {
    if (stripe.trials <= 0) continue;
    ++informative;
    const double s = std::log(stripe.level / fit.median) / fit.log_std;
    const double fitted = normal_cdf(s), fitted_complement = normal_survival(s);
    const auto n = static_cast<double>(stripe.trials), z = static_cast<double>(stripe.count);
    result.max_abs_difference = std::max(result.max_abs_difference, std::abs(fitted - z / n));
    if (fitted < stripe.lower || fitted > stripe.upper) ++result.stripes_outside_interval;
    const double expected = n * fitted;
    const double variance = n * fitted * fitted_complement;
    const double residual = z - expected;
    if (variance > 0.0) {
      result.chi_square += residual * residual / variance;
    } else if (residual != 0.0) {
      // the fit says impossible (P underflows to 0 or 1) and it happened: infinitely unlikely
      result.chi_square = std::numeric_limits<double>::infinity();
    }
  }
  if (informative == 0) return result;
  result.degrees_of_freedom = std::max(1, informative - 2);
  if (std::isinf(result.chi_square)) {
    result.p_value = 0.0;
  } else {
    const boost::math::chi_squared_distribution<double> reference(result.degrees_of_freedom);
    result.p_value = boost::math::cdf(boost::math::complement(reference, result.chi_square));
  }
  return result;
}

}  // namespace caskdem::fragility
