#pragma once
// Realisations that a caller chose (the Python module's caskdem.rollout): each realisation's
// motion, its scale (a factor or the level of the ensemble's intensity measure) and any of the
// cask's parameters, given as columns of numbers, one row per realisation, instead of drawn
// from the ensemble file's distributions. They run on the ensemble engine (the CPU's SIMD lanes
// and threads, or a GPU) as the file's realisations do, and a row equal to one the file draws
// (plan_columns) gives the bits `caskdem ensemble` gives.
//
// A parameter not given keeps the ensemble file's nominal value. What the columns may hold is
// what the engine can run without another plan: the masses no lighter than the one the
// ensemble's time step was chosen for, the restitutions within the cask's calibrated range,
// the centre of mass inside the base; anything else is an InputError naming the column and row.

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ensemble/plan.h"
#include "ensemble/results.h"
#include "ensemble/runner.h"
#include "kernels/lane_device.h"

namespace caskdem {

// The columns rollout takes, in order, with their SI units ("1" for none; "index" for the motion).
struct RolloutParameter {
  std::string name;
  std::string unit;
  std::string meaning;
};
const std::vector<RolloutParameter>& rollout_parameters();

// One value per realisation, or one value for all.
using ParameterColumns = std::map<std::string, std::vector<double>>;

// The realisations the columns describe; `count` is their number (a column of one value is
// repeated). The plan is calibrated first when restitutions are given and the file drew none.
std::vector<RealisationInput> realisations_from_columns(EnsemblePlan& plan, const ParameterColumns& columns,
                                                        std::int64_t count, InstructionSet isa);

// The ensemble file's own realisations as columns: motion, scale_factor and every parameter the
// file samples (restitution rather than its damping ratio), in realisation order.
ParameterColumns plan_columns(const EnsemblePlan& plan);

struct RolloutOptions {
  InstructionSet isa = InstructionSet::automatic;
  int threads = 0;               // 0: OpenMP's default
  LaneDevice* device = nullptr;  // a GPU (open_device), or null: the CPU's SIMD engine
  // Called, one call at a time, with the number of realisations finished so far; it may throw
  // to stop the run (the exception comes out of rollout once the engine has stopped).
  std::function<void(std::int64_t done)> on_progress;
};

// Runs every realisation of the plan (one with set_realisations) on the tables (of the same
// motions); the outcomes as the result file stores them, in realisation order.
EnsembleResults rollout(const EnsemblePlan& plan, const MotionTables& tables, const RolloutOptions& options);

}  // namespace caskdem
