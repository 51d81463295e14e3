#pragma once
// Lane arithmetic. The step (kernels/step.h) is written once against these functions and
// compiles for T = double (one realisation: the scalar reference path, and one GPU thread's
// lane, kernels/cuda/) and for T = xsimd::batch<double, Arch> (one realisation per SIMD lane:
// the CPU ensemble path, kernels/lane_simd.h).
//
// Every function here is exact or correctly rounded (IEEE +,-,*,/,sqrt, compare, blend,
// min/max, abs, copysign, nearbyint), so the scalar path, every SIMD width and the GPU give
// the same bits, provided the build forbids FMA contraction (-ffp-contract=off, nvcc's
// -fmad=false). min/max follow the x86 minpd/maxpd rule (the second operand when either is
// NaN); the scalar overloads are written to match it.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "kernels/host_device.h"

namespace caskdem::lane {

template <class T>
struct Traits;

template <>
struct Traits<double> {
  using Mask = bool;
  using Index = std::int64_t;
  static constexpr std::size_t width = 1;
};

template <class T>
using Mask = typename Traits<T>::Mask;

// One array index per lane (a lane's position in a table of the table motion).
template <class T>
using Index = typename Traits<T>::Index;

template <class T>
inline constexpr std::size_t width = Traits<T>::width;

// ---- scalar (T = double) -------------------------------------------------------------
CASKDEM_HOST_DEVICE inline double select(bool mask, double if_true, double if_false) {
  return mask ? if_true : if_false;
}
CASKDEM_HOST_DEVICE inline double min(double a, double b) { return a < b ? a : b; }
CASKDEM_HOST_DEVICE inline double max(double a, double b) { return a > b ? a : b; }
CASKDEM_HOST_DEVICE inline double abs(double a) { return std::fabs(a); }
CASKDEM_HOST_DEVICE inline double sqrt(double a) { return std::sqrt(a); }
CASKDEM_HOST_DEVICE inline double copysign(double magnitude, double sign) { return std::copysign(magnitude, sign); }
CASKDEM_HOST_DEVICE inline double nearbyint(double a) { return std::nearbyint(a); }
CASKDEM_HOST_DEVICE inline bool isfinite(double a) { return std::isfinite(a); }
CASKDEM_HOST_DEVICE inline bool any(bool m) { return m; }
CASKDEM_HOST_DEVICE inline bool all(bool m) { return m; }

// 2^k, exactly, for integer-valued k in [-1022, 1023], built from the exponent bits:
// k + (2^52 + 1023) has the bit pattern 0x4330000000000000 + (k + 1023), and shifting it
// left by 52 leaves (k + 1023) in the exponent field of a double with a zero mantissa.
CASKDEM_HOST_DEVICE inline double power_of_two(double k) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(k + 4503599627371519.0) << 52;
  return std::bit_cast<double>(bits);
}

CASKDEM_HOST_DEVICE inline void store(double* field, double value) { *field = value; }
CASKDEM_HOST_DEVICE inline void store_index(std::int64_t* field, std::int64_t value) { *field = value; }

}  // namespace caskdem::lane

// The same functions for SIMD batches, on the CPU only: nvcc never reads xsimd.
#if !defined(__CUDACC__)
#include "kernels/lane_simd.h"
#endif

namespace caskdem::lane {

// ---- both ----------------------------------------------------------------------------
template <class T>
CASKDEM_HOST_DEVICE inline T broadcast(double value) {
  if constexpr (std::is_same_v<T, double>) {
    return value;
  } else {
    return T(value);
  }
}

// Aligned load of one lane (double) or one batch from a structure-of-arrays field.
template <class T>
CASKDEM_HOST_DEVICE inline T load(const double* field) {
  if constexpr (std::is_same_v<T, double>) {
    return *field;
  } else {
    return T::load_aligned(field);
  }
}

// Each lane's index array entry, and each lane's value of table[index]: lanes at different
// steps of their runs read the table motion at their own step.
template <class T>
CASKDEM_HOST_DEVICE inline Index<T> load_index(const std::int64_t* field) {
  if constexpr (std::is_same_v<T, double>) {
    return *field;
  } else {
    return Index<T>::load_aligned(field);
  }
}
template <class T>
CASKDEM_HOST_DEVICE inline T gather(const double* table, const Index<T>& index) {
  if constexpr (std::is_same_v<T, double>) {
    return table[index];
  } else {
    // Lane by lane, inlined: xsimd's gather compiled to a call that spilled the step's registers
    // (docs/performance.md, "The table motion's gather"). The same values.
    alignas(64) std::int64_t at[width<T>];
    alignas(64) double values[width<T>];
    index.store_aligned(at);
    for (std::size_t l = 0; l < width<T>; ++l) values[l] = table[at[l]];
    return T::load_aligned(values);
  }
}

template <class T>
CASKDEM_HOST_DEVICE inline T clamp(const T& value, const T& low, const T& high) {
  return min(max(value, low), high);
}

// Where sqrt(squared) > bound is surely false, decided without the root: squared is zero and
// the bound not negative, or squared < (bound (1 - 1e-12))^2, which keeps the root below the
// bound whatever the roundings of that square and of the root (each relative 2^-53) unless the
// square underflows (below DBL_MIN its rounding is no longer relative; an overflow to infinity
// is safe, as squared < infinity is finite and its root below 1.4e154). False where it cannot
// tell (and for NaN): the caller then takes the root. A batch where every lane is so skips a
// square root, and often the division that follows it, with the same bits.
template <class T>
CASKDEM_HOST_DEVICE inline Mask<T> root_not_above(const T& squared, const T& bound) {
  const T zero = broadcast<T>(0.0);
  const T inside = bound * broadcast<T>(1.0 - 1e-12);
  const T inside_squared = inside * inside;
  return (squared == zero && bound >= zero) ||
         (bound > zero && inside_squared >= broadcast<T>(std::numeric_limits<double>::min()) && squared < inside_squared);
}

// A mask as 1.0 / 0.0, for masks kept in double state arrays between steps.
template <class T>
CASKDEM_HOST_DEVICE inline T as_number(const Mask<T>& mask) {
  return select(mask, broadcast<T>(1.0), broadcast<T>(0.0));
}

}  // namespace caskdem::lane
