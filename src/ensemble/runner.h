#pragma once
// Running realisations: blocks of SIMD lanes (kernels/block.h, or kernels/block3d.h for the
// cask in 3D, each lane at its realisation's incidence), one block per OpenMP thread, each lane
// one realisation. A lane that tips over, leaves the floor, slides off or reaches
// the end of its run is harvested at the end of the chunk of steps it stopped in and
// replaced by the next pending realisation, of any motion, which starts on its own clock at
// step 0: a block's width stays busy until the work runs out, and no lane rides on stopped.
// The lanes read one table of every motion's whole run (MotionTables). A realisation's
// result does not depend on the lane, block, thread or the time it started: it sees the
// same table values at the same steps of its own clock.
//
// When the whole-run table would not fit its memory budget, blocks of one motion run in
// lockstep on tables sampled chunk by chunk instead, each until all its lanes have stopped
// (the same results, more lane-steps on stopped lanes).

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "ensemble/plan.h"

namespace caskdem {

struct RealisationOutcome {
  LaneStatus status = LaneStatus::running;
  double max_abs_rotation = 0.0;  // rad (3D: the axis' tilt from vertical)
  double max_abs_slide = 0.0;
  double residual_slide = 0.0;
  double max_uplift = 0.0;
  double impacts = 0.0;  // -1 in 3D: not counted
  double end_time = 0.0;
  double instability_time = -1.0;
  double spin = 0.0;  // rad, about the cask's axis (3D)
  double max_slip = 0.0, residual_slip = 0.0;  // m, sliding where the cask bears, rolling excluded (3D)
};

// The table acceleration of every motion at every step of its run (steps 0 .. steps(m) - 1 of
// motion m at offset(m)), end to end, one table per component that any motion has (the
// horizontal; in 3D also the second horizontal and the vertical), or nothing when that exceeds
// the budget.
class MotionTables {
 public:
  using Components = std::array<const double*, 3>;  // H1, H2, vertical; null where absent
  static constexpr std::int64_t kDefaultBudgetBytes = std::int64_t(1) << 29;  // 512 MiB
  // The GPU engine has no lockstep fallback: it takes every motion whole, up to 4 GiB.
  static constexpr std::int64_t kDeviceBudgetBytes = std::int64_t(1) << 32;
  explicit MotionTables(const EnsemblePlan& plan, std::int64_t budget_bytes = kDefaultBudgetBytes);
  bool whole() const { return !table_[0].empty(); }
  std::int64_t length() const { return length_; }  // steps of all motions together
  const double* data(int component = 0) const { return table_[component].empty() ? nullptr : table_[component].data(); }
  std::int64_t offset(int motion) const { return offset_[motion]; }
  std::int64_t steps(int motion) const { return steps_[motion]; }

 private:
  std::vector<std::int64_t> offset_, steps_;
  std::int64_t length_ = 0;
  std::vector<double> table_[3];
};

class DeviceLanes;  // ensemble/device_runner.h

struct RunOptions {
  InstructionSet isa = InstructionSet::automatic;
  int threads = 1;
  int lanes = 64;       // per block
  bool refill = true;   // false: blocks of one motion in lockstep (the results are the same)
  // Run on this GPU (or the host in its place) instead of the CPU's SIMD blocks: the same
  // results; isa, threads, lanes and refill are then the CPU's and unused.
  DeviceLanes* device = nullptr;
};

// Lane-steps the kernel was asked to advance, and those of them on lanes that had already
// stopped (or held nothing), counted per chunk over each SIMD batch with a running lane; and
// of those, the ones spent while realisations were still waiting to start (none, refilled).
struct LaneOccupancy {
  double lane_steps = 0.0;
  double stopped_lane_steps = 0.0;
  double stopped_while_waiting = 0.0;
  double stopped_fraction() const { return lane_steps > 0.0 ? stopped_lane_steps / lane_steps : 0.0; }
};

using OutcomeSink = std::function<void(const std::vector<std::int64_t>& indices,
                                       const std::vector<RealisationOutcome>& outcomes)>;

// Runs the realisations. on_done is called, one call at a time, with realisations as they
// finish; it may throw to stop the run (the exception is rethrown here once the threads have
// stopped). Adds to *occupancy when given.
void run_realisations(const EnsemblePlan& plan, const MotionTables& tables, const std::vector<std::int64_t>& realisations,
                      const RunOptions& options, const OutcomeSink& on_done, LaneOccupancy* occupancy = nullptr);

}  // namespace caskdem
