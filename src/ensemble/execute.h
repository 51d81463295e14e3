#pragma once
// Running a whole ensemble on this machine: resume from a checkpoint if asked, run the
// pending realisations on the threaded SIMD engine or a GPU (ensemble/device_runner.h),
// checkpoint the file every few seconds, and finish with the fragility analysis.

#include <chrono>
#include <filesystem>
#include <vector>

#include "ensemble/analysis.h"
#include "ensemble/plan.h"
#include "ensemble/results.h"
#include "ensemble/runner.h"
#include "kernels/lane_device.h"

namespace caskdem {

struct ExecuteOptions {
  InstructionSet isa = InstructionSet::automatic;
  int threads = 0;  // 0: OpenMP's default
  bool resume = false;
  bool progress = true;
  bool refill = true;  // false: lockstep blocks (the same results; for measuring what refilling saves)
  std::filesystem::path output;
  LaneDevice* device = nullptr;  // a GPU (open_device), or null: the CPU's SIMD engine
};

struct ExecuteReport {
  std::int64_t realisations_run = 0;  // in this invocation
  double wall_seconds = 0.0;          // in total, over resumed runs
  std::vector<LimitStateSummary> limit_states;
  std::vector<std::filesystem::path> tables;  // the fragility JSON and CSV beside the result file
  LaneOccupancy occupancy;            // of this invocation's lanes (ensemble/runner.h)
};

ExecuteReport execute_ensemble(const EnsemblePlan& plan, const ExecuteOptions& options);

// The motions' tables for the GPU engine, which has no lockstep fallback: an InputError naming
// the ensemble file when they did not fit their budget.
const MotionTables& device_tables(const EnsemblePlan& plan, const MotionTables& tables);

// What an execution keeps beside its result file, on one process or on each MPI rank: the
// results so far (fresh, or read back from the file with --resume), how the run is made, and
// the wall time, carried over a resume.
class ResultFile {
 public:
  ResultFile(const EnsemblePlan& plan, const ExecuteOptions& options);
  EnsembleResults& results() { return results_; }
  const RunInformation& run() const { return run_; }
  double elapsed() const;  // s since this execution started
  // Writes the file as it stands (atomically; src/ensemble/results.h), with the limit states
  // when the run is complete.
  void write(const std::vector<LimitStateSummary>* summaries);
  // Writes the file when the plan's checkpoint interval has passed since the last write, so a
  // stopped run loses at most that much finished work.
  void checkpoint_if_due();
  // The run is complete: the fragility analysis into the report and the file, and the wall time.
  void finish(ExecuteReport& report);
  // A GPU run's lanes (one realisation per thread), for the file's `threads`.
  void set_device_lanes(std::int64_t lanes);

 private:
  const EnsemblePlan& plan_;
  std::filesystem::path output_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double earlier_wall_ = 0.0;
  double last_write_ = 0.0;  // s, elapsed() at the last write
  EnsembleResults results_;
  RunInformation run_;
};

}  // namespace caskdem
