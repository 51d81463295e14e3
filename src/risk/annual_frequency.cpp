#include "risk/annual_frequency.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <boost/math/distributions/normal.hpp>

#include "core/text.h"

namespace caskdem::risk {

namespace {

constexpr double kCoverage = 0.01;          // the part beyond the curve allowed, of the answer
constexpr double kHclpfZ = 1.6448536269514722;     // Phi^-1(0.95)
constexpr double kOnePercentZ = 2.3263478740408408;  // Phi^-1(0.99)

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// ln Phi(z), finite far into the lower tail (where Phi underflows but a steep hazard continued
// below its first point can still outgrow it): the asymptotic series there (Abramowitz and
// Stegun 26.2.12) to its z^-6 term, whose first term left out, 105 / z^8, is 2e-10 at z = -30.
double log_normal_cdf(double z) {
  if (z > -30.0) return std::log(normal_cdf(z));
  const double z2 = z * z;
  return -0.5 * z2 - std::log(-z) - 0.5 * std::log(2.0 * std::numbers::pi) + std::log1p(-1.0 / z2 + 3.0 / (z2 * z2) - 15.0 / (z2 * z2 * z2));
}

// The hazard as power laws in x = ln a: on segment i (and continued beyond the ends),
// H(x) = H_i exp(-k_i (x - x_i)).
struct LogLogHazard {
  std::vector<double> x, log_h, slope;  // slope[i]: k on [x_i, x_i+1]
  explicit LogLogHazard(const HazardCurve& curve) {
    for (std::size_t i = 0; i < curve.intensity.size(); ++i) {
      x.push_back(std::log(curve.intensity[i]));
      log_h.push_back(std::log(curve.annual_frequency[i]));
    }
    for (std::size_t i = 0; i + 1 < x.size(); ++i) slope.push_back(-(log_h[i + 1] - log_h[i]) / (x[i + 1] - x[i]));
  }
  std::size_t last() const { return x.size() - 1; }
  // ln H at x on the power law of segment i (i = last: the last segment continued).
  double log_hazard(std::size_t i, double at) const {
    return log_h[i] - slope[std::min(i, slope.size() - 1)] * (at - x[i]);
  }
};

// The integral of F(x) |dH/dx| over [a, b] on the power law of segment i, in closed form. With
// u = (x - m) / beta, v = u + k beta and G = H_i exp(-k (m - x_i) + k^2 beta^2 / 2) (G phi(v) =
// H phi(u), so d/dx [G Phi(v)] = H phi(u) / beta), integration by parts of k H Phi(u) gives
//   I = H(a) Phi(u_a) - H(b) Phi(u_b) + G (Phi(v_b) - Phi(v_a)),
// and with Phi = 1 - Q (Q the upper tail) the same identity for k H Q gives
//   I = H(a) - H(b) - [H(a) Q(u_a) - H(b) Q(u_b) - G (Q(v_a) - Q(v_b))].
// The first form is used below the median (u <= 0), the second above, each term as the
// exponential of its logarithm, so that no tail underflows early and no factor overflows alone.
// a may be -infinity and b +infinity (the curve's ends continued). Zero on a flat segment.
double segment_integral(const LogLogHazard& h, std::size_t i, double a, double b, double m, double beta) {
  const double k = h.slope[std::min(i, h.slope.size() - 1)];
  if (!(k > 0.0) || !(b > a)) return 0.0;
  const double log_g = h.log_h[i] - k * (m - h.x[i]) + 0.5 * k * k * beta * beta;
  // H(x) Phi(u), H(x) Q(u) and G Phi(v), G Q(v) at an end, 0 where x is infinite.
  const auto hazard_times = [&](double x, bool upper) {
    if (std::isinf(x)) return 0.0;  // the Gaussian tail below, the falling power law above
    const double u = (x - m) / beta;
    return std::exp(h.log_hazard(i, x) + log_normal_cdf(upper ? -u : u));
  };
  const auto g_times = [&](double x, bool upper) {
    if (std::isinf(x)) return (x > 0.0) != upper ? std::exp(log_g) : 0.0;
    const double v = (x - m) / beta + k * beta;
    return std::exp(log_g + log_normal_cdf(upper ? -v : v));
  };
  if (b <= m) return hazard_times(a, false) - hazard_times(b, false) + (g_times(b, false) - g_times(a, false));
  if (a >= m) {
    const double fall = (std::isinf(a) ? INFINITY : std::exp(h.log_hazard(i, a))) - (std::isinf(b) ? 0.0 : std::exp(h.log_hazard(i, b)));
    return fall - (hazard_times(a, true) - hazard_times(b, true) - (g_times(a, true) - g_times(b, true)));
  }
  return segment_integral(h, i, a, m, m, beta) + segment_integral(h, i, m, b, m, beta);
}

}  // namespace

double LognormalFragility::beta_c() const { return std::sqrt(beta_r * beta_r + beta_u * beta_u); }

double LognormalFragility::probability(double intensity, double confidence) const {
  if (intensity <= 0.0) return 0.0;
  if (confidence == 0.0) return normal_cdf(std::log(intensity / median) / beta_c());
  const double z = boost::math::quantile(boost::math::normal(), confidence);
  return normal_cdf((std::log(intensity / median) + beta_u * z) / beta_r);
}

void check_fragility(const LognormalFragility& f) {
  if (!std::isfinite(f.median) || f.median <= 0.0) throw std::invalid_argument("the fragility's median must be above 0");
  if (!(f.beta_r > 0.0 && f.beta_r <= 5.0)) throw std::invalid_argument("beta_R must be in (0, 5]");
  if (!(f.beta_u >= 0.0 && f.beta_u <= 5.0)) throw std::invalid_argument("beta_U must be in [0, 5]");
}

double hclpf_conservative(const LognormalFragility& f) { return f.median * std::exp(-kHclpfZ * (f.beta_r + f.beta_u)); }
double hclpf_composite(const LognormalFragility& f) { return f.median * std::exp(-kOnePercentZ * f.beta_c()); }

FrequencyIntegral convolve(const HazardCurve& hazard, double median, double beta) {
  check_hazard_curve(hazard);
  if (!std::isfinite(median) || median <= 0.0 || !(beta > 0.0) || !std::isfinite(beta))
    throw std::invalid_argument("a fragility needs a median above 0 and a log standard deviation above 0");
  const LogLogHazard h(hazard);
  const double m = std::log(median);
  const auto fragility = [&](double x) { return normal_cdf((x - m) / beta); };
  FrequencyIntegral result;
  result.below_curve = segment_integral(h, 0, -INFINITY, h.x.front(), m, beta);
  result.segment_frequency.reserve(h.slope.size());
  for (std::size_t i = 0; i + 1 < h.x.size(); ++i) {
    result.segment_frequency.push_back(segment_integral(h, i, h.x[i], h.x[i + 1], m, beta));
  }
  const std::size_t n = h.last();
  result.above_curve = segment_integral(h, n, h.x[n], INFINITY, m, beta);
  result.undetermined_above = hazard.annual_frequency.back() * (1.0 - fragility(h.x[n]));
  result.annual_frequency = result.below_curve + result.above_curve;
  for (double s : result.segment_frequency) result.annual_frequency += s;
  // A curve whose end segment is steep enough continues, below its first point, to
  // frequencies that outgrow any fragility's tail: no answer.
  if (!std::isfinite(result.annual_frequency))
    throw std::invalid_argument("the hazard curve continued below its first point (slope " + number_text(h.slope.front()) +
                                " in log-log) grows faster than the fragility falls: expected a curve reaching down to "
                                "intensities where the fragility is negligible");
  return result;
}

namespace {

// Refuses a curve whose ends leave more than kCoverage of `integral` unsettled, saying about
// where it would have to reach.
void check_coverage(const HazardCurve& hazard, double median, double beta, const FrequencyIntegral& integral,
                    const std::string& which) {
  const LogLogHazard h(hazard);
  const double total = integral.annual_frequency, m = std::log(median);
  const std::string unit = display_unit(hazard.measure);
  const double to_unit = 1.0 / display_unit_to_si(hazard.measure);
  if (integral.undetermined_above > kCoverage * total) {
    // Where the continued curve would leave less than kCoverage unsettled.
    double x = h.x.back();
    for (int j = 0; j < 2000; ++j, x += 0.01) {
      const double rest = std::exp(h.log_h.back() - h.slope.back() * (x - h.x.back())) * (1.0 - normal_cdf((x - m) / beta));
      if (rest <= kCoverage * total) break;
    }
    throw std::invalid_argument(
        "the hazard curve ends at " + number_text(hazard.intensity.back() * to_unit) + " " + unit + ", where the " + which +
        " fragility is " + number_text(normal_cdf((h.x.back() - m) / beta)) + ": the part above it that no curve can " +
        "settle, up to " + number_text(integral.undetermined_above) + " per year, is " +
        number_text(100.0 * integral.undetermined_above / total) + " % of the annual frequency; expected a curve reaching " +
        "about " + number_text(std::exp(x) * to_unit) + " " + unit + " or beyond (1 % unsettled)");
  }
  if (integral.below_curve > kCoverage * total) {
    double x = h.x.front();
    for (int j = 0; j < 2000; ++j, x -= 0.01) {
      if (segment_integral(h, 0, -INFINITY, x, m, beta) <= kCoverage * total) break;
    }
    throw std::invalid_argument(
        "the hazard curve starts at " + number_text(hazard.intensity.front() * to_unit) + " " + unit + ", where the " +
        which + " fragility is already " + number_text(normal_cdf((h.x.front() - m) / beta)) +
        ": the part below it (the first segment continued) is " + number_text(100.0 * integral.below_curve / total) +
        " % of the annual frequency; expected a curve starting at about " + number_text(std::exp(x) * to_unit) + " " +
        unit + " or below (1 % continued)");
  }
}

}  // namespace

SiteRisk site_risk(const HazardCurve& hazard, const LognormalFragility& fragility) {
  check_fragility(fragility);
  SiteRisk risk;
  risk.fragility = fragility;
  risk.mean_integral = convolve(hazard, fragility.median, fragility.beta_c());
  check_coverage(hazard, fragility.median, fragility.beta_c(), risk.mean_integral, "mean");
  risk.mean = risk.mean_integral.annual_frequency;
  // The family's members: median A_m exp(beta_U z), the q fractile at z = Phi^-1(1 - q).
  const auto member = [&](double z, const char* which) {
    const double median = fragility.median * std::exp(fragility.beta_u * z);
    const FrequencyIntegral integral = convolve(hazard, median, fragility.beta_r);
    check_coverage(hazard, median, fragility.beta_r, integral, which);
    return integral.annual_frequency;
  };
  risk.median = member(0.0, "median");
  risk.fractile_95 = fragility.beta_u > 0.0 ? member(-kHclpfZ, "95 % fractile") : risk.median;
  risk.fractile_05 = fragility.beta_u > 0.0 ? member(kHclpfZ, "5 % fractile") : risk.median;
  risk.hclpf_conservative = hclpf_conservative(fragility);
  risk.hclpf_composite = hclpf_composite(fragility);
  return risk;
}

}  // namespace caskdem::risk
