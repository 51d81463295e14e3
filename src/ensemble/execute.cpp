#include "ensemble/execute.h"

#include <omp.h>

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "ensemble/device_runner.h"
#include "ensemble/limit_state_file.h"
#include "ensemble/progress.h"
#include "ensemble/runner.h"

namespace caskdem {

ResultFile::ResultFile(const EnsemblePlan& plan, const ExecuteOptions& options)
    : plan_(plan),
      output_(options.output),
      results_(options.resume ? read_ensemble_results(options.output, plan, &earlier_wall_) : EnsembleResults(plan)) {
  run_.instruction_set =
      instruction_set_name(options.isa == InstructionSet::automatic ? best_instruction_set() : options.isa);
  run_.threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  if (options.device) {
    run_.device = options.device->name();
    run_.instruction_set = "cuda";
    run_.threads = 0;  // set by the run (set_device_lanes)
  }
}

void ResultFile::set_device_lanes(std::int64_t lanes) { run_.threads = static_cast<int>(lanes); }

double ResultFile::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ResultFile::write(const std::vector<LimitStateSummary>* summaries) {
  last_write_ = elapsed();
  run_.wall_seconds = earlier_wall_ + last_write_;
  write_ensemble_file(output_, plan_, results_, run_, summaries);
}

void ResultFile::checkpoint_if_due() {
  if (elapsed() - last_write_ >= plan_.spec().checkpoint_interval) write(nullptr);
}

void ResultFile::finish(ExecuteReport& report) {
  report.limit_states = analyse(plan_, results_);
  write(&report.limit_states);
  report.tables = write_fragility_tables(output_, plan_, report.limit_states);
  report.wall_seconds = run_.wall_seconds;
}

const MotionTables& device_tables(const EnsemblePlan& plan, const MotionTables& tables) {
  if (!tables.whole()) {
    std::int64_t steps = 0;
    for (int m = 0; m < plan.motion_count(); ++m) steps += tables.steps(m);
    throw InputError(located(plan.spec().file, 0,
                             "the GPU engine holds every motion's whole run on the device, and these motions' " +
                                 std::to_string(steps) + " steps of table exceed its " +
                                 std::to_string(MotionTables::kDeviceBudgetBytes >> 30) +
                                 " GiB; expected fewer or shorter motions, a longer time step, or --device cpu"));
  }
  return tables;
}

ExecuteReport execute_ensemble(const EnsemblePlan& plan, const ExecuteOptions& options) {
  ResultFile file(plan, options);
  EnsembleResults& results = file.results();
  const MotionTables tables(plan,
                            options.device ? MotionTables::kDeviceBudgetBytes : MotionTables::kDefaultBudgetBytes);
  RunOptions run;
  run.isa = options.isa;
  run.threads = file.run().threads;
  run.lanes = plan.spec().block_lanes;
  run.refill = options.refill;
  std::optional<DeviceLanes> device_lanes;
  if (options.device) {
    device_lanes.emplace(plan, device_tables(plan, tables), *options.device);
    run.device = &*device_lanes;
    file.set_device_lanes(std::min<std::int64_t>(device_lanes->lane_capacity(), results.size));
  }
  // The file exists, valid and resumable, from the moment the run can start.
  file.write(nullptr);
  Progress progress(results.size, results.completed_count(), options.progress);
  std::int64_t done = results.completed_count();
  ExecuteReport report;
  run_realisations(
      plan, tables, results.pending(), run,
      [&](const std::vector<std::int64_t>& indices, const std::vector<RealisationOutcome>& outcomes) {
        for (std::size_t k = 0; k < indices.size(); ++k) results.record(indices[k], outcomes[k], plan.stability_angle());
        done += static_cast<std::int64_t>(indices.size());
        report.realisations_run += static_cast<std::int64_t>(indices.size());
        progress.update(done);
        file.checkpoint_if_due();
      },
      &report.occupancy);
  progress.finish();
  file.finish(report);
  return report;
}

}  // namespace caskdem
