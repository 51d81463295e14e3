#pragma once
// From a physical description (section, contact, friction, limits) and one realisation's
// physical parameters to the kernel's Model and LaneParameters, and the initial states.
//
// Time step (the source paper's): dt = f_s * 2 sqrt(m / K), K the total normal spring
// constant of the corners the cask stands on, f_s = 0.01 by default. The explicit scheme is
// stable for dt <= (2 / w_max)(sqrt(1 + z^2) - z) (z the damping ratio at w_max; Belytschko
// & Hughes 1983); w_max is bounded by the trace of M^-1 K of the three rigid-body modes on
// their springs, and build_model refuses a safety factor that breaks the bound.
//
// Damping: stiffness-proportional, C = beta K, with beta = 2 h / w for a damping ratio h
// at the circular frequency w (given, or sqrt(K / m) of the cask on its springs). Contact-
// stiffness scaling by s (ModelSpec::contact_stiffness_scale) multiplies K by s and a given
// w by sqrt(s): the softened contact keeps its damping ratio, and so nearly its restitution.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/units.h"
#include "kernels/lane_state.h"
#include "kernels/model.h"
#include "model/contact_stiffness.h"
#include "model/section.h"

namespace caskdem {

// The slider schemes by name, as case and ensemble files give them ([integration] slider):
// "half-step" (the source paper's), "whole-step" (every term), and one term alone for studying
// what each contributes ("whole-step-normal-dashpot", "whole-step-shear-dashpot",
// "whole-step-friction", "spring-since-touch"), or the three velocities without the spring's
// touch rule ("whole-step-velocities").
const std::vector<std::string>& slider_names();
std::int32_t whole_step_terms_of(const std::string& slider_name);
std::string slider_name_of(std::int32_t whole_step_terms);

struct ModelSpec {
  Section section;
  DistributedStiffness stiffness;
  FrictionLaw friction_law = FrictionLaw::constant;
  std::vector<std::pair<double, double>> friction_table;  // (slip speed m/s, coefficient), for the tabulated law
  // The contact's normal law (kernels/contact_law.h); the Hunt-Crossley law's d_H is the nominal
  // cask's settlement on the linear springs.
  NormalLaw normal_law = NormalLaw::linear;
  double safety_factor = 0.01;   // f_s
  // Contact-stiffness scaling, a numerical device (docs/time-step.md): the normal and shear
  // springs times this factor, a given damping frequency times its square root (the damping
  // ratio kept at the softened contact's frequency), so the step grows by 1/sqrt(factor).
  double contact_stiffness_scale = 1.0;
  // The spring-slider's velocity-dependent terms read at the whole step (WholeStepTerm bits,
  // kernels/slider.h); 0: the source paper's half-step scheme.
  std::int32_t whole_step_terms = 0;
  double time_step = 0.0;        // s; 0: from f_s and the nominal mass
  double tip_over_angle = 0.0;   // rad; 0: pi/2 (lying on its side)
  double lift_off_height = 0.0;  // m; 0: a quarter of the section's height
  double pad_half_width = 0.0;   // m; 0: an unbounded pad
  double gravity = units::standard_gravity;
  // Add a contact corner at the middle of the base edge, which a realisation's base_camber
  // lowers (a slightly convex base). The base's contact length is shared: half to the middle
  // corner, a quarter to each end. On a distributed footprint (odd N) its centre point is that corner.
  bool base_centre_contact = false;
};

// One realisation's physical parameters, SI.
struct RealisationParameters {
  double mass = 0.0;
  double inertia = 0.0;   // about the centre of mass (in 3D about the horizontal axes through it)
  double axial_inertia = 0.0;  // about the cask's axis, 3D only (0 in 2D)
  Point centre_of_mass;   // body frame
  double friction_static = 0.0;
  double friction_kinetic = 0.0;
  double friction_decay_speed = 1.0;  // v0, m/s (exponential law)
  double damping_ratio = 0.0;         // h
  double damping_frequency = 0.0;     // rad/s; 0: sqrt(K / m)
  double horizontal_scale = 1.0;
  double vertical_scale = 1.0;
  double stiffness_scale = 1.0;
  // Mechanisms beyond the source paper's model (kernels/lane_state.h); these values leave it.
  double impact_damping = 0.0;   // s/m
  double floor_soft_ratio = 1.0;
  double floor_soft_depth = 0.0; // m
  double base_camber = 0.0;      // m
  double wobble_damping = 0.0;
};

RealisationParameters nominal_parameters(const ModelSpec& spec);  // mass properties from the section

// Throws std::invalid_argument when the specification cannot make a stable model.
Model build_model(const ModelSpec& spec, const RealisationParameters& nominal);
// The tabulated law's rows into the model (2D and 3D), refusing a table it cannot evaluate:
// 2 to kMaxFrictionTable rows, finite, speeds increasing, coefficients non-negative, and each
// segment's slope finite (rows too close in speed would give inf x 0 at a row).
void set_friction_table(Model& model, const std::vector<std::pair<double, double>>& table);
LaneParameters<double> lane_parameters(const Model& model, const RealisationParameters& parameters);

// Numbers derived from a model that users and tests want to see.
struct ModelFacts {
  double total_normal_stiffness = 0.0;  // N/m, corners standing on the floor
  double total_shear_stiffness = 0.0;
  double static_penetration = 0.0;      // m g / K
  double natural_frequency = 0.0;       // sqrt(K / m), rad/s
  double damping_beta = 0.0;            // s
  double normal_damper = 0.0;           // s/m, Hunt & Crossley's lambda of the normal law (the damping's share included)
  double stability_angle_positive = 0.0;  // rad
  double stability_angle_negative = 0.0;
  double highest_frequency = 0.0;       // bound on the rigid-body modes on their springs, rad/s
  double stable_time_step = 0.0;        // s
  double half_span = 0.0;               // half the distance between the outermost standing corners
};
ModelFacts model_facts(const Model& model, const ModelSpec& spec, const RealisationParameters& parameters);

double damping_beta(const Model& model, const RealisationParameters& parameters);
double total_standing_normal_stiffness(const Model& model);  // sum over corners with rest gap 0

// The normal laws by name, as case files give them ([contact] normal_law): "linear",
// "hunt-crossley".
const std::vector<std::string>& normal_law_names();
NormalLaw normal_law_of(const std::string& name);  // throws std::invalid_argument naming the choices
std::string normal_law_name(NormalLaw law);
// "linear law", or "hunt-crossley law (d_H 7.3e-06 m, damper 2 s/m)": what a printout says of
// the contact; `damper_note` follows the damper's value ("" or, say, " + each realisation's damping").
std::string contact_law_text(const Model& model, double impact_damping, const std::string& damper_note = "");
// The overlap at which a contact of spring constant K carries the force F at rest under the
// model's law without soft layer: F / K (linear), (F / K)^(2/3) d_H^(1/3) (Hunt-Crossley).
double overlap_carrying(const Model& model, double stiffness, double force);
// Under the Hunt-Crossley law the paper's damping acts through Hunt & Crossley's damper: the
// dashpot beta K_t of the cask at rest (K_t = (3/2) K sqrt(d_r / d_H), the tangent stiffness of
// its standing contacts K at their rest overlap d_r) equals lambda m g, the damper's coefficient
// there, so lambda = beta K_t / (m g) and the standing cask is damped as on the linear law's
// dashpot with its tangent stiffness. 0 under the linear law.
double hunt_crossley_damper(const Model& model, double beta, double standing_stiffness, double mass);

// Standing upright at rest, its height in vertical equilibrium on its springs (m g / K for
// linear springs; solved for a soft floor layer, a convex base or the Hunt-Crossley law).
BodyState<double> rest_state(const Model& model, const LaneParameters<double>& lane);
// Tilted by `rotation` about the pivot corner it then rests on, at rest, the pivot carrying the weight.
BodyState<double> tilted_state(const Model& model, const LaneParameters<double>& lane, double rotation);
// Response at t = 0 (the base centre's initial position is the sliding datum).
Response<double> initial_response(const LaneParameters<double>& lane, const BodyState<double>& body);
inline constexpr double kNotReached = -1.0;  // instability time before anything happened

}  // namespace caskdem
