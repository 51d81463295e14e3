#pragma once
// One explicit central-difference step of the cask on its floor, for one realisation
// (T = double) or one SIMD batch of realisations (T = xsimd::batch<double, Arch>).
//
// Equations of motion in the floor frame, which translates with the table (a relative
// frame: the sliding displacement is the state itself, so integrating a record cannot make
// it drift; the table's motion enters only as an inertial force):
//
//   m x''     = sum F_s - m a_h(t)
//   m y''     = sum F_n - m (g + a_v(t))
//   I theta'' = sum (l_x F_n - l_y F_s)        l: contact point relative to the centre of mass
//
// Central differences (the DEM's explicit scheme; Cundall 1971, Hart et al. 1988):
//   v(n+1/2) = v(n-1/2) + a(n) dt,   x(n+1) = x(n) + v(n+1/2) dt,
// with contact forces from positions at t_n and shear-spring increments from velocities at
// t_{n-1/2}; the dashpots and the friction law read the velocity at t_{n-1/2} (the source paper's
// scheme) or extrapolated to t_n (Model::whole_step_terms; kernels/slider.h). The step observes
// the state at t_n (running maxima, impacts, end criteria) before advancing it; a lane that has
// stopped keeps its state.

#include "kernels/contact_law.h"
#include "kernels/end_criteria.h"
#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/lane_state.h"
#include "kernels/model.h"
#include "kernels/portable_math.h"
#include "kernels/slider.h"

namespace caskdem::kernels {

template <FrictionLaw Law, class T>
CASKDEM_HOST_DEVICE inline void step(const Model& model, const LaneParameters<T>& p, const T& table_horizontal,
                                     const T& table_vertical, const T& time, BodyState<T>& body,
                                     CornerState<T>* corners, Response<T>& response,
                                     ContactForces<T>* forces = nullptr) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0);
  const T one = broadcast<T>(1.0);
  const T dt = broadcast<T>(model.time_step);
  const T radius = broadcast<T>(model.rounding_radius);
  const auto active = response.status == zero;

  // ---- contact forces at t_n -----------------------------------------------------------
  const SinCos<T> rotation = sin_cos(body.theta);
  const T s = rotation.sin;
  const T c = rotation.cos;
  // The body's velocity at t_n, for the terms that read it there (kernels/slider.h); the
  // half-step slider reads none of it.
  const std::int32_t whole_step_terms = model.whole_step_terms;
  BodyVelocity<T> at_n{body.vx, body.vy, body.omega};
  if (whole_step_terms) {
    at_n = {at_whole_step(body.vx, body.kick_vx), at_whole_step(body.vy, body.kick_vy),
            at_whole_step(body.omega, body.kick_omega)};
  }
  T force_x = zero, force_y = zero, moment = zero;
  T lowest_gap = broadcast<T>(1e300);
  T uplift = zero;
  CornerState<T> next[kMaxCorners];
  for (int k = 0; k < model.corner_count; ++k) {
    const T arm_x = broadcast<T>(model.corner_x[k]) - p.centre_x;  // arc centre from the centre of mass, body frame
    // A convex base: the base-centre corner sits base_camber below the others.
    const T corner_y = k == model.camber_corner ? broadcast<T>(model.corner_y[k]) - p.base_camber
                                                : broadcast<T>(model.corner_y[k]);
    const T arm_y = corner_y - p.centre_y;
    const T centre_x = c * arm_x - s * arm_y;  // ... and in the floor frame
    const T centre_y = s * arm_x + c * arm_y;
    const T gap = body.y + centre_y - radius;
    const T lever_x = centre_x;  // contact point: the bottom of the arc
    const T lever_y = centre_y - radius;
    const ContactVelocity<T> half{body.vy + body.omega * lever_x, body.vx - body.omega * lever_y, zero};
    const ContactVelocity<T> whole =
        whole_step_terms ? ContactVelocity<T>{at_n.vy + at_n.omega * lever_x, at_n.vx - at_n.omega * lever_y, zero}
                         : half;
    const CornerContact<T> contact =
        corner_contact<Law>(model, p, k, gap, slider_velocities(whole_step_terms, half, whole), corners[k]);
    force_x = force_x + contact.shear_force;
    force_y = force_y + contact.normal_force;
    moment = moment + (lever_x * contact.normal_force - lever_y * contact.shear_force);
    next[k] = contact.next;
    lowest_gap = lane::min(lowest_gap, gap);
    uplift = lane::max(uplift, gap - broadcast<T>(model.corner_rest_gap[k]));
    if (forces) {
      forces->normal[k] = contact.normal_force;
      forces->shear[k] = contact.shear_force;
    }
  }

  // ---- observe the state at t_n ----------------------------------------------------------
  const T base_x = body.x - c * p.centre_x + s * p.centre_y;  // body-frame origin, the base centre
  const T slide = base_x - response.base_x0;
  const T abs_rotation = lane::abs(body.theta);
  if (forces) {
    forces->uplift = uplift;
    forces->slide = slide;
  }

  Response<T>& r = response;
  const auto finite = lane::isfinite(body.x + body.y + body.theta + body.vx + body.vy + body.omega);
  const auto tipped = abs_rotation >= broadcast<T>(model.tip_over_angle);
  const auto left_floor = lowest_gap > broadcast<T>(model.lift_off_height);
  const double pad = model.pad_clearance > 0.0 ? model.pad_clearance : 1e300;
  const auto slid_off = lane::abs(slide) > broadcast<T>(pad);
  record_stop(active, finite, tipped, left_floor, slid_off, time, r.status, r.end_time);
  const auto running = r.status == zero;

  // Running maxima. A stopped lane's state is frozen, so observing it again changes nothing;
  // max(x, m) returns m when x is NaN (minpd/maxpd rule), so a non-finite state is never recorded.
  r.max_abs_rotation = lane::max(abs_rotation, r.max_abs_rotation);
  r.max_abs_slide = lane::max(lane::abs(slide), r.max_abs_slide);
  r.max_uplift = lane::max(uplift, r.max_uplift);

  // Rocking half-cycles: the side changes when theta passes the threshold on the other
  // side; each change is an impact. A half-cycle's peak |omega| is taken while the cask
  // falls toward the impact (theta omega < 0), as on a measured record: the impact that
  // opened the half-cycle is still decelerating the cask when the side changes.
  const T threshold = broadcast<T>(model.rocking_threshold_angle);
  const T side = select(body.theta > threshold, one, select(body.theta < -threshold, -one, r.rocking_side));
  const auto flip = side * r.rocking_side < zero;
  if (lane::any(flip)) {
    for (int j = 0; j < kPeakCount; ++j) {
      r.peak[j] = select(flip && (r.impacts == broadcast<T>(double(j))), r.current_peak, r.peak[j]);
    }
    r.impacts = select(flip, r.impacts + one, r.impacts);
    r.current_peak = select(flip, zero, r.current_peak);
  }
  const auto falling = body.theta * body.omega < zero;
  r.current_peak = select(falling, lane::max(lane::abs(body.omega), r.current_peak), r.current_peak);
  r.rocking_side = side;

  // When a tipping cask passed its stability angle for the last time.
  const auto above = abs_rotation > broadcast<T>(model.stability_angle);
  const auto rose_past_alpha = above && (r.above_stability < broadcast<T>(0.5));
  if (lane::any(rose_past_alpha)) r.instability_time = select(rose_past_alpha, time, r.instability_time);
  r.above_stability = lane::as_number<T>(above);

  // ---- advance to t_{n+1} (stopped lanes keep their state) --------------------------------
  const T accel_x = force_x * p.inverse_mass - p.horizontal_scale * table_horizontal;
  const T accel_y = force_y * p.inverse_mass - (broadcast<T>(model.gravity) + p.vertical_scale * table_vertical);
  // Out-of-plane losses (wobbling, top-spinning of a real cylinder) as a damping couple
  // -I 2 zeta_w p (|theta| / alpha) omega whose ratio grows with the amplitude: zeta_w at
  // |theta| = alpha, zero when it stands.
  const T wobble = broadcast<T>(2.0 * model.rocking_frequency / model.stability_angle) * p.wobble_damping *
                   lane::abs(body.theta) * body.omega;
  const T accel_theta = moment * p.inverse_inertia - wobble;
  const T kick_vx = accel_x * dt, kick_vy = accel_y * dt, kick_omega = accel_theta * dt;
  const T vx = body.vx + kick_vx;
  const T vy = body.vy + kick_vy;
  const T omega = body.omega + kick_omega;
  body.x = select(running, body.x + vx * dt, body.x);
  body.y = select(running, body.y + vy * dt, body.y);
  body.theta = select(running, body.theta + omega * dt, body.theta);
  body.kick_vx = select(running, kick_vx, body.kick_vx);
  body.kick_vy = select(running, kick_vy, body.kick_vy);
  body.kick_omega = select(running, kick_omega, body.kick_omega);
  body.vx = select(running, vx, body.vx);
  body.vy = select(running, vy, body.vy);
  body.omega = select(running, omega, body.omega);
  for (int k = 0; k < model.corner_count; ++k) {
    corners[k].shear_spring = select(running, next[k].shear_spring, corners[k].shear_spring);
    corners[k].slipping = select(running, next[k].slipping, corners[k].slipping);
  }
}

// The end of a run: the final rotation and sliding (residual sliding) from the final state,
// and the end time of lanes still running. A stopped lane's state is the one it stopped in;
// a non-finite lane reports zeros there (its status says why).
template <class T>
CASKDEM_HOST_DEVICE inline void finish(const Model& model, const LaneParameters<T>& p, const BodyState<T>& body,
                                       double end_time, Response<T>& response) {
  using lane::broadcast;
  using lane::select;
  const SinCos<T> rotation = sin_cos(body.theta);
  const T slide = body.x - rotation.cos * p.centre_x + rotation.sin * p.centre_y - response.base_x0;
  const auto finite = lane::isfinite(slide + body.theta);
  const auto running = response.status == broadcast<T>(0.0);
  response.final_rotation = select(finite, body.theta, broadcast<T>(0.0));
  response.final_slide = select(finite, slide, broadcast<T>(0.0));
  response.end_time = select(running, broadcast<T>(end_time), response.end_time);
  (void)model;
}

}  // namespace caskdem::kernels
