#pragma once
// Elementary functions from + - * and exact operations alone, so that the scalar path and
// every SIMD width give the same bits. libm (scalar) and xsimd (wide) implement exp and
// sin with different algorithms whose last bits differ, and a rocking cask amplifies a
// last-bit difference over a million steps into a visibly different history; these
// versions give one answer everywhere.
//
// Both use the classic scheme (Cody & Waite, "Software Manual for the Elementary
// Functions", 1980; Muller, "Elementary Functions", 3rd ed., ch. 11): reduce the argument
// by a multiple of a constant split into an exact high part and a low part, evaluate a
// Taylor polynomial on the reduced interval, reconstruct. The polynomials are evaluated
// with Estrin's scheme (Knuth, TAOCP vol. 2, 4.6.4) rather than Horner's: the same
// accuracy here, but a dependency chain of log2(degree) multiply-adds instead of degree of
// them, and these functions sit on the critical path of every step.

#include <array>
#include <cstddef>

#include "kernels/host_device.h"
#include "kernels/lane.h"

namespace caskdem::kernels {

// sum_k c[k] x^k by Estrin's scheme: pair terms as c[2i] + c[2i+1] x, then pairs of pairs
// with x^2, and so on. The order of operations is fixed, so every lane width agrees.
template <class T, std::size_t N>
CASKDEM_HOST_DEVICE inline T estrin(const T& x, const std::array<double, N>& c) {
  std::array<T, (N + 1) / 2> level;
  for (std::size_t i = 0; i < N / 2; ++i) {
    level[i] = lane::broadcast<T>(c[2 * i]) + lane::broadcast<T>(c[2 * i + 1]) * x;
  }
  if (N % 2 == 1) level[N / 2] = lane::broadcast<T>(c[N - 1]);
  std::size_t size = (N + 1) / 2;
  T power = x * x;
  while (size > 1) {
    for (std::size_t i = 0; i < size / 2; ++i) level[i] = level[2 * i] + level[2 * i + 1] * power;
    if (size % 2 == 1) level[size / 2] = level[size - 1];
    size = (size + 1) / 2;
    if (size > 1) power = power * power;
  }
  return level[0];
}

// exp(-x) for x >= 0. Used by the velocity-dependent friction law mu_k + (mu_s - mu_k) exp(-|v|/v0).
// x is clamped to [0, 40]: exp(-40) = 4.2e-18 is below any friction coefficient's last bit.
//   x = n ln2 + r, |r| <= ln2/2, n = round(x / ln2) in [0, 58]
//   exp(-x) = 2^-n exp(-r); exp(-r) by Taylor to degree 13 (remainder < 4e-18 relative),
//   2^-n exactly from its exponent bits.
template <class T>
CASKDEM_HOST_DEVICE inline T exp_negative(T x) {
  using lane::broadcast;
  static constexpr std::array<double, 14> taylor = {
      1.0,         1.0,          1.0 / 2.0,      1.0 / 6.0,       1.0 / 24.0,       1.0 / 120.0,        1.0 / 720.0,
      1.0 / 5040.0, 1.0 / 40320.0, 1.0 / 362880.0, 1.0 / 3628800.0, 1.0 / 39916800.0, 1.0 / 479001600.0, 1.0 / 6227020800.0};
  x = lane::clamp(x, broadcast<T>(0.0), broadcast<T>(40.0));
  // ln2 split: the high part has 11 trailing zero bits, so n * ln2_high is exact for n < 2^11.
  const T n = lane::nearbyint(x * broadcast<T>(1.4426950408889634074));
  const T r = (x - n * broadcast<T>(6.93145751953125e-1)) - n * broadcast<T>(1.42860682030941723212e-6);
  return estrin(-r, taylor) * lane::power_of_two(-n);
}

// sin and cos of an angle in radians, accurate to about one ulp for |a| < 1e5.
//   a = k pi/2 + r, |r| <= pi/4, k = round(2a/pi), pi/2 split in three parts (Cody-Waite)
//   sin r = r + r z S(z), cos r = 1 + z C(z), z = r^2, Taylor to r^17 and r^18
//   (remainder < 3e-19 on |r| <= pi/4)
//   quadrant q = k mod 4 selects (sin, cos) = (s, c), (c, -s), (-s, -c), (-c, s).
template <class T>
struct SinCos {
  T sin;
  T cos;
};

// Always inlined: as a call it would make every live SIMD register of the step a spill (none
// survives a call in the x86-64 ABI); with its fast branch the compiler stopped inlining it.
template <class T>
CASKDEM_HOST_DEVICE CASKDEM_ALWAYS_INLINE SinCos<T> sin_cos(T a) {
  using lane::broadcast;
  using lane::select;
  static constexpr std::array<double, 8> sine_tail = {
      -1.0 / 6.0,         1.0 / 120.0,           -1.0 / 5040.0,          1.0 / 362880.0,
      -1.0 / 39916800.0, 1.0 / 6227020800.0, -1.0 / 1307674368000.0, 1.0 / 355687428096000.0};
  static constexpr std::array<double, 9> cosine_tail = {
      -1.0 / 2.0,          1.0 / 24.0,          -1.0 / 720.0,           1.0 / 40320.0,          -1.0 / 3628800.0,
      1.0 / 479001600.0, -1.0 / 87178291200.0, 1.0 / 20922789888000.0, -1.0 / 6402373705728000.0};
  // A rocking cask's rotation stays well inside the first octant. For |a| < 0.75 (pi/4 = 0.785
  // less room for the rounding of a 2/pi) k = +-0, the reduced argument is a (but +0 for
  // a = -0, which the polynomial turns to +0 too) and the quadrant is 0: this branch, taken
  // when every lane is there, gives the reduction's bits for less work.
  if (lane::all(lane::abs(a) < broadcast<T>(0.75))) {
    const T z = a * a;
    return {a + (a * z) * estrin(z, sine_tail), broadcast<T>(1.0) + z * estrin(z, cosine_tail)};
  }
  // pi/2 = p1 + p2 + p3; p1 and p2 have 33 significant bits, so k * p1 and k * p2 are exact for |k| < 2^20.
  const T k = lane::nearbyint(a * broadcast<T>(0.63661977236758134308));
  const T r = ((a - k * broadcast<T>(1.5707963267341256141662597656250)) - k * broadcast<T>(6.077100506303965976596e-11)) -
              k * broadcast<T>(2.022266248795950631541e-21);
  const T z = r * r;
  const T s = r + (r * z) * estrin(z, sine_tail);
  const T c = broadcast<T>(1.0) + z * estrin(z, cosine_tail);
  // Quadrant q = k mod 4 from exact arithmetic on k (an integer-valued double):
  // k/4 - 3/8 rounds to floor(k/4) for every integer k.
  const T quarter = lane::nearbyint(k * broadcast<T>(0.25) - broadcast<T>(0.375));
  const T q = k - broadcast<T>(4.0) * quarter;  // 0, 1, 2, 3
  const auto odd = (q == broadcast<T>(1.0)) || (q == broadcast<T>(3.0));
  const auto sin_negative = q > broadcast<T>(1.5);
  const auto cos_negative = (q == broadcast<T>(1.0)) || (q == broadcast<T>(2.0));
  const T sin_magnitude = select(odd, c, s);
  const T cos_magnitude = select(odd, s, c);
  return {select(sin_negative, -sin_magnitude, sin_magnitude), select(cos_negative, -cos_magnitude, cos_magnitude)};
}

}  // namespace caskdem::kernels
