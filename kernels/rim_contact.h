#pragma once
// The 3D cask's rim as one continuous contact: where the ring of the base touches the floor,
// and the nodes that carry its springs there (kernels/step3d.h).
//
// The ring. The rim (rounded by r) is the circle of sphere centres c(theta) = (R_c cos theta,
// r, R_c sin theta) in the body frame, R_c = R - r, with a normal stiffness K_ring / (2 pi) per
// radian (and K_s,ring / (2 pi) in shear): the continuous limit of a ring of N points, which
// pivots on the rim itself instead of a chord R_c cos(pi / N), and rolls instead of falling
// from point to point (a polygon's every next point lands with an impact, docs/cask3d.md).
//
// Where it touches. The gap of c(theta) is linear in cos and sin of theta,
//   gap(theta) = g_c + R_c (e1_y cos theta + e3_y sin theta) = g_c - A cos(theta - theta_0),
// g_c the gap of the ring's centre, e1 and e3 the body's x and z axes in the floor frame,
// A = R_c |(e1_y, e3_y)| and theta_0 the lowest point. It touches on the arc
// |theta - theta_0| < phi, cos phi = g_c / A (clamped to [-1, 1]: the whole ring or none).
//
// The nodes. The arc's integral of a contact point's force per radian is taken by
// Gauss-Legendre quadrature with 2M nodes that move with the arc, not with the material:
// psi = theta - theta_0 is mapped to u = tan(psi / 4), which runs over [-U, U],
// U = tan(phi / 4) = sin(phi/2) / (1 + cos(phi/2)) in [0, 1], so that no inverse cosine is
// needed and the whole ring (U = 1) stays a finite interval; dpsi = 4 du / (1 + u^2), and with
// w = psi / 2, cos w = (1 - u^2) / (1 + u^2), sin w = 2 u / (1 + u^2). The integrand is
// analytic in u on [-1, 1] (poles at +-i), so the rule converges as (1 + sqrt 2)^(-4M) for
// the spring: 16 nodes give the standing cask its ring's vertical stiffness to 1e-12 and its
// rocking stiffness to 1e-7. The no-tension clip of spring and dashpot together, and the soft
// floor layer, put kinks inside the arc, where the rule converges only algebraically. Each node pushes with the 2D contact law's normal force at its share of
// the ring's stiffness. Nodes come in mirror pairs psi, -psi, summed one after the other, so
// that a cask shaken in its plane from a symmetric start stays in it exactly. Where the whole
// ring is pressed and every node pushes under the linear law, the sums are linear in the
// nodes' positions and the step takes them in closed form (kernels/rim_forces.h).
//
// Friction. The nodes' normal forces act together at the arc's centre of pressure, and the
// rim's friction is one spring-slider there (kernels/step3d.h), slipping with the material
// point at that place: the rim touches as a point contact, without friction torque about the
// floor normal. The arc's width is set by the penalty stiffness (centimetres at the paper's),
// not by the rim, and a drilling friction over it would stop a rolling cask within a turn
// (measured with a spring-slider at every node: the tilt fell by 40 % in the first turn).

#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/model3d.h"

namespace caskdem::kernels {

template <class T>
struct RimArc {
  T towards_cos, towards_sin;  // (cos theta_0, sin theta_0): the lowest point's direction in the body frame
  T half_width;                // U = tan(phi / 4) in [0, 1]
};

// centre_gap: g_c; slope_x, slope_z: R_c e1_y and R_c e3_y.
template <class T>
CASKDEM_HOST_DEVICE inline RimArc<T> touching_arc(const T& centre_gap, const T& slope_x, const T& slope_z) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0), one = broadcast<T>(1.0), half = broadcast<T>(0.5);
  const T amplitude = lane::sqrt(slope_x * slope_x + slope_z * slope_z);
  const auto tilted = amplitude > zero;
  const T per_amplitude = one / select(tilted, amplitude, one);
  // Upright (A = 0) the ring touches all round or not at all, and any direction serves.
  const T towards_cos = select(tilted, -slope_x * per_amplitude, one);
  const T towards_sin = select(tilted, -slope_z * per_amplitude, zero);
  const T all_or_none = select(centre_gap < zero, -one, one);
  const T cos_phi = select(tilted, lane::clamp(centre_gap * per_amplitude, -one, one), all_or_none);
  // The whole ring (cos phi = -1) gives U = sqrt(1) / (1 + sqrt(0)) = 1 and none (cos phi = 1)
  // U = 0 / 2 = +0 exactly: a batch all so (a standing cask) skips the roots and the division.
  if (lane::all(cos_phi == -one || cos_phi == one)) return {towards_cos, towards_sin, select(cos_phi < zero, one, zero)};
  const T half_width = lane::sqrt((one - cos_phi) * half) / (one + lane::sqrt((one + cos_phi) * half));
  return {towards_cos, towards_sin, half_width};
}

// The node pair of abscissa `pair` relative to the lowest point: psi = theta - theta_0 of the node
// ahead (the one behind is at -psi) and each node's share of K_ring.
template <class T>
struct RimPair {
  T cos_psi, sin_psi;
  T share;
};

// Every pair at once, with one division for the eight reciprocals 1 / (1 + u_j^2): their product's
// reciprocal times the other factors (prefix and suffix products; each factor is in [1, 2], so
// nothing overflows), a few roundings more than eight divisions, at a fraction of their cost.
template <class T>
CASKDEM_HOST_DEVICE inline void rim_pairs(const Contacts3D& contacts, const RimArc<T>& arc,
                                          RimPair<T> (&pairs)[kRimNodePairs]) {
  using lane::broadcast;
  const T one = broadcast<T>(1.0), two = broadcast<T>(2.0);
  T u[kRimNodePairs], factor[kRimNodePairs], before[kRimNodePairs];
  T product = one;
  for (int j = 0; j < kRimNodePairs; ++j) {
    u[j] = arc.half_width * broadcast<T>(contacts.node_abscissa[j]);
    factor[j] = one + u[j] * u[j];
    before[j] = product;  // the factors before j
    product = product * factor[j];
  }
  T after = one / product;  // 1 / (all factors), then times each factor as j falls
  for (int j = kRimNodePairs - 1; j >= 0; --j) {
    const T inverse = after * before[j];  // 1 / factor[j]
    after = after * factor[j];
    const T cos_w = (one - u[j] * u[j]) * inverse, sin_w = two * u[j] * inverse;
    const T share =
        broadcast<T>(contacts.node_weight[j] * 4.0 / (2.0 * 3.14159265358979323846)) * arc.half_width * inverse;
    pairs[j] = {cos_w * cos_w - sin_w * sin_w, two * sin_w * cos_w, share};
  }
}

}  // namespace caskdem::kernels
