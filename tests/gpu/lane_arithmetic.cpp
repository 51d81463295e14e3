// The lane functions on the host: the reference the GPU's must equal bit for bit.

#include "lane_arithmetic.h"

#include "lane_arithmetic_kernel.h"

namespace caskdem::testing {

std::vector<double> lane_arithmetic_on_host(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> out(x.size() * kLaneResults);
  for (std::size_t i = 0; i < x.size(); ++i) lane_arithmetic(x[i], y[i], out.data() + i * kLaneResults);
  return out;
}

#if !defined(CASKDEM_WITH_CUDA)
bool lane_arithmetic_on_device(const std::vector<double>&, const std::vector<double>&, std::vector<double>&,
                               std::string* why) {
  if (why) *why = "this build has no CUDA engine";
  return false;
}
#endif

}  // namespace caskdem::testing
