#pragma once
// The 3D cask's contact points: what, beside Model (friction law, gravity, step, end
// criteria; kernels/model.h), all realisations of a 3D cask share. Plain data like Model, read
// by the scalar reference and by every SIMD width alike.
//
// Frames. The floor frame moves with the table; x and z are horizontal (the directions of
// the H1 and H2 components before any incidence angle), y is up, the floor is y = 0: the 2D
// model's plane is z = 0. The body frame is fixed to the cask, origin at the centre of its
// base, y along its axis.
//
// The base. A real cask stands on the circle of its base: a distributed Winkler foundation of
// k_n per unit area has vertical stiffness k_n A and rocking stiffness k_n I_base (A = pi R^2,
// I_base = pi R^4 / 4), and a tilted cask pivots on its rim. The points here give both: a ring
// of N points at radius R_c = R - r (the rim, rounded by r: each point is a sphere of radius r)
// with K_ring = k_n I_base / (R_c^2 / 2) in all, and one point at the centre with the rest,
// k_n A - K_ring (>= 0 for R_c >= R / sqrt 2). A tilted cask pivots on a chord of the ring,
// R_c cos(pi / N) from the axis: 0.12 % inside for N = 64. Shear springs take the same shares
// of k_s A.

#include <cstdint>

namespace caskdem {

inline constexpr int kMaxContactPoints3D = 129;  // a ring of up to 128 and the centre

struct Contacts3D {
  std::int32_t count = 0;
  // Sphere centres in the body frame.
  double x[kMaxContactPoints3D] = {};
  double y[kMaxContactPoints3D] = {};
  double z[kMaxContactPoints3D] = {};
  double normal_stiffness[kMaxContactPoints3D] = {};  // N/m
  double shear_stiffness[kMaxContactPoints3D] = {};   // N/m
  double rounding_radius = 0.0;  // r, m
  double base_radius = 0.0;      // R, m
  double height = 0.0;           // H, m
  // The tilt criteria as |e - e_y|^2 = (2 sin(t/2))^2 of the axis e (kernels/step3d.h): of
  // Model's tip_over_angle and stability_angle, so that no lane takes an inverse sine.
  double tip_departure = 0.0;
  double stability_departure = 0.0;
};

}  // namespace caskdem
