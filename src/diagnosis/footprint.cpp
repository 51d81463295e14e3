#include "diagnosis/footprint.h"

#include <stdexcept>

namespace caskdem::diagnosis {

const std::vector<Footprint>& all_footprints() {
  static const std::vector<Footprint> all = {Footprint::gyration, Footprint::radius, Footprint::distributed};
  return all;
}

std::string footprint_name(Footprint footprint) {
  switch (footprint) {
    case Footprint::gyration: return "gyration";
    case Footprint::radius: return "radius";
    case Footprint::distributed: return "distributed";
  }
  return "?";
}

std::optional<Footprint> footprint_of(const Case& specimen) {
  if (specimen.cask.shape != "cylinder") return std::nullopt;
  const Cylinder& c = specimen.cask.cylinder;
  if (c.footprint_points > 0) return Footprint::distributed;
  return c.rule == HalfWidthRule::radius ? Footprint::radius : Footprint::gyration;
}

Case with_footprint(const Case& specimen, Footprint footprint) {
  if (!footprint_of(specimen)) throw std::invalid_argument("only a cylinder's footprint can be changed");
  Case c = specimen;
  Cylinder& cylinder = c.cask.cylinder;
  const int points = cylinder.footprint_points > 0 ? cylinder.footprint_points : kDefaultFootprintPoints;
  cylinder.rule = footprint == Footprint::gyration ? HalfWidthRule::gyration : HalfWidthRule::radius;
  cylinder.footprint_points = footprint == Footprint::distributed ? points : 0;
  c.model.section = cylinder_section(cylinder, specimen.model.section.rounding);
  return c;
}

}  // namespace caskdem::diagnosis
