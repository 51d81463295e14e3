#include "ensemble/runner.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>

#include <omp.h>

#include "kernels/step.h"

namespace caskdem {

namespace {
constexpr int kChunk = 2048;  // steps of table motion sampled at a time (16 kB)
}

std::vector<WorkBlock> make_blocks(const EnsemblePlan& plan, const std::vector<std::int64_t>& realisations, int lanes) {
  std::vector<std::vector<std::int64_t>> by_motion(plan.motion_count());
  for (std::int64_t i : realisations) by_motion[plan.realisation(i).motion].push_back(i);
  std::vector<WorkBlock> blocks;
  for (int m = 0; m < plan.motion_count(); ++m) {
    const auto& list = by_motion[m];
    for (std::size_t first = 0; first < list.size(); first += static_cast<std::size_t>(lanes)) {
      WorkBlock block;
      block.motion = m;
      block.indices.assign(list.begin() + first, list.begin() + std::min(list.size(), first + lanes));
      blocks.push_back(std::move(block));
    }
  }
  return blocks;
}

std::vector<RealisationOutcome> run_block(const EnsemblePlan& plan, const WorkBlock& work, InstructionSet isa) {
  const Model& model = plan.model();
  const auto lanes = static_cast<std::int64_t>(work.indices.size());
  LaneBlock block(lanes, model.corner_count);
  std::vector<LaneParameters<double>> parameters(lanes);
  for (std::int64_t l = 0; l < lanes; ++l) {
    const RealisationInput in = plan.realisation(work.indices[l]);
    parameters[l] = lane_parameters(model, in.parameters);
    const BodyState<double> body = rest_state(model, parameters[l]);
    const CornerState<double> corners[kMaxCorners] = {};
    block.set_lane(l, parameters[l], body, corners, initial_response(parameters[l], body));
  }
  if (block.lane_count() > lanes) block.pad_from(0);

  const motion::TableMotion& motion = plan.motion(work.motion);
  const auto steps = static_cast<std::int64_t>(std::ceil(plan.run_duration(work.motion) / model.time_step));
  std::vector<double> horizontal(kChunk);
  const std::vector<double> vertical(kChunk, 0.0);
  for (std::int64_t first = 0; first < steps && !block.all_stopped(); first += kChunk) {
    const int count = static_cast<int>(std::min<std::int64_t>(kChunk, steps - first));
    motion::sample_acceleration(motion, model.time_step, first, count, horizontal.data());
    advance_block(isa, model, block, horizontal.data(), vertical.data(), first, count);
  }

  std::vector<RealisationOutcome> outcomes(lanes);
  for (std::int64_t l = 0; l < lanes; ++l) {
    BodyState<double> body;
    Response<double> response;
    block.get_lane(l, nullptr, &body, nullptr, &response);
    kernels::finish(model, parameters[l], body, static_cast<double>(steps) * model.time_step, response);
    RealisationOutcome& o = outcomes[l];
    o.status = static_cast<LaneStatus>(static_cast<int>(response.status));
    o.max_abs_rotation = response.max_abs_rotation;
    o.max_abs_slide = response.max_abs_slide;
    o.residual_slide = response.final_slide;
    o.max_uplift = response.max_uplift;
    o.impacts = response.impacts;
    o.end_time = response.end_time;
    o.instability_time = o.status == LaneStatus::tipped_over ? response.instability_time : -1.0;
  }
  return outcomes;
}

void run_blocks(const EnsemblePlan& plan, const std::vector<WorkBlock>& blocks, InstructionSet isa, int threads,
                const std::function<void(const WorkBlock&, const std::vector<RealisationOutcome>&)>& on_done) {
  std::mutex done_mutex;
  std::exception_ptr failure;
  const auto count = static_cast<std::int64_t>(blocks.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t b = 0; b < count; ++b) {
    {
      std::lock_guard<std::mutex> lock(done_mutex);
      if (failure) continue;  // stop starting blocks once something failed
    }
    try {
      const std::vector<RealisationOutcome> outcomes = run_block(plan, blocks[b], isa);
      std::lock_guard<std::mutex> lock(done_mutex);
      if (!failure) on_done(blocks[b], outcomes);
    } catch (...) {
      std::lock_guard<std::mutex> lock(done_mutex);
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace caskdem
