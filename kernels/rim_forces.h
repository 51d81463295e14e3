#pragma once
// The normal forces of the 3D cask's rim, summed over the nodes of its touching arc
// (kernels/rim_contact.h), and the same sums in closed form where the rim is pressed all round.
//
// The sums. In the arc's frame the node pair at +-psi from the lowest point has the one gap
// g_c - A cos psi and the normal velocities v_r + P cos psi +- Q sin psi (kernels/step3d.h
// derives them); each node pushes with the contact law's normal force F_+- at its share s of the
// ring's stiffness K. The step needs
//   N = sum (F_+ + F_-),  N_along = sum (F_+ + F_-) cos psi,  N_across = sum (F_+ - F_-) sin psi,
// and the rim's shear stiffness K_s sum 2 s over the nodes that touch.
//
// Pressed all round. With the linear law (kernels/contact_law.h, linear_normal_force) a node
// that touches and pushes has F = K s (-gap - beta v), here
//   F_+- = K s (p + b cos psi -+ c sin psi),   p = -(g_c + beta v_r), b = A - beta P, c = beta Q,
// so that, with the rule's constants S0 = sum s, S1 = sum s cos psi, S2 = sum s cos^2 psi and
// S3 = sum s sin^2 psi over the pairs of the whole ring (Contacts3D),
//   N = 2 K (p S0 + b S1),   N_along = 2 K (p S1 + b S2),   N_across = -2 K c S3,
// and the shear stiffness 2 K_s S0. It holds where the arc is the whole ring (U = 1, the node
// positions the constants were taken at), every node's gap is negative (g_c + A < 0) and every
// node pushes: p + b cos psi -+ c sin psi > 0 for every psi, which is p > |(b, c)|. That is a
// standing cask's state (a quarter of the 3D benchmark's lane-steps, docs/cask3d.md), and
// there the closed form replaces sixteen evaluations of the law with a few operations. It is the
// node sum rearranged, equal to it to rounding (tests/kernels/test_rim_forces.cpp); a lane
// takes it by its own state alone, so a realisation's result does not depend on its neighbours
// in a SIMD batch, nor on the instruction set.

#include "kernels/contact_law.h"
#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/model.h"
#include "kernels/model3d.h"
#include "kernels/rim_contact.h"

namespace caskdem::kernels {

// Where the rim touches and how it moves in the arc's frame, at t_n.
template <class T>
struct RimMotion {
  T centre_gap, amplitude;  // g_c and A
  RimArc<T> arc;
  T ring_velocity;          // v_r, the ring centre's normal velocity
  T velocity_along;         // P
  T velocity_across;        // Q
};

template <class T>
struct RimSums {
  T normal;           // N, N
  T normal_along;     // N_along, N
  T normal_across;    // N_across, N
  T shear_stiffness;  // the touching nodes' K_s, N/m
};

// The sums node by node, with the full contact law or, where every lane has the paper's linear
// floor, its shortcut (the same bits either way, kernels/contact_law.h).
template <class T>
CASKDEM_HOST_DEVICE inline RimSums<T> rim_sums_by_nodes(const Model& model, const Contacts3D& contacts,
                                                        const LaneParameters<T>& p, const RimMotion<T>& rim) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0);
  const T ring_normal_stiffness = broadcast<T>(contacts.ring_normal_stiffness) * p.stiffness_scale;
  const T ring_shear_stiffness = broadcast<T>(contacts.ring_shear_stiffness) * p.stiffness_scale;
  RimSums<T> sums{zero, zero, zero, zero};
  RimPair<T> pairs[kRimNodePairs];
  rim_pairs(contacts, rim.arc, pairs);
  auto each_pair = [&](auto&& law) {
    for (const RimPair<T>& pair : pairs) {
      const T gap = rim.centre_gap - rim.amplitude * pair.cos_psi;
      const T mean_velocity = rim.ring_velocity + rim.velocity_along * pair.cos_psi;
      const T turn_velocity = rim.velocity_across * pair.sin_psi;
      const T normal_stiffness = ring_normal_stiffness * pair.share;
      const T ahead = law(normal_stiffness, gap, mean_velocity + turn_velocity);
      const T behind = law(normal_stiffness, gap, mean_velocity - turn_velocity);
      const T both = ahead + behind;
      sums.normal = sums.normal + both;
      sums.normal_along = sums.normal_along + both * pair.cos_psi;
      sums.normal_across = sums.normal_across + (ahead - behind) * pair.sin_psi;
      const T shear_stiffness = shear_stiffness_at(model, ring_shear_stiffness * pair.share, gap);
      sums.shear_stiffness = sums.shear_stiffness + select(gap < zero, shear_stiffness + shear_stiffness, zero);
    }
  };
  if (linear_floor(model, p)) {
    each_pair([&](const T& k, const T& gap, const T& v) { return linear_normal_force(k, p.damping_beta, gap, v); });
  } else {
    each_pair([&](const T& k, const T& gap, const T& v) { return normal_force(model, k, p, gap, v); });
  }
  return sums;
}

// p, b and c of a node's force F_+- = K s (p + b cos psi -+ c sin psi) (above).
template <class T>
struct RimForceTerms {
  T pressing, rocking, twisting;
};

template <class T>
CASKDEM_HOST_DEVICE inline RimForceTerms<T> force_terms(const LaneParameters<T>& p, const RimMotion<T>& rim) {
  return {-(rim.centre_gap + p.damping_beta * rim.ring_velocity), rim.amplitude - p.damping_beta * rim.velocity_along,
          p.damping_beta * rim.velocity_across};
}

// The lanes whose rim is pressed all round, with the paper's linear floor (above).
template <class T>
CASKDEM_HOST_DEVICE inline auto pressed_all_round(const Model& model, const LaneParameters<T>& p,
                                                  const RimMotion<T>& rim, const RimForceTerms<T>& f) {
  using lane::broadcast;
  const T zero = broadcast<T>(0.0);
  return linear_floor_lanes(model, p) && rim.arc.half_width == broadcast<T>(1.0) &&
         rim.centre_gap + rim.amplitude < zero && f.pressing > zero &&
         f.pressing * f.pressing > f.rocking * f.rocking + f.twisting * f.twisting;
}

// The sums in closed form, for the lanes pressed all round (meaningless elsewhere).
template <class T>
CASKDEM_HOST_DEVICE inline RimSums<T> rim_sums_pressed_all_round(const Contacts3D& contacts, const LaneParameters<T>& p,
                                                                 const RimForceTerms<T>& f) {
  using lane::broadcast;
  const T twice_normal = broadcast<T>(2.0 * contacts.ring_normal_stiffness) * p.stiffness_scale;
  const T s0 = broadcast<T>(contacts.whole_ring_share), s1 = broadcast<T>(contacts.whole_ring_share_cos);
  const T s2 = broadcast<T>(contacts.whole_ring_share_cos2), s3 = broadcast<T>(contacts.whole_ring_share_sin2);
  return {twice_normal * (f.pressing * s0 + f.rocking * s1), twice_normal * (f.pressing * s1 + f.rocking * s2),
          -(twice_normal * f.twisting * s3),
          broadcast<T>(2.0 * contacts.ring_shear_stiffness * contacts.whole_ring_share) * p.stiffness_scale};
}

// The rim's sums for every lane: in closed form where pressed all round, node by node elsewhere;
// each lane takes its own, and the branches only skip what no lane of the batch takes. Always
// inlined: as a call it spilled the step's live registers (avx2 lanes 20 % slower); the node
// sums stay a call, which inlined made the avx512f step slower (docs/cask3d.md, "Speed").
template <class T>
CASKDEM_HOST_DEVICE CASKDEM_ALWAYS_INLINE RimSums<T> rim_sums(const Model& model, const Contacts3D& contacts,
                                                              const LaneParameters<T>& p, const RimMotion<T>& rim) {
  using lane::select;
  const RimForceTerms<T> f = force_terms(p, rim);
  const auto closed = pressed_all_round(model, p, rim, f);
  if (lane::all(closed)) return rim_sums_pressed_all_round(contacts, p, f);
  const RimSums<T> nodes = rim_sums_by_nodes(model, contacts, p, rim);
  if (!lane::any(closed)) return nodes;
  const RimSums<T> pressed = rim_sums_pressed_all_round(contacts, p, f);
  return {select(closed, pressed.normal, nodes.normal), select(closed, pressed.normal_along, nodes.normal_along),
          select(closed, pressed.normal_across, nodes.normal_across),
          select(closed, pressed.shear_stiffness, nodes.shear_stiffness)};
}

}  // namespace caskdem::kernels
