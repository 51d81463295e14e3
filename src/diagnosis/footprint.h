#pragma once
// The footprint rules a diagnosis weighs for a cylindrical specimen (model/section.h): how its
// circular base stands on the floor in the plane of excitation. The rule is the analyst's
// guess, and a wrong one is made good by a calibration only with implausible values (a
// contact stiffness five times off, a friction far from the stated one), so the diagnosis
// calibrates the baseline with each rule and keeps the one the held-out tests prefer.
//   gyration     two corners at b = r/2 (the source paper's rule)
//   radius       two corners at b = r (a rigid cylinder's pivots)
//   distributed  a row of contacts across the diameter weighted by the circle's chords

#include <optional>
#include <string>
#include <vector>

#include "casefile/case_file.h"

namespace caskdem::diagnosis {

enum class Footprint { gyration, radius, distributed };

const std::vector<Footprint>& all_footprints();
std::string footprint_name(Footprint footprint);

// The specimen's own rule; none for a polygon section.
std::optional<Footprint> footprint_of(const Case& specimen);

// The specimen with its cylinder standing on another footprint (the same cask otherwise).
Case with_footprint(const Case& specimen, Footprint footprint);

}  // namespace caskdem::diagnosis
