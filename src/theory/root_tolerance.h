#pragma once
// Root finding in time with Boost.Math's TOMS 748 (Alefeld, Potra & Shi 1995). The bracket is
// narrow enough once it is below an absolute width, or below a few ulps of the time itself
// (a bracket around t = 1e4 s cannot be narrower than about 1e-12 s).

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace caskdem::theory {

struct TimeBracketTolerance {
  double absolute_width;  // s

  bool operator()(double a, double b) const {
    const double ulps = 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b));
    return std::abs(b - a) <= std::max(absolute_width, ulps);
  }
};

// Root of f in [a, b], where f(a) and f(b) have opposite signs (or one is 0). Returns the end of
// the final bracket on b's side, so a state evaluated there is already past the event.
template <class Function>
double locate_time(Function f, double a, double b, double f_a, double f_b, double absolute_width) {
  std::uintmax_t iterations = 200;
  return boost::math::tools::toms748_solve(f, a, b, f_a, f_b, TimeBracketTolerance{absolute_width}, iterations)
      .second;
}

}  // namespace caskdem::theory
