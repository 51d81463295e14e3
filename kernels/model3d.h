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
// I_base = pi R^4 / 4), and a tilted cask pivots on its rim. Two contacts give both: the rim, a
// continuous ring at radius R_c = R - r (rounded by r: a ring of spheres of radius r) with
// K_ring = k_n I_base / (R_c^2 / 2) in all, and one point at the centre with the rest,
// k_n A - K_ring (>= 0 for R_c >= R / sqrt 2). The ring touches on an arc around its lowest
// point, integrated by nodes that move with the arc (kernels/rim_contact.h): it pivots on the
// rim itself and can roll on it. Shear springs take the same shares of k_s A; the rim's
// friction is one spring-slider at its centre of pressure (kernels/step3d.h).

#include <cstdint>

namespace caskdem {

inline constexpr int kRimNodePairs = 8;                        // 16 Gauss nodes on the touching arc
inline constexpr int kContactSliders3D = 2;  // the rim's spring-slider, then the centre's

struct Contacts3D {
  // Gauss-Legendre rule of 2 kRimNodePairs nodes on [-1, 1]: the positive abscissae, weights.
  double node_abscissa[kRimNodePairs] = {};
  double node_weight[kRimNodePairs] = {};
  // The rule's sums over its pairs on the whole ring (U = 1), of each node's share s of K_ring:
  // sum s, sum s cos psi, sum s cos^2 psi, sum s sin^2 psi (kernels/rim_forces.h).
  double whole_ring_share = 0.0;
  double whole_ring_share_cos = 0.0;
  double whole_ring_share_cos2 = 0.0;
  double whole_ring_share_sin2 = 0.0;
  double ring_radius = 0.0;            // R_c, m: the sphere centres' circle
  double ring_normal_stiffness = 0.0;  // K_ring, N/m, the whole ring
  double ring_shear_stiffness = 0.0;   // N/m
  double centre_normal_stiffness = 0.0;
  double centre_shear_stiffness = 0.0;
  double rounding_radius = 0.0;  // r, m
  double base_radius = 0.0;      // R, m
  double height = 0.0;           // H, m
  // The tilt criteria as |e - e_y|^2 = (2 sin(t/2))^2 of the axis e (kernels/step3d.h): of
  // Model's tip_over_angle and stability_angle, so that no lane takes an inverse sine.
  double tip_departure = 0.0;
  double stability_departure = 0.0;
};

}  // namespace caskdem
