#pragma once
// Per-realisation data, templated on the number type: T = double holds one realisation,
// T = xsimd::batch<double, Arch> holds one per SIMD lane. In an ensemble block each field
// is an aligned array over lanes (structure of arrays); for_each_field lists the fields
// once, for loading, storing and sizing those arrays.

#include "kernels/host_device.h"
#include "kernels/model.h"

namespace caskdem {

// What may differ between realisations of one model.
template <class T>
struct LaneParameters {
  T inverse_mass;          // 1/kg
  T inverse_inertia;       // 1/(kg m^2), about the centre of mass
  T centre_x, centre_y;    // centre of mass in the body frame, m
  T friction_static;       // mu_s (the only coefficient of the constant law)
  T friction_kinetic;      // mu_k
  T inverse_decay_speed;   // 1/v0 of the exponential law, s/m
  T damping_beta;          // stiffness-proportional damping C = beta K, s
  T horizontal_scale;      // factor on the horizontal table acceleration
  T vertical_scale;        // factor on the vertical table acceleration
  T stiffness_scale;       // factor on every contact spring constant
  // Mechanisms beyond the source paper's model (src/diagnosis/mechanisms.h); zero, or one
  // for floor_soft_ratio, leaves the paper's model.
  T impact_damping;        // lambda, s/m: Hunt-Crossley damper, loss growing with impact speed (kernels/contact_law.h)
  T floor_soft_ratio;      // s: a floor layer of stiffness s K over the first floor_soft_depth of overlap
  T floor_soft_depth;      // d0, m
  T base_camber;           // c, m: the base-centre corner (Model::camber_corner) sits c below the base corners
  T wobble_damping;        // zeta_w: rocking damper -2 zeta_w p (|theta|/alpha) omega, out-of-plane losses
  // The 3D cask (kernels/step3d.h) also turns about its own axis: inverse_inertia is then about
  // the horizontal axes through the centre of mass, this about the cask's axis (0 in 2D).
  T inverse_axial_inertia;  // 1/(kg m^2)

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(inverse_mass); f(inverse_inertia); f(centre_x); f(centre_y); f(friction_static); f(friction_kinetic);
    f(inverse_decay_speed); f(damping_beta); f(horizontal_scale); f(vertical_scale); f(stiffness_scale);
    f(impact_damping); f(floor_soft_ratio); f(floor_soft_depth); f(base_camber); f(wobble_damping);
    f(inverse_axial_inertia);
  }
  static constexpr int field_count = 17;
};

// Rigid-body state in the floor frame. Central differences keep positions at whole steps
// (t_n) and velocities at half steps (t_{n-1/2} on entry to a step). The last step's change of
// each velocity, v(n-1/2) - v(n-3/2), is kept for the whole-step slider (kernels/slider.h),
// which extrapolates the velocity to t_n; zero (no history) reads the half-step velocity.
template <class T>
struct BodyState {
  T x, y;      // centre of mass, m
  T theta;     // rotation, rad
  T vx, vy;    // m/s
  T omega;     // rad/s
  T kick_vx, kick_vy;  // m/s, the last step's change of vx and vy
  T kick_omega;        // rad/s, the last step's change of omega

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(x); f(y); f(theta); f(vx); f(vy); f(omega); f(kick_vx); f(kick_vy); f(kick_omega);
  }
  static constexpr int field_count = 9;
};

// The spring-slider state of one corner contact.
template <class T>
struct CornerState {
  T shear_spring;  // K_s times the spring's stretch, N: its force under the linear law (kernels/contact_law.h)
  T slipping;      // 1 if the contact slipped in the last step, else 0

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(shear_spring); f(slipping);
  }
  static constexpr int field_count = 2;
};

// What a realisation's response has done so far: the running maxima and events that make
// its result, so that no time history is needed to summarise a run.
template <class T>
struct Response {
  T status;              // LaneStatus as a number
  T end_time;            // time the lane stopped, or the end of the run (set by finish())
  T max_abs_rotation;    // rad
  T max_abs_slide;       // m, base centre relative to the floor
  T max_uplift;          // m, largest rise of a corner above its rest position
  T final_rotation;      // rad, at end_time (set by finish())
  T final_slide;         // m, at end_time: the residual sliding (set by finish())
  T base_x0;             // m, base centre at t = 0 (sliding datum)
  T rocking_side;        // -1, 0 (not yet rocked), +1: the side |theta| last passed the rocking threshold on
  T impacts;             // number of changes of rocking side
  T current_peak;        // max |omega| in the current rocking half-cycle
  T peak[kPeakCount];    // max |omega| of the first half-cycles (free-vibration restitution)
  T above_stability;     // 1 while |theta| > alpha
  T instability_time;    // last time |theta| rose past alpha (when a tipped cask passed its stability angle)

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_field(F&& f) {
    f(status); f(end_time); f(max_abs_rotation); f(max_abs_slide); f(max_uplift); f(final_rotation);
    f(final_slide); f(base_x0); f(rocking_side); f(impacts); f(current_peak);
    for (auto& p : peak) f(p);
    f(above_stability); f(instability_time);
  }
  static constexpr int field_count = 14 + kPeakCount;
};

// Per-corner contact forces of one step, for time histories (the scalar path records them).
template <class T>
struct ContactForces {
  T normal[kMaxCorners];
  T shear[kMaxCorners];
  T uplift;  // largest rise of a corner above its rest position, m
  T slide;   // base centre relative to its initial position, m
};

}  // namespace caskdem
