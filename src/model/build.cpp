#include "model/build.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/text.h"
#include "kernels/contact_law.h"
#include "kernels/portable_math.h"

namespace caskdem {

namespace {
constexpr double kRestGapTolerance = 1e-12;  // m: a corner with a rest gap this small stands on the floor
}

RealisationParameters nominal_parameters(const ModelSpec& spec) {
  RealisationParameters p;
  p.mass = spec.section.mass;
  p.inertia = spec.section.inertia;
  p.centre_of_mass = spec.section.centre_of_mass;
  return p;
}

double total_standing_normal_stiffness(const Model& model) {
  double total = 0.0;
  for (int k = 0; k < model.corner_count; ++k) {
    if (model.corner_rest_gap[k] <= kRestGapTolerance) total += model.corner_normal_stiffness[k];
  }
  return total;
}

static double total_standing_shear_stiffness(const Model& model) {
  double total = 0.0;
  for (int k = 0; k < model.corner_count; ++k) {
    if (model.corner_rest_gap[k] <= kRestGapTolerance) total += model.corner_shear_stiffness[k];
  }
  return total;
}

double damping_beta(const Model& model, const RealisationParameters& p) {
  const double stiffness = total_standing_normal_stiffness(model) * p.stiffness_scale;
  const double omega = p.damping_frequency > 0.0 ? p.damping_frequency * std::sqrt(model.contact_stiffness_scale)
                                                : std::sqrt(stiffness / p.mass);
  return 2.0 * p.damping_ratio / omega;
}

ModelFacts model_facts(const Model& model, const ModelSpec& spec, const RealisationParameters& p) {
  ModelFacts f;
  f.total_normal_stiffness = total_standing_normal_stiffness(model) * p.stiffness_scale;
  f.total_shear_stiffness = total_standing_shear_stiffness(model) * p.stiffness_scale;
  f.static_penetration = overlap_carrying(model, f.total_normal_stiffness, p.mass * model.gravity);
  f.natural_frequency = std::sqrt(f.total_normal_stiffness / p.mass);
  f.damping_beta = damping_beta(model, p);
  f.normal_damper = p.impact_damping + hunt_crossley_damper(model, f.damping_beta, f.total_normal_stiffness, p.mass);
  f.stability_angle_positive = stability_angle(spec.section, +1);
  f.stability_angle_negative = stability_angle(spec.section, -1);
  // Upper bound on the highest rigid-body frequency on the springs: trace of M^-1 K, with the
  // Hunt-Crossley spring's tangent stiffness at rest, (3/2) K (it stiffens further in an impact,
  // as sqrt(d / d_H): the default step's margin of 1/f_s = 100 covers overlaps of 10^4 d_H).
  const double normal_tangent = model.normal_law == NormalLaw::hunt_crossley ? 1.5 : 1.0;
  double rotational = 0.0;
  double low = 1e300, high = -1e300;
  for (int k = 0; k < model.corner_count; ++k) {
    if (model.corner_rest_gap[k] > kRestGapTolerance) continue;
    const double arm_x = model.corner_x[k] - p.centre_of_mass.x;
    const double arm_y = model.corner_y[k] - model.rounding_radius - p.centre_of_mass.y;
    rotational += p.stiffness_scale * (normal_tangent * model.corner_normal_stiffness[k] * arm_x * arm_x +
                                       model.corner_shear_stiffness[k] * arm_y * arm_y);
    low = std::min(low, model.corner_x[k]);
    high = std::max(high, model.corner_x[k]);
  }
  f.half_span = 0.5 * (high - low);
  f.highest_frequency =
      std::sqrt((normal_tangent * f.total_normal_stiffness + f.total_shear_stiffness) / p.mass + rotational / p.inertia);
  const double z = f.damping_beta * f.highest_frequency / 2.0;
  f.stable_time_step = 2.0 / f.highest_frequency * (std::sqrt(1.0 + z * z) - z);
  return f;
}

namespace {
struct SliderScheme {
  const char* name;
  std::int32_t whole_step_terms;
};
constexpr SliderScheme kSliderSchemes[] = {
    {"half-step", 0},
    {"whole-step", kWholeStepSlider},
    {"whole-step-normal-dashpot", kWholeStepNormalDashpot},
    {"whole-step-shear-dashpot", kWholeStepShearDashpot},
    {"whole-step-friction", kWholeStepFriction},
    {"spring-since-touch", kSpringSinceTouch},
    // The whole-step slider without the spring's touch rule: its velocities alone.
    {"whole-step-velocities", kWholeStepNormalDashpot | kWholeStepShearDashpot | kWholeStepFriction},
};
}  // namespace

const std::vector<std::string>& slider_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const SliderScheme& scheme : kSliderSchemes) all.emplace_back(scheme.name);
    return all;
  }();
  return names;
}

std::int32_t whole_step_terms_of(const std::string& slider_name) {
  for (const SliderScheme& scheme : kSliderSchemes) {
    if (slider_name == scheme.name) return scheme.whole_step_terms;
  }
  throw std::invalid_argument("unknown slider scheme '" + slider_name + "'");
}

std::string slider_name_of(std::int32_t whole_step_terms) {
  for (const SliderScheme& scheme : kSliderSchemes) {
    if (whole_step_terms == scheme.whole_step_terms) return scheme.name;
  }
  return "whole-step terms " + std::to_string(whole_step_terms);
}

Model build_model(const ModelSpec& spec, const RealisationParameters& nominal) {
  const std::vector<ContactCorner> corners = contact_corners(spec.section);
  if (static_cast<int>(corners.size()) > kMaxCorners) {
    throw std::invalid_argument("the section has " + std::to_string(corners.size()) +
                                " corners facing the floor; at most " + std::to_string(kMaxCorners) + " are supported");
  }
  if (!(spec.stiffness.normal > 0.0) || !(spec.stiffness.shear > 0.0)) {
    throw std::invalid_argument("the contact stiffnesses must be positive");
  }
  if (!(spec.contact_stiffness_scale > 0.0 && spec.contact_stiffness_scale <= 1.0)) {
    throw std::invalid_argument("the contact stiffness scale must be above 0 and at most 1");
  }
  std::vector<ContactCorner> all = corners;
  Model m;
  if (spec.base_centre_contact && spec.section.footprint_points > 0) {
    // A distributed footprint with an odd number of points has one at the base centre already.
    const int n = spec.section.footprint_points;
    if (n % 2 == 0) throw std::invalid_argument("a convex base on a distributed footprint needs an odd number of points");
    m.camber_corner = n / 2;
  } else if (spec.base_centre_contact) {
    // The two corners of the base edge (standing on the floor) hand half their contact length
    // to a corner midway between them.
    std::vector<int> base;
    for (int k = 0; k < static_cast<int>(all.size()); ++k) {
      if (std::abs(all[k].rest_gap) <= kRestGapTolerance) base.push_back(k);
    }
    if (base.size() != 2) throw std::invalid_argument("a base-centre contact needs a base edge with exactly two corners");
    ContactCorner middle;
    middle.arc_centre = {0.5 * (all[base[0]].arc_centre.x + all[base[1]].arc_centre.x), all[base[0]].arc_centre.y};
    middle.rest_gap = all[base[0]].rest_gap;
    middle.contact_length = 0.0;
    for (int k : base) {
      const double share = 0.5 * all[k].contact_length;
      all[k].contact_length -= share;
      middle.contact_length += share;
    }
    all.push_back(middle);
    m.camber_corner = static_cast<int>(all.size()) - 1;
  }
  if (static_cast<int>(all.size()) > kMaxCorners) {
    throw std::invalid_argument("the section has " + std::to_string(all.size()) + " contact corners; at most " +
                                std::to_string(kMaxCorners) + " are supported");
  }
  const std::vector<ContactCorner>& contact = all;
  m.corner_count = static_cast<int>(contact.size());
  for (int k = 0; k < m.corner_count; ++k) {
    m.corner_x[k] = contact[k].arc_centre.x;
    m.corner_y[k] = contact[k].arc_centre.y;
    m.corner_rest_gap[k] = contact[k].rest_gap;
    m.corner_normal_stiffness[k] =
        spec.contact_stiffness_scale * spec.stiffness.normal * contact[k].contact_length * spec.section.depth;
    m.corner_shear_stiffness[k] =
        spec.contact_stiffness_scale * spec.stiffness.shear * contact[k].contact_length * spec.section.depth;
  }
  m.contact_stiffness_scale = spec.contact_stiffness_scale;
  m.whole_step_terms = spec.whole_step_terms;
  m.rounding_radius = spec.section.rounding;
  m.friction_law = spec.friction_law;
  if (spec.friction_law == FrictionLaw::tabulated) set_friction_table(m, spec.friction_table);
  m.gravity = spec.gravity;

  const double standing = total_standing_normal_stiffness(m);
  if (!(standing > 0.0)) throw std::invalid_argument("no corner stands on the floor at rest");
  m.normal_law = spec.normal_law;
  if (spec.normal_law == NormalLaw::hunt_crossley) m.hertz_overlap = nominal.mass * m.gravity / standing;
  if (!(spec.safety_factor > 0.0)) throw std::invalid_argument("the safety factor must be positive");
  m.time_step = spec.time_step > 0.0 ? spec.time_step : spec.safety_factor * 2.0 * std::sqrt(nominal.mass / standing);

  const double alpha_positive = stability_angle(spec.section, +1);
  const double alpha_negative = stability_angle(spec.section, -1);
  m.stability_angle = std::min(alpha_positive, alpha_negative);
  m.tip_over_angle = spec.tip_over_angle > 0.0 ? spec.tip_over_angle : 0.5 * std::numbers::pi;
  if (m.tip_over_angle <= std::max(alpha_positive, alpha_negative) || m.tip_over_angle > 0.5 * std::numbers::pi) {
    throw std::invalid_argument("the tip-over angle must lie between the stability angle and 90 degrees");
  }
  m.lift_off_height = spec.lift_off_height > 0.0 ? spec.lift_off_height : 0.25 * section_height(spec.section);
  if (spec.pad_half_width > 0.0) {
    double base_half = 0.0;
    for (const Point& p : spec.section.outline) base_half = std::max(base_half, std::abs(p.x));
    m.pad_clearance = spec.pad_half_width - base_half;
    if (!(m.pad_clearance > 0.0)) throw std::invalid_argument("the pad is narrower than the cask");
  }

  {
    // p of the rigid equivalent: pivots at the outermost standing corners' arc centres.
    double low = 1e300, high = -1e300;
    for (int k = 0; k < m.corner_count; ++k) {
      if (m.corner_rest_gap[k] > kRestGapTolerance) continue;
      low = std::min(low, m.corner_x[k]);
      high = std::max(high, m.corner_x[k]);
    }
    const double size = std::hypot(0.5 * (high - low), nominal.centre_of_mass.y - m.corner_y[0]);
    m.rocking_frequency = std::sqrt(nominal.mass * m.gravity * size / (nominal.inertia + nominal.mass * size * size));
  }
  const ModelFacts facts = model_facts(m, spec, nominal);
  // Twice the elastic tilt at which a corner would lift under a quasi-static push: rotations
  // below it are the cask swaying on its springs, not rocking.
  m.rocking_threshold_angle = 2.0 * facts.static_penetration / facts.half_span;
  if (m.time_step > facts.stable_time_step) {
    throw std::invalid_argument("the time step " + number_text(m.time_step) + " s exceeds the stability limit " +
                                number_text(facts.stable_time_step) + " s of the contact springs; lower the safety factor");
  }
  return m;
}

void set_friction_table(Model& m, const std::vector<std::pair<double, double>>& table) {
  if (table.size() < 2 || static_cast<int>(table.size()) > kMaxFrictionTable) {
    throw std::invalid_argument("a friction table needs 2 to " + std::to_string(kMaxFrictionTable) + " rows");
  }
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (!(table[i].second >= 0.0) || !std::isfinite(table[i].second) || !std::isfinite(table[i].first)) {
      throw std::invalid_argument("friction table entries must be finite and the coefficients non-negative");
    }
    if (i > 0 && !(table[i].first > table[i - 1].first)) {
      throw std::invalid_argument("friction table speeds must increase strictly");
    }
    if (i > 0 && !std::isfinite((table[i].second - table[i - 1].second) / (table[i].first - table[i - 1].first))) {
      throw std::invalid_argument("friction table rows " + std::to_string(i) + " and " + std::to_string(i + 1) +
                                  " are too close in speed for their change of coefficient");
    }
  }
  m.friction_table_size = static_cast<int>(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    m.friction_table_speed[i] = table[i].first;
    m.friction_table_coefficient[i] = table[i].second;
  }
}

LaneParameters<double> lane_parameters(const Model& model, const RealisationParameters& p) {
  if (!(p.mass > 0.0) || !(p.inertia > 0.0)) throw std::invalid_argument("mass and inertia must be positive");
  if (!(p.friction_static >= 0.0) || !(p.friction_kinetic >= 0.0) || !std::isfinite(p.friction_static) ||
      !std::isfinite(p.friction_kinetic)) {
    throw std::invalid_argument("friction coefficients must be finite and non-negative");
  }
  if (!(p.friction_decay_speed > 0.0)) throw std::invalid_argument("the friction decay speed must be positive");
  if (!(p.damping_ratio >= 0.0)) throw std::invalid_argument("the damping ratio must be non-negative");
  if (!(p.stiffness_scale > 0.0)) throw std::invalid_argument("the stiffness scale must be positive");
  LaneParameters<double> lane;
  lane.inverse_mass = 1.0 / p.mass;
  lane.inverse_inertia = 1.0 / p.inertia;
  lane.centre_x = p.centre_of_mass.x;
  lane.centre_y = p.centre_of_mass.y;
  lane.friction_static = p.friction_static;
  lane.friction_kinetic = p.friction_kinetic;
  lane.inverse_decay_speed = 1.0 / p.friction_decay_speed;
  lane.damping_beta = damping_beta(model, p);
  lane.horizontal_scale = p.horizontal_scale;
  lane.vertical_scale = p.vertical_scale;
  lane.stiffness_scale = p.stiffness_scale;
  if (!(p.impact_damping >= 0.0)) throw std::invalid_argument("the impact damping must be non-negative");
  if (!(p.floor_soft_ratio > 0.0 && p.floor_soft_ratio <= 1.0)) {
    throw std::invalid_argument("the floor's soft-layer ratio must lie in (0, 1]");
  }
  if (!(p.floor_soft_depth >= 0.0)) throw std::invalid_argument("the floor's soft-layer depth must be non-negative");
  if (!(p.base_camber >= 0.0)) throw std::invalid_argument("the base camber must be non-negative");
  if (p.base_camber > 0.0 && model.camber_corner < 0) {
    throw std::invalid_argument("a base camber needs a model with a base-centre contact");
  }
  if (!(p.wobble_damping >= 0.0)) throw std::invalid_argument("the wobble damping must be non-negative");
  lane.impact_damping = p.impact_damping + hunt_crossley_damper(model, lane.damping_beta,
                                                                 total_standing_normal_stiffness(model) * p.stiffness_scale, p.mass);
  lane.floor_soft_ratio = p.floor_soft_ratio;
  lane.floor_soft_depth = p.floor_soft_depth;
  lane.base_camber = p.base_camber;
  lane.wobble_damping = p.wobble_damping;
  if (!(p.axial_inertia >= 0.0)) throw std::invalid_argument("the axial inertia must be non-negative");
  lane.inverse_axial_inertia = p.axial_inertia > 0.0 ? 1.0 / p.axial_inertia : 0.0;
  return lane;
}

namespace {
struct NormalLawName {
  const char* name;
  NormalLaw law;
};
constexpr NormalLawName kNormalLaws[] = {{"linear", NormalLaw::linear}, {"hunt-crossley", NormalLaw::hunt_crossley}};
}  // namespace

const std::vector<std::string>& normal_law_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const NormalLawName& law : kNormalLaws) all.emplace_back(law.name);
    return all;
  }();
  return names;
}

NormalLaw normal_law_of(const std::string& name) {
  for (const NormalLawName& law : kNormalLaws) {
    if (name == law.name) return law.law;
  }
  throw std::invalid_argument("unknown normal law '" + name + "' (expected \"linear\" or \"hunt-crossley\")");
}

std::string normal_law_name(NormalLaw law) {
  for (const NormalLawName& entry : kNormalLaws) {
    if (law == entry.law) return entry.name;
  }
  return "unknown";
}

std::string contact_law_text(const Model& model, double impact_damping, const std::string& damper_note) {
  std::string text = normal_law_name(model.normal_law) + " law";
  if (model.normal_law == NormalLaw::hunt_crossley) {
    text += " (d_H " + number_text(model.hertz_overlap) + " m, damper " + number_text(impact_damping) + " s/m" +
            damper_note + ")";
  } else if (impact_damping > 0.0) {
    text += " (impact damper " + number_text(impact_damping) + " s/m" + damper_note + ")";
  }
  return text;
}

double hunt_crossley_damper(const Model& model, double beta, double standing_stiffness, double mass) {
  if (model.normal_law != NormalLaw::hunt_crossley) return 0.0;
  const double weight = mass * model.gravity;
  const double rest = overlap_carrying(model, standing_stiffness, weight);
  const double tangent = 1.5 * standing_stiffness * std::sqrt(rest / model.hertz_overlap);
  return beta * tangent / weight;
}

double overlap_carrying(const Model& model, double stiffness, double force) {
  const double linear = force / stiffness;
  // K d sqrt(d / d_H) = F  <=>  d = (F / K)^(2/3) d_H^(1/3)
  return model.normal_law == NormalLaw::hunt_crossley ? std::cbrt(linear * linear * model.hertz_overlap) : linear;
}

BodyState<double> rest_state(const Model& model, const LaneParameters<double>& lane) {
  // Vertical equilibrium of the upright cask: the total spring force of the corners equals its
  // weight. The force grows monotonically as the cask sinks, so bisection on the height finds
  // it for any floor law and base camber (for linear springs it is m g / K exactly, to rounding).
  const double weight = model.gravity / lane.inverse_mass;
  auto spring_force = [&](double sink) {  // sink: how far the base level is below the floor
    double total = 0.0;
    for (int k = 0; k < model.corner_count; ++k) {
      const double lowered = k == model.camber_corner ? lane.base_camber : 0.0;
      const double gap = -std::max(0.0, sink + lowered - model.corner_rest_gap[k]);
      // At rest: the contact law's spring alone.
      total += kernels::normal_force(model, model.corner_normal_stiffness[k] * lane.stiffness_scale, lane, gap, 0.0);
    }
    return total;
  };
  const double linear = weight / (total_standing_normal_stiffness(model) * lane.stiffness_scale);
  double sink = linear;
  if (lane.floor_soft_ratio != 1.0 || lane.base_camber != 0.0 || model.normal_law != NormalLaw::linear) {
    // The Hertz spring pushes at least as the linear one beyond d_H.
    double low = -lane.base_camber, high = linear / lane.floor_soft_ratio + lane.floor_soft_depth + model.hertz_overlap;
    for (int i = 0; i < 200 && high - low > 1e-15 * (1.0 + high); ++i) {
      const double middle = 0.5 * (low + high);
      (spring_force(middle) < weight ? low : high) = middle;
    }
    sink = 0.5 * (low + high);
  }
  BodyState<double> body{};
  body.x = lane.centre_x;
  body.y = lane.centre_y - sink;
  return body;
}

BodyState<double> tilted_state(const Model& model, const LaneParameters<double>& lane, double rotation) {
  const kernels::SinCos<double> r = kernels::sin_cos(rotation);
  // The pivot is the corner lowest after the rotation.
  int pivot = 0;
  double lowest = 1e300;
  for (int k = 0; k < model.corner_count; ++k) {
    const double arm_x = model.corner_x[k] - lane.centre_x;
    const double arm_y = model.corner_y[k] - lane.centre_y;
    const double y = r.sin * arm_x + r.cos * arm_y;
    if (y < lowest) {
      lowest = y;
      pivot = k;
    }
  }
  const double penetration = overlap_carrying(model, model.corner_normal_stiffness[pivot] * lane.stiffness_scale,
                                              model.gravity / lane.inverse_mass);
  const double arm_x = model.corner_x[pivot] - lane.centre_x;
  const double arm_y = model.corner_y[pivot] - lane.centre_y;
  BodyState<double> body{};
  body.theta = rotation;
  // Keep the pivot's arc centre where it is when the cask stands upright.
  body.x = model.corner_x[pivot] - (r.cos * arm_x - r.sin * arm_y);
  body.y = model.rounding_radius - penetration - (r.sin * arm_x + r.cos * arm_y);
  return body;
}

Response<double> initial_response(const LaneParameters<double>& lane, const BodyState<double>& body) {
  Response<double> response{};
  const kernels::SinCos<double> r = kernels::sin_cos(body.theta);
  // Same expression as the step's, so an undisturbed cask reads exactly zero sliding.
  response.base_x0 = body.x - r.cos * lane.centre_x + r.sin * lane.centre_y;
  response.instability_time = kNotReached;
  return response;
}

}  // namespace caskdem
