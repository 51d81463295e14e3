#include "model/build3d.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <boost/math/quadrature/gauss.hpp>

#include "kernels/rigid_rotation.h"
#include "kernels/step3d.h"

namespace caskdem {

namespace {
double departure_of(double tilt) { return std::pow(2.0 * std::sin(0.5 * tilt), 2); }

// The contact points of the upright cask, each as (x, z, K_n, K_s): the rim's nodes spread
// over the whole ring, and the centre.
template <class Visit>
void for_standing_points(const Contacts3D& c, Visit&& visit) {
  LaneParameters<double> unscaled{};
  unscaled.stiffness_scale = 1.0;
  const kernels::RimTouch<double> whole{-1.0, 0.0, kernels::touching_arc(-1.0, 0.0, 0.0)};
  kernels::for_each_rim_node(c, unscaled, whole, visit);
  visit(0.0, 0.0, c.centre_normal_stiffness, c.centre_shear_stiffness);
}
}  // namespace

double standing_stiffness(const Contacts3D& c) {
  double total = 0.0;
  for_standing_points(c, [&](double, double, double kn, double) { total += kn; });
  return total;
}

double standing_rocking_stiffness(const Contacts3D& c) {
  double total = 0.0;
  for_standing_points(c, [&](double x, double, double kn, double) { total += kn * x * x; });
  return total;
}

namespace {

// beta = 2 h / w at the given frequency (softened with the contact, model/build.h) or at
// sqrt(K / m) of the cask on its base.
double damping_beta3d(const Model3D& m, const RealisationParameters& p) {
  const double omega = p.damping_frequency > 0.0 ? p.damping_frequency * std::sqrt(m.model.contact_stiffness_scale)
                                                 : std::sqrt(standing_stiffness(m.contacts) * p.stiffness_scale / p.mass);
  return 2.0 * p.damping_ratio / omega;
}
}  // namespace

CaskSpec3D cask_spec3d(const Cylinder& cylinder, double rounding, double mass) {
  return {0.5 * cylinder.diameter, cylinder.height, rounding, mass, cylinder.eccentricity, cylinder.inertia,
          cylinder.axial_inertia};
}

RealisationParameters nominal_parameters3d(const CaskSpec3D& cask, const RealisationParameters& base) {
  RealisationParameters p = base;
  p.mass = cask.mass;
  p.inertia = cask.inertia.value_or(cask.mass * (cask.radius * cask.radius / 4.0 + cask.height * cask.height / 12.0));
  p.axial_inertia = cask.axial_inertia.value_or(cask.mass * cask.radius * cask.radius / 2.0);
  p.centre_of_mass = {cask.eccentricity, 0.5 * cask.height};
  return p;
}

Model3D build_model3d(const ModelSpec& spec, const CaskSpec3D& cask, const RealisationParameters& nominal) {
  if (!(cask.radius > 0.0) || !(cask.height > 0.0) || !(cask.mass > 0.0)) {
    throw std::invalid_argument("the cask's radius, height and mass must be positive");
  }
  if (!(cask.rounding >= 0.0 && cask.rounding < 0.25 * cask.radius)) {
    throw std::invalid_argument("the rim's rounding must be at least 0 and below a quarter of the radius");
  }
  if (!(spec.stiffness.normal > 0.0) || !(spec.stiffness.shear > 0.0)) {
    throw std::invalid_argument("the contact stiffnesses must be positive");
  }
  Model3D out;
  Contacts3D& c = out.contacts;
  const double R = cask.radius, r = cask.rounding, ring = R - r;
  const double eccentricity = std::abs(nominal.centre_of_mass.x);
  if (!(eccentricity < ring)) throw std::invalid_argument("the eccentricity puts the centre of mass outside the base");
  const double area = std::numbers::pi * R * R, base_inertia = std::numbers::pi * std::pow(R, 4) / 4.0;
  const double scale = spec.contact_stiffness_scale;
  const double normal_total = scale * spec.stiffness.normal * area;
  const double shear_total = scale * spec.stiffness.shear * area;
  // The ring carries the rocking stiffness k_n I_base (a ring of radius R_c has R_c^2 / 2 per
  // unit stiffness about a diameter); the centre the rest of k_n A.
  const double ring_share = base_inertia / (0.5 * ring * ring) / area;
  using Rule = boost::math::quadrature::gauss<double, 2 * kRimNodePairs>;
  for (int j = 0; j < kRimNodePairs; ++j) {
    c.node_abscissa[j] = Rule::abscissa()[j];
    c.node_weight[j] = Rule::weights()[j];
  }
  // The same nodes as the step's on the whole ring, by the step's own rim_pairs.
  kernels::RimPair<double> whole_ring[kRimNodePairs];
  kernels::rim_pairs(c, kernels::RimArc<double>{1.0, 0.0, 1.0}, whole_ring);
  for (const kernels::RimPair<double>& pair : whole_ring) {
    c.whole_ring_share += pair.share;
    c.whole_ring_share_cos += pair.share * pair.cos_psi;
    c.whole_ring_share_cos2 += pair.share * pair.cos_psi * pair.cos_psi;
    c.whole_ring_share_sin2 += pair.share * pair.sin_psi * pair.sin_psi;
  }
  c.ring_radius = ring;
  c.ring_normal_stiffness = normal_total * ring_share;
  c.ring_shear_stiffness = shear_total * ring_share;
  c.centre_normal_stiffness = normal_total * (1.0 - ring_share);
  c.centre_shear_stiffness = shear_total * (1.0 - ring_share);
  c.rounding_radius = r;
  c.base_radius = R;
  c.height = cask.height;

  Model& m = out.model;
  m.corner_count = 0;
  m.contact_stiffness_scale = scale;
  m.whole_step_terms = spec.whole_step_terms;
  m.friction_law = spec.friction_law;
  if (spec.friction_law == FrictionLaw::tabulated) set_friction_table(m, spec.friction_table);
  m.gravity = spec.gravity;
  if (!(spec.safety_factor > 0.0)) throw std::invalid_argument("the safety factor must be positive");
  m.time_step = spec.time_step > 0.0 ? spec.time_step : spec.safety_factor * 2.0 * std::sqrt(nominal.mass / standing_stiffness(c));
  m.normal_law = spec.normal_law;
  if (spec.normal_law == NormalLaw::hunt_crossley) m.hertz_overlap = nominal.mass * m.gravity / standing_stiffness(c);
  // The centre of mass passes over the pivot (a ring point's sphere centre) at alpha; first
  // over the ring point nearest to it, towards the eccentricity.
  m.stability_angle = std::atan2(ring - eccentricity, nominal.centre_of_mass.y - r);
  m.tip_over_angle = spec.tip_over_angle > 0.0 ? spec.tip_over_angle : 0.5 * std::numbers::pi;
  if (m.tip_over_angle <= m.stability_angle) throw std::invalid_argument("the tip-over angle must exceed alpha");
  m.lift_off_height = spec.lift_off_height > 0.0 ? spec.lift_off_height : 0.25 * cask.height;
  m.pad_clearance = spec.pad_half_width > 0.0 ? spec.pad_half_width - R : 0.0;
  if (spec.pad_half_width > 0.0 && !(m.pad_clearance > 0.0)) throw std::invalid_argument("the pad is narrower than the cask");
  const double pivot = std::hypot(ring - eccentricity, nominal.centre_of_mass.y - r);
  m.rocking_frequency = std::sqrt(nominal.mass * m.gravity * pivot / (nominal.inertia + nominal.mass * pivot * pivot));
  c.tip_departure = departure_of(m.tip_over_angle);
  c.stability_departure = departure_of(m.stability_angle);

  // Stability: w_max^2 <= trace(M^-1 K) of the six rigid-body modes on the springs, standing.
  // The Hunt-Crossley spring's tangent stiffness at rest is (3/2) K (model/build.cpp, model_facts).
  const double normal_tangent = m.normal_law == NormalLaw::hunt_crossley ? 1.5 : 1.0;
  double trace = 0.0;
  for_standing_points(c, [&](double x, double z, double normal_stiffness, double shear_stiffness) {
    const double lx = x - nominal.centre_of_mass.x, ly = -nominal.centre_of_mass.y, lz = z;
    const double I1 = nominal.inertia, I3 = nominal.axial_inertia;
    // normal (along y): l x e_y = (-lz, 0, lx); shear along x: l x e_x = (0, lz, -ly); along z: (ly, -lx, 0)
    trace += normal_tangent * normal_stiffness * (1.0 / nominal.mass + (lz * lz + lx * lx) / I1);
    trace += shear_stiffness * (1.0 / nominal.mass + lz * lz / I3 + ly * ly / I1);
    trace += shear_stiffness * (1.0 / nominal.mass + ly * ly / I1 + lx * lx / I3);
  });
  const double w_max = std::sqrt(trace);
  const double beta = damping_beta3d(out, nominal);
  const double zeta = beta * w_max / 2.0;
  const double stable = 2.0 / w_max * (std::sqrt(1.0 + zeta * zeta) - zeta);
  if (m.time_step > stable) {
    throw std::invalid_argument("the time step " + std::to_string(m.time_step) + " s exceeds the stability limit " +
                                std::to_string(stable) + " s of the contact springs; lower the safety factor");
  }
  return out;
}

LaneParameters<double> lane_parameters3d(const Model3D& model, const RealisationParameters& p) {
  if (!(p.axial_inertia > 0.0)) throw std::invalid_argument("a 3D cask needs its axial inertia");
  Model two_d = model.model;
  two_d.camber_corner = -1;
  RealisationParameters q = p;
  q.damping_frequency = 1.0;  // any: the 2D beta is replaced below
  LaneParameters<double> lane = lane_parameters(two_d, q);
  lane.damping_beta = damping_beta3d(model, p);
  lane.impact_damping = p.impact_damping + hunt_crossley_damper(model.model, lane.damping_beta,
                                                                standing_stiffness(model.contacts) * p.stiffness_scale, p.mass);
  return lane;
}

BodyState3D<double> rest_state3d(const Model3D& model, const LaneParameters<double>& lane) {
  // Every point of the flat base sinks alike, so the base carries the weight as one contact.
  const double penetration = overlap_carrying(model.model, standing_stiffness(model.contacts) * lane.stiffness_scale,
                                              model.model.gravity / lane.inverse_mass);
  BodyState3D<double> b{};
  b.x = lane.centre_x;
  b.y = lane.centre_y - penetration;
  b.z = 0.0;
  b.qw = 1.0;
  return b;
}

BodyState3D<double> tilted_state3d(const Model3D& model, const LaneParameters<double>& lane, double tilt, double azimuth) {
  BodyState3D<double> b = rest_state3d(model, lane);
  const double ring = model.contacts.base_radius - model.contacts.rounding_radius, r = model.contacts.rounding_radius;
  const double c = std::cos(azimuth), s = std::sin(azimuth);
  // Rotating e_y towards d = (c, 0, s) is a turn about e_y x d = (s, 0, -c).
  const double half = 0.5 * tilt;
  b.qw = std::cos(half);
  b.qx = std::sin(half) * s;
  b.qy = 0.0;
  b.qz = -std::sin(half) * c;
  const kernels::Rotation<double> R = kernels::rotation_of(kernels::Quaternion<double>{b.qw, b.qx, b.qy, b.qz});
  // The pivot (the rim point towards psi) keeps its place at rest: x = P - R (c_P - c_m).
  const kernels::Vector3<double> pivot_rest{ring * c, r + (b.y - lane.centre_y), ring * s};
  const kernels::Vector3<double> arm = R.apply({ring * c - lane.centre_x, r - lane.centre_y, ring * s});
  b.x = pivot_rest.x - arm.x;
  b.y = pivot_rest.y - arm.y;
  b.z = pivot_rest.z - arm.z;
  return b;
}

Response3D<double> initial_response3d(const LaneParameters<double>& lane, const BodyState3D<double>& body) {
  Response3D<double> r{};
  const kernels::Rotation<double> R = kernels::rotation_of(kernels::Quaternion<double>{body.qw, body.qx, body.qy, body.qz});
  const kernels::Vector3<double> to_base = R.apply({-lane.centre_x, -lane.centre_y, 0.0});
  r.base_x0 = body.x + to_base.x;
  r.base_z0 = body.z + to_base.z;
  r.instability_time = -1.0;
  return r;
}

double axis_tilt(const BodyState3D<double>& b) {
  // e = R e_y = (2(xy - wz), 1 - 2(x^2 + z^2), 2(yz + wx)); tilt = atan2(|e_horizontal|, e_y).
  const double ex = 2.0 * (b.qx * b.qy - b.qw * b.qz), ez = 2.0 * (b.qy * b.qz + b.qw * b.qx);
  const double ey = 1.0 - 2.0 * (b.qx * b.qx + b.qz * b.qz);
  return std::atan2(std::hypot(ex, ez), ey);
}

}  // namespace caskdem
