// The block kernel compiled for avx512f (flags set in kernels/CMakeLists.txt).
#include "kernels/block_kernel.h"

namespace caskdem::kernels {
template void AdvanceBlock::operator()<xsimd::avx512f>(xsimd::avx512f, const Model&, BlockView, const double*, const double*,
                                                    std::int64_t, int) const;
}  // namespace caskdem::kernels
