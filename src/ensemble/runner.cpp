#include "ensemble/runner.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>

#include "ensemble/device_runner.h"
#include "ensemble/lane_io.h"
#include "kernels/block3d.h"

namespace caskdem {

namespace {
constexpr int kChunk = 2048;  // steps between harvests (and of table motion sampled at a time in lockstep)

int batch_width(InstructionSet isa) {
  switch (isa == InstructionSet::automatic ? best_instruction_set() : isa) {
    case InstructionSet::avx512f: return 8;
    case InstructionSet::avx2: return 4;
    case InstructionSet::sse2: return 2;
    default: return 1;
  }
}

// Which realisation each lane of a block holds (planar or 3D alike).
class Holdings {
 public:
  explicit Holdings(int width) : held_(width, -1), motion_(width, 0), loaded_(width, false) {}
  int width() const { return static_cast<int>(held_.size()); }
  bool holds(int lane) const { return held_[lane] >= 0; }
  bool loaded(int lane) const { return loaded_[lane]; }
  std::int64_t realisation(int lane) const { return held_[lane]; }
  int motion(int lane) const { return motion_[lane]; }
  void hold(int lane, std::int64_t index, int motion) {
    held_[lane] = index;
    motion_[lane] = motion;
    loaded_[lane] = true;
  }
  void release(int lane) { held_[lane] = -1; }

 private:
  std::vector<std::int64_t> held_;
  std::vector<int> motion_;
  std::vector<bool> loaded_;
};

// A planar block's lanes and the realisations they hold.
class Lanes2D : public Holdings {
 public:
  Lanes2D(const EnsemblePlan& plan, int width)
      : Holdings(width), plan_(plan), block_(width, plan.model().corner_count), parameters_(width) {}

  LaneBlock& block() { return block_; }
  bool running(int lane) const { return holds(lane) && block_.status(lane) == 0.0; }

  void load(int lane, std::int64_t index, std::int64_t table_index) {
    const LaneStart start = lane_start(plan_, index);
    parameters_[lane] = start.parameters;
    const CornerState<double> corners[kMaxCorners] = {};
    block_.set_lane(lane, start.parameters, start.body, corners, start.response);
    block_.set_clock(lane, 0.0, table_index);
    hold(lane, index, start.motion);
  }

  // Nothing left to load: the lane keeps its last realisation's numbers (lane 0's if it never
  // held one), marked stopped so that it is never advanced and never divides by zero.
  void empty(int lane) {
    LaneParameters<double> parameters;
    BodyState<double> body;
    CornerState<double> corners[kMaxCorners];
    Response<double> response;
    block_.get_lane(loaded(lane) ? lane : 0, &parameters, &body, corners, &response);
    response.status = double(LaneStatus::tipped_over);
    block_.set_lane(lane, parameters, body, corners, response);
    release(lane);
  }

  // The lane's result: its frozen state if it stopped, else its state at the end of its run.
  RealisationOutcome harvest(int lane, std::int64_t steps) {
    BodyState<double> body;
    Response<double> response;
    block_.get_lane(lane, nullptr, &body, nullptr, &response);
    return lane_outcome(plan_, parameters_[lane], body, response, steps);
  }

  void advance(InstructionSet isa, const MotionTables::Components& table, std::int64_t first_step, int steps) {
    advance_block(isa, plan_.model(), block_, table[0], nullptr, first_step, steps);
  }

 private:
  const EnsemblePlan& plan_;
  LaneBlock block_;
  std::vector<LaneParameters<double>> parameters_;
};

// A 3D block's lanes (kernels/block3d.h), each at its realisation's incidence.
class Lanes3D : public Holdings {
 public:
  Lanes3D(const EnsemblePlan& plan, int width) : Holdings(width), plan_(plan), block_(width), parameters_(width) {}

  LaneBlock3D& block() { return block_; }
  bool running(int lane) const { return holds(lane) && block_.status(lane) == 0.0; }

  void load(int lane, std::int64_t index, std::int64_t table_index) {
    const LaneStart3D start = lane_start3d(plan_, index);
    parameters_[lane] = start.parameters;
    const ContactState3D<double> free[kContactSliders3D] = {};
    block_.set_lane(lane, start.parameters, start.body, free, start.response, start.incidence);
    block_.set_clock(lane, 0.0, table_index);
    hold(lane, index, start.motion);
  }

  void empty(int lane) {
    block_.stop_as_copy(lane, loaded(lane) ? lane : 0);
    release(lane);
  }

  RealisationOutcome harvest(int lane, std::int64_t steps) {
    BodyState3D<double> body;
    Response3D<double> response;
    block_.get_lane(lane, &body, nullptr, &response);
    return lane_outcome3d(plan_, parameters_[lane], body, response, steps);
  }

  void advance(InstructionSet isa, const MotionTables::Components& table, std::int64_t first_step, int steps) {
    const Model3D& model = plan_.model3d();
    advance_block3d(isa, model.model, model.contacts, block_, table[0], table[1], table[2], first_step, steps);
  }

 private:
  const EnsemblePlan& plan_;
  LaneBlock3D block_;
  std::vector<LaneParameters<double>> parameters_;
};

// Lanes that hold nothing (and the block's padding) read the start of the table: a stopped
// lane's index still advances with its batch, and must stay inside the table.
template <class Lanes>
void park_idle(Lanes& lanes) {
  for (std::int64_t l = 0; l < lanes.block().lane_count(); ++l) {
    if (l >= lanes.width() || !lanes.holds(static_cast<int>(l))) lanes.block().set_clock(l, 0.0, 0);
  }
}

// Lane-steps of the next `steps` steps: every lane of a SIMD batch that has a running lane
// is computed, running or not.
template <class Lanes>
void count(Lanes& lanes, int steps, int batch, bool waiting, LaneOccupancy& occupancy) {
  for (int first = 0; first < lanes.block().lane_count(); first += batch) {
    int running_lanes = 0;
    for (int l = first; l < std::min<int>(first + batch, lanes.width()); ++l) running_lanes += lanes.running(l);
    if (running_lanes == 0) continue;
    occupancy.lane_steps += double(batch) * steps;
    occupancy.stopped_lane_steps += double(batch - running_lanes) * steps;
    if (waiting) occupancy.stopped_while_waiting += double(batch - running_lanes) * steps;
  }
}

// What the threads share: the queue of realisations, the sink, the first failure.
struct Shared {
  Shared(const EnsemblePlan& p, const MotionTables& t, const RunOptions& o, const OutcomeSink& sink)
      : plan(p), tables(t), options(o), on_done(sink) {}
  const EnsemblePlan& plan;
  const MotionTables& tables;
  const RunOptions& options;
  const OutcomeSink& on_done;
  std::atomic<std::size_t> next{0};  // the next realisation (refilled) or block (lockstep) to start
  std::size_t blocks = 0;            // lockstep
  std::atomic<bool> failed{false};
  std::mutex mutex;
  std::exception_ptr failure;
  LaneOccupancy occupancy;

  void report(const std::vector<std::int64_t>& indices, const std::vector<RealisationOutcome>& outcomes,
              const LaneOccupancy& counted) {
    std::lock_guard<std::mutex> lock(mutex);
    occupancy.lane_steps += counted.lane_steps;
    occupancy.stopped_lane_steps += counted.stopped_lane_steps;
    occupancy.stopped_while_waiting += counted.stopped_while_waiting;
    if (failure || indices.empty()) return;
    on_done(indices, outcomes);
  }
  void fail() {
    std::lock_guard<std::mutex> lock(mutex);
    if (!failure) failure = std::current_exception();
    failed = true;
  }
};

// One thread's block with refill: lanes of any motion, each on its own clock, reading the
// whole-run table; a lane that stopped or ran out its steps is replaced at the end of the chunk.
template <class Lanes>
void run_refilled(Shared& shared, const std::vector<std::int64_t>& queue) {
  const MotionTables& tables = shared.tables;
  const int batch = batch_width(shared.options.isa);
  auto claim = [&]() -> std::int64_t {
    const std::size_t k = shared.next.fetch_add(1);
    return k < queue.size() ? queue[k] : -1;
  };
  const std::int64_t first = claim();
  if (first < 0) return;
  Lanes lanes(shared.plan, std::max(1, std::min<int>(shared.options.lanes, static_cast<int>(queue.size()))));
  const MotionTables::Components table = {tables.data(0), tables.data(1), tables.data(2)};
  lanes.load(0, first, tables.offset(shared.plan.realisation(first).motion));
  for (int l = 1; l < lanes.width(); ++l) {
    const std::int64_t i = claim();
    if (i < 0) break;
    lanes.load(l, i, tables.offset(shared.plan.realisation(i).motion));
  }
  for (int l = 1; l < lanes.width(); ++l) {
    if (!lanes.holds(l)) lanes.empty(l);
  }
  if (lanes.block().lane_count() > lanes.width()) lanes.block().pad_from(0);
  std::vector<std::int64_t> indices;
  std::vector<RealisationOutcome> outcomes;
  while (!shared.failed) {
    indices.clear();
    outcomes.clear();
    for (int l = 0; l < lanes.width(); ++l) {
      if (!lanes.holds(l)) continue;
      const std::int64_t steps = tables.steps(lanes.motion(l));
      if (lanes.running(l) && lanes.block().clock(l) < static_cast<double>(steps)) continue;
      indices.push_back(lanes.realisation(l));
      outcomes.push_back(lanes.harvest(l, steps));
      const std::int64_t i = claim();
      if (i >= 0) {
        lanes.load(l, i, tables.offset(shared.plan.realisation(i).motion));
      } else {
        lanes.empty(l);
      }
    }
    park_idle(lanes);
    // The chunk ends where the first running lane ends its run, so that none runs past it.
    std::int64_t chunk = kChunk;
    bool any = false;
    for (int l = 0; l < lanes.width(); ++l) {
      if (!lanes.running(l)) continue;
      any = true;
      chunk = std::min(chunk, tables.steps(lanes.motion(l)) - static_cast<std::int64_t>(lanes.block().clock(l)));
    }
    LaneOccupancy counted;
    if (any) count(lanes, static_cast<int>(chunk), batch, shared.next.load() < queue.size(), counted);
    shared.report(indices, outcomes, counted);
    if (!any) break;
    lanes.advance(shared.options.isa, table, 0, static_cast<int>(chunk));
  }
}

// One block of one motion in lockstep, on table motion sampled chunk by chunk, until all its
// lanes have stopped or run out their steps.
template <class Lanes>
void run_lockstep(Shared& shared, int motion, const std::vector<std::int64_t>& indices) {
  const EnsemblePlan& plan = shared.plan;
  const Model& model = plan.model();
  const int batch = batch_width(shared.options.isa);
  Lanes lanes(plan, static_cast<int>(indices.size()));
  for (int l = 0; l < lanes.width(); ++l) lanes.load(l, indices[l], 0);
  if (lanes.block().lane_count() > lanes.width()) lanes.block().pad_from(0);
  const std::int64_t steps = shared.tables.steps(motion);
  std::vector<double> sampled[3];
  MotionTables::Components table = {};
  for (int c = 0; c < 3; ++c) {
    if (!plan.component(motion, c)) continue;
    sampled[c].resize(kChunk);
    table[c] = sampled[c].data();
  }
  LaneOccupancy counted;
  for (std::int64_t first = 0; first < steps && !lanes.block().all_stopped() && !shared.failed; first += kChunk) {
    const int n = static_cast<int>(std::min<std::int64_t>(kChunk, steps - first));
    for (int c = 0; c < 3; ++c) {
      if (table[c]) motion::sample_acceleration(*plan.component(motion, c), model.time_step, first, n, sampled[c].data());
    }
    count(lanes, n, batch, shared.next.load() < shared.blocks, counted);
    lanes.advance(shared.options.isa, table, first, n);
  }
  std::vector<RealisationOutcome> outcomes;
  for (int l = 0; l < lanes.width(); ++l) outcomes.push_back(lanes.harvest(l, steps));
  shared.report(indices, outcomes, counted);
}

}  // namespace

MotionTables::MotionTables(const EnsemblePlan& plan, std::int64_t budget_bytes) {
  std::int64_t total = 0;
  bool present[3] = {};
  for (int m = 0; m < plan.motion_count(); ++m) {
    offset_.push_back(total);
    steps_.push_back(static_cast<std::int64_t>(std::ceil(plan.run_duration(m) / plan.model().time_step)));
    total += steps_.back();
    for (int c = 0; c < 3; ++c) present[c] = present[c] || plan.component(m, c);
  }
  length_ = total;
  const int components = int(present[0]) + int(present[1]) + int(present[2]);
  if (double(total) * components * sizeof(double) > double(budget_bytes)) return;
  for (int c = 0; c < 3; ++c) {
    if (!present[c]) continue;
    // A motion without this component (a 3D ensemble mixing sets and single records) reads zeros.
    table_[c].assign(static_cast<std::size_t>(total), 0.0);
    for (int m = 0; m < plan.motion_count(); ++m) {
      const motion::TableMotion* component = plan.component(m, c);
      if (!component) continue;
      for (std::int64_t first = 0; first < steps_[m]; first += kChunk) {
        const int count = static_cast<int>(std::min<std::int64_t>(kChunk, steps_[m] - first));
        motion::sample_acceleration(*component, plan.model().time_step, first, count, &table_[c][offset_[m] + first]);
      }
    }
  }
}

void run_realisations(const EnsemblePlan& plan, const MotionTables& tables, const std::vector<std::int64_t>& realisations,
                      const RunOptions& options, const OutcomeSink& on_done, LaneOccupancy* occupancy) {
  if (options.device) {
    options.device->run(realisations, on_done, occupancy);
    return;
  }
  Shared shared(plan, tables, options, on_done);
  if (options.refill && tables.whole()) {
#pragma omp parallel num_threads(options.threads)
    {
      try {
        if (plan.three_d()) {
          run_refilled<Lanes3D>(shared, realisations);
        } else {
          run_refilled<Lanes2D>(shared, realisations);
        }
      } catch (...) {
        shared.fail();
      }
    }
  } else {
    // Blocks of neighbouring realisations of one motion: lanes of one intensity tend to stop together.
    std::vector<std::vector<std::int64_t>> by_motion(plan.motion_count());
    for (std::int64_t i : realisations) by_motion[plan.realisation(i).motion].push_back(i);
    std::vector<std::pair<int, std::vector<std::int64_t>>> blocks;
    const auto width = static_cast<std::size_t>(std::max(1, options.lanes));
    for (int m = 0; m < plan.motion_count(); ++m) {
      const auto& list = by_motion[m];
      for (std::size_t first = 0; first < list.size(); first += width) {
        blocks.push_back({m, {list.begin() + first, list.begin() + std::min(list.size(), first + width)}});
      }
    }
    shared.blocks = blocks.size();
#pragma omp parallel num_threads(options.threads)
    for (std::size_t b = shared.next.fetch_add(1); b < blocks.size(); b = shared.next.fetch_add(1)) {
      if (shared.failed) break;  // stop starting blocks once something failed
      try {
        if (plan.three_d()) {
          run_lockstep<Lanes3D>(shared, blocks[b].first, blocks[b].second);
        } else {
          run_lockstep<Lanes2D>(shared, blocks[b].first, blocks[b].second);
        }
      } catch (...) {
        shared.fail();
      }
    }
  }
  if (occupancy) {
    occupancy->lane_steps += shared.occupancy.lane_steps;
    occupancy->stopped_lane_steps += shared.occupancy.stopped_lane_steps;
    occupancy->stopped_while_waiting += shared.occupancy.stopped_while_waiting;
  }
  if (shared.failure) std::rethrow_exception(shared.failure);
}

}  // namespace caskdem
