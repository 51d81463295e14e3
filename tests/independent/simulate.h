#pragma once
// One shaking-table test of the cylinder: its response sampled on a time grid.

#include <vector>

#include "cylinder_model.h"

namespace independent {

struct IntegratorSettings {
  double absolute_tolerance = 1e-9;  // on the state's entries (m, rad, m/s, rad/s)
  double relative_tolerance = 1e-7;
  double max_step = 1e-3;            // s: never step over a feature of the table's input
  double tip_over_angle = 1.2;       // rad: beyond this the cask has fallen; the run stops
};

struct Response {
  std::vector<double> rotation;      // rad, at each requested time
  std::vector<double> slide;         // m: base centre relative to its place at rest
  std::vector<State> states;
  bool tipped_over = false;
  long steps = 0;                    // right-hand-side evaluations
};

// Integrates from the resting state `start` at t = 0 and samples at `times` (ascending; a
// time below 0 gets the resting state, so a delayed sensor reads rest before the motion).
Response simulate(const CylinderModel& model, const TableInput& input, const State& start,
                  const std::vector<double>& times, const IntegratorSettings& settings = {});

}  // namespace independent
