#pragma once
// The velocities a spring-slider reads: at the half step, as the source paper's central
// differences give them, or extrapolated to the whole step (Model::whole_step_terms).
//
// Central differences keep velocities at half steps: on entry to step n the state holds
// v(n-1/2), and the contact forces are computed at t_n from positions at t_n. The springs are
// exact to the scheme: the shear spring's increment K_s v(n-1/2) dt is K_s times the slip from
// t_{n-1} to t_n. The terms that read a velocity rather than a displacement are not: the normal
// and shear dashpots (beta K v) and a velocity-dependent friction coefficient mu(|v_s|) read
// v(n-1/2) = v(t_n) - a dt/2 + O(dt^2), half a step behind the springs, a first-order lag
// (docs/time-step.md traces the sliding block's first-order error to it). The whole-step value
//
//   v(t_n) = v(n-1/2) + (v(n-1/2) - v(n-3/2)) / 2 + O(dt^2)
//
// (linear extrapolation over the last two half steps; Taylor expansion of v about t_n) is second
// order and stays explicit: the state keeps the last step's velocity change, the "kick"
// v(n-1/2) - v(n-3/2) (kernels/lane_state.h). At a step where the kick is zero (the first step
// from rest) both readings agree. Each of the three terms can read either, so that what each
// contributes can be measured alone (kernels/model.h, WholeStepTerm).
//
// The spring at a touch. A contact that opens between t_{n-1} and t_n (gap g_{n-1} > 0 >= g_n)
// touched at t* within the step; the spring stretches only from t*, so its increment is K_s
// times the slip from t* to t_n, not the step's. The scheme moves the body linearly over the
// step (x_n = x_{n-1} + v(n-1/2) dt), so the gap falls linearly, g_{n-1} - g_n = -v_n dt + O(dt^2)
// with v_n the contact point's half-step normal velocity, and the slip after t* is the fraction
//
//   phi = d_n / (-v_n dt)    where d_n = -g_n < -v_n dt (the contact was open at t_{n-1}),
//   phi = 1                  otherwise (it touched at t_{n-1} as well),
//
// of the step's. The paper's scheme takes phi = 1 always, which stretches a new spring by half a
// step's slip too much on average, always against the slip: a first-order error with a sign.
// Where the contact sticks at once (high friction, a short contact: a landing, a bounce) the
// extra stretch stays in the spring and throws the cask off too hard; lightly damped contacts
// bounce many times a rocking impact, so the error accumulates into a bias of the ensemble's
// fragility (docs/time-step.md, "The spring at a touch"). phi makes it second order.

#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/model.h"

namespace caskdem::kernels {

// The velocity of a contact point relative to the floor, along the floor normal and along the
// floor (2D), or the floor-plane slip (3D: slip_z is its second component).
template <class T>
struct ContactVelocity {
  T normal, slip_x, slip_z;
};

// What one spring-slider reads: the half-step slip that stretches its shear spring, and the
// velocities its dashpots and friction law read (half- or whole-step, per Model::whole_step_terms).
template <class T>
struct SliderVelocities {
  ContactVelocity<T> spring;  // half step: the slip from t_{n-1} to t_n over dt
  T normal_dashpot;
  T shear_dashpot_x, shear_dashpot_z;
  T friction_x, friction_z;  // the slip velocity whose magnitude mu(|v|) reads
};

template <class T>
CASKDEM_HOST_DEVICE inline SliderVelocities<T> slider_velocities(std::int32_t whole_step_terms,
                                                                 const ContactVelocity<T>& half,
                                                                 const ContactVelocity<T>& whole) {
  // A model-wide choice, the same for every lane: a branch, not a blend.
  const ContactVelocity<T>& normal = (whole_step_terms & kWholeStepNormalDashpot) ? whole : half;
  const ContactVelocity<T>& shear = (whole_step_terms & kWholeStepShearDashpot) ? whole : half;
  const ContactVelocity<T>& friction = (whole_step_terms & kWholeStepFriction) ? whole : half;
  return {half, normal.normal, shear.slip_x, shear.slip_z, friction.slip_x, friction.slip_z};
}

// A planar body's velocity (its centre of mass and its rotation rate).
template <class T>
struct BodyVelocity {
  T vx, vy, omega;
};

// The fraction phi of the step's slip that a contact's shear spring takes (above): 1 unless the
// contact opened within the step, where it is the overlap over the step's approach.
template <class T>
CASKDEM_HOST_DEVICE inline T slip_since_touch(const T& overlap, const T& normal_velocity, double time_step) {
  using lane::broadcast;
  using lane::select;
  const T one = broadcast<T>(1.0);
  const T approach = lane::max(-normal_velocity, broadcast<T>(0.0)) * broadcast<T>(time_step);
  const auto opened = overlap < approach;  // false wherever the contact does not approach
  // Most steps no lane touches: the division only where some lane may (1 either way elsewhere).
  if (!lane::any(opened)) return one;
  // Both sides computed, blended per lane: the division only where it is taken (approach > 0).
  return select(opened, overlap / select(opened, approach, one), one);
}

// How long a contact's shear spring stretched in this step: dt, or under the whole-step slider
// the time since a touch within it (a model-wide choice: a uniform branch). The planar corners
// (kernels/contact_law.h) and the 3D rim and centre (kernels/step3d.h) read it alike.
template <class T>
CASKDEM_HOST_DEVICE inline T spring_stretch_time(const Model& model, const T& overlap, const T& normal_velocity) {
  const T dt = lane::broadcast<T>(model.time_step);
  if (!(model.whole_step_terms & kSpringSinceTouch)) return dt;
  return dt * slip_since_touch(overlap, normal_velocity, model.time_step);
}

// v(n-1/2) + kick / 2: the whole-step value of a half-step velocity from its last change.
template <class T>
CASKDEM_HOST_DEVICE inline T at_whole_step(const T& half_step, const T& kick) {
  return half_step + lane::broadcast<T>(0.5) * kick;
}

}  // namespace caskdem::kernels
