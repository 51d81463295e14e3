#include "core/quantity.h"

#include <charconv>
#include <cmath>
#include <numbers>

#include "core/units.h"

namespace caskdem {

const std::vector<UnitFactor>& units_of(Dimension dimension) {
  using namespace units;
  static const std::vector<UnitFactor> none = {{"", 1.0}};
  static const std::vector<UnitFactor> length = {{"m", 1.0}, {"cm", centimetre}, {"mm", millimetre}};
  static const std::vector<UnitFactor> time = {{"s", 1.0}, {"ms", 1e-3}};
  static const std::vector<UnitFactor> mass = {{"kg", 1.0}, {"t", tonne}};
  static const std::vector<UnitFactor> velocity = {{"m/s", 1.0}, {"cm/s", 0.01}, {"kine", kine}, {"mm/s", 1e-3}};
  static const std::vector<UnitFactor> acceleration = {{"m/s^2", 1.0}, {"gal", gal}, {"g", standard_gravity}, {"cm/s^2", 0.01}};
  static const std::vector<UnitFactor> frequency = {{"Hz", 1.0}};
  static const std::vector<UnitFactor> angle = {{"rad", 1.0}, {"deg", degree}};
  static const std::vector<UnitFactor> density = {{"kg/m^3", 1.0}, {"g/cm^3", gram_per_cm3}, {"t/m^3", 1000.0}};
  static const std::vector<UnitFactor> stress = {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}, {"bar", bar}};
  static const std::vector<UnitFactor> distributed = {{"N/m^3", 1.0}, {"bar/cm", bar_per_cm}, {"MPa/m", 1e6}, {"GPa/m", 1e9}};
  static const std::vector<UnitFactor> stiffness = {{"N/m", 1.0}, {"kN/m", 1e3}, {"MN/m", 1e6}, {"GN/m", 1e9}};
  static const std::vector<UnitFactor> inertia = {{"kg m^2", 1.0}, {"t m^2", tonne}};
  static const std::vector<UnitFactor> slowness = {{"s/m", 1.0}, {"s/cm", 100.0}};
  switch (dimension) {
    case Dimension::dimensionless: return none;
    case Dimension::length: return length;
    case Dimension::time: return time;
    case Dimension::mass: return mass;
    case Dimension::velocity: return velocity;
    case Dimension::acceleration: return acceleration;
    case Dimension::frequency: return frequency;
    case Dimension::angle: return angle;
    case Dimension::density: return density;
    case Dimension::stress: return stress;
    case Dimension::distributed_stiffness: return distributed;
    case Dimension::stiffness: return stiffness;
    case Dimension::moment_of_inertia: return inertia;
    case Dimension::slowness: return slowness;
  }
  return none;
}

std::string dimension_name(Dimension dimension) {
  switch (dimension) {
    case Dimension::dimensionless: return "a number";
    case Dimension::length: return "a length";
    case Dimension::time: return "a time";
    case Dimension::mass: return "a mass";
    case Dimension::velocity: return "a velocity";
    case Dimension::acceleration: return "an acceleration";
    case Dimension::frequency: return "a frequency";
    case Dimension::angle: return "an angle";
    case Dimension::density: return "a density";
    case Dimension::stress: return "a stress";
    case Dimension::distributed_stiffness: return "a stiffness per unit area";
    case Dimension::stiffness: return "a stiffness";
    case Dimension::moment_of_inertia: return "a moment of inertia";
    case Dimension::slowness: return "an inverse speed";
  }
  return "a quantity";
}

static std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_quantity(std::string_view text, Dimension dimension, std::string& error) {
  text = trim(text);
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr == begin) {
    error = "expected " + dimension_name(dimension) + " such as \"1.5 " +
            std::string(units_of(dimension).back().name) + "\", got \"" + std::string(text) + "\"";
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    error = "expected a finite number, got \"" + std::string(text) + "\"";
    return std::nullopt;
  }
  std::string_view unit = trim(std::string_view(ptr, static_cast<std::size_t>(end - ptr)));
  for (const UnitFactor& u : units_of(dimension)) {
    if (unit == u.name) return value * u.to_si;
  }
  std::string accepted;
  for (const UnitFactor& u : units_of(dimension)) {
    if (u.name.empty()) continue;
    accepted += (accepted.empty() ? "" : ", ") + std::string(u.name);
  }
  error = "unit \"" + std::string(unit) + "\" is not " + dimension_name(dimension) + " unit" +
          (accepted.empty() ? " (expected a plain number)" : " (accepted: " + accepted + ")");
  return std::nullopt;
}

}  // namespace caskdem
