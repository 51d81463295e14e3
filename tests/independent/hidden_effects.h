#pragma once
// The hidden physical effects the independent data may carry, one at a time, each with
// values drawn from the seed in a range where it shows in the data. Named as the diagnosis
// names its mechanisms, but written here from their physical descriptions alone.
//
//   velocity_dependent_friction      Stribeck: mu falls from mu_s to r mu_s above slip speeds ~ v_s
//   amplitude_dependent_restitution  a larger Hunt-Crossley c_h: loss per impact grows with its speed
//   eccentric_mass                   centre of mass e off the axis
//   base_imperfection                convex base: centre c below the rim, c (1 - x^2/r^2)
//   vertical_excitation              the table's vertical motion (0.5-0.7 of the horizontal peak) acts
//   floor_compliance                 a soft top layer: pressure s times smaller over the first d0
//   out_of_plane_loss                rocking couple -2 zeta_w p I_O omega
//   sensor_delay                     theta and slide lag the table channel by tau

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cylinder_model.h"

namespace independent {

const std::vector<std::string>& effect_names();  // the eight, without "none"
bool is_effect(const std::string& name);         // one of the eight, or "none"

// The true specimen of a data set.
struct Truth {
  std::string effect = "none";
  std::uint64_t seed = 1;
  CaskParameters cask;
  double friction = 0.6;          // mu_s
  double stiffness = 0.0;         // N/m^3, pressure slope at the flat static settlement
  double stiffness_scale = 1.0;   // stiffness / nominal
  double damping_ratio = 0.03;    // standing vertical mode, from the baseline c_h
  double vertical_ratio = 0.0;    // vertical peak / horizontal peak; 0 = the table moves only horizontally
  double sensor_delay = 0.0;      // s
  std::vector<std::pair<std::string, double>> effect_parameters;  // SI
};

inline constexpr double kNominalStiffness = 2.38e10;  // N/m^3: "2.38e3 bar/cm"
inline constexpr double kNominalFriction = 0.6;

// Throws std::invalid_argument for an unknown effect.
Truth draw_truth(const std::string& effect, std::uint64_t seed);

}  // namespace independent
