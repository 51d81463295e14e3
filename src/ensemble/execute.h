#pragma once
// Running a whole ensemble on this machine: resume from a checkpoint if asked, run the
// pending realisations on the threaded SIMD engine, checkpoint the file every few seconds,
// and finish with the fragility analysis.

#include <filesystem>
#include <vector>

#include "ensemble/analysis.h"
#include "ensemble/plan.h"
#include "ensemble/results.h"

namespace caskdem {

struct ExecuteOptions {
  InstructionSet isa = InstructionSet::automatic;
  int threads = 0;  // 0: OpenMP's default
  bool resume = false;
  bool progress = true;
  std::filesystem::path output;
};

struct ExecuteReport {
  std::int64_t realisations_run = 0;  // in this invocation
  double wall_seconds = 0.0;          // in total, over resumed runs
  std::vector<LimitStateSummary> limit_states;
};

ExecuteReport execute_ensemble(const EnsemblePlan& plan, const ExecuteOptions& options);

}  // namespace caskdem
