#pragma once
// Rotation of a rigid body with an axis of symmetry, for the 3D cask (kernels/step3d.h).
//
// Orientation: a unit quaternion q = (w, x, y, z) taking body coordinates to floor
// coordinates, R(q) its matrix. Angular momentum: pi, in body coordinates, L = R pi in the
// floor frame. Body axes: x and z across the cask (inertia I_1 about each, through the centre
// of mass), y along its axis (I_3).
//
// Free rotation by the splitting of Dullweber, Leimkuhler & McLachlan (1997, "Symplectic
// splitting methods for rigid body molecular dynamics", J. Chem. Phys. 107(15), 5840), the
// scheme NO_SQUISH and LAMMPS's rigid integrators build on: the free rigid body's flow is the
// composition of exact rotations about one body axis at a time,
//   R_x(h/2) R_z(h/2) R_y(h) R_z(h/2) R_x(h/2),
// each turning the body by theta = h pi_j / I_j about its axis j: q <- q (cos theta/2, sin
// theta/2 e_j) and pi <- R_j(theta)^T pi. Each factor conserves |pi| and L exactly (up to
// rounding), the composition is symplectic and time-reversible, and its error is O(h^3) per
// step; the gyroscopic coupling of Euler's equations, omega x (I omega), is what the
// sequence of rotations about different axes produces.

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

// sin and cos of half a step's turn. A step turns the cask by h omega, about 1e-4 rad, so where
// every lane's angle is below 1/32 a Taylor polynomial of half sin_cos's degree (to x^9 and
// x^10; the remainders x^11/11! and x^12/12! are below 1e-22 of the result there) gives the
// answer to rounding. Each lane takes the polynomial or sin_cos by its own angle alone, so its
// bits do not depend on the lanes beside it.
template <class T>
CASKDEM_HOST_DEVICE inline SinCos<T> sin_cos_of_turn(const T& a) {
  using lane::broadcast;
  static constexpr std::array<double, 4> sine_tail = {-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0};
  static constexpr std::array<double, 5> cosine_tail = {-1.0 / 2.0, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0,
                                                        -1.0 / 3628800.0};
  const T z = a * a;
  const SinCos<T> small{a + (a * z) * estrin(z, sine_tail), broadcast<T>(1.0) + z * estrin(z, cosine_tail)};
  const auto is_small = lane::abs(a) < broadcast<T>(0.03125);
  if (lane::all(is_small)) return small;
  const SinCos<T> any = sin_cos(a);
  return {lane::select(is_small, small.sin, any.sin), lane::select(is_small, small.cos, any.cos)};
}

// One exact rotation about body axis j (0 = x, 1 = y, 2 = z) by theta = h pi_j / I_j: the
// half angle's sine and cosine turn the quaternion, and the double-angle formulas give the
// full angle's, cos = 1 - 2 sin^2(theta/2) (no cancellation for small angles), sin = 2 sin cos.
template <class T>
CASKDEM_HOST_DEVICE inline void rotate_about_body_axis(int axis, const T& h, const T& inverse_inertia, Quaternion<T>& q,
                                                       Vector3<T>& pi) {
  const T momentum = axis == 0 ? pi.x : axis == 1 ? pi.y : pi.z;
  const T theta = h * momentum * inverse_inertia;
  const SinCos<T> half = sin_cos_of_turn(theta * lane::broadcast<T>(0.5));
  const T hc = half.cos, hs = half.sin;
  const T two = lane::broadcast<T>(2.0);
  const T c = lane::broadcast<T>(1.0) - two * (hs * hs), s = two * (hs * hc);
  // pi <- R_j(theta)^T pi
  if (axis == 0) {
    const T y = c * pi.y + s * pi.z, z = c * pi.z - s * pi.y;
    pi.y = y;
    pi.z = z;
  } else if (axis == 1) {
    const T x = c * pi.x - s * pi.z, z = s * pi.x + c * pi.z;
    pi.x = x;
    pi.z = z;
  } else {
    const T x = c * pi.x + s * pi.y, y = c * pi.y - s * pi.x;
    pi.x = x;
    pi.y = y;
  }
  // q <- q (hc, hs e_j)
  const Quaternion<T> p = q;
  if (axis == 0) {
    q = {p.w * hc - p.x * hs, p.x * hc + p.w * hs, p.y * hc + p.z * hs, p.z * hc - p.y * hs};
  } else if (axis == 1) {
    q = {p.w * hc - p.y * hs, p.x * hc - p.z * hs, p.y * hc + p.w * hs, p.z * hc + p.x * hs};
  } else {
    q = {p.w * hc - p.z * hs, p.x * hc + p.y * hs, p.y * hc - p.x * hs, p.z * hc + p.w * hs};
  }
}

// The free rotation over h (DLM's symmetric splitting), then q renormalised: the rotations
// keep it unit to rounding, and renormalising stops that rounding from accumulating. |q|^2 is
// within a few ulp of 1, so one Newton step for 1/sqrt from 1, (3 - |q|^2) / 2, is the
// reciprocal norm to O((|q|^2 - 1)^2), below rounding, without a square root or a division.
template <class T>
CASKDEM_HOST_DEVICE inline void free_rotation(const T& h, const T& inverse_transverse, const T& inverse_axial,
                                              Quaternion<T>& q, Vector3<T>& pi) {
  const T half = h * lane::broadcast<T>(0.5);
  rotate_about_body_axis(0, half, inverse_transverse, q, pi);
  rotate_about_body_axis(2, half, inverse_transverse, q, pi);
  rotate_about_body_axis(1, h, inverse_axial, q, pi);
  rotate_about_body_axis(2, half, inverse_transverse, q, pi);
  rotate_about_body_axis(0, half, inverse_transverse, q, pi);
  const T norm_squared = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  const T inverse_norm = lane::broadcast<T>(1.5) - lane::broadcast<T>(0.5) * norm_squared;
  q = {q.w * inverse_norm, q.x * inverse_norm, q.y * inverse_norm, q.z * inverse_norm};
}

}  // namespace caskdem::kernels
