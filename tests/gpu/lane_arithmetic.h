#pragma once
// The lane functions the step is built from (kernels/lane.h, kernels/portable_math.h), evaluated
// on a GPU for the arithmetic check of tests/gpu/test_gpu.cpp: where a GPU run and the CPU
// disagree, this says which operation does.

#include <string>
#include <vector>

namespace caskdem::testing {

// The results per input pair (x, y), kLaneResults of them, in this order.
inline constexpr int kLaneResults = 10;
inline const char* const kLaneResultNames[kLaneResults] = {"sin_cos(x).sin", "sin_cos(x).cos", "exp_negative(|x|)",
                                                           "min(x, y)",      "max(x, y)",      "nearbyint(x)",
                                                           "sqrt(|x|)",      "x / y",          "copysign(|x|, y)",
                                                           "power_of_two(k)"};

// On the host (the reference) and on the first CUDA device; the device's false, with the reason,
// when there is none.
std::vector<double> lane_arithmetic_on_host(const std::vector<double>& x, const std::vector<double>& y);
bool lane_arithmetic_on_device(const std::vector<double>& x, const std::vector<double>& y, std::vector<double>& out,
                               std::string* why);

}  // namespace caskdem::testing
