// The block kernel compiled for sse2 (flags set in kernels/CMakeLists.txt).
#include "kernels/block_kernel.h"

namespace caskdem::kernels {
template void AdvanceBlock::operator()<xsimd::sse2>(xsimd::sse2, const Model&, BlockView, const double*, const double*,
                                                    std::int64_t, int) const;
}  // namespace caskdem::kernels
