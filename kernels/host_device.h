#pragma once
// CASKDEM_HOST_DEVICE marks the functions the step calls, so that nvcc compiles them for the
// GPU as well as for the CPU (kernels/cuda/); every other compiler sees nothing.
// CASKDEM_ALWAYS_INLINE keeps a function out of the call graph on both.

#if defined(__CUDACC__)
#define CASKDEM_HOST_DEVICE __host__ __device__
#define CASKDEM_ALWAYS_INLINE __forceinline__
#else
#define CASKDEM_HOST_DEVICE
#define CASKDEM_ALWAYS_INLINE [[gnu::always_inline]] inline
#endif
