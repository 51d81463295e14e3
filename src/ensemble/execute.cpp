#include "ensemble/execute.h"

#include <chrono>

#include <omp.h>

#include "ensemble/progress.h"
#include "ensemble/runner.h"

namespace caskdem {

ExecuteReport execute_ensemble(const EnsemblePlan& plan, const ExecuteOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  double earlier_wall = 0.0;
  EnsembleResults results = options.resume ? read_ensemble_results(options.output, plan, &earlier_wall)
                                           : EnsembleResults(plan);
  RunInformation run;
  run.instruction_set = instruction_set_name(options.isa == InstructionSet::automatic ? best_instruction_set() : options.isa);
  run.threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  auto checkpoint = [&](const std::vector<LimitStateSummary>* summaries) {
    run.wall_seconds = earlier_wall + elapsed();
    write_ensemble_file(options.output, plan, results, run, summaries);
  };
  // The file exists, valid and resumable, from the first moment.
  checkpoint(nullptr);

  const std::vector<WorkBlock> blocks = make_blocks(plan, results.pending(), plan.spec().block_lanes);
  Progress progress(results.size, results.completed_count(), options.progress);
  std::int64_t done = results.completed_count();
  double last_checkpoint = elapsed();
  ExecuteReport report;
  run_blocks(plan, blocks, options.isa, run.threads,
             [&](const WorkBlock& block, const std::vector<RealisationOutcome>& outcomes) {
               for (std::size_t l = 0; l < block.indices.size(); ++l) {
                 results.record(block.indices[l], outcomes[l], plan.stability_angle());
               }
               done += static_cast<std::int64_t>(block.indices.size());
               report.realisations_run += static_cast<std::int64_t>(block.indices.size());
               progress.update(done);
               if (elapsed() - last_checkpoint >= plan.spec().checkpoint_interval) {
                 checkpoint(nullptr);
                 last_checkpoint = elapsed();
               }
             });
  progress.finish();
  report.limit_states = analyse(plan, results);
  checkpoint(&report.limit_states);
  report.wall_seconds = run.wall_seconds;
  return report;
}

}  // namespace caskdem
