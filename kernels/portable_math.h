#pragma once
// Elementary functions from + - * and exact rounding alone, so that the scalar path and
// every SIMD width give the same bits. libm (scalar) and xsimd (wide) implement exp and
// sin with different algorithms whose last bits differ, and a rocking cask amplifies a
// last-bit difference over a million steps into a visibly different history; these
// versions are slower than either but identical everywhere.
//
// Both use the classic scheme (Cody & Waite, "Software Manual for the Elementary
// Functions", 1980; Muller, "Elementary Functions", 3rd ed., ch. 11): reduce the argument
// by a multiple of a constant split into an exact high part and a low part, evaluate a
// short Taylor polynomial on the reduced interval, reconstruct.

#include "kernels/lane.h"

namespace caskdem::kernels {

// exp(-x) for x >= 0. Used by the velocity-dependent friction law mu_k + (mu_s - mu_k) exp(-|v|/v0).
// x is clamped to [0, 40]: exp(-40) = 4.2e-18 is below any friction coefficient's last bit.
//   x = n ln2 + r, |r| <= ln2/2, n = round(x / ln2) in [0, 58]
//   exp(-x) = 2^-n exp(-r); exp(-r) by Taylor to degree 13 (remainder < 4e-18 relative)
//   2^-n = product over the 6 bits of n of 2^(-2^b): exact powers of two.
template <class T>
inline T exp_negative(T x) {
  using lane::broadcast;
  using lane::select;
  x = lane::clamp(x, broadcast<T>(0.0), broadcast<T>(40.0));
  const T inverse_ln2 = broadcast<T>(1.4426950408889634074);
  // ln2 split: the high part has 11 trailing zero bits, so n * ln2_high is exact for n < 2^11.
  const T ln2_high = broadcast<T>(6.93145751953125e-1);
  const T ln2_low = broadcast<T>(1.42860682030941723212e-6);
  T n = lane::nearbyint(x * inverse_ln2);
  T r = (x - n * ln2_high) - n * ln2_low;
  // exp(-r) = sum_k (-r)^k / k!, Horner from degree 13 down.
  T minus_r = -r;
  T p = broadcast<T>(1.0 / 6227020800.0);  // 1/13!
  p = p * minus_r + broadcast<T>(1.0 / 479001600.0);
  p = p * minus_r + broadcast<T>(1.0 / 39916800.0);
  p = p * minus_r + broadcast<T>(1.0 / 3628800.0);
  p = p * minus_r + broadcast<T>(1.0 / 362880.0);
  p = p * minus_r + broadcast<T>(1.0 / 40320.0);
  p = p * minus_r + broadcast<T>(1.0 / 5040.0);
  p = p * minus_r + broadcast<T>(1.0 / 720.0);
  p = p * minus_r + broadcast<T>(1.0 / 120.0);
  p = p * minus_r + broadcast<T>(1.0 / 24.0);
  p = p * minus_r + broadcast<T>(1.0 / 6.0);
  p = p * minus_r + broadcast<T>(0.5);
  p = p * minus_r + broadcast<T>(1.0);
  p = p * minus_r + broadcast<T>(1.0);
  // Multiply by 2^-n bit by bit: the bit b of n is (n - 2 floor(n/2)) after b halvings,
  // computed with nearbyint on exact halves (n/2 - 0.25 rounds to floor(n/2) for integer n).
  double factor = 0.5;  // 2^(-2^b)
  T remaining = n;
  for (int bit = 0; bit < 6; ++bit) {
    T half = lane::nearbyint(remaining * broadcast<T>(0.5) - broadcast<T>(0.25));
    T is_set = remaining - half - half;  // 0 or 1
    p = select(is_set > broadcast<T>(0.5), p * broadcast<T>(factor), p);
    remaining = half;
    factor = factor * factor;
  }
  return p;
}

// sin and cos of an angle in radians, accurate to about one ulp for |a| < 1e5.
//   a = k pi/2 + r, |r| <= pi/4, k = round(2a/pi), pi/2 split in three parts (Cody-Waite)
//   sin r, cos r by Taylor to degree 17 and 18 (remainder < 3e-19 on |r| <= pi/4)
//   quadrant q = k mod 4 selects (sin, cos) = (s, c), (c, -s), (-s, -c), (-c, s).
template <class T>
struct SinCos {
  T sin;
  T cos;
};

template <class T>
inline SinCos<T> sin_cos(T a) {
  using lane::broadcast;
  using lane::select;
  const T two_over_pi = broadcast<T>(0.63661977236758134308);
  // pi/2 = p1 + p2 + p3; p1 and p2 have 33 significant bits, so k * p1 and k * p2 are exact for |k| < 2^20.
  const T p1 = broadcast<T>(1.5707963267341256141662597656250);  // 33 significant bits
  const T p2 = broadcast<T>(6.077100506303965976596e-11);
  const T p3 = broadcast<T>(2.022266248795950631541e-21);
  T k = lane::nearbyint(a * two_over_pi);
  T r = ((a - k * p1) - k * p2) - k * p3;
  T r2 = r * r;
  // sin r = r (1 - r^2/3! + r^4/5! - ... - r^16/17!)
  T s = broadcast<T>(-1.0 / 355687428096000.0);  // -1/17!
  s = s * r2 + broadcast<T>(1.0 / 1307674368000.0);
  s = s * r2 + broadcast<T>(-1.0 / 6227020800.0);
  s = s * r2 + broadcast<T>(1.0 / 39916800.0);
  s = s * r2 + broadcast<T>(-1.0 / 362880.0);
  s = s * r2 + broadcast<T>(1.0 / 5040.0);
  s = s * r2 + broadcast<T>(-1.0 / 120.0);
  s = s * r2 + broadcast<T>(1.0 / 6.0);
  s = r - r * r2 * s;
  // cos r = 1 - r^2/2! + r^4/4! - ... + r^18/18! (sign pattern folded into the coefficients)
  T c = broadcast<T>(-1.0 / 6402373705728000.0);  // -1/18!
  c = c * r2 + broadcast<T>(1.0 / 20922789888000.0);
  c = c * r2 + broadcast<T>(-1.0 / 87178291200.0);
  c = c * r2 + broadcast<T>(1.0 / 479001600.0);
  c = c * r2 + broadcast<T>(-1.0 / 3628800.0);
  c = c * r2 + broadcast<T>(1.0 / 40320.0);
  c = c * r2 + broadcast<T>(-1.0 / 720.0);
  c = c * r2 + broadcast<T>(1.0 / 24.0);
  c = c * r2 + broadcast<T>(-0.5);
  c = c * r2 + broadcast<T>(1.0);
  // Quadrant q = k mod 4 from exact arithmetic on k (an integer-valued double).
  T quarter = lane::nearbyint(k * broadcast<T>(0.25) - broadcast<T>(0.375));  // floor(k/4)
  T q = k - broadcast<T>(4.0) * quarter;                                       // 0, 1, 2, 3
  auto odd = (q == broadcast<T>(1.0)) || (q == broadcast<T>(3.0));
  auto sin_negative = q > broadcast<T>(1.5);
  auto cos_negative = (q == broadcast<T>(1.0)) || (q == broadcast<T>(2.0));
  T sin_magnitude = select(odd, c, s);
  T cos_magnitude = select(odd, s, c);
  return {select(sin_negative, -sin_magnitude, sin_magnitude), select(cos_negative, -cos_magnitude, cos_magnitude)};
}

}  // namespace caskdem::kernels
