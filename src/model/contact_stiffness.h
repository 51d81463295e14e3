#pragma once
// Contact spring constants.
//
// The source paper gives the cask-floor contact as a distributed stiffness k (force per
// unit area per unit displacement, its Tab. 3 in bar/cm: 1 bar/cm = 1e7 N/m^3). A corner
// contact that represents a contact length L_c of a section of out-of-plane depth d gets
// K = k L_c d.
//
// Alternatively the stiffness follows from the floor's elastic half-space (Barkan 1962,
// "Dynamics of Bases and Foundations"; the paper's Tab. 2) for a base of area A, a = sqrt(A):
//   K_n = G beta_z a / (1 - nu)          vertical
//   K_s = 2 (1 + nu) G beta_x a           horizontal
// with Barkan's shape coefficients beta_z = 2.1 and beta_x = 1.0 for a nearly square base;
// the distributed stiffness is then K / A.

namespace caskdem {

struct DistributedStiffness {
  double normal = 0.0;  // N/m^3
  double shear = 0.0;   // N/m^3
};

struct BarkanFloor {
  double shear_modulus = 0.0;  // G, Pa
  double poisson_ratio = 0.0;  // nu
  double beta_z = 2.1;
  double beta_x = 1.0;
};

DistributedStiffness barkan_stiffness(const BarkanFloor& floor, double base_area);

}  // namespace caskdem
