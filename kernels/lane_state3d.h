#pragma once
// Per-realisation state of the 3D cask (kernels/step3d.h), templated on the number type as in
// 2D (kernels/lane_state.h): one realisation (double) or one per SIMD lane. The parameters
// are the 2D ones (LaneParameters, with its axial inertia).

#include "kernels/host_device.h"

namespace caskdem {

// Rigid-body state in the floor frame: the centre of mass and its velocity (at the half step),
// the orientation (unit quaternion, body -> floor) and the angular momentum in body
// coordinates (at the half step, before the step's torque kick). The last step's change of the
// velocity and of the body-frame angular momentum are kept for the whole-step slider
// (kernels/slider.h); zero reads the half-step values.
template <class T>
struct BodyState3D {
  T x, y, z;
  T vx, vy, vz;
  T qw, qx, qy, qz;
  T pi_x, pi_y, pi_z;
  T kick_vx, kick_vy, kick_vz;  // m/s
  T kick_pi_x, kick_pi_y, kick_pi_z;  // kg m^2/s, body frame

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(x); f(y); f(z); f(vx); f(vy); f(vz); f(qw); f(qx); f(qy); f(qz); f(pi_x); f(pi_y); f(pi_z);
    f(kick_vx); f(kick_vy); f(kick_vz); f(kick_pi_x); f(kick_pi_y); f(kick_pi_z);
  }
  static constexpr int field_count = 19;
};

// The spring-slider of one contact: its shear spring is a vector in the floor plane; the rim's
// stiffness changes with the arc it touches on, so the last one is kept (kernels/step3d.h).
template <class T>
struct ContactState3D {
  T shear_x, shear_z;  // N
  T stiffness;         // N/m, K_s when it last touched (0: it did not)
  T slipping;          // 1 if it slipped in the last step

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(shear_x); f(shear_z); f(stiffness); f(slipping);
  }
  static constexpr int field_count = 4;
};

// What a 3D realisation has done so far.
template <class T>
struct Response3D {
  T status;              // LaneStatus as a number
  T end_time;            // s
  T max_axis_departure;  // max |e - e_y|^2 of the axis e: the max tilt is 2 asin(sqrt / 2)
  T max_slide;           // m, largest |sliding| of the base centre in the floor plane
  T max_uplift;          // m, largest gap of a contact point (its rest gap is 0)
  T base_x0, base_z0;    // m, base centre at t = 0 (the sliding datum)
  T spin;                // rad, the turn about the cask's own axis, accumulated
  T above_stability;     // 1 while the tilt is beyond alpha
  T instability_time;    // s, the last time the tilt rose past alpha
  // Slip: how far the cask's material slid over the floor where it touches, apart from the walk of
  // its base centre while it rolls on its rim (kernels/step3d.h): a vector in the floor plane,
  // accumulated, and its largest magnitude.
  T slip_x, slip_z;      // m
  T max_slip;            // m

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(status); f(end_time); f(max_axis_departure); f(max_slide); f(max_uplift); f(base_x0); f(base_z0); f(spin);
    f(above_stability); f(instability_time); f(slip_x); f(slip_z); f(max_slip);
  }
  static constexpr int field_count = 13;
};

}  // namespace caskdem
