#pragma once
// One input pair's results (tests/gpu/lane_arithmetic.h), the same source for host and device.

#include <cmath>

#include "kernels/lane.h"
#include "kernels/portable_math.h"

namespace caskdem::testing {

CASKDEM_HOST_DEVICE inline void lane_arithmetic(double x, double y, double* out) {
  const kernels::SinCos<double> r = kernels::sin_cos(x);
  out[0] = r.sin;
  out[1] = r.cos;
  out[2] = kernels::exp_negative(lane::abs(x));
  out[3] = lane::min(x, y);
  out[4] = lane::max(x, y);
  out[5] = lane::nearbyint(x);
  out[6] = lane::sqrt(lane::abs(x));
  out[7] = x / y;
  out[8] = lane::copysign(lane::abs(x), y);
  // 2^k for an integer-valued k in [-1022, 1023], as the exponential's reconstruction makes it.
  out[9] = lane::power_of_two(lane::clamp(lane::nearbyint(x), -1022.0, 1023.0));
}

}  // namespace caskdem::testing
