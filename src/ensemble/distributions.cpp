#include "ensemble/distributions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <boost/math/distributions/normal.hpp>

namespace caskdem {

namespace {

// Quantile of a normal truncated to [low, high] (in its own variable).
double truncated_normal_quantile(double mean, double std, double low, double high, double u) {
  const boost::math::normal_distribution<double> normal(mean, std);
  const double lower = std::isfinite(low) ? boost::math::cdf(normal, low) : 0.0;
  const double upper = std::isfinite(high) ? boost::math::cdf(normal, high) : 1.0;
  const double p = lower + u * (upper - lower);
  // Guard the ends: p of exactly 0 or 1 has no finite quantile.
  const double clamped = std::clamp(p, 1e-300, 1.0 - 1e-16);
  return std::clamp(boost::math::quantile(normal, clamped), low, high);
}

}  // namespace

double Distribution::quantile(double u) const {
  switch (kind) {
    case Kind::constant:
      return first;
    case Kind::uniform:
      return first + u * (second - first);
    case Kind::normal:
      return truncated_normal_quantile(first, second, low, high, u);
    case Kind::lognormal: {
      const double log_low = low > 0.0 ? std::log(low) : -std::numeric_limits<double>::infinity();
      const double log_high = std::isfinite(high) ? std::log(high) : std::numeric_limits<double>::infinity();
      return std::exp(truncated_normal_quantile(std::log(first), second, log_low, log_high, u));
    }
  }
  return first;
}

double Distribution::truncation_mass() const {
  if (kind != Kind::normal && kind != Kind::lognormal) return 1.0;
  const bool logarithmic = kind == Kind::lognormal;
  const boost::math::normal_distribution<double> normal(logarithmic ? std::log(first) : first, second);
  const double lower = logarithmic ? (low > 0.0 ? std::log(low) : -std::numeric_limits<double>::infinity()) : low;
  const double upper = logarithmic ? std::log(high) : high;
  const double below_high = std::isfinite(upper) ? boost::math::cdf(normal, upper) : 1.0;
  const double below_low = std::isfinite(lower) ? boost::math::cdf(normal, lower) : 0.0;
  return below_high - below_low;
}

double Distribution::lowest() const {
  switch (kind) {
    case Kind::constant: return first;
    case Kind::uniform: return first;
    case Kind::normal: return low;
    case Kind::lognormal: return std::max(0.0, low);
  }
  return first;
}

double Distribution::highest() const {
  switch (kind) {
    case Kind::constant: return first;
    case Kind::uniform: return second;
    case Kind::normal:
    case Kind::lognormal: return high;
  }
  return first;
}

std::string Distribution::describe() const {
  std::ostringstream out;
  switch (kind) {
    case Kind::constant: out << "constant " << first; break;
    case Kind::uniform: out << "uniform [" << first << ", " << second << "]"; break;
    case Kind::normal: out << "normal mean " << first << " std " << second; break;
    case Kind::lognormal: out << "lognormal median " << first << " log-std " << second; break;
  }
  if ((kind == Kind::normal || kind == Kind::lognormal) && (std::isfinite(low) || std::isfinite(high))) {
    out << " truncated to [" << low << ", " << high << "]";
  }
  return out.str();
}

}  // namespace caskdem
