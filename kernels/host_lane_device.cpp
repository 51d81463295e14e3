// The host in a GPU's place (kernels/lane_device.h): the queued lanes' arrays in host memory and
// each launch one lane after another, the same run_queued_lane a GPU thread runs, compiled by
// the host compiler. It answers for the GPU's host side in tests where no GPU is present: the
// ring, the claims, the finished list and the chunking between launches.

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "kernels/lane_device.h"
#include "kernels/queue_lanes.h"

namespace caskdem {

namespace {

class HostLaneDevice final : public LaneDevice {
 public:
  explicit HostLaneDevice(std::int64_t lanes) : lanes_(lanes) {
    if (lanes < 1) throw std::invalid_argument("a host lane device needs at least one lane");
  }

  std::string name() const override { return "host (" + std::to_string(lanes_) + " lanes, one after another)"; }

  std::int64_t lane_capacity(int, FrictionLaw) const override { return lanes_; }

  void set_tables(const double* const table[3], std::int64_t table_length) override {
    for (int c = 0; c < 3; ++c) {
      if (table[c]) {
        table_[c].assign(table[c], table[c] + table_length);
      } else {
        table_[c].clear();
      }
    }
  }

  void configure(const QueueShape& shape, const Model& model, const Contacts3D* contacts) override {
    shape_ = shape;
    model_ = model;
    spatial_ = contacts ? *contacts : Contacts3D{};
    lanes_data_.assign(std::size_t(shape.lane_rows() * shape.lanes), 0.0);
    lane_index_.assign(std::size_t(kLaneIndexRows * shape.lanes), 0);
    std::fill_n(lane_index_.begin() + kHeldRow * shape.lanes, shape.lanes, std::int64_t(-1));
    pending_.assign(std::size_t(shape.record_rows() * shape.pending), 0.0);
    pending_index_.assign(std::size_t(kPendingIndexRows * shape.pending), 0);
    finished_.assign(std::size_t(shape.record_rows() * shape.finished), 0.0);
    finished_index_.assign(std::size_t(kFinishedIndexRows * shape.finished), 0);
    claimed_ = 0;
  }

  void write_pending(std::int64_t first, std::int64_t count, const double* records,
                     const std::int64_t* indices) override {
    if (first < 0 || first + count > shape_.pending) throw std::out_of_range("pending columns outside the ring");
    copy_columns(records, count, 0, pending_.data(), shape_.pending, first, shape_.record_rows(), count);
    copy_columns(indices, count, 0, pending_index_.data(), shape_.pending, first, kPendingIndexRows, count);
  }

  LaunchCounters launch(int steps, std::int64_t tail) override {
    const QueueView q = view();
    std::int64_t finished = 0;
    auto claim = [&]() -> std::int64_t {
      const std::int64_t k = claimed_++;
      return k < tail ? k : -1;
    };
    auto finish = [&]() -> std::int64_t {
      if (finished >= shape_.finished)
        throw std::logic_error("a launch finished more realisations than its list holds");
      return finished++;
    };
    const Contacts3D* spatial = shape_.dimensions == 3 ? &spatial_ : nullptr;
    visit_lane_kind(shape_.dimensions, model_.friction_law, [&](auto lane_kind, auto law) {
      using Lane = typename decltype(lane_kind)::type;
      for (std::int64_t lane = 0; lane < shape_.lanes; ++lane) {
        run_queued_lane<Lane, decltype(law)::value>(model_, spatial, q, lane, steps, claim, finish);
      }
    });
    return {claimed_, finished};
  }

  void read_finished(std::int64_t count, double* records, std::int64_t* indices) override {
    copy_columns(finished_.data(), shape_.finished, 0, records, count, 0, shape_.record_rows(), count);
    copy_columns(finished_index_.data(), shape_.finished, 0, indices, count, 0, kFinishedIndexRows, count);
  }

  void set_claimed(std::int64_t claimed) override { claimed_ = claimed; }

  double busy_steps() override {
    double total = 0.0;
    for (std::int64_t lane = 0; lane < shape_.lanes; ++lane)
      total += double(lane_index_[kBusyStepsRow * shape_.lanes + lane]);
    return total;
  }

 private:
  // `rows` rows of `count` columns from (source, stride, first column) to (target, stride, first column).
  template <class Number>
  static void copy_columns(const Number* source, std::int64_t source_stride, std::int64_t source_first, Number* target,
                           std::int64_t target_stride, std::int64_t target_first, int rows, std::int64_t count) {
    for (int row = 0; row < rows; ++row) {
      std::copy_n(source + row * source_stride + source_first, count, target + row * target_stride + target_first);
    }
  }

  QueueView view() {
    QueueView q;
    q.shape = shape_;
    q.lanes = {lanes_data_.data(), shape_.lanes};
    q.lane_index = {lane_index_.data(), shape_.lanes};
    q.pending = {pending_.data(), shape_.pending};
    q.pending_index = {pending_index_.data(), shape_.pending};
    q.finished = {finished_.data(), shape_.finished};
    q.finished_index = {finished_index_.data(), shape_.finished};
    for (int c = 0; c < 3; ++c) q.table[c] = table_[c].empty() ? nullptr : table_[c].data();
    return q;
  }

  std::int64_t lanes_;
  QueueShape shape_;
  Model model_;
  Contacts3D spatial_;
  std::vector<double> table_[3];
  std::vector<double> lanes_data_, pending_, finished_;
  std::vector<std::int64_t> lane_index_, pending_index_, finished_index_;
  std::int64_t claimed_ = 0;
};

}  // namespace

std::unique_ptr<LaneDevice> open_host_lane_device(std::int64_t lanes) {
  return std::make_unique<HostLaneDevice>(lanes);
}

}  // namespace caskdem
