#pragma once
// A block of 3D realisations (kernels/step3d.h) in structure-of-arrays form, as the planar
// block (kernels/block.h): one realisation per lane, each field of LaneParameters,
// BodyState3D, the two spring-sliders (ContactState3D) and Response3D one aligned array over
// the lanes, with each lane's incidence (the direction of H1 in the floor plane) and clock.
// advance_block3d() loops over time outside and SIMD batches inside; the instruction set is
// chosen at run time or forced, and every choice gives the same bits.

#include <cstdint>
#include <vector>

#include <xsimd/xsimd.hpp>

#include "kernels/block.h"
#include "kernels/lane_state.h"
#include "kernels/lane_state3d.h"
#include "kernels/model.h"
#include "kernels/model3d.h"

namespace caskdem {

struct BlockView3D {
  std::int64_t lane_count = 0;  // a multiple of kLaneAlignment
  double* parameters = nullptr;  // [field][lane]
  double* body = nullptr;        // [field][lane]
  double* sliders = nullptr;     // [slider][field][lane]
  double* response = nullptr;    // [field][lane]
  double* incidence = nullptr;   // [cos, sin][lane]
  double* clock = nullptr;       // [lane]
  std::int64_t* table_index = nullptr;  // [lane]
};

class LaneBlock3D {
 public:
  explicit LaneBlock3D(std::int64_t lanes);

  std::int64_t lane_count() const { return lane_count_; }  // padded
  std::int64_t used_lanes() const { return used_lanes_; }

  // incidence: rad, the direction of the H1 table component from x towards z.
  void set_lane(std::int64_t lane, const LaneParameters<double>& parameters, const BodyState3D<double>& body,
                const ContactState3D<double>* sliders, const Response3D<double>& response, double incidence);
  void get_lane(std::int64_t lane, BodyState3D<double>* body, ContactState3D<double>* sliders,
                Response3D<double>* response) const;
  void pad_from(std::int64_t source_lane);  // padding lanes copy a real one, stopped
  // The lane holds a copy of source_lane, stopped: an empty lane that is never advanced and
  // whose numbers stay finite in the batch it rides in.
  void stop_as_copy(std::int64_t lane, std::int64_t source_lane);
  void set_clock(std::int64_t lane, double step, std::int64_t table_index);
  double clock(std::int64_t lane) const;
  double status(std::int64_t lane) const;  // LaneStatus as a number
  bool all_stopped() const;                // of the used lanes

  BlockView3D view();

 private:
  std::int64_t lane_count_, used_lanes_;
  std::vector<double, xsimd::aligned_allocator<double, 64>> storage_;
  std::vector<std::int64_t, xsimd::aligned_allocator<std::int64_t, 64>> table_index_;
  std::int64_t body_offset_, sliders_offset_, response_offset_, incidence_offset_, clock_offset_;
};

// Advances every lane step_count steps, as advance_block: a lane at its step c is at time c dt
// and reads the tables at [i - first_step], i its table index. The table's H1 and H2 are turned
// by the lane's incidence, a_x = a_1 cos - a_2 sin, a_z = a_1 sin + a_2 cos (sim/simulate3d.h);
// table_h2 and table_vertical may be null.
void advance_block3d(InstructionSet isa, const Model& model, const Contacts3D& contacts, LaneBlock3D& block,
                     const double* table_h1, const double* table_h2, const double* table_vertical,
                     std::int64_t first_step, int step_count);

}  // namespace caskdem
