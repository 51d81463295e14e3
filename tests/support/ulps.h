#pragma once
// How many units in the last place b's neighbourhood a is from b: the elementary-function tests'
// measure of agreement with the C library.

#include <cmath>

namespace caskdem::testing {

inline double ulps_apart(double a, double b) {
  if (a == b) return 0.0;
  return std::abs(a - b) / std::abs(std::nextafter(b, 2.0 * b + 1.0) - b);
}

}  // namespace caskdem::testing
