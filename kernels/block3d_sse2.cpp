// The 3D block kernel compiled for sse2 (flags set in kernels/CMakeLists.txt).
#include "kernels/block3d_kernel.h"

namespace caskdem::kernels {
CASKDEM_ADVANCE_BLOCK3D(sse2);
}  // namespace caskdem::kernels
