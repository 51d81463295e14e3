#include "kernels/block3d.h"

#include <cmath>
#include <stdexcept>

#include "kernels/block3d_kernel.h"

namespace caskdem {

namespace {
using Architectures = xsimd::arch_list<xsimd::avx512f, xsimd::avx2, xsimd::sse2>;
std::int64_t padded(std::int64_t lanes) { return (lanes + kLaneAlignment - 1) / kLaneAlignment * kLaneAlignment; }
}  // namespace

LaneBlock3D::LaneBlock3D(std::int64_t lanes) : lane_count_(padded(lanes)), used_lanes_(lanes) {
  if (lanes <= 0) throw std::invalid_argument("a lane block needs at least one lane");
  body_offset_ = LaneParameters<double>::field_count * lane_count_;
  sliders_offset_ = body_offset_ + BodyState3D<double>::field_count * lane_count_;
  response_offset_ = sliders_offset_ + kContactSliders3D * ContactState3D<double>::field_count * lane_count_;
  incidence_offset_ = response_offset_ + Response3D<double>::field_count * lane_count_;
  clock_offset_ = incidence_offset_ + 2 * lane_count_;
  storage_.assign(static_cast<std::size_t>(clock_offset_ + lane_count_), 0.0);
  table_index_.assign(static_cast<std::size_t>(lane_count_), 0);
}

BlockView3D LaneBlock3D::view() {
  double* base = storage_.data();
  return {lane_count_,           base,                     base + body_offset_, base + sliders_offset_,
          base + response_offset_, base + incidence_offset_, base + clock_offset_, table_index_.data()};
}

void LaneBlock3D::set_lane(std::int64_t lane, const LaneParameters<double>& parameters, const BodyState3D<double>& body,
                           const ContactState3D<double>* sliders, const Response3D<double>& response, double incidence) {
  const BlockView3D v = view();
  const std::int64_t stride = lane_count_;
  auto put = [&](double* base, auto s) {
    int field = 0;
    s.for_each_field([&](double& value) { base[(field++) * stride + lane] = value; });
  };
  put(v.parameters, parameters);
  put(v.body, body);
  for (int k = 0; k < kContactSliders3D; ++k) put(v.sliders + k * ContactState3D<double>::field_count * stride, sliders[k]);
  put(v.response, response);
  v.incidence[lane] = std::cos(incidence);
  v.incidence[stride + lane] = std::sin(incidence);
}

void LaneBlock3D::get_lane(std::int64_t lane, BodyState3D<double>* body, ContactState3D<double>* sliders,
                           Response3D<double>* response) const {
  const double* base = storage_.data();
  const std::int64_t stride = lane_count_;
  auto get = [&](const double* field_base, auto* s) {
    if (!s) return;
    int field = 0;
    s->for_each_field([&](double& value) { value = field_base[(field++) * stride + lane]; });
  };
  get(base + body_offset_, body);
  if (sliders) {
    for (int k = 0; k < kContactSliders3D; ++k) {
      get(base + sliders_offset_ + k * ContactState3D<double>::field_count * stride, &sliders[k]);
    }
  }
  get(base + response_offset_, response);
}

void LaneBlock3D::set_clock(std::int64_t lane, double step, std::int64_t table_index) {
  storage_[clock_offset_ + lane] = step;
  table_index_[lane] = table_index;
}

void LaneBlock3D::stop_as_copy(std::int64_t lane, std::int64_t source_lane) {
  const std::int64_t stride = lane_count_;
  // Every array is [field][lane]: copy each field's value across.
  for (std::int64_t offset = 0; offset < clock_offset_ + stride; offset += stride) {
    storage_[offset + lane] = storage_[offset + source_lane];
  }
  table_index_[lane] = table_index_[source_lane];
  storage_[response_offset_ + lane] = double(LaneStatus::tipped_over);  // stopped: never advanced
}

void LaneBlock3D::pad_from(std::int64_t source_lane) {
  for (std::int64_t lane = used_lanes_; lane < lane_count_; ++lane) stop_as_copy(lane, source_lane);
}

double LaneBlock3D::clock(std::int64_t lane) const { return storage_[clock_offset_ + lane]; }

double LaneBlock3D::status(std::int64_t lane) const { return storage_[response_offset_ + lane]; }

bool LaneBlock3D::all_stopped() const {
  for (std::int64_t lane = 0; lane < used_lanes_; ++lane) {
    if (status(lane) == 0.0) return false;
  }
  return true;
}

void advance_block3d(InstructionSet isa, const Model& model, const Contacts3D& contacts, LaneBlock3D& block,
                     const double* table_h1, const double* table_h2, const double* table_vertical,
                     std::int64_t first_step, int step_count) {
  if (isa != InstructionSet::automatic && isa != InstructionSet::scalar && !instruction_set_available(isa)) {
    throw std::runtime_error("instruction set " + instruction_set_name(isa) + " is not available on this machine");
  }
  const BlockView3D view = block.view();
  const kernels::AdvanceBlock3D kernel;
  switch (isa) {
    case InstructionSet::automatic:
      xsimd::dispatch<Architectures>(kernel)(model, contacts, view, table_h1, table_h2, table_vertical, first_step, step_count);
      break;
    case InstructionSet::avx512f:
      kernel(xsimd::avx512f{}, model, contacts, view, table_h1, table_h2, table_vertical, first_step, step_count);
      break;
    case InstructionSet::avx2:
      kernel(xsimd::avx2{}, model, contacts, view, table_h1, table_h2, table_vertical, first_step, step_count);
      break;
    case InstructionSet::sse2:
      kernel(xsimd::sse2{}, model, contacts, view, table_h1, table_h2, table_vertical, first_step, step_count);
      break;
    case InstructionSet::scalar:
      kernels::advance_lanes3d_for_law<double>(model, contacts, view, table_h1, table_h2, table_vertical, first_step, step_count);
      break;
  }
}

}  // namespace caskdem
