#pragma once
// The 3D cask from its physical description: a solid circular cylinder on a distributed
// circular base (kernels/model3d.h), the shared Model (friction, gravity, step, end criteria)
// and one realisation's parameters and rest state. The same description serves the scalar
// reference (src/sim/simulate3d.h) and SIMD lanes, as in 2D (model/build.h).
//
// Mass properties of the solid cylinder, radius R, height H: I_1 = m (R^2 / 4 + H^2 / 12)
// about a horizontal axis through the centre of mass, I_3 = m R^2 / 2 about its axis.
// Time step: dt = f_s 2 sqrt(m / (k_n A)), as in 2D with the base's whole standing stiffness;
// refused beyond the explicit scheme's bound (2 / w_max)(sqrt(1 + z^2) - z), w_max^2 bounded by
// the trace of M^-1 K of the six rigid-body modes on the contact springs.

#include <optional>

#include "kernels/lane_state.h"
#include "kernels/lane_state3d.h"
#include "kernels/model.h"
#include "kernels/model3d.h"
#include "model/build.h"

namespace caskdem {

struct CaskSpec3D {
  double radius = 0.0;    // R, m
  double height = 0.0;    // H, m
  double rounding = 0.0;  // r of the base rim, m
  double mass = 0.0;      // kg
  double eccentricity = 0.0;  // m, the centre of mass off the axis (along body x), as in 2D
  // kg m^2, I_1 and I_3 when given (else the solid cylinder's)
  std::optional<double> inertia = std::nullopt, axial_inertia = std::nullopt;
};

// The 3D cask of a case's cylinder ([cask] dimensions = 3).
CaskSpec3D cask_spec3d(const Cylinder& cylinder, double rounding, double mass);

struct Model3D {
  Model model;  // friction law, gravity, time step, criteria (its 2D corners unused)
  Contacts3D contacts;
};

// The cask's mass, I_1, I_3 (the solid cylinder's unless given) and centre of mass (at H / 2,
// off the axis by the eccentricity: eccentric contents, the moments of inertia kept about it).
RealisationParameters nominal_parameters3d(const CaskSpec3D& cask, const RealisationParameters& base);

// Friction, damping and integration from `spec` (its section unused; its contact stiffness is
// the base's distributed k_n and k_s). Throws std::invalid_argument for a cask that cannot
// stand (a rounding not smaller than R / 4, a centre of mass not over the ring) or an unstable
// step. alpha is the smallest stability angle, towards the eccentricity: atan((R_c - e) / (h - r)).
Model3D build_model3d(const ModelSpec& spec, const CaskSpec3D& cask, const RealisationParameters& nominal);

// One realisation's lane parameters: the 2D ones (model/build.h), with the axial inertia and
// the damping coefficient of the 3D base (beta = 2 h / w, w given or sqrt(k_n A / m)).
LaneParameters<double> lane_parameters3d(const Model3D& model, const RealisationParameters& parameters);

// Standing upright at rest on its springs (penetration m g / (k_n A) on linear springs), and the response's datum.
BodyState3D<double> rest_state3d(const Model3D& model, const LaneParameters<double>& lane);
// Leaning at `tilt` towards the azimuth psi (from +x towards +z: the top moves along
// (cos psi, 0, sin psi)), on the rim point of that direction, which stays where it stood, at rest.
BodyState3D<double> tilted_state3d(const Model3D& model, const LaneParameters<double>& lane, double tilt, double azimuth);
Response3D<double> initial_response3d(const LaneParameters<double>& lane, const BodyState3D<double>& body);

// The upright cask's vertical stiffness, N/m, and its rocking stiffness about a diameter, N m,
// from its contact points as the step sees them (k_n A and k_n I_base, up to the quadrature).
double standing_stiffness(const Contacts3D& contacts);
double standing_rocking_stiffness(const Contacts3D& contacts);

// Tilt from vertical of the cask's axis, rad, from the quaternion (0 to pi).
double axis_tilt(const BodyState3D<double>& body);

}  // namespace caskdem
