#pragma once
// Lane arithmetic. The step (kernels/step.h) is written once against these functions and
// compiles for T = double (one realisation: the scalar reference path) and for
// T = xsimd::batch<double, Arch> (one realisation per SIMD lane: the ensemble path).
//
// Every function here is exact or correctly rounded (IEEE +,-,*,/,sqrt, compare, blend,
// min/max, abs, copysign, nearbyint), so the scalar path and every SIMD width give the
// same bits, provided the build forbids FMA contraction (-ffp-contract=off).
// min/max follow the x86 minpd/maxpd rule (the second operand when either is NaN);
// the scalar overloads are written to match it.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <xsimd/xsimd.hpp>

namespace caskdem::lane {

template <class T>
struct Traits;

template <>
struct Traits<double> {
  using Mask = bool;
  using Index = std::int64_t;
  static constexpr std::size_t width = 1;
};

template <class Arch>
struct Traits<xsimd::batch<double, Arch>> {
  using Mask = xsimd::batch_bool<double, Arch>;
  using Index = xsimd::batch<std::int64_t, Arch>;
  static constexpr std::size_t width = xsimd::batch<double, Arch>::size;
};

template <class T>
using Mask = typename Traits<T>::Mask;

// One array index per lane (a lane's position in a table of the table motion).
template <class T>
using Index = typename Traits<T>::Index;

template <class T>
inline constexpr std::size_t width = Traits<T>::width;

// ---- scalar (T = double) -------------------------------------------------------------
inline double select(bool mask, double if_true, double if_false) { return mask ? if_true : if_false; }
inline double min(double a, double b) { return a < b ? a : b; }
inline double max(double a, double b) { return a > b ? a : b; }
inline double abs(double a) { return std::fabs(a); }
inline double sqrt(double a) { return std::sqrt(a); }
inline double copysign(double magnitude, double sign) { return std::copysign(magnitude, sign); }
inline double nearbyint(double a) { return std::nearbyint(a); }
inline bool isfinite(double a) { return std::isfinite(a); }
inline bool any(bool m) { return m; }
inline bool all(bool m) { return m; }

// ---- wide (T = xsimd::batch<double, Arch>) -------------------------------------------
template <class A>
inline xsimd::batch<double, A> select(const xsimd::batch_bool<double, A>& mask, const xsimd::batch<double, A>& if_true,
                                      const xsimd::batch<double, A>& if_false) {
  return xsimd::select(mask, if_true, if_false);
}
template <class A>
inline xsimd::batch<double, A> min(const xsimd::batch<double, A>& a, const xsimd::batch<double, A>& b) {
  return xsimd::min(a, b);
}
template <class A>
inline xsimd::batch<double, A> max(const xsimd::batch<double, A>& a, const xsimd::batch<double, A>& b) {
  return xsimd::max(a, b);
}
template <class A>
inline xsimd::batch<double, A> abs(const xsimd::batch<double, A>& a) {
  return xsimd::abs(a);
}
template <class A>
inline xsimd::batch<double, A> sqrt(const xsimd::batch<double, A>& a) {
  return xsimd::sqrt(a);
}
template <class A>
inline xsimd::batch<double, A> copysign(const xsimd::batch<double, A>& magnitude, const xsimd::batch<double, A>& sign) {
  return xsimd::copysign(magnitude, sign);
}
template <class A>
inline xsimd::batch<double, A> nearbyint(const xsimd::batch<double, A>& a) {
  return xsimd::nearbyint(a);
}
template <class A>
inline xsimd::batch_bool<double, A> isfinite(const xsimd::batch<double, A>& a) {
  return xsimd::isfinite(a);
}
template <class A>
inline bool any(const xsimd::batch_bool<double, A>& m) {
  return xsimd::any(m);
}
template <class A>
inline bool all(const xsimd::batch_bool<double, A>& m) {
  return xsimd::all(m);
}

// 2^k, exactly, for integer-valued k in [-1022, 1023], built from the exponent bits:
// k + (2^52 + 1023) has the bit pattern 0x4330000000000000 + (k + 1023), and shifting it
// left by 52 leaves (k + 1023) in the exponent field of a double with a zero mantissa.
inline double power_of_two(double k) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(k + 4503599627371519.0) << 52;
  return std::bit_cast<double>(bits);
}
template <class A>
inline xsimd::batch<double, A> power_of_two(const xsimd::batch<double, A>& k) {
  using Bits = xsimd::batch<std::uint64_t, A>;
  const Bits bits = xsimd::bitwise_cast<Bits>(k + xsimd::batch<double, A>(4503599627371519.0)) << 52;
  return xsimd::bitwise_cast<xsimd::batch<double, A>>(bits);
}

template <class A>
inline void store(double* field, const xsimd::batch<double, A>& value) {
  value.store_aligned(field);
}

// ---- both ----------------------------------------------------------------------------
template <class T>
inline T broadcast(double value) {
  if constexpr (std::is_same_v<T, double>) {
    return value;
  } else {
    return T(value);
  }
}

// Aligned load and store of one lane (double) or one batch from a structure-of-arrays field.
template <class T>
inline T load(const double* field) {
  if constexpr (std::is_same_v<T, double>) {
    return *field;
  } else {
    return T::load_aligned(field);
  }
}
inline void store(double* field, double value) { *field = value; }

// Each lane's index array entry, and each lane's value of table[index]: lanes at different
// steps of their runs read the table motion at their own step.
template <class T>
inline Index<T> load_index(const std::int64_t* field) {
  if constexpr (std::is_same_v<T, double>) {
    return *field;
  } else {
    return Index<T>::load_aligned(field);
  }
}
inline void store_index(std::int64_t* field, std::int64_t value) { *field = value; }
template <class A>
inline void store_index(std::int64_t* field, const xsimd::batch<std::int64_t, A>& value) {
  value.store_aligned(field);
}
template <class T>
inline T gather(const double* table, const Index<T>& index) {
  if constexpr (std::is_same_v<T, double>) {
    return table[index];
  } else {
    return T::gather(table, index);
  }
}

template <class T>
inline T clamp(const T& value, const T& low, const T& high) {
  return min(max(value, low), high);
}

// A mask as 1.0 / 0.0, for masks kept in double state arrays between steps.
template <class T>
inline T as_number(const Mask<T>& mask) {
  return select(mask, broadcast<T>(1.0), broadcast<T>(0.0));
}

}  // namespace caskdem::lane
