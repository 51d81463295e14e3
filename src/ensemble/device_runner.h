#pragma once
// Realisations on a GPU: queued lanes (kernels/queue_lanes.h), one realisation per thread, on a
// LaneDevice (kernels/lane_device.h). The host side of the run lives here:
//
//   - the ring of pending realisations: each started from the plan as the CPU engine starts it
//     (ensemble/lane_io.h), written to the device ahead of the lanes that will claim it;
//   - launches of a number of steps each (chunks), adapted so that a launch takes about a
//     quarter of a second, between which the finished realisations are read back, their outcomes
//     made as the CPU engine makes them and handed to the sink: the caller's checkpoint runs
//     between launches, and a run stopped part-way keeps what has finished;
//   - the device's choice: `--device auto|cpu|cuda` (and [run] device).
//
// A realisation's outcome is the same bits as on the CPU, whatever lane, launch or chunk it ran
// in: its step is the scalar reference's, and the lanes read the same tables at the same steps.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "kernels/lane_device.h"

namespace caskdem {

enum class DeviceKind { automatic, cpu, cuda };
std::string device_kind_name(DeviceKind kind);          // "auto", "cpu", "cuda"
DeviceKind parse_device_kind(const std::string& name);  // throws std::invalid_argument

// The device a run takes, or null for the CPU's SIMD engine. automatic: the first usable CUDA
// device (the one at `preferred` among several, an MPI rank's local rank), else the CPU; cuda:
// that device, or an InputError that says why there is none, naming `source` (the option or
// the ensemble file's key that asked for it).
std::unique_ptr<LaneDevice> open_device(DeviceKind kind, int preferred, const std::string& source);

class DeviceLanes {
 public:
  // The motions' tables go to the device once, whole (every motion's every step).
  DeviceLanes(const EnsemblePlan& plan, const MotionTables& tables, LaneDevice& device);
  DeviceLanes(const DeviceLanes&) = delete;
  DeviceLanes& operator=(const DeviceLanes&) = delete;

  std::string name() const { return device_.name(); }
  std::int64_t lane_capacity() const;

  // How the work is cut (tests): lanes and ring capacity (0: the device's and twice that), steps
  // per launch (0: adapted to about 0.25 s a launch).
  struct Tuning {
    std::int64_t lanes = 0;
    std::int64_t ring = 0;
    int steps_per_launch = 0;
  };
  void set_tuning(const Tuning& tuning) { tuning_ = tuning; }

  // Runs the realisations; on_done gets them as they finish, between launches, on this thread
  // (it may throw to stop the run). Adds to *occupancy when given: lane-steps offered by the
  // launches, and those on lanes without a realisation.
  void run(const std::vector<std::int64_t>& realisations, const OutcomeSink& on_done,
           LaneOccupancy* occupancy = nullptr);

  // What the runs so far cost on the device (bench/bench_device.cpp).
  struct Statistics {
    int launches = 0;
    double launch_seconds = 0.0;  // in launches: the steps and the counters read back
    double busy_steps = 0.0;      // realisation-steps advanced
    double lane_steps = 0.0;      // lane-steps the launches offered
  };
  const Statistics& statistics() const { return statistics_; }

 private:
  const EnsemblePlan& plan_;
  const MotionTables& tables_;
  LaneDevice& device_;
  Tuning tuning_;
  Statistics statistics_;
};

}  // namespace caskdem
