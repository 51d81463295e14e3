#include "ensemble/distributions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <boost/math/distributions/normal.hpp>

namespace caskdem {

namespace {

// The normal behind a normal or lognormal distribution, in its own variable (ln x for a
// lognormal), with the truncation bounds in that variable.
struct UnderlyingNormal {
  boost::math::normal_distribution<double> normal;
  double lower, upper;

  double probability_below_lower() const { return std::isfinite(lower) ? boost::math::cdf(normal, lower) : 0.0; }
  double probability_below_upper() const { return std::isfinite(upper) ? boost::math::cdf(normal, upper) : 1.0; }
};

UnderlyingNormal underlying_normal(const Distribution& d) {
  if (d.kind == Distribution::Kind::normal) return {boost::math::normal_distribution<double>(d.first, d.second), d.low, d.high};
  constexpr double infinity = std::numeric_limits<double>::infinity();
  return {boost::math::normal_distribution<double>(std::log(d.first), d.second), d.low > 0.0 ? std::log(d.low) : -infinity,
          std::isfinite(d.high) ? std::log(d.high) : infinity};
}

// Quantile of the underlying normal truncated to [lower, upper].
double truncated_quantile(const UnderlyingNormal& n, double u) {
  const double lower = n.probability_below_lower();
  const double p = lower + u * (n.probability_below_upper() - lower);
  // Guard the ends: p of exactly 0 or 1 has no finite quantile.
  const double clamped = std::clamp(p, 1e-300, 1.0 - 1e-16);
  return std::clamp(boost::math::quantile(n.normal, clamped), n.lower, n.upper);
}

}  // namespace

double Distribution::quantile(double u) const {
  switch (kind) {
    case Kind::constant:
      return first;
    case Kind::uniform:
      return first + u * (second - first);
    case Kind::normal:
      return truncated_quantile(underlying_normal(*this), u);
    case Kind::lognormal:
      return std::exp(truncated_quantile(underlying_normal(*this), u));
  }
  return first;
}

double Distribution::truncation_mass() const {
  if (kind != Kind::normal && kind != Kind::lognormal) return 1.0;
  const UnderlyingNormal n = underlying_normal(*this);
  return n.probability_below_upper() - n.probability_below_lower();
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
