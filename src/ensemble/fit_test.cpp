#include "ensemble/fit_test.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/special_functions/beta.hpp>

#include "ensemble/sampling.h"

namespace caskdem::fragility {

namespace {

constexpr double kHighestRho = 0.99;
// Counter streams of the bootstrap's draws (ensemble/sampling.h, philox_uniform).
constexpr std::uint64_t kCellProbabilityStream = 0, kCellCountStream = 1;

double normal_cdf(double s) { return 0.5 * std::erfc(-s / std::sqrt(2.0)); }

void check_cells(const std::vector<Cell>& cells) {
  for (const Cell& c : cells) {
    if (!(c.level > 0.0) || !std::isfinite(c.level)) throw std::invalid_argument("fit test: levels must be finite and > 0");
    if (c.trials < 0 || c.count < 0 || c.count > c.trials)
      throw std::invalid_argument("fit test: need 0 <= count <= trials in every cell");
    if (c.stripe < 0) throw std::invalid_argument("fit test: a cell's stripe must be >= 0");
  }
}

double probability(const LognormalFit& fit, double level) {
  return normal_cdf(std::log(level / fit.median) / fit.log_std);
}

// Pearson's chi-square of the stripe totals against the curve, and the stripes it covered.
double stripe_chi_square(const LognormalFit& fit, const std::vector<Cell>& cells, int& stripes) {
  std::map<int, std::array<double, 3>> by_stripe;  // observed, expected, variance
  for (const Cell& c : cells) {
    if (c.trials == 0) continue;
    const double p = probability(fit, c.level), n = static_cast<double>(c.trials);
    auto& s = by_stripe[c.stripe];
    s[0] += static_cast<double>(c.count);
    s[1] += n * p;
    s[2] += n * p * (1.0 - p);
  }
  double total = 0.0;
  for (const auto& [stripe, s] : by_stripe) {
    const double residual = s[0] - s[1];
    if (s[2] > 0.0) {
      total += residual * residual / s[2];
    } else if (std::abs(residual) > 0.5) {
      return std::numeric_limits<double>::infinity();  // the curve says impossible, and it happened
    }
  }
  stripes = static_cast<int>(by_stripe.size());
  return total;
}

// rho and n0 of the header's ANOVA estimator, on residuals from the curve centred per stripe.
// Returns false when it cannot be estimated (every stripe a single cell, or no run left within
// cells).
bool intraclass_correlation(const LognormalFit& fit, const std::vector<Cell>& cells, double& rho, double& n0) {
  std::map<int, std::array<double, 3>> stripe;  // runs, sum n r, sum n^2
  double runs = 0.0, within = 0.0;
  int informative = 0;
  for (const Cell& c : cells) {
    if (c.trials == 0) continue;
    const double n = static_cast<double>(c.trials), z = static_cast<double>(c.count);
    auto& s = stripe[c.stripe];
    s[0] += n;
    s[1] += n * (z / n - probability(fit, c.level));
    s[2] += n * n;
    runs += n;
    within += z * (n - z) / n;
    ++informative;
  }
  const double between_df = informative - static_cast<double>(stripe.size());
  const double within_df = runs - informative;
  if (between_df < 1.0 || within_df < 1.0) return false;
  double between = 0.0, size_sum = 0.0;
  for (const Cell& c : cells) {
    if (c.trials == 0) continue;
    const double n = static_cast<double>(c.trials), z = static_cast<double>(c.count);
    const auto& s = stripe.at(c.stripe);
    const double residual = z / n - probability(fit, c.level) - s[1] / s[0];
    between += n * residual * residual;
  }
  for (const auto& [index, s] : stripe) size_sum += s[2] / s[0];
  const double msb = between / between_df, msw = within / within_df;
  n0 = (runs - size_sum) / between_df;
  const double denominator = msb + (n0 - 1.0) * msw;
  rho = denominator > 0.0 ? std::clamp((msb - msw) / denominator, 0.0, kHighestRho) : 0.0;
  return true;
}

}  // namespace

LognormalFit fit_cells(const std::vector<Cell>& cells, const LevelText& level_text) {
  check_cells(cells);
  std::vector<double> levels;
  std::vector<std::int64_t> trials, counts;
  for (const Cell& c : cells) {
    levels.push_back(c.level);
    trials.push_back(c.trials);
    counts.push_back(c.count);
  }
  return fit_lognormal(levels, trials, counts, level_text);
}

FitTest test_fit(const LognormalFit& fit, const std::vector<Cell>& cells, int replicates, std::uint64_t seed) {
  check_cells(cells);
  FitTest test;
  if (!fit.fitted) return test;
  int stripes = 0;
  test.chi_square = stripe_chi_square(fit, cells, stripes);
  if (stripes == 0) return test;
  test.evaluated = true;
  test.degrees_of_freedom = std::max(1, stripes - 2);
  test.binomial_p = std::isinf(test.chi_square)
                        ? 0.0
                        : boost::math::cdf(boost::math::complement(
                              boost::math::chi_squared_distribution<double>(test.degrees_of_freedom), test.chi_square));
  double n0 = 1.0;
  test.record_to_record_estimated = intraclass_correlation(fit, cells, test.record_to_record, n0);
  const double rho = test.record_to_record;
  test.design_effect = 1.0 + std::max(0.0, n0 - 1.0) * rho;

  // The bootstrap: beta-binomial cells about the curve, refitted.
  using Binomial = boost::math::binomial_distribution<double,
      boost::math::policies::policy<boost::math::policies::discrete_quantile<boost::math::policies::integer_round_up>>>;
  std::vector<Cell> replicate = cells;
  int as_large = 0;
  for (int r = 0; r < replicates; ++r) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      replicate[c].count = 0;
      if (cells[c].trials == 0) continue;
      double p = probability(fit, cells[c].level);
      if (rho > 0.0 && p > 0.0 && p < 1.0) {
        const double a = p * (1.0 - rho) / rho, b = (1.0 - p) * (1.0 - rho) / rho;
        p = boost::math::ibeta_inv(a, b, philox_uniform(seed, std::uint64_t(r), c, kCellProbabilityStream));
      }
      if (p <= 0.0) continue;
      if (p >= 1.0) {
        replicate[c].count = cells[c].trials;
        continue;
      }
      const double u = philox_uniform(seed, std::uint64_t(r), c, kCellCountStream);
      replicate[c].count = static_cast<std::int64_t>(
          boost::math::quantile(Binomial(static_cast<double>(cells[c].trials), p), u));
    }
    const LognormalFit refit = fit_cells(replicate);
    if (!refit.fitted) continue;
    int replicate_stripes = 0;
    if (stripe_chi_square(refit, replicate, replicate_stripes) >= test.chi_square) ++as_large;
    ++test.replicates;
  }
  test.p_value = test.replicates > 0 ? (1.0 + as_large) / (1.0 + test.replicates) : test.binomial_p;
  test.rejected = test.p_value < kRejectionLevel;
  return test;
}

std::string fit_test_text(const FitTest& test) {
  if (!test.evaluated) return "fit not tested";
  std::ostringstream out;
  out << std::setprecision(3);
  out << (test.rejected ? "fit REJECTED at " : "fit holds at ") << 100.0 * kRejectionLevel << " % (p " << test.p_value
      << " with motions clustered";
  if (test.record_to_record_estimated) {
    out << "; record to record " << test.record_to_record << " of an outcome's variance, design effect "
        << test.design_effect;
  } else {
    out << "; one motion: record to record not estimable";
  }
  out << "; binomial p " << test.binomial_p << ")";
  return out.str();
}

}  // namespace caskdem::fragility
