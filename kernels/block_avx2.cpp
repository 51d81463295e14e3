// The block kernel compiled for avx2 (flags set in kernels/CMakeLists.txt).
#include "kernels/block_kernel.h"

namespace caskdem::kernels {
template void AdvanceBlock::operator()<xsimd::avx2>(xsimd::avx2, const Model&, BlockView, const double*, const double*,
                                                    std::int64_t, int) const;
}  // namespace caskdem::kernels
