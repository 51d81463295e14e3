#pragma once
// The lane functions of kernels/lane.h for T = xsimd::batch<double, Arch>: one realisation per
// SIMD lane, the CPU ensemble path (kernels/block.h). Included by kernels/lane.h on the CPU;
// nvcc never reads it. Each wraps the xsimd operation of the same IEEE meaning, so that a
// batch's lanes give the scalar overloads' bits (xsimd's min/max are minpd/maxpd).

#include <cstddef>
#include <cstdint>
#include <xsimd/xsimd.hpp>

#include "kernels/lane.h"

namespace caskdem::lane {

template <class Arch>
struct Traits<xsimd::batch<double, Arch>> {
  using Mask = xsimd::batch_bool<double, Arch>;
  using Index = xsimd::batch<std::int64_t, Arch>;
  static constexpr std::size_t width = xsimd::batch<double, Arch>::size;
};

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

// 2^k lane by lane (kernels/lane.h, power_of_two).
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
template <class A>
inline void store_index(std::int64_t* field, const xsimd::batch<std::int64_t, A>& value) {
  value.store_aligned(field);
}

}  // namespace caskdem::lane
