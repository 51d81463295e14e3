#pragma once
// Running a 3D case file's analysis (`[cask] dimensions = 3`): the cylinder from the case's
// cask, contact, friction, damping, integration and limits (model/build3d.h), its motion's
// components (a horizontal pair and the station's vertical read as one set, or one component),
// the incidence, the run (sim/simulate3d.h).
//
// How long it runs: `duration` when given; else the motion and `settle_time` when that is given;
// else until the cask is at rest after the motion: its kinetic energy (translation and rotation)
// below kRestEnergy m g H for kRestHold in a row, at most `rest_cap` (60 s) after the motion. A
// cask that rolls on its rim or wobbles goes on for tens of seconds after the table stops, and its
// residual slide and spin are not settled before then.

#include <memory>
#include <optional>
#include <string>

#include "casefile/case_file.h"
#include "motion/pair_intensity.h"
#include "sim/simulate3d.h"

namespace caskdem {

inline constexpr double kRestEnergy = 1e-6;  // of m g H (H the cask's height)
inline constexpr double kRestHold = 1.0;     // s

struct CaseMotions3D {
  std::unique_ptr<motion::TableMotion> h1, h2, vertical;  // h2 and vertical may be null
  double incidence = 0.0;                                 // rad
  double scale_factor = 1.0;                              // applied to every component of a set
  std::string time_base;  // what putting a set's components on one time base did ("" if nothing)
  std::optional<motion::PairIntensity> pair;  // of the pair as applied (scaled), when there is one
  Excitation3D excitation() const;
};

struct RunReport3D {
  const Case* source = nullptr;
  CaskSpec3D cask;
  RealisationParameters parameters;
  Model3D model;
  CaseMotions3D motions;
  RunResult3D result;
  double wall_seconds = 0.0;
};

// A record that cannot be read, a set whose components do not fit together or a scaling out of
// range is an InputError naming the file.
// One [motion] or [[motions]] table's components: a record's pair and the station's vertical
// (scaled together by the spec's factor or to its target on the pair's measure), or one
// horizontal component; `owner` is the file that names it.
CaseMotions3D make_motions3d(const MotionSpec& spec, const std::filesystem::path& owner);
CaseMotions3D make_case_motions3d(const Case& c);
RunReport3D run_case3d(const Case& c, double output_interval);

}  // namespace caskdem
