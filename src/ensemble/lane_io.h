#pragma once
// A realisation as a lane starts it and as its result is read back, one definition for every
// engine: the CPU's SIMD blocks (ensemble/runner.cpp) and the queued lanes of a GPU
// (ensemble/device_runner.cpp). Both start a realisation from the plan's parameters at rest on
// its springs and read its outcome from the lane's final state in the same way, so that the
// engines differ only in where the step runs.

#include <cstdint>

#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "kernels/lane_state.h"
#include "kernels/lane_state3d.h"

namespace caskdem {

// A planar realisation at t = 0: standing at rest, its spring-sliders unstretched (all zero).
struct LaneStart {
  LaneParameters<double> parameters;
  BodyState<double> body;
  Response<double> response;
  int motion = 0;
};
LaneStart lane_start(const EnsemblePlan& plan, std::int64_t index);

// A 3D realisation at t = 0, with its incidence (rad, the direction of H1) and its cosine and sine.
struct LaneStart3D {
  LaneParameters<double> parameters;
  BodyState3D<double> body;
  Response3D<double> response;
  double incidence = 0.0, incidence_cos = 1.0, incidence_sin = 0.0;
  int motion = 0;
};
LaneStart3D lane_start3d(const EnsemblePlan& plan, std::int64_t index);

// The outcome of a lane that stopped (its frozen state) or ran its `steps` steps.
RealisationOutcome lane_outcome(const EnsemblePlan& plan, const LaneParameters<double>& parameters,
                                const BodyState<double>& body, Response<double> response, std::int64_t steps);
RealisationOutcome lane_outcome3d(const EnsemblePlan& plan, const LaneParameters<double>& parameters,
                                  const BodyState3D<double>& body, const Response3D<double>& response,
                                  std::int64_t steps);

}  // namespace caskdem
