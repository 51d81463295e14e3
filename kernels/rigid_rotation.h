#pragma once
// Rotation of a rigid body with an axis of symmetry, for the 3D cask (kernels/step3d.h).
//
// Orientation: a unit quaternion q = (w, x, y, z) taking body coordinates to floor
// coordinates, R(q) its matrix. Angular momentum: pi, in body coordinates, L = R pi in the
// floor frame. Body axes: x and z across the cask (inertia I_1 about each, through the centre
// of mass), y along its axis (I_3).
//
// Free rotation: the torque-free symmetric top's exact flow (Goldstein, Classical Mechanics,
// 3rd ed., 5.6; Landau & Lifshitz, Mechanics, 33). Its body angular velocity is
//   omega = I^-1 pi = pi / I_1 + c e_y,   c = pi_y (1/I_3 - 1/I_1),
// so Euler's equations, pi' = pi x omega = c pi x e_y, turn pi about the body axis at the
// constant rate -c (pi_y is constant), and R' = R [omega]x is solved by
//   R(t) = R(0) Rot(pi(0), |pi(0)| t / I_1) Rot(e_y, c t),   pi(t) = Rot(e_y, c t)^T pi(0)
// (differentiate: R' = R [B^T pi(0) / I_1 + c e_y]x with B = Rot(e_y, c t), and B^T pi(0) = pi(t)).
// Two rotations a step, one about the momentum and one about the cask's axis, with no
// splitting error: |pi|, L and the kinetic energy are kept to rounding at any step. (The
// splitting into five rotations about body axes of Dullweber, Leimkuhler & McLachlan 1997,
// which any rigid body needs, is second order; a cask is a symmetric top and needs none.)

#include <array>

#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/portable_math.h"

namespace caskdem::kernels {

template <class T>
struct Quaternion {
  T w, x, y, z;
};

template <class T>
struct Vector3 {
  T x, y, z;
};

// Rotation matrix of a unit quaternion, rows of R (body -> floor).
template <class T>
struct Rotation {
  T r00, r01, r02, r10, r11, r12, r20, r21, r22;

  CASKDEM_HOST_DEVICE Vector3<T> apply(const Vector3<T>& v) const {  // R v
    return {r00 * v.x + r01 * v.y + r02 * v.z, r10 * v.x + r11 * v.y + r12 * v.z, r20 * v.x + r21 * v.y + r22 * v.z};
  }
  CASKDEM_HOST_DEVICE Vector3<T> apply_transpose(const Vector3<T>& v) const {  // R^T v
    return {r00 * v.x + r10 * v.y + r20 * v.z, r01 * v.x + r11 * v.y + r21 * v.z, r02 * v.x + r12 * v.y + r22 * v.z};
  }
};

template <class T>
CASKDEM_HOST_DEVICE inline Rotation<T> rotation_of(const Quaternion<T>& q) {
  const T one = lane::broadcast<T>(1.0), two = lane::broadcast<T>(2.0);
  const T xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const T xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const T wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  return {one - two * (yy + zz), two * (xy - wz),       two * (xz + wy),
          two * (xy + wz),       one - two * (xx + zz), two * (yz - wx),
          two * (xz - wy),       two * (yz + wx),       one - two * (xx + yy)};
}

template <class T>
CASKDEM_HOST_DEVICE inline Vector3<T> cross(const Vector3<T>& a, const Vector3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The Hamilton product p q: the rotation q, then p (of body -> floor maps: p q takes the body
// frame turned by q to the floor).
template <class T>
CASKDEM_HOST_DEVICE inline Quaternion<T> product(const Quaternion<T>& p, const Quaternion<T>& q) {
  return {p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z, p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
          p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x, p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w};
}

// A step turns the cask by h omega, about 1e-4 rad, so where every lane's half angle is below
// 1/32 Taylor polynomials of half sin_cos's degree give the answer to rounding (remainders below
// 1e-22 of the result). Each lane takes the polynomial or the general path by its own angle
// alone, so its bits do not depend on the lanes beside it.
inline constexpr double kSmallTurn = 0.03125;  // rad
// The polynomials' coefficients (functions rather than namespace-scope arrays, which CUDA device
// code cannot read).
CASKDEM_HOST_DEVICE constexpr std::array<double, 4> turn_sine_tail() {
  return {-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0};
}
CASKDEM_HOST_DEVICE constexpr std::array<double, 5> turn_cosine_tail() {
  return {-1.0 / 2.0, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0, -1.0 / 3628800.0};
}

// sin and cos of an angle a (sin_cos's answer, to a few ulp).
template <class T>
CASKDEM_HOST_DEVICE CASKDEM_ALWAYS_INLINE SinCos<T> sin_cos_of_turn(const T& a) {
  using lane::broadcast;
  const T z = a * a;
  const SinCos<T> small{a + (a * z) * estrin(z, turn_sine_tail()),
                        broadcast<T>(1.0) + z * estrin(z, turn_cosine_tail())};
  const auto is_small = lane::abs(a) < broadcast<T>(kSmallTurn);
  if (lane::all(is_small)) return small;
  const SinCos<T> any = sin_cos(a);
  return {lane::select(is_small, small.sin, any.sin), lane::select(is_small, small.cos, any.cos)};
}

// cos a and sin(a) / a from a^2 >= 0: a rotation's quaternion (cos a, sin(a)/a v) about a vector
// v of length a, with no square root or division where the angle is small.
template <class T>
struct HalfTurn {
  T cos, sin_over_angle;
};

template <class T>
CASKDEM_HOST_DEVICE CASKDEM_ALWAYS_INLINE HalfTurn<T> half_turn_of_squared(const T& z) {
  using lane::broadcast;
  const T one = broadcast<T>(1.0);
  const HalfTurn<T> small{one + z * estrin(z, turn_cosine_tail()), one + z * estrin(z, turn_sine_tail())};
  const auto is_small = z < broadcast<T>(kSmallTurn * kSmallTurn);
  if (lane::all(is_small)) return small;
  // Beyond the small turn the angle is at least 1/32, so the division is safe.
  const T angle = lane::sqrt(lane::select(is_small, one, z));
  const SinCos<T> any = sin_cos(angle);
  return {lane::select(is_small, small.cos, any.cos), lane::select(is_small, small.sin_over_angle, any.sin / angle)};
}

// The free rotation over h (the exact flow above), then q renormalised: the rotations keep it
// unit to rounding, and renormalising stops that rounding from accumulating. |q|^2 is within a
// few ulp of 1, so one Newton step for 1/sqrt from 1, (3 - |q|^2) / 2, is the reciprocal norm to
// O((|q|^2 - 1)^2), below rounding, without a square root or a division.
template <class T>
CASKDEM_HOST_DEVICE CASKDEM_ALWAYS_INLINE void free_rotation(const T& h, const T& inverse_transverse,
                                                             const T& inverse_axial, Quaternion<T>& q, Vector3<T>& pi) {
  using lane::broadcast;
  const T zero = broadcast<T>(0.0), one = broadcast<T>(1.0), two = broadcast<T>(2.0);
  const T half = h * broadcast<T>(0.5);
  // About pi by |pi| h / I_1: half that angle times the axis is v = pi h / (2 I_1).
  const T per_momentum = half * inverse_transverse;
  const Vector3<T> v{per_momentum * pi.x, per_momentum * pi.y, per_momentum * pi.z};
  const HalfTurn<T> about_momentum = half_turn_of_squared(v.x * v.x + v.y * v.y + v.z * v.z);
  const T s = about_momentum.sin_over_angle;
  q = product(q, Quaternion<T>{about_momentum.cos, s * v.x, s * v.y, s * v.z});
  // About the cask's axis by c h; pi turns back by the same angle (it is unchanged by the first).
  const SinCos<T> about_axis = sin_cos_of_turn(half * pi.y * (inverse_axial - inverse_transverse));
  q = product(q, Quaternion<T>{about_axis.cos, zero, about_axis.sin, zero});
  const T c = one - two * (about_axis.sin * about_axis.sin), sn = two * (about_axis.sin * about_axis.cos);
  pi = {c * pi.x - sn * pi.z, pi.y, sn * pi.x + c * pi.z};
  const T norm_squared = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  const T inverse_norm = broadcast<T>(1.5) - broadcast<T>(0.5) * norm_squared;
  q = {q.w * inverse_norm, q.x * inverse_norm, q.y * inverse_norm, q.z * inverse_norm};
}

}  // namespace caskdem::kernels
