#pragma once
// The per-instruction-set kernel behind advance_block3d(), as kernels/block_kernel.h is for
// the planar block: block3d_avx512f.cpp, block3d_avx2.cpp and block3d_sse2.cpp instantiate it
// with their own flags, block3d.cpp dispatches.

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "kernels/block3d.h"
#include "kernels/block_kernel.h"
#include "kernels/step3d.h"

namespace caskdem::kernels {

template <FrictionLaw Law, class T>
void advance_lanes3d(const Model& model, const Contacts3D& contacts, BlockView3D block, const double* table_h1,
                     const double* table_h2, const double* table_vertical, std::int64_t first_step, int step_count) {
  constexpr std::int64_t width = static_cast<std::int64_t>(lane::width<T>);
  const std::int64_t stride = block.lane_count;
  const std::int64_t slider_stride = ContactState3D<T>::field_count * stride;
  for (std::int64_t lane_index = 0; lane_index < block.lane_count; lane_index += width) {
    auto response = load_fields<T, Response3D<T>>(block.response, stride, lane_index);
    if (lane::all(response.status != lane::broadcast<T>(0.0))) continue;
    const auto parameters = load_fields<T, LaneParameters<T>>(block.parameters, stride, lane_index);
    auto body = load_fields<T, BodyState3D<T>>(block.body, stride, lane_index);
    ContactState3D<T> sliders[kContactSliders3D];
    for (int k = 0; k < kContactSliders3D; ++k) {
      sliders[k] = load_fields<T, ContactState3D<T>>(block.sliders + k * slider_stride, stride, lane_index);
    }
    const T cosine = lane::load<T>(block.incidence + lane_index);
    const T sine = lane::load<T>(block.incidence + stride + lane_index);
    T clock = lane::load<T>(block.clock + lane_index);
    lane::Index<T> table_index = lane::load_index<T>(block.table_index + lane_index);
    const lane::Index<T> first = lane::Index<T>(first_step);
    const lane::Index<T> one_index = lane::Index<T>(1);
    const T one = lane::broadcast<T>(1.0), zero = lane::broadcast<T>(0.0);
    const T dt = lane::broadcast<T>(model.time_step);
    for (int n = 0; n < step_count; ++n) {
      const lane::Index<T> at = table_index - first;
      const T a1 = lane::gather<T>(table_h1, at);
      const T a2 = table_h2 ? lane::gather<T>(table_h2, at) : zero;
      const T vertical = table_vertical ? lane::gather<T>(table_vertical, at) : zero;
      const T table_x = cosine * a1 - sine * a2, table_z = sine * a1 + cosine * a2;
      step3d<Law>(model, contacts, parameters, table_x, vertical, table_z, clock * dt, body, sliders, response);
      clock = clock + one;
      table_index = table_index + one_index;
      if (lane::all(response.status != lane::broadcast<T>(0.0))) break;
    }
    lane::store(block.clock + lane_index, clock);
    lane::store_index(block.table_index + lane_index, table_index);
    store_fields<T>(body, block.body, stride, lane_index);
    for (int k = 0; k < kContactSliders3D; ++k) store_fields<T>(sliders[k], block.sliders + k * slider_stride, stride, lane_index);
    store_fields<T>(response, block.response, stride, lane_index);
  }
}

template <class T>
void advance_lanes3d_for_law(const Model& model, const Contacts3D& contacts, BlockView3D block, const double* h1,
                             const double* h2, const double* vertical, std::int64_t first_step, int step_count) {
  switch (model.friction_law) {
    case FrictionLaw::constant:
      advance_lanes3d<FrictionLaw::constant, T>(model, contacts, block, h1, h2, vertical, first_step, step_count);
      break;
    case FrictionLaw::static_kinetic:
      advance_lanes3d<FrictionLaw::static_kinetic, T>(model, contacts, block, h1, h2, vertical, first_step, step_count);
      break;
    case FrictionLaw::exponential:
      advance_lanes3d<FrictionLaw::exponential, T>(model, contacts, block, h1, h2, vertical, first_step, step_count);
      break;
    case FrictionLaw::tabulated:
      advance_lanes3d<FrictionLaw::tabulated, T>(model, contacts, block, h1, h2, vertical, first_step, step_count);
      break;
  }
}

struct AdvanceBlock3D {
  template <class Arch>
  void operator()(Arch, const Model& model, const Contacts3D& contacts, BlockView3D block, const double* h1,
                  const double* h2, const double* vertical, std::int64_t first_step, int step_count) const;
};

// Defined out of the class, so that it is not implicitly inline: the extern declarations below
// then keep every translation unit but its own instruction set's from instantiating it.
template <class Arch>
void AdvanceBlock3D::operator()(Arch, const Model& model, const Contacts3D& contacts, BlockView3D block, const double* h1,
                                const double* h2, const double* vertical, std::int64_t first_step, int step_count) const {
  advance_lanes3d_for_law<xsimd::batch<double, Arch>>(model, contacts, block, h1, h2, vertical, first_step, step_count);
}

#define CASKDEM_ADVANCE_BLOCK3D(ARCH)                                                                            \
  template void AdvanceBlock3D::operator()<xsimd::ARCH>(xsimd::ARCH, const Model&, const Contacts3D&, BlockView3D, \
                                                         const double*, const double*, const double*, std::int64_t, int) const
extern CASKDEM_ADVANCE_BLOCK3D(avx512f);
extern CASKDEM_ADVANCE_BLOCK3D(avx2);
extern CASKDEM_ADVANCE_BLOCK3D(sse2);

}  // namespace caskdem::kernels
