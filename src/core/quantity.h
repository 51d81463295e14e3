#pragma once
// Quantities with units, as users write them: a bare number is SI; a string is
// "<number> <unit>", e.g. "2.38e3 bar/cm", "400 gal", "0.5 cm", "12.6 t", "135 Hz".
// Each key of a case file expects one dimension; a unit of another dimension is an error
// that names the key and lists the units it accepts.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace caskdem {

enum class Dimension {
  dimensionless,
  length,
  time,
  mass,
  velocity,
  acceleration,
  frequency,
  angle,
  density,
  stress,                // Pa: shear modulus
  distributed_stiffness,  // N/m^3: stiffness per unit contact area
  stiffness,             // N/m
  moment_of_inertia,     // kg m^2
  slowness,              // s/m: an inverse speed (the Hunt-Crossley damper)
};

struct UnitFactor {
  std::string_view name;
  double to_si;
};

// The units a dimension accepts, SI first.
const std::vector<UnitFactor>& units_of(Dimension dimension);
std::string dimension_name(Dimension dimension);

// Parses "<number> [unit]" into SI; std::nullopt with `error` set when it cannot.
std::optional<double> parse_quantity(std::string_view text, Dimension dimension, std::string& error);

}  // namespace caskdem
