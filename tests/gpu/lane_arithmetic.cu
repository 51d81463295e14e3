// The lane functions on the GPU (tests/gpu/lane_arithmetic.h), built with the engine's flags.

#include <cuda_runtime.h>

#include "lane_arithmetic.h"
#include "lane_arithmetic_kernel.h"

namespace caskdem::testing {

namespace {
__global__ void evaluate(const double* x, const double* y, long long n, double* out) {
  const long long i = static_cast<long long>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) lane_arithmetic(x[i], y[i], out + i * kLaneResults);
}

bool failed(cudaError_t status, const char* what, std::string* why) {
  if (status == cudaSuccess) return false;
  if (why) *why = std::string(what) + ": " + cudaGetErrorString(status);
  return true;
}
}  // namespace

bool lane_arithmetic_on_device(const std::vector<double>& x, const std::vector<double>& y, std::vector<double>& out,
                               std::string* why) {
  const std::size_t n = x.size();
  out.assign(n * kLaneResults, 0.0);
  double *dx = nullptr, *dy = nullptr, *dout = nullptr;
  bool ok = !failed(cudaMalloc(&dx, n * sizeof(double)), "cudaMalloc", why) &&
            !failed(cudaMalloc(&dy, n * sizeof(double)), "cudaMalloc", why) &&
            !failed(cudaMalloc(&dout, out.size() * sizeof(double)), "cudaMalloc", why) &&
            !failed(cudaMemcpy(dx, x.data(), n * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy", why) &&
            !failed(cudaMemcpy(dy, y.data(), n * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy", why);
  if (ok) {
    evaluate<<<static_cast<unsigned>((n + 127) / 128), 128>>>(dx, dy, static_cast<long long>(n), dout);
    ok = !failed(cudaGetLastError(), "launch", why) &&
         !failed(cudaMemcpy(out.data(), dout, out.size() * sizeof(double), cudaMemcpyDeviceToHost), "cudaMemcpy", why);
  }
  cudaFree(dx);
  cudaFree(dy);
  cudaFree(dout);
  return ok;
}

}  // namespace caskdem::testing
