#pragma once
// The per-instruction-set kernel behind advance_block(). Each instruction set gets its own
// translation unit (block_avx512f.cpp, block_avx2.cpp, block_sse2.cpp) compiled with its own
// flags, which instantiates AdvanceBlock::operator() for its architecture; block.cpp
// dispatches at run time. Only templates on the architecture's batch type are instantiated
// there, so no function compiled for a wide instruction set is shared with other callers.

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "kernels/block.h"
#include "kernels/lane.h"
#include "kernels/lane_state.h"
#include "kernels/model.h"
#include "kernels/step.h"

namespace caskdem::kernels {

template <class T, class S>
inline S load_fields(const double* base, std::int64_t stride, std::int64_t lane) {
  S s;
  int field = 0;
  s.for_each_field([&](T& value) { value = lane::load<T>(base + (field++) * stride + lane); });
  return s;
}

template <class T, class S>
inline void store_fields(S& s, double* base, std::int64_t stride, std::int64_t lane) {
  int field = 0;
  s.for_each_field([&](T& value) { lane::store(base + (field++) * stride + lane, value); });
}

template <FrictionLaw Law, class T>
void advance_lanes(const Model& model, BlockView block, const double* table_horizontal, const double* table_vertical,
                   std::int64_t first_step, int step_count) {
  constexpr std::int64_t width = static_cast<std::int64_t>(lane::width<T>);
  const std::int64_t stride = block.lane_count;
  const std::int64_t corner_stride = CornerState<T>::field_count * stride;
  // One batch at a time through all the steps of the call: its state stays in registers and
  // the stack frame instead of travelling through the block's arrays at every step.
  for (std::int64_t lane_index = 0; lane_index < block.lane_count; lane_index += width) {
    auto response = load_fields<T, Response<T>>(block.response, stride, lane_index);
    if (lane::all(response.status != lane::broadcast<T>(0.0))) continue;
    const auto parameters = load_fields<T, LaneParameters<T>>(block.parameters, stride, lane_index);
    auto body = load_fields<T, BodyState<T>>(block.body, stride, lane_index);
    CornerState<T> corners[kMaxCorners];
    for (int k = 0; k < model.corner_count; ++k) {
      corners[k] = load_fields<T, CornerState<T>>(block.corners + k * corner_stride, stride, lane_index);
    }
    // Each lane on its own clock (kernels/block.h): its time, and its place in the table motion.
    T clock = lane::load<T>(block.clock + lane_index);
    lane::Index<T> table_index = lane::load_index<T>(block.table_index + lane_index);
    const lane::Index<T> first = lane::Index<T>(first_step);
    const lane::Index<T> one_index = lane::Index<T>(1);
    const T one = lane::broadcast<T>(1.0);
    const T dt = lane::broadcast<T>(model.time_step);
    const T no_vertical = lane::broadcast<T>(0.0);
    for (int n = 0; n < step_count; ++n) {
      const lane::Index<T> at = table_index - first;
      const T horizontal = lane::gather<T>(table_horizontal, at);
      const T vertical = table_vertical ? lane::gather<T>(table_vertical, at) : no_vertical;
      step<Law>(model, parameters, horizontal, vertical, clock * dt, body, corners, response);
      clock = clock + one;
      table_index = table_index + one_index;
      // Tipped-over lanes are frozen; once the whole batch has stopped there is nothing to advance.
      if (lane::all(response.status != lane::broadcast<T>(0.0))) break;
    }
    lane::store(block.clock + lane_index, clock);
    lane::store_index(block.table_index + lane_index, table_index);
    store_fields<T>(body, block.body, stride, lane_index);
    for (int k = 0; k < model.corner_count; ++k) {
      store_fields<T>(corners[k], block.corners + k * corner_stride, stride, lane_index);
    }
    store_fields<T>(response, block.response, stride, lane_index);
  }
}

template <class T>
void advance_lanes_for_law(const Model& model, BlockView block, const double* table_horizontal,
                           const double* table_vertical, std::int64_t first_step, int step_count) {
  switch (model.friction_law) {
    case FrictionLaw::constant:
      advance_lanes<FrictionLaw::constant, T>(model, block, table_horizontal, table_vertical, first_step, step_count);
      break;
    case FrictionLaw::static_kinetic:
      advance_lanes<FrictionLaw::static_kinetic, T>(model, block, table_horizontal, table_vertical, first_step, step_count);
      break;
    case FrictionLaw::exponential:
      advance_lanes<FrictionLaw::exponential, T>(model, block, table_horizontal, table_vertical, first_step, step_count);
      break;
    case FrictionLaw::tabulated:
      advance_lanes<FrictionLaw::tabulated, T>(model, block, table_horizontal, table_vertical, first_step, step_count);
      break;
  }
}

struct AdvanceBlock {
  template <class Arch>
  void operator()(Arch, const Model& model, BlockView block, const double* table_horizontal,
                  const double* table_vertical, std::int64_t first_step, int step_count) const;
};

template <class Arch>
void AdvanceBlock::operator()(Arch, const Model& model, BlockView block, const double* table_horizontal,
                              const double* table_vertical, std::int64_t first_step, int step_count) const {
  advance_lanes_for_law<xsimd::batch<double, Arch>>(model, block, table_horizontal, table_vertical, first_step,
                                                    step_count);
}

extern template void AdvanceBlock::operator()<xsimd::avx512f>(xsimd::avx512f, const Model&, BlockView, const double*,
                                                               const double*, std::int64_t, int) const;
extern template void AdvanceBlock::operator()<xsimd::avx2>(xsimd::avx2, const Model&, BlockView, const double*,
                                                            const double*, std::int64_t, int) const;
extern template void AdvanceBlock::operator()<xsimd::sse2>(xsimd::sse2, const Model&, BlockView, const double*,
                                                            const double*, std::int64_t, int) const;

}  // namespace caskdem::kernels
