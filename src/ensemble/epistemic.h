#pragma once
// Aleatory and epistemic uncertainty apart (Kennedy and Ravindra 1984; EPRI TR-103959): the
// capacity is A = A_m e_R e_U, ln e_R ~ N(0, beta_R) varying from earthquake to earthquake
// (records, friction from place to place) and ln e_U ~ N(0, beta_U) fixed for this cask but
// unknown (its mean friction, its restitution). An ensemble with epistemic parameters samples
// M outer points of them; each outer point's stripes give a lognormal fit (ln A_j, beta_j).
// Then
//
//   ln A_m  = mean_j ln A_j
//   beta_R  = mean_j (beta_j - b_j)
//   beta_U^2 = var_j(ln A_j) - mean_j s_j^2      (0 when negative)
//
// where b_j is the bias of a maximum-likelihood beta at outer point j's design (it comes out
// low by a few per cent at tens of runs per stripe), estimated by a parametric bootstrap:
// counts drawn from the fit itself and refitted, 40 times, with Philox Bernoulli draws;
// and s_j^2 is the sampling variance of the fitted ln A_j (its statistical uncertainty,
// which would otherwise be counted as epistemic): the (ln median, ln median) element of the
// inverse expected Fisher information of the binomial probit likelihood at the fit,
//
//   I = sum_k w_k [1 z_k; z_k z_k^2] / beta^2,  w_k = n_k phi(z_k)^2 / (Phi(z_k)(1 - Phi(z_k))),
//   z_k = (ln x_k - ln A) / beta,  so  s^2 = beta^2 sum w z^2 / (sum w sum w z^2 - (sum w z)^2).
//
// The statistical uncertainty of the three is shown beside them, as intervals for M normal
// samples: Student's t with M - 1 degrees of freedom for ln A_m and beta_R (the spread of the
// outer points' values holds their fits' noise too), and chi-square with M - 1 for
// var_j(ln A_j) = beta_U^2 + s^2, less the noise as above. The outer points are taken as
// independent draws; a Latin hypercube over them spreads them more evenly, so the intervals
// are then conservative.

#include <cstdint>
#include <string>
#include <vector>

#include "ensemble/fragility.h"

namespace caskdem::fragility {

// s^2 above for a fitted curve over stripes at `levels` with `trials` runs each; +infinity
// when the stripes carry no information (every stripe far outside the curve).
double log_median_variance(const LognormalFit& fit, const std::vector<double>& levels,
                           const std::vector<std::int64_t>& trials);

struct NestedFit {
  bool fitted = false;
  std::string reason;  // why not, when not
  int outer_points = 0;
  double median = 0.0;  // A_m, in IM units
  double beta_r = 0.0;
  double beta_u = 0.0;
  double beta_c() const;
  double log_median_spread = 0.0;  // sd of the outer points' ln A_j (epistemic and statistical together)
  double fit_noise = 0.0;          // sqrt(mean_j s_j^2): the statistical part taken out of it
  double confidence = 0.0;         // of the intervals below
  double median_low = 0.0, median_high = 0.0;
  double beta_r_low = 0.0, beta_r_high = 0.0;
  double beta_u_low = 0.0, beta_u_high = 0.0;
  std::vector<double> outer_median, outer_log_std;  // each outer point's fit (0 and 0 where not fitted)
};

// trials[j][k] and counts[j][k]: outer point j, stripe k at levels[k]. Not fitted (with the
// reason) when fewer than 3 outer points are given or any outer point's stripes cannot be
// fitted (dropping it would bias A_m). The bias bootstrap draws from Philox keyed by `seed`.
// Throws std::invalid_argument for mismatched sizes or a confidence outside (0, 1).
NestedFit fit_nested(const std::vector<double>& levels, const std::vector<std::vector<std::int64_t>>& trials,
                     const std::vector<std::vector<std::int64_t>>& counts, double confidence, std::uint64_t seed);

}  // namespace caskdem::fragility
