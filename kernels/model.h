#pragma once
// The model: everything about an analysis that all realisations share, read-only while
// they run (like MuJoCo's mjModel). It is plain data with fixed-size arrays so that the
// same object is read by the scalar reference path and by every SIMD kernel, and could be
// copied to an accelerator as it is. What varies from realisation to realisation lives in
// LaneParameters (kernels/lane_state.h); src/model/ builds both from a case file.
//
// Frames. The floor frame moves with the shaking table; x is horizontal in the plane of
// excitation, y is up, the floor surface is y = 0. The body frame is fixed to the cask with
// its origin at the centre of the base of the outer section, x along the base, y up.
// Rotation theta is counter-clockwise positive: theta > 0 lifts the +x side.

#include <cstdint>

namespace caskdem {

inline constexpr int kMaxCorners = 16;  // a distributed footprint's points (model/section.h), or a polygon's corners
inline constexpr int kMaxFrictionTable = 32;
inline constexpr int kPeakCount = 8;  // half-cycle peaks of |omega| a lane remembers

enum class FrictionLaw : std::int32_t {
  constant = 0,        // mu = mu_s
  static_kinetic = 1,  // mu_s while the contact sticks, mu_k once it slips
  exponential = 2,     // mu(v) = mu_k + (mu_s - mu_k) exp(-|v| / v0)
  tabulated = 3,       // mu(|v|) interpolated in a table (speed, coefficient)
};

// The contact's normal law (kernels/contact_law.h): the source paper's linear spring-dashpot, or a
// Hertz spring K d sqrt(d / d_H) with Hunt & Crossley's damper, a model form of its own.
enum class NormalLaw : std::int32_t {
  linear = 0,         // K d - beta K v_n
  hunt_crossley = 1,  // K d sqrt(d / d_H) (1 - lambda v_n)
};

// Where the whole-step slider departs from the source paper's central-difference scheme
// (kernels/slider.h), a bit set per term, so that each can be studied alone: which of the
// spring-slider's velocity-dependent terms read the velocity at the whole step t_n
// (extrapolated) rather than at the half step t_{n-1/2}, and whether a contact that touches
// within a step stretches its shear spring by the slip since the touch rather than the step's.
enum WholeStepTerm : std::int32_t {
  kWholeStepNormalDashpot = 1,  // the normal dashpot beta K_n v_n (and the impact damper)
  kWholeStepShearDashpot = 2,   // the sticking contact's shear dashpot beta K_s v_s
  kWholeStepFriction = 4,       // the slip speed the friction law reads, mu(|v_s|)
  kSpringSinceTouch = 8,        // a new contact's shear spring: the slip since the touch
  kWholeStepSlider = kWholeStepNormalDashpot | kWholeStepShearDashpot | kWholeStepFriction | kSpringSinceTouch,
};

// How a lane ended. A tipped cask is a result, not an error.
enum class LaneStatus : std::int32_t {
  running = 0,     // still running, or ran to the end of the motion
  tipped_over = 1,  // |theta| reached the tip-over angle
  left_floor = 2,   // the lowest corner rose higher than the lift-off height
  slid_off_pad = 3,  // the base slid further than the pad allows
  non_finite = 4,    // a state variable became NaN or infinite (frozen, flagged)
};

struct Model {
  // Contact corners: the rounded corners of the section that can touch the floor. Each is a
  // circular arc of radius rounding_radius centred at (corner_x, corner_y) in the body frame.
  std::int32_t corner_count = 0;
  double corner_x[kMaxCorners] = {};
  double corner_y[kMaxCorners] = {};
  double corner_rest_gap[kMaxCorners] = {};  // gap to the floor when standing at rest (uplift datum)
  double rounding_radius = 0.0;
  // A corner at the middle of the base that lanes may lower by their base_camber (a slightly
  // convex base); -1 when the section has none (kernels/lane_state.h).
  std::int32_t camber_corner = -1;
  // Spring constants of each corner's contact: distributed stiffness [N/m^3] times the
  // contact length the corner represents times the out-of-plane depth.
  double corner_normal_stiffness[kMaxCorners] = {};  // N/m
  double corner_shear_stiffness[kMaxCorners] = {};   // N/m
  double contact_stiffness_scale = 1.0;  // already in the two above; kept for the damping (model/build.h)
  NormalLaw normal_law = NormalLaw::linear;
  // d_H, m: the overlap at which the Hunt-Crossley law's spring pushes as the linear one does,
  // the nominal cask's settlement on linear springs (so both laws carry its weight at the same
  // overlap); 0 for the linear law.
  double hertz_overlap = 0.0;

  FrictionLaw friction_law = FrictionLaw::constant;
  std::int32_t friction_table_size = 0;
  double friction_table_speed[kMaxFrictionTable] = {};        // m/s, increasing from 0
  double friction_table_coefficient[kMaxFrictionTable] = {};  // mu at that speed

  double gravity = 9.80665;  // m/s^2
  double time_step = 0.0;    // s, dt = f_s * 2 sqrt(m / K)
  // WholeStepTerm bits: 0 is the source paper's half-step slider, kWholeStepSlider the whole-step one.
  std::int32_t whole_step_terms = 0;

  // Observation and end criteria.
  double stability_angle = 0.0;           // alpha: rotation at which the centre of mass passes over the pivot
  double rocking_frequency = 0.0;         // p = sqrt(m g R / I_O) of the rigid equivalent, rad/s
  double tip_over_angle = 0.0;            // |theta| at which a lane counts as tipped over and stops
  double rocking_threshold_angle = 0.0;   // |theta| beyond which the cask rocks on one side (impact counting)
  double lift_off_height = 0.0;           // lowest corner above the floor by more than this: left the floor
  double pad_clearance = 0.0;             // |sliding| beyond this: slid off the pad (0: unbounded pad)
};

}  // namespace caskdem
