// Queued lanes on a CUDA GPU (kernels/lane_device.h): one realisation per thread, each thread
// running run_queued_lane (kernels/queue_lanes.h) with the scalar step, the same source as the
// CPU's reference path; claims and finished rows by atomic adds on two counters.
//
// Bit for bit with the CPU. The build gives nvcc -fmad=false (no multiply-add contracted, as
// -ffp-contract=off on the host), IEEE division and square root (-prec-div=true,
// -prec-sqrt=true), no flush of subnormals (-ftz=false), and the step uses no device intrinsic:
// its sin, cos and exp are the project's own (kernels/portable_math.h), so every operation is
// an exact or correctly rounded IEEE one, as on the CPU (cmake/Cuda.cmake).
//
// Memory. The model and the 3D contacts live in device memory, read by every thread at the
// same address (broadcast); the motions' tables, read-only, every motion's whole run; the
// lanes, the pending ring and the finished list as rows over their capacity, so that the
// threads of a warp touch neighbouring addresses. A lane's state stays in registers (and the
// stack frame) for a whole launch.

#include <cuda_runtime.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/lane_device.h"
#include "kernels/queue_lanes.h"

namespace caskdem {

namespace {

constexpr int kThreadsPerBlock = 128;

void check(cudaError_t status, const char* what) {
  if (status != cudaSuccess) throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(status));
}

// Counters: [0] queue positions claimed, [1] finished rows written in this launch.
template <class Lane, FrictionLaw Law>
__global__ void __launch_bounds__(kThreadsPerBlock)
    advance_queued_lanes(const Model* __restrict__ model, const Contacts3D* __restrict__ contacts, QueueView q,
                         int steps, long long tail, unsigned long long* counters) {
  const long long lane = static_cast<long long>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (lane >= q.shape.lanes) return;
  auto claim = [&]() -> std::int64_t {
    const unsigned long long k = atomicAdd(&counters[0], 1ull);
    return k < static_cast<unsigned long long>(tail) ? static_cast<std::int64_t>(k) : -1;
  };
  auto finish = [&]() -> std::int64_t { return static_cast<std::int64_t>(atomicAdd(&counters[1], 1ull)); };
  run_queued_lane<Lane, Law>(*model, contacts, q, lane, steps, claim, finish);
}

// Device memory for `count` numbers, freed with the object.
template <class Number>
class DeviceArray {
 public:
  DeviceArray() = default;
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  ~DeviceArray() { release(); }
  void allocate(std::size_t count, const char* what) {
    release();
    if (count == 0) return;
    check(cudaMalloc(reinterpret_cast<void**>(&data_), count * sizeof(Number)), what);
    count_ = count;
  }
  Number* data() const { return data_; }
  std::size_t count() const { return count_; }

 private:
  void release() {
    if (data_) cudaFree(data_);
    data_ = nullptr;
    count_ = 0;
  }
  Number* data_ = nullptr;
  std::size_t count_ = 0;
};

class CudaLaneDevice final : public LaneDevice {
 public:
  explicit CudaLaneDevice(const CudaDeviceInfo& info) : info_(info) {
    check(cudaSetDevice(info.ordinal), "cudaSetDevice");
    model_.allocate(1, "model");
    contacts_.allocate(1, "3D contacts");
    counters_.allocate(2, "counters");
  }

  std::string name() const override {
    return info_.name + " (CUDA device " + std::to_string(info_.ordinal) + ", compute " +
           std::to_string(info_.compute_major) + "." + std::to_string(info_.compute_minor) + ", " +
           std::to_string(info_.multiprocessors) + " multiprocessors, " + std::to_string(info_.memory_bytes >> 30) +
           " GiB)";
  }

  std::int64_t lane_capacity(int dimensions, FrictionLaw law) const override {
    int blocks = 0;
    visit_lane_kind(dimensions, law, [&](auto lane_kind, auto law_constant) {
      using Lane = typename decltype(lane_kind)::type;
      check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(
                &blocks, advance_queued_lanes<Lane, decltype(law_constant)::value>, kThreadsPerBlock, 0),
            "cudaOccupancyMaxActiveBlocksPerMultiprocessor");
    });
    return std::int64_t(blocks > 0 ? blocks : 1) * kThreadsPerBlock * info_.multiprocessors;
  }

  void set_tables(const double* const table[3], std::int64_t table_length) override {
    for (int c = 0; c < 3; ++c) {
      if (!table[c]) {
        table_[c].allocate(0, "table");
        continue;
      }
      table_[c].allocate(std::size_t(table_length), "the motions' tables");
      check(cudaMemcpy(table_[c].data(), table[c], table_length * sizeof(double), cudaMemcpyHostToDevice),
            "copying the motions' tables");
    }
  }

  void configure(const QueueShape& shape, const Model& model, const Contacts3D* contacts) override {
    shape_ = shape;
    friction_law_ = model.friction_law;
    check(cudaMemcpy(model_.data(), &model, sizeof(Model), cudaMemcpyHostToDevice), "copying the model");
    const Contacts3D none{};
    check(cudaMemcpy(contacts_.data(), contacts ? contacts : &none, sizeof(Contacts3D), cudaMemcpyHostToDevice),
          "copying the 3D contacts");
    lanes_.allocate(std::size_t(shape.lane_rows() * shape.lanes), "lanes");
    lane_index_.allocate(std::size_t(kLaneIndexRows * shape.lanes), "lanes");
    pending_.allocate(std::size_t(shape.record_rows() * shape.pending), "pending realisations");
    pending_index_.allocate(std::size_t(kPendingIndexRows * shape.pending), "pending realisations");
    finished_.allocate(std::size_t(shape.record_rows() * shape.finished), "finished realisations");
    finished_index_.allocate(std::size_t(kFinishedIndexRows * shape.finished), "finished realisations");
    check(cudaMemset(lane_index_.data(), 0, lane_index_.count() * sizeof(std::int64_t)), "clearing the lanes");
    // All bits set: -1, no realisation held.
    check(cudaMemset(lane_index_.data() + kHeldRow * shape.lanes, 0xff, shape.lanes * sizeof(std::int64_t)),
          "emptying the lanes");
    check(cudaMemset(counters_.data(), 0, 2 * sizeof(unsigned long long)), "clearing the counters");
  }

  void write_pending(std::int64_t first, std::int64_t count, const double* records,
                     const std::int64_t* indices) override {
    if (count <= 0) return;
    if (first < 0 || first + count > shape_.pending) throw std::out_of_range("pending columns outside the ring");
    copy_rows(pending_.data() + first, shape_.pending, records, count, shape_.record_rows(), count,
              cudaMemcpyHostToDevice);
    copy_rows(pending_index_.data() + first, shape_.pending, indices, count, kPendingIndexRows, count,
              cudaMemcpyHostToDevice);
  }

  LaunchCounters launch(int steps, std::int64_t tail) override {
    check(cudaMemset(counters_.data() + 1, 0, sizeof(unsigned long long)), "clearing the finished count");
    const QueueView q = view();
    const auto blocks = static_cast<unsigned>((shape_.lanes + kThreadsPerBlock - 1) / kThreadsPerBlock);
    visit_lane_kind(shape_.dimensions, friction_law_, [&](auto lane_kind, auto law) {
      using Lane = typename decltype(lane_kind)::type;
      advance_queued_lanes<Lane, decltype(law)::value><<<blocks, kThreadsPerBlock>>>(
          model_.data(), contacts_.data(), q, steps, static_cast<long long>(tail), counters_.data());
    });
    check(cudaGetLastError(), "launching the lanes");
    unsigned long long counters[2] = {};
    check(cudaMemcpy(counters, counters_.data(), sizeof counters, cudaMemcpyDeviceToHost), "the lanes' launch");
    return {static_cast<std::int64_t>(counters[0]), static_cast<std::int64_t>(counters[1])};
  }

  void read_finished(std::int64_t count, double* records, std::int64_t* indices) override {
    if (count <= 0) return;
    copy_rows(records, count, finished_.data(), shape_.finished, shape_.record_rows(), count, cudaMemcpyDeviceToHost);
    copy_rows(indices, count, finished_index_.data(), shape_.finished, kFinishedIndexRows, count,
              cudaMemcpyDeviceToHost);
  }

  void set_claimed(std::int64_t claimed) override {
    const auto value = static_cast<unsigned long long>(claimed);
    check(cudaMemcpy(counters_.data(), &value, sizeof value, cudaMemcpyHostToDevice), "setting the claim counter");
  }

  double busy_steps() override {
    std::vector<std::int64_t> busy(std::size_t(shape_.lanes));
    check(cudaMemcpy(busy.data(), lane_index_.data() + kBusyStepsRow * shape_.lanes, busy.size() * sizeof(std::int64_t),
                     cudaMemcpyDeviceToHost),
          "reading the lanes' step counts");
    double total = 0.0;
    for (std::int64_t b : busy) total += double(b);
    return total;
  }

 private:
  // `rows` rows of `count` numbers between two row arrays of the given strides (in numbers).
  template <class Number>
  static void copy_rows(Number* target, std::int64_t target_stride, const Number* source, std::int64_t source_stride,
                        int rows, std::int64_t count, cudaMemcpyKind kind) {
    check(cudaMemcpy2D(target, target_stride * sizeof(Number), source, source_stride * sizeof(Number),
                       count * sizeof(Number), rows, kind),
          "copying realisations");
  }

  QueueView view() const {
    QueueView q;
    q.shape = shape_;
    q.lanes = {lanes_.data(), shape_.lanes};
    q.lane_index = {lane_index_.data(), shape_.lanes};
    q.pending = {pending_.data(), shape_.pending};
    q.pending_index = {pending_index_.data(), shape_.pending};
    q.finished = {finished_.data(), shape_.finished};
    q.finished_index = {finished_index_.data(), shape_.finished};
    for (int c = 0; c < 3; ++c) q.table[c] = table_[c].data();
    return q;
  }

  CudaDeviceInfo info_;
  QueueShape shape_;
  FrictionLaw friction_law_ = FrictionLaw::constant;
  DeviceArray<Model> model_;
  DeviceArray<Contacts3D> contacts_;
  DeviceArray<unsigned long long> counters_;
  DeviceArray<double> table_[3];
  DeviceArray<double> lanes_, pending_, finished_;
  DeviceArray<std::int64_t> lane_index_, pending_index_, finished_index_;
};

// The oldest architecture the build has machine code or PTX for (cmake/Cuda.cmake: sm_90).
constexpr int kLowestComputeMajor = 9;

}  // namespace

bool cuda_compiled() { return true; }

std::vector<CudaDeviceInfo> cuda_devices(std::string* why_none) {
  std::vector<CudaDeviceInfo> devices;
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess) {
    if (why_none) {
      int runtime = 0;
      cudaRuntimeGetVersion(&runtime);
      const std::string version = std::to_string(runtime / 1000) + "." + std::to_string(runtime % 1000 / 10);
      *why_none = status == cudaErrorInsufficientDriver
                      ? "no CUDA driver on this machine, or one older than this build's CUDA " + version + " runtime"
                  : status == cudaErrorNoDevice ? std::string("no CUDA device")
                                                : std::string("CUDA found no device: ") + cudaGetErrorString(status);
    }
    return devices;
  }
  std::string skipped;
  for (int ordinal = 0; ordinal < count; ++ordinal) {
    cudaDeviceProp properties{};
    if (cudaGetDeviceProperties(&properties, ordinal) != cudaSuccess) continue;
    if (properties.major < kLowestComputeMajor) {
      skipped += (skipped.empty() ? "" : "; ") + std::string(properties.name) + " has compute capability " +
                 std::to_string(properties.major) + "." + std::to_string(properties.minor) +
                 ", this build runs on 9.0 (Hopper) and later";
      continue;
    }
    CudaDeviceInfo info{ordinal, properties.name, properties.major, properties.minor, properties.multiProcessorCount,
                        static_cast<std::int64_t>(properties.totalGlobalMem)};
    int clock_khz = 0, fp32_to_fp64 = 0;
    cudaDeviceGetAttribute(&clock_khz, cudaDevAttrClockRate, ordinal);
    cudaDeviceGetAttribute(&fp32_to_fp64, cudaDevAttrSingleToDoublePrecisionPerfRatio, ordinal);
    info.clock_hz = 1e3 * clock_khz;
    // 128 single-precision lanes a multiprocessor since Volta; the ratio gives the double ones
    // (64 on the H100 and H200, 2 on gaming cards).
    info.fp64_per_clock_per_multiprocessor = fp32_to_fp64 > 0 ? 128 / fp32_to_fp64 : 0;
    devices.push_back(info);
  }
  if (devices.empty() && why_none) *why_none = count == 0 ? "no CUDA device" : "no usable CUDA device: " + skipped;
  return devices;
}

std::unique_ptr<LaneDevice> open_cuda_device(int ordinal) {
  std::string why;
  for (const CudaDeviceInfo& info : cuda_devices(&why)) {
    if (info.ordinal == ordinal) return std::make_unique<CudaLaneDevice>(info);
  }
  throw std::runtime_error("CUDA device " + std::to_string(ordinal) + " cannot be used" +
                           (why.empty() ? "" : ": " + why));
}

}  // namespace caskdem
