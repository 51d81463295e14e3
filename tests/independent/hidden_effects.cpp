#include "hidden_effects.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "random_stream.h"

namespace independent {

const std::vector<std::string>& effect_names() {
  static const std::vector<std::string> names{
      "velocity_dependent_friction", "amplitude_dependent_restitution", "eccentric_mass", "base_imperfection",
      "vertical_excitation",         "floor_compliance",                "out_of_plane_loss", "sensor_delay"};
  return names;
}

bool is_effect(const std::string& name) {
  return name == "none" || std::find(effect_names().begin(), effect_names().end(), name) != effect_names().end();
}

Truth draw_truth(const std::string& effect, std::uint64_t seed) {
  if (!is_effect(effect)) throw std::invalid_argument("unknown effect '" + effect + "'");
  Truth t;
  t.effect = effect;
  t.seed = seed;
  // Every value is drawn whatever the effect, each from its own stream, so that the baseline
  // of a seed is the same with every effect and the null differs from it by the effect alone.
  RandomStream base(seed, 1), fx(seed, 2);
  t.friction = base.uniform(0.5, 0.7);
  t.stiffness_scale = base.uniform(0.7, 1.4);
  t.damping_ratio = base.uniform(0.01, 0.05);
  t.stiffness = t.stiffness_scale * kNominalStiffness;
  t.cask.mu_static = t.friction;
  set_standing_stiffness(t.cask, t.stiffness, t.damping_ratio);

  const double kinetic_ratio = fx.uniform(0.55, 0.75);
  const double stribeck_speed = fx.uniform(0.02, 0.10);
  const double extra_c_h = fx.uniform(8.0, 20.0);
  const double eccentricity = (fx.uniform() < 0.5 ? -1.0 : 1.0) * fx.uniform(0.015, 0.035);
  const double camber = fx.uniform(0.2e-3, 0.5e-3);
  const double vertical_ratio = fx.uniform(0.5, 0.7);
  const double soft_ratio = fx.uniform(0.05, 0.15);
  const double soft_depth_factor = fx.uniform(2.0, 4.0);
  const double rocking_damping = fx.uniform(0.15, 0.30);
  const double delay = fx.uniform(0.02, 0.06);

  auto add = [&](const char* name, double v) { t.effect_parameters.emplace_back(name, v); };
  if (effect == "velocity_dependent_friction") {
    t.cask.kinetic_ratio = kinetic_ratio;
    t.cask.stribeck_speed = stribeck_speed;
    add("kinetic_ratio", kinetic_ratio);
    add("stribeck_speed_m_s", stribeck_speed);
  } else if (effect == "amplitude_dependent_restitution") {
    t.cask.c_h += extra_c_h;
    add("extra_hunt_crossley_c_h_s_m", extra_c_h);
    add("hunt_crossley_c_h_s_m", t.cask.c_h);
  } else if (effect == "eccentric_mass") {
    t.cask.eccentricity = eccentricity;
    add("eccentricity_m", eccentricity);
  } else if (effect == "base_imperfection") {
    t.cask.camber = camber;
    add("camber_m", camber);
  } else if (effect == "vertical_excitation") {
    t.vertical_ratio = vertical_ratio;
    add("vertical_to_horizontal_peak", vertical_ratio);
  } else if (effect == "floor_compliance") {
    // The layer's depth is a few times the settlement on it, so that the cask stands in the
    // soft layer and its rim reaches the stiff floor only when it lands from a rock.
    t.cask.soft_ratio = soft_ratio;
    t.cask.soft_depth = soft_depth_factor * flat_settlement(t.cask) / std::pow(soft_ratio, 1.0 / t.cask.exponent);
    add("soft_ratio", soft_ratio);
    add("soft_depth_m", t.cask.soft_depth);
  } else if (effect == "out_of_plane_loss") {
    t.cask.rocking_damping_ratio = rocking_damping;
    add("rocking_damping_ratio", rocking_damping);
  } else if (effect == "sensor_delay") {
    t.sensor_delay = delay;
    add("sensor_delay_s", delay);
  }
  return t;
}

}  // namespace independent
