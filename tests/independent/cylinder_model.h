#pragma once
// A rigid circular cylinder rocking, sliding and bouncing in the plane of a shaking table,
// on a distributed circular footprint. Written apart from caskdem's model (src/, kernels/) so
// that data made with it test the diagnosis on physics it did not make.
//
// State, in the table's frame (the table's acceleration enters as an inertial force):
//   X, Y   centre of mass (Y up, the table's surface at Y = 0), m
//   theta  rotation about a horizontal diameter through the centre of mass, rad (counter-clockwise)
//   vx, vy, omega  their rates
// The equations are in cylinder_model.cpp.

#include <array>
#include <functional>
#include <vector>

namespace independent {

using State = std::array<double, 6>;  // X, Y, theta, vx, vy, omega

struct CaskParameters {
  // The 1/3-scale cask.
  double radius = 0.475;        // m
  double half_height = 1.0165;  // m (height 2.033 m)
  double density = 8743.0;      // kg/m^3
  double gravity = 9.80665;     // m/s^2

  // Normal contact (Hunt & Crossley 1975): pressure k_h d^n (1 + 1.5 c_h d'), no tension.
  double k_h = 0.0;        // Pa / m^n (set by set_standing_stiffness)
  double exponent = 1.5;   // n
  double c_h = 0.0;        // s/m
  // Floor compliance: over the first soft_depth of penetration the pressure law is softer,
  // as a function of s^(1/n) d (pressure times s there), and continuous beyond it.
  double soft_ratio = 1.0;  // s; 1 = no soft layer
  double soft_depth = 0.0;  // m

  // Friction: mu(v) = mu_k + (mu_s - mu_k) exp(-|v|/v_s), regularised by tanh(v / v_eps).
  double mu_static = 0.6;
  double kinetic_ratio = 1.0;     // mu_k / mu_s; 1 = constant friction
  double stribeck_speed = 0.05;   // m/s
  double regularisation = 1e-3;   // v_eps, m/s

  // Hidden geometry.
  double eccentricity = 0.0;  // m: centre of mass this far (+x) off the axis
  double camber = 0.0;        // m: base centre this far below its rim (a convex base)

  // Out-of-plane loss: a rocking couple -2 zeta_w p I_O omega (p: Housner's frequency).
  double rocking_damping_ratio = 0.0;

  int quadrature_points = 64;

  double mass() const;
  double inertia() const;            // about a horizontal diameter through the centre of mass
  double pivot_inertia() const;      // about a rim point, I_O
  double housner_frequency() const;  // p = sqrt(m g R / I_O)
  double slenderness() const;        // alpha = atan(r / h)
  double footprint_area() const;
};

// Sets k_h so that the pressure's slope at the static settlement (no soft layer) is
// `stiffness` (N/m^3), and c_h so that the standing vertical mode has damping ratio `zeta`.
void set_standing_stiffness(CaskParameters& p, double stiffness, double zeta);
// The static settlement d_s of a flat base (no soft layer): k_h d_s^n A = m g.
double flat_settlement(const CaskParameters& p);

// Table accelerations, m/s^2, as functions of time.
struct TableInput {
  std::function<double(double)> horizontal;
  std::function<double(double)> vertical;  // acts on the cask (zero when the table moves only horizontally)
};

class CylinderModel {
 public:
  explicit CylinderModel(const CaskParameters& p);

  const CaskParameters& parameters() const { return p_; }

  // dS/dt at time t: the right-hand side Boost.Odeint integrates.
  void derivative(const State& s, State& ds, double t, const TableInput& input) const;

  // Contact resultants at rest-free evaluation: vertical force, moment about the centre of
  // mass, horizontal force (zero velocities give zero friction).
  struct Resultant {
    double normal = 0.0, horizontal = 0.0, moment = 0.0;
  };
  Resultant contact(const State& s) const;

  // Kinetic + gravity + elastic energy (exact for c_h = 0, no friction, no soft layer).
  double energy(const State& s, double vertical_acceleration = 0.0) const;

  // The resting state under gravity and an applied couple (N m, counter-clockwise).
  State equilibrium(double applied_moment = 0.0) const;

  // Horizontal position of the base's geometric centre (the sliding sensor's target).
  double base_centre_x(const State& s) const;

 private:
  double pressure(double penetration, double rate) const;
  double elastic_energy_density(double penetration) const;

  CaskParameters p_;
  double mass_, inertia_, pivot_damping_;
  // Quadrature strips of the footprint: body coordinates (from the centre of mass) of each
  // strip's base point, and the footprint area it carries.
  std::vector<double> xi_, eta_, area_;
};

}  // namespace independent
