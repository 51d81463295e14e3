#pragma once
// A block of realisations in structure-of-arrays form, and the kernel that advances it.
//
// Each field of LaneParameters, BodyState, CornerState and Response is one aligned array
// over the block's lanes; one realisation is one lane. advance_block() runs a range of
// time steps for the whole block, looping over time outside and over SIMD batches inside,
// so the block's state stays in cache and independent batches overlap in the pipeline.
// The instruction set is chosen at run time (xsimd dispatch over avx512f, avx2, sse2) or
// forced, and every choice gives the same bits (see kernels/lane.h).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <xsimd/xsimd.hpp>

#include "kernels/lane_state.h"
#include "kernels/model.h"

namespace caskdem {

enum class InstructionSet { automatic, avx512f, avx2, sse2, scalar };

std::string instruction_set_name(InstructionSet isa);
InstructionSet parse_instruction_set(const std::string& name);  // throws std::invalid_argument
// The widest instruction set this machine runs, among those compiled in.
InstructionSet best_instruction_set();
bool instruction_set_available(InstructionSet isa);

// Raw view of a block's arrays, what the per-instruction-set kernels receive.
struct BlockView {
  std::int64_t lane_count = 0;  // a multiple of kLaneAlignment
  double* parameters = nullptr;  // [field][lane]
  double* body = nullptr;        // [field][lane]
  double* corners = nullptr;     // [corner][field][lane]
  double* response = nullptr;    // [field][lane]
  double* clock = nullptr;       // [lane]: the lane's own step number (a whole number)
  std::int64_t* table_index = nullptr;  // [lane]: where the lane reads the table motion
};

// Lanes are padded to a multiple of the widest batch (8 doubles, one AVX-512 register).
inline constexpr std::int64_t kLaneAlignment = 8;

class LaneBlock {
 public:
  LaneBlock(std::int64_t lanes, int corner_count);

  std::int64_t lane_count() const { return lane_count_; }      // padded
  std::int64_t used_lanes() const { return used_lanes_; }      // realisations held
  int corner_count() const { return corner_count_; }

  // Scalar access for setting up and reading back one lane.
  void set_lane(std::int64_t lane, const LaneParameters<double>& parameters, const BodyState<double>& body,
                const CornerState<double>* corners, const Response<double>& response);
  void get_lane(std::int64_t lane, LaneParameters<double>* parameters, BodyState<double>* body,
                CornerState<double>* corners, Response<double>* response) const;
  // Padding lanes copy a real lane and are marked stopped, so they cost nothing but never divide by zero.
  void pad_from(std::int64_t source_lane);
  // A lane's clock: the step it is at (0 in a fresh block) and the index at which it reads the
  // table motion (see advance_block). Both advance by one per step.
  void set_clock(std::int64_t lane, double step, std::int64_t table_index);
  double clock(std::int64_t lane) const;
  double status(std::int64_t lane) const;  // LaneStatus as a number

  BlockView view();
  bool all_stopped() const;

 private:
  std::int64_t lane_count_;
  std::int64_t used_lanes_;
  int corner_count_;
  std::vector<double, xsimd::aligned_allocator<double, 64>> storage_;
  std::vector<std::int64_t, xsimd::aligned_allocator<std::int64_t, 64>> table_index_;
  std::int64_t parameters_offset_, body_offset_, corners_offset_, response_offset_, clock_offset_;
};

// Advances every lane of the block by step_count steps. Each lane runs on its own clock: at
// its step c it is at time c dt and reads the table accelerations at [i - first_step], i its
// table index, and both advance by one per step. In a fresh block every lane's clock and
// index are 0, so the lanes run in lockstep and the tables hold steps first_step ..
// first_step + step_count - 1 (calls in turn, first_step advancing). A block whose lanes are
// replaced as they stop (ensemble/runner.h) gives each new lane clock 0 and the index of its
// motion's first step in one table of whole runs, and passes first_step = 0. Each lane scales
// the accelerations by its own factors; table_vertical may be null (no vertical component).
void advance_block(InstructionSet isa, const Model& model, LaneBlock& block, const double* table_horizontal,
                   const double* table_vertical, std::int64_t first_step, int step_count);

}  // namespace caskdem
