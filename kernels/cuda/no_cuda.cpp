// The CUDA engine's entry points in a build without it (CASKDEM_WITH_CUDA off, or no nvcc when
// the build was configured): no device, and the reason.

#include <stdexcept>

#include "kernels/lane_device.h"

namespace caskdem {

namespace {
constexpr const char* kWithoutCuda =
    "this caskdem was built without CUDA (no nvcc when it was configured, or CASKDEM_WITH_CUDA=OFF)";
}

bool cuda_compiled() { return false; }

std::vector<CudaDeviceInfo> cuda_devices(std::string* why_none) {
  if (why_none) *why_none = kWithoutCuda;
  return {};
}

std::unique_ptr<LaneDevice> open_cuda_device(int) { throw std::runtime_error(kWithoutCuda); }

}  // namespace caskdem
