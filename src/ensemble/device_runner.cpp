#include "ensemble/device_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "core/error.h"
#include "ensemble/lane_io.h"

namespace caskdem {

namespace {

constexpr double kLaunchSeconds = 0.25;  // what the adapted launches aim at
constexpr int kFirstLaunchSteps = 2048, kFewestLaunchSteps = 256, kMostLaunchSteps = 1 << 20;

// A realisation's record (kernels/queue_lanes.h: parameters, body, response, incidence) into
// column `column` of rows of `stride`.
template <class Start>
void put_record(Start& start, double* rows, std::int64_t stride, std::int64_t column) {
  int row = 0;
  auto put = [&](double& v) { rows[(row++) * stride + column] = v; };
  start.parameters.for_each_field(put);
  start.body.for_each_field(put);
  start.response.for_each_field(put);
  if constexpr (std::is_same_v<Start, LaneStart3D>) {
    put(start.incidence_cos);
    put(start.incidence_sin);
  }
}

// The parameters, body and response of column `column` of a finished record's rows.
template <class Body, class Result>
void get_record(const double* rows, std::int64_t stride, std::int64_t column, LaneParameters<double>& parameters,
                Body& body, Result& response) {
  int row = 0;
  auto get = [&](double& v) { v = rows[(row++) * stride + column]; };
  parameters.for_each_field(get);
  body.for_each_field(get);
  response.for_each_field(get);
}

}  // namespace

std::string device_kind_name(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::automatic: return "auto";
    case DeviceKind::cpu: return "cpu";
    case DeviceKind::cuda: return "cuda";
  }
  return "unknown";
}

DeviceKind parse_device_kind(const std::string& name) {
  for (DeviceKind kind : {DeviceKind::automatic, DeviceKind::cpu, DeviceKind::cuda}) {
    if (device_kind_name(kind) == name) return kind;
  }
  throw std::invalid_argument("unknown device \"" + name + "\" (expected auto, cpu or cuda)");
}

std::unique_ptr<LaneDevice> open_device(DeviceKind kind, int preferred, const std::string& source) {
  if (kind == DeviceKind::cpu) return nullptr;
  std::string why;
  const std::vector<CudaDeviceInfo> devices = cuda_devices(&why);
  if (devices.empty()) {
    if (kind == DeviceKind::automatic) return nullptr;
    throw InputError(source + ": no GPU to run on: " + why + "; expected auto or cpu");
  }
  const CudaDeviceInfo& chosen = devices[static_cast<std::size_t>(std::max(0, preferred)) % devices.size()];
  try {
    return open_cuda_device(chosen.ordinal);
  } catch (const std::runtime_error& e) {
    if (kind == DeviceKind::automatic) return nullptr;
    throw InputError(source + ": no GPU to run on: " + e.what() + "; expected auto or cpu");
  }
}

DeviceLanes::DeviceLanes(const EnsemblePlan& plan, const MotionTables& tables, LaneDevice& device)
    : plan_(plan), tables_(tables), device_(device) {
  if (!tables.whole()) {
    throw std::invalid_argument(
        "the GPU engine needs every motion's whole run in one table, and the motions' tables "
        "exceeded their memory budget");
  }
  const double* table[3] = {tables.data(0), tables.data(1), tables.data(2)};
  device_.set_tables(table, tables.length());
}

std::int64_t DeviceLanes::lane_capacity() const {
  if (tuning_.lanes > 0) return tuning_.lanes;
  return device_.lane_capacity(plan_.three_d() ? 3 : 2, plan_.model().friction_law);
}

void DeviceLanes::run(const std::vector<std::int64_t>& realisations, const OutcomeSink& on_done,
                      LaneOccupancy* occupancy) {
  const auto total = static_cast<std::int64_t>(realisations.size());
  if (total == 0) return;
  const bool three_d = plan_.three_d();
  QueueShape shape;
  shape.dimensions = three_d ? 3 : 2;
  shape.contact_count = three_d ? kContactSliders3D : plan_.model().corner_count;
  shape.lanes = std::min(total, std::max<std::int64_t>(1, lane_capacity()));
  shape.pending = std::min(total, tuning_.ring > 0 ? tuning_.ring : 2 * std::max<std::int64_t>(shape.lanes, 1024));
  shape.finished = shape.lanes + shape.pending;
  device_.configure(shape, plan_.model(), three_d ? &plan_.model3d().contacts : nullptr);
  const int record_rows = shape.record_rows();

  // Queue position k holds realisations[k]; positions [claimed, tail) are in the ring, unclaimed.
  std::int64_t tail = 0, claimed = 0, done = 0;
  std::vector<double> records, finished;
  std::vector<std::int64_t> indices, positions;
  std::vector<std::int64_t> outcome_index;
  std::vector<RealisationOutcome> outcomes;
  int steps = tuning_.steps_per_launch > 0 ? tuning_.steps_per_launch : kFirstLaunchSteps;
  double busy_before = device_.busy_steps();
  while (done < total) {
    // Fill the ring up to the positions the lanes have freed, in at most two runs of slots.
    const std::int64_t limit = std::min(total, claimed + shape.pending);
    while (tail < limit) {
      const std::int64_t first = tail % shape.pending;
      const std::int64_t count = std::min(limit - tail, shape.pending - first);
      records.assign(std::size_t(record_rows * count), 0.0);
      indices.assign(std::size_t(kPendingIndexRows * count), 0);
      std::exception_ptr failure;
#pragma omp parallel for schedule(static)
      for (std::int64_t c = 0; c < count; ++c) {
        try {
          const std::int64_t index = realisations[std::size_t(tail + c)];
          int motion = 0;
          if (three_d) {
            LaneStart3D start = lane_start3d(plan_, index);
            put_record(start, records.data(), count, c);
            motion = start.motion;
          } else {
            LaneStart start = lane_start(plan_, index);
            put_record(start, records.data(), count, c);
            motion = start.motion;
          }
          indices[std::size_t(kTableOffsetRow * count + c)] = tables_.offset(motion);
          indices[std::size_t(kStepsRow * count + c)] = tables_.steps(motion);
        } catch (...) {
#pragma omp critical
          if (!failure) failure = std::current_exception();
        }
      }
      if (failure) std::rethrow_exception(failure);
      device_.write_pending(first, count, records.data(), indices.data());
      tail += count;
    }

    const auto started = std::chrono::steady_clock::now();
    const LaunchCounters counters = device_.launch(steps, tail);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    // Claims that found the ring empty counted past the tail: set the counter back.
    claimed = std::min(counters.claimed, tail);
    if (counters.claimed != claimed) device_.set_claimed(claimed);

    const std::int64_t count = counters.finished;
    if (count < 0 || count > shape.finished)
      throw std::runtime_error("the device reported an impossible finished count");
    finished.assign(std::size_t(record_rows * count), 0.0);
    positions.assign(std::size_t(kFinishedIndexRows * count), 0);
    device_.read_finished(count, finished.data(), positions.data());
    outcome_index.assign(std::size_t(count), 0);
    outcomes.assign(std::size_t(count), RealisationOutcome{});
    for (std::int64_t c = 0; c < count; ++c) {
      const std::int64_t position = positions[std::size_t(kPositionRow * count + c)];
      if (position < 0 || position >= tail) throw std::runtime_error("the device finished a realisation it never held");
      const std::int64_t index = realisations[std::size_t(position)];
      const std::int64_t run_steps = tables_.steps(plan_.motion_of(index));
      LaneParameters<double> parameters;
      outcome_index[std::size_t(c)] = index;
      if (three_d) {
        BodyState3D<double> body;
        Response3D<double> response;
        get_record(finished.data(), count, c, parameters, body, response);
        outcomes[std::size_t(c)] = lane_outcome3d(plan_, parameters, body, response, run_steps);
      } else {
        BodyState<double> body;
        Response<double> response;
        get_record(finished.data(), count, c, parameters, body, response);
        outcomes[std::size_t(c)] = lane_outcome(plan_, parameters, body, response, run_steps);
      }
    }
    done += count;

    const double busy = device_.busy_steps();
    const double offered = double(shape.lanes) * steps;
    const double idle = std::max(0.0, offered - (busy - busy_before));
    statistics_.launches += 1;
    statistics_.launch_seconds += seconds;
    statistics_.busy_steps += busy - busy_before;
    statistics_.lane_steps += offered;
    busy_before = busy;
    if (occupancy) {
      occupancy->lane_steps += offered;
      occupancy->stopped_lane_steps += idle;
      // Realisations still waited after the launch: its idle lanes could not take them.
      if (claimed < total) occupancy->stopped_while_waiting += idle;
    }
    if (count > 0) on_done(outcome_index, outcomes);

    if (tuning_.steps_per_launch <= 0 && seconds > 0.0) {
      const double scaled = steps * std::clamp(kLaunchSeconds / seconds, 0.5, 2.0);
      steps = static_cast<int>(std::clamp(scaled, double(kFewestLaunchSteps), double(kMostLaunchSteps)));
    }
  }
}

}  // namespace caskdem
