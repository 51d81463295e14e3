#include "diagnosis/mechanisms.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"

namespace caskdem::diagnosis {

const std::vector<Mechanism>& all_mechanisms() {
  static const std::vector<Mechanism> all = {
      Mechanism::velocity_dependent_friction, Mechanism::amplitude_dependent_restitution, Mechanism::eccentric_mass,
      Mechanism::base_imperfection,           Mechanism::vertical_excitation,             Mechanism::floor_compliance,
      Mechanism::out_of_plane_loss,           Mechanism::sensor_delay};
  return all;
}

std::string mechanism_name(Mechanism m) {
  switch (m) {
    case Mechanism::velocity_dependent_friction: return "velocity_dependent_friction";
    case Mechanism::amplitude_dependent_restitution: return "amplitude_dependent_restitution";
    case Mechanism::eccentric_mass: return "eccentric_mass";
    case Mechanism::base_imperfection: return "base_imperfection";
    case Mechanism::vertical_excitation: return "vertical_excitation";
    case Mechanism::floor_compliance: return "floor_compliance";
    case Mechanism::out_of_plane_loss: return "out_of_plane_loss";
    case Mechanism::sensor_delay: return "sensor_delay";
  }
  return "unknown";
}

std::optional<Mechanism> parse_mechanism(const std::string& name) {
  for (Mechanism m : all_mechanisms()) {
    if (mechanism_name(m) == name) return m;
  }
  return std::nullopt;
}

std::vector<Mechanism> parse_mechanism_list(const std::string& text, const std::string& where) {
  std::string normalised = text;
  std::replace(normalised.begin(), normalised.end(), '+', ',');
  std::stringstream list(normalised);
  std::vector<Mechanism> mechanisms;
  std::string name;
  while (std::getline(list, name, ',')) {
    name = std::string(trim(name));
    // "none" is the cause's word for the baseline alone.
    if (name.empty() || name == "baseline" || name == "none") continue;
    const auto m = parse_mechanism(name);
    if (!m) {
      std::string known;
      for (Mechanism k : all_mechanisms()) known.append(" ").append(mechanism_name(k));
      throw InputError(where + ": unknown mechanism \"" + name + "\"; expected baseline (or none) or one or more of:" +
                       known);
    }
    if (std::find(mechanisms.begin(), mechanisms.end(), *m) != mechanisms.end())
      throw InputError(where + ": the mechanism " + name + " is named twice; expected each once");
    mechanisms.push_back(*m);
  }
  return mechanisms;
}

ModelVariant::ModelVariant(const Case& specimen, std::vector<Mechanism> mechanisms, bool vertical_measured)
    : specimen_(specimen), mechanisms_(std::move(mechanisms)), vertical_measured_(vertical_measured) {
  std::sort(mechanisms_.begin(), mechanisms_.end());
  if (specimen_.model.friction_law != FrictionLaw::constant) {
    throw std::invalid_argument("the baseline model of a diagnosis has constant friction ([friction] law = \"constant\")");
  }
  ModelSpec spec = specimen_.model;
  if (has(Mechanism::velocity_dependent_friction)) spec.friction_law = FrictionLaw::exponential;
  if (has(Mechanism::base_imperfection)) spec.base_centre_contact = true;
  model_ = build_model(spec, specimen_.parameters);

  double left = model_.corner_x[0], right = model_.corner_x[0];
  for (int k = 1; k < model_.corner_count; ++k) {
    left = std::min(left, model_.corner_x[k]);
    right = std::max(right, model_.corner_x[k]);
  }
  const double half_span = 0.5 * (right - left);
  const double penetration = specimen_.parameters.mass * model_.gravity / total_standing_normal_stiffness(model_);
  parameters_ = {
      {"friction", "", 0.05, 1.5, false, specimen_.parameters.friction_static},
      {"damping_ratio", "", 2e-3, 0.5, true, std::max(2e-3, specimen_.parameters.damping_ratio)},
      {"stiffness_scale", "", 0.1, 10.0, true, 1.0},
  };
  const std::size_t baseline_count = parameters_.size();
  for (Mechanism m : mechanisms_) {
    switch (m) {
      case Mechanism::velocity_dependent_friction:
        parameters_.push_back({"kinetic_ratio", "", 0.3, 1.5, false, 1.0});
        parameters_.push_back({"decay_speed", "m/s", 0.005, 1.0, true, 0.05, true, false});
        break;
      case Mechanism::amplitude_dependent_restitution:
        parameters_.push_back({"impact_damping", "s/m", 0.0, 30.0, false, 0.0});
        break;
      case Mechanism::eccentric_mass:
        parameters_.push_back({"eccentricity", "m", -0.3 * half_span, 0.3 * half_span, false, 0.0});
        break;
      case Mechanism::base_imperfection:
        parameters_.push_back({"base_camber", "m", 0.0, 0.02 * half_span, false, 0.0});
        break;
      case Mechanism::vertical_excitation:
        parameters_.push_back({"vertical_gain", "", 0.0, vertical_measured_ ? 1.5 : 1.0, false, 0.0});
        break;
      case Mechanism::floor_compliance:
        parameters_.push_back({"floor_soft_ratio", "", 0.01, 1.0, true, 1.0});
        parameters_.push_back(
            {"floor_soft_depth", "m", 0.1 * penetration, 100.0 * penetration, true, penetration, true, false});
        break;
      case Mechanism::out_of_plane_loss:
        parameters_.push_back({"wobble_damping", "", 0.0, 0.5, false, 0.0});
        break;
      case Mechanism::sensor_delay:
        parameters_.push_back({"sensor_delay", "s", -0.1, 0.1, false, 0.0});
        break;
    }
  }
  for (std::size_t i = baseline_count; i < parameters_.size(); ++i) parameters_[i].mechanism = true;
}

std::vector<double> ModelVariant::nominal_baseline() const {
  return {specimen_.parameters.friction_static, std::max(2e-3, specimen_.parameters.damping_ratio), 1.0};
}

bool ModelVariant::has(Mechanism m) const {
  return std::find(mechanisms_.begin(), mechanisms_.end(), m) != mechanisms_.end();
}

std::string ModelVariant::name() const {
  std::string text = "baseline";
  for (Mechanism m : mechanisms_) text += " + " + mechanism_name(m);
  return text;
}

VerticalSource ModelVariant::vertical_source() const {
  if (!has(Mechanism::vertical_excitation)) return VerticalSource::none;
  return vertical_measured_ ? VerticalSource::measured : VerticalSource::from_horizontal;
}

int ModelVariant::index_of(const std::string& name) const {
  for (int i = 0; i < size(); ++i) {
    if (parameters_[i].name == name) return i;
  }
  return -1;
}

RealisationParameters ModelVariant::realisation(const std::vector<double>& x) const {
  RealisationParameters p = specimen_.parameters;
  p.friction_static = p.friction_kinetic = x[0];
  p.damping_ratio = x[1];
  p.stiffness_scale = x[2];
  auto value = [&](const char* name) { return x[index_of(name)]; };
  if (has(Mechanism::velocity_dependent_friction)) {
    p.friction_kinetic = value("kinetic_ratio") * x[0];
    p.friction_decay_speed = value("decay_speed");
  }
  if (has(Mechanism::amplitude_dependent_restitution)) p.impact_damping = value("impact_damping");
  if (has(Mechanism::eccentric_mass)) p.centre_of_mass.x += value("eccentricity");
  if (has(Mechanism::base_imperfection)) p.base_camber = value("base_camber");
  p.vertical_scale = has(Mechanism::vertical_excitation) ? value("vertical_gain") : 0.0;
  if (has(Mechanism::floor_compliance)) {
    p.floor_soft_ratio = value("floor_soft_ratio");
    p.floor_soft_depth = value("floor_soft_depth");
  }
  if (has(Mechanism::out_of_plane_loss)) p.wobble_damping = value("wobble_damping");
  return p;
}

double ModelVariant::sensor_delay(const std::vector<double>& x) const {
  const int i = index_of("sensor_delay");
  return i < 0 ? 0.0 : x[i];
}

std::vector<double> ModelVariant::reference(const std::vector<double>* baseline) const {
  std::vector<double> x;
  for (const Parameter& p : parameters_) x.push_back(p.reference);
  if (baseline) std::copy(baseline->begin(), baseline->begin() + baseline_size(), x.begin());
  return x;
}

}  // namespace caskdem::diagnosis
