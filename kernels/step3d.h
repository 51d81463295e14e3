#pragma once
// One explicit step of the 3D cask on its floor, for one realisation (T = double) or one SIMD
// batch (T = xsimd::batch<double, Arch>): the 2D step (kernels/step.h) with the cask free to
// tilt in any direction, roll on its rim and spin about its axis.
//
// Equations of motion in the floor frame, which translates with the table (kernels/model3d.h):
//   m x'' = sum F - m (a_x(t), g + a_y(t), a_z(t))       a_y the vertical component
//   L'    = sum l_k x F_k                               L = R pi, about the centre of mass
// Time stepping as in 2D (central differences: forces from positions at t_n and velocities at
// t_{n-1/2}, or at t_n for the whole-step slider's terms, kernels/slider.h, the angular momentum
// extrapolated in the body frame as the velocity is): v(n+1/2) = v(n-1/2) + a(n) dt,
// x(n+1) = x(n) + v(n+1/2) dt; for the rotation the torque kicks the angular momentum,
// pi <- pi + dt R(n)^T tau(n), and the free rotation over dt turns the body and pi together, the
// torque-free symmetric top's exact flow (kernels/rigid_rotation.h).
//
// Each contact point is a sphere of radius r at a body point c_k, a node of the rim's touching
// arc or the base's centre (kernels/model3d.h, kernels/rim_contact.h): its gap
// is the centre's height less r, its contact point the sphere's lowest point, lever arm
// l_k = R (c_k - c_m) - r e_y from the centre of mass c_m. The normal force is the 2D law's
// (kernels/contact_law.h, normal_force), the friction coefficient the 2D law's
// (kernels/friction_law.h) at the slip speed |v_s|; the shear spring is the 2D incremental
// spring made a vector in the floor plane: F_s* = F_s(previous) - K_s v_s dt, capped in
// magnitude at mu F_n along its own direction (Cundall 1988, the 3D DEM's Mohr-Coulomb
// slider), with the stiffness-proportional dashpot -beta K_s v_s while it sticks.

#include <cstdint>

#include "kernels/contact_law.h"
#include "kernels/end_criteria.h"
#include "kernels/friction_law.h"
#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/lane_state.h"
#include "kernels/lane_state3d.h"
#include "kernels/model.h"
#include "kernels/model3d.h"
#include "kernels/rigid_rotation.h"
#include "kernels/rim_contact.h"
#include "kernels/rim_forces.h"
#include "kernels/slider.h"

namespace caskdem::kernels {

// |e - e_y|^2 of the cask's axis e = R e_y: grows monotonically with the tilt t from vertical,
// (2 sin(t/2))^2, and is exact near upright (1 - e_y from the quaternion, not by cancellation).
template <class T>
CASKDEM_HOST_DEVICE inline T axis_departure(const Quaternion<T>& q, const Rotation<T>& rotation) {
  const T drop = lane::broadcast<T>(2.0) * (q.x * q.x + q.z * q.z);  // 1 - e_y
  return rotation.r01 * rotation.r01 + drop * drop + rotation.r21 * rotation.r21;
}

// Where the rim touches at t_n: its centre's gap, the amplitude A of its gap around the ring
// and the touching arc (kernels/rim_contact.h).
template <class T>
struct RimTouch {
  T centre_gap, amplitude;
  RimArc<T> arc;
};

template <class T>
CASKDEM_HOST_DEVICE inline RimTouch<T> rim_touch(const Contacts3D& contacts, const LaneParameters<T>& p,
                                                 const Rotation<T>& rotation, const T& height) {
  const T radius = lane::broadcast<T>(contacts.rounding_radius), ring = lane::broadcast<T>(contacts.ring_radius);
  const T centre_gap = height + rotation.apply({-p.centre_x, radius - p.centre_y, lane::broadcast<T>(0.0)}).y - radius;
  const T slope_x = ring * rotation.r10, slope_z = ring * rotation.r12;
  return {centre_gap, lane::sqrt(slope_x * slope_x + slope_z * slope_z), touching_arc(centre_gap, slope_x, slope_z)};
}

// The rim's nodes on its touching arc in mirror pairs, each with its body-frame sphere centre
// (x, r, z) and stiffnesses: visit(x, z, K_n, K_s). The step itself works in the arc's frame
// (step3d, below) from the same pairs; this is the nodes one by one, for the model's standing
// stiffness and the tests' energy.
template <class T, class Visit>
CASKDEM_HOST_DEVICE inline void for_each_rim_node(const Contacts3D& contacts, const LaneParameters<T>& p,
                                                  const RimTouch<T>& rim, Visit&& visit) {
  using lane::broadcast;
  const T ring = broadcast<T>(contacts.ring_radius);
  const T ring_normal = broadcast<T>(contacts.ring_normal_stiffness) * p.stiffness_scale;
  const T ring_shear = broadcast<T>(contacts.ring_shear_stiffness) * p.stiffness_scale;
  RimPair<T> pairs[kRimNodePairs];
  rim_pairs(contacts, rim.arc, pairs);
  const T c0 = rim.arc.towards_cos, s0 = rim.arc.towards_sin;
  for (const RimPair<T>& pair : pairs) {
    const T ahead_cos = c0 * pair.cos_psi - s0 * pair.sin_psi, ahead_sin = s0 * pair.cos_psi + c0 * pair.sin_psi;
    const T behind_cos = c0 * pair.cos_psi + s0 * pair.sin_psi, behind_sin = s0 * pair.cos_psi - c0 * pair.sin_psi;
    visit(ring * ahead_cos, ring * ahead_sin, ring_normal * pair.share, ring_shear * pair.share);
    visit(ring * behind_cos, ring * behind_sin, ring_normal * pair.share, ring_shear * pair.share);
  }
}

// The spring-slider of one contact in the floor plane: the 2D incremental shear spring made a
// vector, F_s* = F_s(previous) - K_s v_s dt, capped in magnitude at mu F_n along its own
// direction (Cundall 1988), the stiffness-proportional dashpot -beta K_s v_s while it sticks,
// and at most mu F_n transmitted, dashpot included. Returns the shear force on the cask.
// The rim's K_s is that of the arc it touches on, which narrows and widens as the cask rocks:
// springs that leave the arc take their share of the force with them (F_s(previous) scaled by
// K_s / K_s(previous) when that is below 1), and springs that join it come unstretched (the
// force kept). The centre's K_s is constant, and its force is kept as in 2D. Under the whole-step
// slider a contact that opened within the step stretches by the slip since the touch, from its
// overlap (the rim's at its lowest point) and its approach (kernels/slider.h), and the springs
// that joined a touching arc within the step by half the step's slip.
// Always inlined: as a call (two a step) it would spill every live SIMD register of the step.
template <FrictionLaw Law, class T, class Mask>
CASKDEM_HOST_DEVICE CASKDEM_ALWAYS_INLINE Vector3<T> shear_contact(const Model& model, const LaneParameters<T>& p,
                                                                   const Mask& touching, const Mask& active,
                                                                   const T& normal, const T& shear_stiffness,
                                                                   const T& overlap, const SliderVelocities<T>& velocity,
                                                                   ContactState3D<T>& state) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0), one = broadcast<T>(1.0);
  const T stretch_time = spring_stretch_time(model, overlap, velocity.spring.normal);
  const T& slip_x = velocity.spring.slip_x;
  const T& slip_z = velocity.spring.slip_z;
  // Taken only where the friction law is evaluated (friction_limit).
  const auto slip_speed = [&] {
    return lane::sqrt(velocity.friction_x * velocity.friction_x + velocity.friction_z * velocity.friction_z);
  };
  const auto was_slipping = state.slipping > broadcast<T>(0.5);
  // Where it touched before (K_s(previous) > 0), the share of the springs still touching: exactly
  // 1 where the stiffness did not change (the centre under the linear law, the rim pressed all
  // round), so a batch that is all so skips the division.
  const auto had = state.stiffness > zero;
  T kept = select(had, one, zero);
  if (!lane::all(!had || state.stiffness == shear_stiffness)) {
    kept = select(had, lane::min(one, shear_stiffness / select(had, state.stiffness, one)), zero);
  }
  // The stiffness the step's slip stretches: K_s, or under the whole-step slider less half of
  // what joined within the step (springs that joined a touching arc as it widened did so, on
  // average, halfway through it; the trapezoidal rule on K_s(t)).
  T stretch_stiffness = shear_stiffness;
  if (model.whole_step_terms & kSpringSinceTouch) {
    const T joined = select(had, lane::max(shear_stiffness - state.stiffness, zero), zero);
    stretch_stiffness = shear_stiffness - broadcast<T>(0.5) * joined;
  }
  const T trial_x = state.shear_x * kept - stretch_stiffness * slip_x * stretch_time;
  const T trial_z = state.shear_z * kept - stretch_stiffness * slip_z * stretch_time;
  const T trial_squared = trial_x * trial_x + trial_z * trial_z;
  const T dashpot_x = -p.damping_beta * shear_stiffness * velocity.shear_dashpot_x;
  const T dashpot_z = -p.damping_beta * shear_stiffness * velocity.shear_dashpot_z;
  const T sticking_x = trial_x + dashpot_x, sticking_z = trial_z + dashpot_z;
  // Decided from squares (lane::root_not_above), so that the magnitudes taken below (square
  // roots of these same sums) are within the floor whatever their rounding.
  const T limit = friction_limit<Law>(model, p, slip_speed, was_slipping, normal, [&](const T& floor) {
    return lane::root_not_above(trial_squared, floor) &&
           lane::root_not_above(sticking_x * sticking_x + sticking_z * sticking_z, floor);
  });
  // The trial force's magnitude, and the cap's division, only where some lane of the batch may
  // slip (lane::root_not_above decides the rest from squares: the same bits).
  lane::Mask<T> slipping(false);
  T cap = one;
  if (!lane::all(lane::root_not_above(trial_squared, limit))) {
    const T trial = lane::sqrt(trial_squared);
    slipping = touching && (trial > limit);
    // Both branches computed, blended per lane: slip caps the spring at mu F_n along its own
    // direction (trial > limit >= 0, so the division is safe where it is used), stick keeps
    // the trial force, an open contact forgets it.
    if (lane::any(slipping)) cap = select(slipping, limit / select(slipping, trial, one), one);
  }
  const T spring_x = select(touching, trial_x * cap, zero);
  const T spring_z = select(touching, trial_z * cap, zero);
  const auto sticking = touching && !slipping;
  const T shear_x = spring_x + select(sticking, dashpot_x, zero);
  const T shear_z = spring_z + select(sticking, dashpot_z, zero);
  // At most mu F_n transmitted; the magnitude and the division only where some lane may exceed it.
  const T magnitude_squared = shear_x * shear_x + shear_z * shear_z;
  T clip = one;
  if (!lane::all(lane::root_not_above(magnitude_squared, limit))) {
    const T magnitude = lane::sqrt(magnitude_squared);
    const auto over = magnitude > limit;
    clip = select(over, limit / select(over, magnitude, one), one);
  }
  state.shear_x = select(active, spring_x, state.shear_x);
  state.shear_z = select(active, spring_z, state.shear_z);
  state.stiffness = select(active, select(touching, shear_stiffness, zero), state.stiffness);
  state.slipping = select(active, lane::as_number<T>(slipping), state.slipping);
  return {shear_x * clip, zero, shear_z * clip};
}

template <FrictionLaw Law, class T>
CASKDEM_HOST_DEVICE inline void step3d(const Model& model, const Contacts3D& contacts, const LaneParameters<T>& p,
                                       const T& table_x, const T& table_vertical, const T& table_z, const T& time,
                                       BodyState3D<T>& body, ContactState3D<T>* points, Response3D<T>& response) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0);
  const T dt = broadcast<T>(model.time_step);
  const T radius = broadcast<T>(contacts.rounding_radius);
  const Quaternion<T> q{body.qw, body.qx, body.qy, body.qz};
  const Rotation<T> rotation = rotation_of(q);
  const Vector3<T> omega = rotation.apply(
      {body.pi_x * p.inverse_inertia, body.pi_y * p.inverse_axial_inertia, body.pi_z * p.inverse_inertia});
  const Vector3<T> velocity{body.vx, body.vy, body.vz};
  // The body's velocities at t_n, for the terms that read them there (kernels/slider.h).
  const std::int32_t whole_step_terms = model.whole_step_terms;
  const Vector3<T> velocity_n{at_whole_step(body.vx, body.kick_vx), at_whole_step(body.vy, body.kick_vy),
                              at_whole_step(body.vz, body.kick_vz)};
  const Vector3<T> omega_n = whole_step_terms
                                 ? rotation.apply({at_whole_step(body.pi_x, body.kick_pi_x) * p.inverse_inertia,
                                                   at_whole_step(body.pi_y, body.kick_pi_y) * p.inverse_axial_inertia,
                                                   at_whole_step(body.pi_z, body.kick_pi_z) * p.inverse_inertia})
                                 : omega;
  // A contact point's velocity from its lever arm, at the half step and at the whole step.
  auto contact_velocities = [&](const Vector3<T>& lever) {
    const Vector3<T> spin = cross(omega, lever);
    const ContactVelocity<T> half{velocity.y + spin.y, velocity.x + spin.x, velocity.z + spin.z};
    if (!whole_step_terms) return slider_velocities(whole_step_terms, half, half);
    const Vector3<T> spin_n = cross(omega_n, lever);
    const ContactVelocity<T> whole{velocity_n.y + spin_n.y, velocity_n.x + spin_n.x, velocity_n.z + spin_n.z};
    return slider_velocities(whole_step_terms, half, whole);
  };
  // A lane that stopped keeps its state; one that stops in this step still updates its springs,
  // which nothing reads after it stopped.
  const auto active = response.status == zero;

  // ---- contact forces at t_n -----------------------------------------------------------
  // The rim: each node of its touching arc pushes with the contact law's normal force; their
  // sum acts at the arc's centre of pressure, where one spring-slider carries the rim's
  // friction, slipping with the material point there (the rim touches as a point contact: no
  // friction torque about the floor normal; docs/cask3d.md says why).
  //
  // A node at (x_j, r, z_j) on the ring has the lever l_j = a + R (x_j, 0, z_j) - r e_y, a = R (-c_x, r - c_y, 0)
  // the ring's centre from the centre of mass, so its gap and its normal velocity
  // v_y + (w x l_j)_y are linear in (x_j, z_j), and the nodes' moment is
  //   sum F_n,j l_j = (sum F_n,j)(a - r e_y) + R (sum F_n,j x_j, 0, sum F_n,j z_j).
  // In the arc's frame the pair at +-psi from the lowest point theta_0, (x, z) = R_c (cos theta,
  // sin theta) with theta = theta_0 +- psi, has the one gap g_c - A cos psi (kernels/rim_contact.h)
  // and the normal velocities v_a + P cos psi +- Q sin psi, and adds (F_+ + F_-) cos psi and
  // (F_+ - F_-) sin psi to the sums along and across theta_0. A pair's two nodes differ only in
  // the sign of Q: shaken in its plane (Q = 0) they push alike and the sum across stays 0 exactly.
  const RimTouch<T> rim = rim_touch(contacts, p, rotation, body.y);
  const T lowest_gap = rim.centre_gap - rim.amplitude;  // the ring's lowest point
  const Vector3<T> ring_arm = rotation.apply({-p.centre_x, radius - p.centre_y, zero});
  const bool normal_whole = whole_step_terms & kWholeStepNormalDashpot;
  const Vector3<T>& normal_omega = normal_whole ? omega_n : omega;  // the normal dashpot's (kernels/slider.h)
  const T ring_velocity =
      (normal_whole ? velocity_n.y : velocity.y) + normal_omega.z * ring_arm.x - normal_omega.x * ring_arm.z;
  const T velocity_per_x = normal_omega.z * rotation.r00 - normal_omega.x * rotation.r20;
  const T velocity_per_z = normal_omega.z * rotation.r02 - normal_omega.x * rotation.r22;
  const T ring = broadcast<T>(contacts.ring_radius);
  const T c0 = rim.arc.towards_cos, s0 = rim.arc.towards_sin;
  const T velocity_along = ring * (velocity_per_x * c0 + velocity_per_z * s0);   // P
  const T velocity_across = ring * (velocity_per_z * c0 - velocity_per_x * s0);  // Q
  // The nodes' sums, in closed form where the rim is pressed all round (kernels/rim_forces.h).
  const RimSums<T> pushed =
      rim_sums(model, contacts, p, RimMotion<T>{rim.centre_gap, rim.amplitude, rim.arc, ring_velocity, velocity_along,
                                                velocity_across});
  const T& rim_normal = pushed.normal;
  const T& normal_along = pushed.normal_along;
  const T& normal_across = pushed.normal_across;
  const T& rim_shear_stiffness = pushed.shear_stiffness;
  const T normal_x = ring * (c0 * normal_along - s0 * normal_across);  // sum F_n,j x_j
  const T normal_z = ring * (s0 * normal_along + c0 * normal_across);  // sum F_n,j z_j
  const Vector3<T> turned{rotation.r00 * normal_x + rotation.r02 * normal_z,
                          rotation.r10 * normal_x + rotation.r12 * normal_z,
                          rotation.r20 * normal_x + rotation.r22 * normal_z};
  const Vector3<T> pressure_moment{rim_normal * ring_arm.x + turned.x, rim_normal * (ring_arm.y - radius) + turned.y,
                                   rim_normal * ring_arm.z + turned.z};  // sum F_n,j l_j
  const auto rim_touching = rim_shear_stiffness > zero;
  // Where no node pushes, the rim's lowest point stands in for the centre of pressure.
  const auto pushing = rim_normal > zero;
  const T per_pushed = broadcast<T>(1.0) / select(pushing, rim_normal, broadcast<T>(1.0));
  const Vector3<T> lowest = rotation.apply({ring * c0 - p.centre_x, radius - p.centre_y, ring * s0});
  const Vector3<T> rim_lever{select(pushing, pressure_moment.x * per_pushed, lowest.x),
                             select(pushing, pressure_moment.y * per_pushed, lowest.y - radius),
                             select(pushing, pressure_moment.z * per_pushed, lowest.z)};
  const SliderVelocities<T> rim_velocity = contact_velocities(rim_lever);
  const Vector3<T> rim_friction =
      shear_contact<Law>(model, p, rim_touching, active, rim_normal, rim_shear_stiffness,
                         lane::max(-lowest_gap, zero), rim_velocity, points[0]);
  // The normal forces' moment: sum l_j x (0, F_n,j, 0) = (sum F_n,j l_j) x e_y.
  const Vector3<T> rim_moment = cross(rim_lever, rim_friction);
  Vector3<T> force{rim_friction.x, rim_normal, rim_friction.z};
  Vector3<T> torque{rim_moment.x - pressure_moment.z, rim_moment.y, rim_moment.z + pressure_moment.x};

  // The centre of the base: one contact point with its own spring-slider.
  T centre_normal = zero, centre_slip_x = zero, centre_slip_z = zero;
  {
    const Vector3<T> arm = rotation.apply({-p.centre_x, radius - p.centre_y, zero});
    const T gap = body.y + arm.y - radius;
    const Vector3<T> lever{arm.x, arm.y - radius, arm.z};
    const SliderVelocities<T> centre_velocity = contact_velocities(lever);
    const T normal_stiffness = broadcast<T>(contacts.centre_normal_stiffness) * p.stiffness_scale;
    const T shear_stiffness =
        shear_stiffness_at(model, broadcast<T>(contacts.centre_shear_stiffness) * p.stiffness_scale, gap);
    const T normal = normal_force(model, normal_stiffness, p, gap, centre_velocity.normal_dashpot);
    centre_normal = normal;
    centre_slip_x = centre_velocity.spring.slip_x;
    centre_slip_z = centre_velocity.spring.slip_z;
    const Vector3<T> friction =
        shear_contact<Law>(model, p, gap < zero, active, normal, shear_stiffness, lane::max(-gap, zero),
                           centre_velocity, points[1]);
    const Vector3<T> contact{friction.x, normal, friction.z};
    force = {force.x + contact.x, force.y + contact.y, force.z + contact.z};
    const Vector3<T> moment = cross(lever, contact);
    torque = {torque.x + moment.x, torque.y + moment.y, torque.z + moment.z};
  }
  // The highest point of the ring (the centre lies between it and the lowest).
  response.max_uplift = lane::max(rim.centre_gap + rim.amplitude, response.max_uplift);

  // ---- observe the state at t_n ----------------------------------------------------------
  Response3D<T>& r = response;
  // The base centre (body origin) relative to where it stood at t = 0.
  const Vector3<T> to_base = rotation.apply({-p.centre_x, -p.centre_y, zero});
  const T slide_x = body.x + to_base.x - r.base_x0;
  const T slide_z = body.z + to_base.z - r.base_z0;
  const T slide_squared = slide_x * slide_x + slide_z * slide_z;
  const double pad = model.pad_clearance > 0.0 ? model.pad_clearance : 1e300;
  // The slide's magnitude only where some lane may set a new peak or pass the pad's edge: else
  // the peak stays and nothing slid off, the same bits as with the root.
  T slide = r.max_slide;
  lane::Mask<T> slid_off(false);
  if (!lane::all(lane::root_not_above(slide_squared, lane::min(r.max_slide, broadcast<T>(pad))))) {
    slide = lane::sqrt(slide_squared);
    slid_off = slide > broadcast<T>(pad);
  }
  const T departure = axis_departure(q, rotation);
  const auto finite = lane::isfinite(body.x + body.y + body.z + body.vx + body.vy + body.vz + body.qw + body.qx + body.qy +
                                     body.qz + body.pi_x + body.pi_y + body.pi_z);
  const auto tipped = departure >= broadcast<T>(contacts.tip_departure);
  const auto left_floor = lowest_gap > broadcast<T>(model.lift_off_height);
  record_stop(active, finite, tipped, left_floor, slid_off, time, r.status, r.end_time);
  const auto running = r.status == zero;
  r.max_axis_departure = lane::max(departure, r.max_axis_departure);
  r.max_slide = lane::max(slide, r.max_slide);
  // Slip: the velocity of the material where the cask bears on the floor (the rim's centre of
  // pressure and the base centre, weighted by their normal forces), over the step. A cask rolling
  // on its rim without slipping bears where its material stands still: no slip, while its base
  // centre walks.
  const T bearing = rim_normal + centre_normal;
  const auto bears = running && bearing > zero;
  const T weight = broadcast<T>(1.0) / select(bears, bearing, broadcast<T>(1.0));
  const T bearing_x = (rim_normal * rim_velocity.spring.slip_x + centre_normal * centre_slip_x) * weight;
  const T bearing_z = (rim_normal * rim_velocity.spring.slip_z + centre_normal * centre_slip_z) * weight;
  r.slip_x = select(bears, r.slip_x + bearing_x * dt, r.slip_x);
  r.slip_z = select(bears, r.slip_z + bearing_z * dt, r.slip_z);
  const T slip_squared = r.slip_x * r.slip_x + r.slip_z * r.slip_z;
  if (!lane::all(lane::root_not_above(slip_squared, r.max_slip))) {
    r.max_slip = lane::max(lane::sqrt(slip_squared), r.max_slip);
  }
  const auto above = departure > broadcast<T>(contacts.stability_departure);
  const auto rose_past_alpha = above && (r.above_stability < broadcast<T>(0.5));
  if (lane::any(rose_past_alpha)) r.instability_time = select(rose_past_alpha, time, r.instability_time);
  r.above_stability = lane::as_number<T>(above);

  // ---- advance to t_{n+1} (stopped lanes keep their state) --------------------------------
  const T ax = force.x * p.inverse_mass - p.horizontal_scale * table_x;
  const T ay = force.y * p.inverse_mass - (broadcast<T>(model.gravity) + p.vertical_scale * table_vertical);
  const T az = force.z * p.inverse_mass - p.horizontal_scale * table_z;
  const T kick_vx = ax * dt, kick_vy = ay * dt, kick_vz = az * dt;
  const T vx = body.vx + kick_vx, vy = body.vy + kick_vy, vz = body.vz + kick_vz;
  const Vector3<T> body_torque = rotation.apply_transpose(torque);
  Vector3<T> pi{body.pi_x + body_torque.x * dt, body.pi_y + body_torque.y * dt, body.pi_z + body_torque.z * dt};
  Quaternion<T> next = q;
  free_rotation(dt, p.inverse_inertia, p.inverse_axial_inertia, next, pi);
  r.spin = select(running, r.spin + pi.y * p.inverse_axial_inertia * dt, r.spin);
  body.x = select(running, body.x + vx * dt, body.x);
  body.y = select(running, body.y + vy * dt, body.y);
  body.z = select(running, body.z + vz * dt, body.z);
  body.kick_vx = select(running, kick_vx, body.kick_vx);
  body.kick_vy = select(running, kick_vy, body.kick_vy);
  body.kick_vz = select(running, kick_vz, body.kick_vz);
  body.kick_pi_x = select(running, pi.x - body.pi_x, body.kick_pi_x);
  body.kick_pi_y = select(running, pi.y - body.pi_y, body.kick_pi_y);
  body.kick_pi_z = select(running, pi.z - body.pi_z, body.kick_pi_z);
  body.vx = select(running, vx, body.vx);
  body.vy = select(running, vy, body.vy);
  body.vz = select(running, vz, body.vz);
  body.qw = select(running, next.w, body.qw);
  body.qx = select(running, next.x, body.qx);
  body.qy = select(running, next.y, body.qy);
  body.qz = select(running, next.z, body.qz);
  body.pi_x = select(running, pi.x, body.pi_x);
  body.pi_y = select(running, pi.y, body.pi_y);
  body.pi_z = select(running, pi.z, body.pi_z);
}

}  // namespace caskdem::kernels
