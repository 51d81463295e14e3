#pragma once
// Where queued lanes run (kernels/queue_lanes.h): a CUDA GPU, one lane per thread
// (kernels/cuda/cuda_lane_device.cu), or this machine's CPU, one lane after another with the
// same code in place of the GPU (kernels/host_lane_device.cpp), which tests the host's side of a
// GPU run where no GPU is present. The host (src/ensemble/device_runner.h) keeps the ring of
// pending realisations filled and reads the finished ones between launches; a device holds the
// model, the motions' tables, the lanes' state and the three arrays of a QueueView.
//
// Every array crosses as rows (kernels/queue_lanes.h): `rows` x `count` numbers, row-major, that
// fill columns [first, first + count) of the device's rows of the same kind.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "kernels/model.h"
#include "kernels/model3d.h"
#include "kernels/queue_lanes.h"

namespace caskdem {

// What a launch left on the device's counters.
struct LaunchCounters {
  std::int64_t claimed = 0;   // queue positions handed out so far (may pass the tail: the host clamps it)
  std::int64_t finished = 0;  // finished rows written by this launch
};

class LaneDevice {
 public:
  virtual ~LaneDevice() = default;
  // What it is, for the run's header and the result file ("NVIDIA H100 80GB HBM3 (CUDA device 0,
  // sm_90, 132 multiprocessors)").
  virtual std::string name() const = 0;
  // How many lanes it advances at once for this cask and friction law (a GPU: as many threads
  // as stay resident on all its multiprocessors).
  virtual std::int64_t lane_capacity(int dimensions, FrictionLaw law) const = 0;
  // The motions' tables for every run that follows: H1, H2 and the vertical, each
  // `table_length` long (every motion's whole run, end to end), null where absent.
  virtual void set_tables(const double* const table[3], std::int64_t table_length) = 0;
  // A run: its shape, the model and the 3D cask's contacts (null for a planar cask); every lane
  // empty, the counters zero.
  virtual void configure(const QueueShape& shape, const Model& model, const Contacts3D* contacts) = 0;
  // Columns [first, first + count) of the pending ring, from host rows (record_rows() and
  // kPendingIndexRows rows of `count`).
  virtual void write_pending(std::int64_t first, std::int64_t count, const double* records,
                             const std::int64_t* indices) = 0;
  // Every lane advanced by up to `steps` steps, claiming queue positions below `tail`; the
  // finished count restarts at zero. Returns the counters once the launch has ended.
  virtual LaunchCounters launch(int steps, std::int64_t tail) = 0;
  // The first `count` finished rows of the last launch, into host rows of `count`.
  virtual void read_finished(std::int64_t count, double* records, std::int64_t* indices) = 0;
  // The claim counter set back to `claimed` (to the tail, after claims that found nothing).
  virtual void set_claimed(std::int64_t claimed) = 0;
  // Steps the lanes advanced realisations, summed over lanes, since configure().
  virtual double busy_steps() = 0;
};

// This build's CUDA engine: whether it was compiled in, the GPUs present, and one of them.
struct CudaDeviceInfo {
  int ordinal = 0;
  std::string name;
  int compute_major = 0, compute_minor = 0;
  int multiprocessors = 0;
  std::int64_t memory_bytes = 0;
  double clock_hz = 0.0;             // the multiprocessors' peak clock
  int fp64_per_clock_per_multiprocessor = 0;  // double-precision operations each issues a cycle
  // Peak double-precision rate, flop/s, counting a fused multiply-add as two (as datasheets do).
  double fp64_peak() const { return 2.0 * fp64_per_clock_per_multiprocessor * multiprocessors * clock_hz; }
};
bool cuda_compiled();
// The CUDA devices this process sees; empty with the reason in *why_none when there are none
// (no CUDA in this build, no driver, no device).
std::vector<CudaDeviceInfo> cuda_devices(std::string* why_none);
// Throws std::runtime_error when it cannot be opened.
std::unique_ptr<LaneDevice> open_cuda_device(int ordinal);

// The host in a GPU's place: `lanes` lanes advanced one after another by the scalar step.
std::unique_ptr<LaneDevice> open_host_lane_device(std::int64_t lanes);

}  // namespace caskdem
