#pragma once
// The annual frequency of a limit state at a site: a lognormal fragility convolved with the
// site's hazard curve (Cornell 1968; Kennedy and Ravindra 1984, "Seismic fragilities for
// nuclear power plant risk studies", Nucl. Eng. Des. 79):
//
//   lambda_F = integral over a of F(a) |dH(a)/da| da,   F(a) = Phi(ln(a / A_m) / beta)
//
// H is interpolated log-log between its points (a power law H_i (a / a_i)^-k_i on each
// segment), so with x = ln a, |dH| = k_i H(a) dx, and each segment's integral of the lognormal
// F against it has a closed form (annual_frequency.cpp, segment_integral): exact to rounding,
// and linear in the curve's points. Beyond the
// curve's ends the end segments' power laws are continued; what they add is reported apart,
// and the part above the last point that no continuation can settle, H(a_n) (1 - F(a_n))
// (the integral above a_n lies between F(a_n) H(a_n) and H(a_n) for any hazard that falls to
// 0), must stay below 1 % of the answer, as must the continuation below the first point:
// otherwise the curve does not cover the fragility and the answer is refused.
//
// For a power-law hazard H = k0 a^-k the integral is H(A_m) exp(k^2 beta^2 / 2) exactly.
//
// Aleatory and epistemic uncertainty (Kennedy and Ravindra 1984): the capacity is
// A = A_m e_R e_U with ln e_R ~ N(0, beta_R) (record to record) and ln e_U ~ N(0, beta_U)
// (what we do not know about this cask). A member of the family of fragility curves has median
// A_m exp(beta_U z) and log standard deviation beta_R; its annual frequency falls as z rises,
// so the q fractile of the annual frequency is the member at z = Phi^-1(1 - q). The mean
// annual frequency is that of the composite curve, beta_C = sqrt(beta_R^2 + beta_U^2).
// HCLPF (high confidence of a low probability of failure): A_m exp(-1.645 (beta_R + beta_U))
// (95 % confidence of at most 5 % failure), and the 1 % point of the composite curve,
// A_m exp(-2.326 beta_C) (EPRI TR-103959).

#include <string>
#include <vector>

#include "risk/hazard_curve.h"

namespace caskdem::risk {

struct LognormalFragility {
  double median = 0.0;  // A_m, SI (m/s^2 or m/s)
  double beta_r = 0.0;  // aleatory log standard deviation
  double beta_u = 0.0;  // epistemic log standard deviation (0: not separated)

  double beta_c() const;
  // The member curve at confidence q (0.5: the median curve; 0.95: the curve the fragility is
  // below with 95 % confidence, median A_m exp(-1.645 beta_U)), or the composite curve when
  // q is 0 (the mean over the family).
  double probability(double intensity, double confidence) const;
};

// Throws std::invalid_argument unless the median is finite and > 0, beta_r in (0, 5] and
// beta_u in [0, 5].
void check_fragility(const LognormalFragility& fragility);

double hclpf_conservative(const LognormalFragility& fragility);  // A_m exp(-1.645 (beta_R + beta_U))
double hclpf_composite(const LognormalFragility& fragility);     // A_m exp(-2.326 beta_C)

// One convolution of a lognormal curve (median, beta) with the hazard.
struct FrequencyIntegral {
  double annual_frequency = 0.0;          // 1/year
  double below_curve = 0.0;               // the part from the continuation below the first point
  double above_curve = 0.0;               // the part from the continuation above the last point
  double undetermined_above = 0.0;        // H(a_n) (1 - F(a_n)): what the curve cannot settle above it
  std::vector<double> segment_frequency;  // the part from each segment [a_i, a_i+1] of the curve
};

// Throws std::invalid_argument for a malformed curve or fragility; never refuses for coverage
// (site_risk does).
FrequencyIntegral convolve(const HazardCurve& hazard, double median, double beta);

struct SiteRisk {
  LognormalFragility fragility;
  double mean = 0.0;         // annual frequency of the composite curve
  double median = 0.0;       // of the median member (z = 0)
  double fractile_05 = 0.0;  // 5 % and 95 % fractiles over the epistemic family
  double fractile_95 = 0.0;
  FrequencyIntegral mean_integral;  // with its disaggregation by segment
  double hclpf_conservative = 0.0;
  double hclpf_composite = 0.0;
};

// The mean, median and fractile annual frequencies and the HCLPF capacities. Throws
// std::invalid_argument saying which end the curve must reach, and about where, when the
// parts beyond it exceed 1 % of the mean or of a fractile.
SiteRisk site_risk(const HazardCurve& hazard, const LognormalFragility& fragility);

}  // namespace caskdem::risk
