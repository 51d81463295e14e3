#pragma once
// Running realisations: blocks of lanes that share a motion, advanced by the SIMD kernel
// (kernels/block.h) chunk by chunk, threaded with OpenMP across blocks. A lane that tips
// over, leaves the floor or goes non-finite is frozen and flagged by the kernel; a block
// ends early when all its lanes have stopped.

#include <cstdint>
#include <functional>
#include <vector>

#include "ensemble/plan.h"

namespace caskdem {

struct RealisationOutcome {
  LaneStatus status = LaneStatus::running;
  double max_abs_rotation = 0.0;
  double max_abs_slide = 0.0;
  double residual_slide = 0.0;
  double max_uplift = 0.0;
  double impacts = 0.0;
  double end_time = 0.0;
  double instability_time = -1.0;
};

struct WorkBlock {
  int motion = 0;
  std::vector<std::int64_t> indices;  // realisations, ascending
};

// Groups realisations by motion into blocks of at most `lanes` lanes.
std::vector<WorkBlock> make_blocks(const EnsemblePlan& plan, const std::vector<std::int64_t>& realisations, int lanes);

// Runs one block to its end; outcomes in the order of block.indices.
std::vector<RealisationOutcome> run_block(const EnsemblePlan& plan, const WorkBlock& block, InstructionSet isa);

// Runs the blocks on `threads` OpenMP threads (dynamic schedule). on_done is called, one
// call at a time, as each block finishes; it may throw to stop the run (the exception is
// rethrown here once the running blocks have finished).
void run_blocks(const EnsemblePlan& plan, const std::vector<WorkBlock>& blocks, InstructionSet isa, int threads,
                const std::function<void(const WorkBlock&, const std::vector<RealisationOutcome>&)>& on_done);

}  // namespace caskdem
