#include "kernels/block.h"

#include <stdexcept>

#include "kernels/block_kernel.h"

namespace caskdem {

namespace {
using Architectures = xsimd::arch_list<xsimd::avx512f, xsimd::avx2, xsimd::sse2>;

std::int64_t padded(std::int64_t lanes) { return (lanes + kLaneAlignment - 1) / kLaneAlignment * kLaneAlignment; }
}  // namespace

std::string instruction_set_name(InstructionSet isa) {
  switch (isa) {
    case InstructionSet::automatic: return "automatic";
    case InstructionSet::avx512f: return "avx512f";
    case InstructionSet::avx2: return "avx2";
    case InstructionSet::sse2: return "sse2";
    case InstructionSet::scalar: return "scalar";
  }
  return "unknown";
}

InstructionSet parse_instruction_set(const std::string& name) {
  for (InstructionSet isa : {InstructionSet::automatic, InstructionSet::avx512f, InstructionSet::avx2,
                             InstructionSet::sse2, InstructionSet::scalar}) {
    if (instruction_set_name(isa) == name) return isa;
  }
  throw std::invalid_argument("unknown instruction set \"" + name + "\" (expected automatic, avx512f, avx2, sse2 or scalar)");
}

bool instruction_set_available(InstructionSet isa) {
  const auto available = xsimd::available_architectures();
  switch (isa) {
    case InstructionSet::avx512f: return available.avx512f;
    case InstructionSet::avx2: return available.avx2;
    case InstructionSet::sse2: return available.sse2;
    case InstructionSet::automatic:
    case InstructionSet::scalar: return true;
  }
  return false;
}

InstructionSet best_instruction_set() {
  if (instruction_set_available(InstructionSet::avx512f)) return InstructionSet::avx512f;
  if (instruction_set_available(InstructionSet::avx2)) return InstructionSet::avx2;
  if (instruction_set_available(InstructionSet::sse2)) return InstructionSet::sse2;
  return InstructionSet::scalar;
}

LaneBlock::LaneBlock(std::int64_t lanes, int corner_count)
    : lane_count_(padded(lanes)), used_lanes_(lanes), corner_count_(corner_count) {
  if (lanes <= 0) throw std::invalid_argument("a lane block needs at least one lane");
  if (corner_count < 1 || corner_count > kMaxCorners) throw std::invalid_argument("corner count out of range");
  parameters_offset_ = 0;
  body_offset_ = parameters_offset_ + LaneParameters<double>::field_count * lane_count_;
  corners_offset_ = body_offset_ + BodyState<double>::field_count * lane_count_;
  response_offset_ = corners_offset_ + std::int64_t(corner_count) * CornerState<double>::field_count * lane_count_;
  clock_offset_ = response_offset_ + Response<double>::field_count * lane_count_;
  const std::int64_t total = clock_offset_ + lane_count_;
  storage_.assign(static_cast<std::size_t>(total), 0.0);
  table_index_.assign(static_cast<std::size_t>(lane_count_), 0);
}

BlockView LaneBlock::view() {
  double* base = storage_.data();
  return {lane_count_,           base + parameters_offset_, base + body_offset_, base + corners_offset_,
          base + response_offset_, base + clock_offset_,      table_index_.data()};
}

void LaneBlock::set_clock(std::int64_t lane, double step, std::int64_t table_index) {
  storage_[clock_offset_ + lane] = step;
  table_index_[lane] = table_index;
}

double LaneBlock::clock(std::int64_t lane) const { return storage_[clock_offset_ + lane]; }

double LaneBlock::status(std::int64_t lane) const { return storage_[response_offset_ + lane]; }

void LaneBlock::set_lane(std::int64_t lane, const LaneParameters<double>& parameters, const BodyState<double>& body,
                         const CornerState<double>* corners, const Response<double>& response) {
  BlockView v = view();
  const std::int64_t stride = lane_count_;
  auto put = [&](double* base, auto s) {
    int field = 0;
    s.for_each_field([&](double& value) { base[(field++) * stride + lane] = value; });
  };
  put(v.parameters, parameters);
  put(v.body, body);
  for (int k = 0; k < corner_count_; ++k) put(v.corners + k * CornerState<double>::field_count * stride, corners[k]);
  put(v.response, response);
}

void LaneBlock::get_lane(std::int64_t lane, LaneParameters<double>* parameters, BodyState<double>* body,
                         CornerState<double>* corners, Response<double>* response) const {
  const double* base = storage_.data();
  const std::int64_t stride = lane_count_;
  auto get = [&](const double* field_base, auto* s) {
    if (!s) return;
    int field = 0;
    s->for_each_field([&](double& value) { value = field_base[(field++) * stride + lane]; });
  };
  get(base + parameters_offset_, parameters);
  get(base + body_offset_, body);
  if (corners) {
    for (int k = 0; k < corner_count_; ++k) {
      get(base + corners_offset_ + k * CornerState<double>::field_count * stride, &corners[k]);
    }
  }
  get(base + response_offset_, response);
}

void LaneBlock::pad_from(std::int64_t source_lane) {
  LaneParameters<double> parameters;
  BodyState<double> body;
  CornerState<double> corners[kMaxCorners];
  Response<double> response;
  get_lane(source_lane, &parameters, &body, corners, &response);
  response.status = double(LaneStatus::tipped_over);  // any stopped status: the lane is never advanced
  for (std::int64_t lane = used_lanes_; lane < lane_count_; ++lane) {
    set_lane(lane, parameters, body, corners, response);
    set_clock(lane, clock(source_lane), table_index_[source_lane]);
  }
}

bool LaneBlock::all_stopped() const {
  const double* status = storage_.data() + response_offset_;  // status is the first response field
  for (std::int64_t lane = 0; lane < used_lanes_; ++lane) {
    if (status[lane] == 0.0) return false;
  }
  return true;
}

void advance_block(InstructionSet isa, const Model& model, LaneBlock& block, const double* table_horizontal,
                   const double* table_vertical, std::int64_t first_step, int step_count) {
  if (block.corner_count() != model.corner_count) throw std::invalid_argument("block and model disagree on corners");
  if (isa != InstructionSet::automatic && isa != InstructionSet::scalar && !instruction_set_available(isa)) {
    throw std::runtime_error("instruction set " + instruction_set_name(isa) + " is not available on this machine");
  }
  const BlockView view = block.view();
  const kernels::AdvanceBlock kernel;
  switch (isa) {
    case InstructionSet::automatic:
      xsimd::dispatch<Architectures>(kernel)(model, view, table_horizontal, table_vertical, first_step, step_count);
      break;
    case InstructionSet::avx512f:
      kernel(xsimd::avx512f{}, model, view, table_horizontal, table_vertical, first_step, step_count);
      break;
    case InstructionSet::avx2:
      kernel(xsimd::avx2{}, model, view, table_horizontal, table_vertical, first_step, step_count);
      break;
    case InstructionSet::sse2:
      kernel(xsimd::sse2{}, model, view, table_horizontal, table_vertical, first_step, step_count);
      break;
    case InstructionSet::scalar:
      kernels::advance_lanes_for_law<double>(model, view, table_horizontal, table_vertical, first_step, step_count);
      break;
  }
}

}  // namespace caskdem
