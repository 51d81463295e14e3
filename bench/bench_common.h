#pragma once
// What the benchmarks share: the paper's 1/3 model cask, a block of lanes with spread
// parameters, the table motion, and the machine's peak.

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "casefile/case_file.h"
#include "kernels/block.h"
#include "model/build.h"

namespace caskdem::bench {

// The kernel benchmark's work: a block of 64 lanes advanced 20000 steps (about 4 s of the
// 1/3 model's rocking at f_s = 0.01).
constexpr int kKernelLanes = 64;
constexpr int kKernelSteps = 20000;

inline Case paper_model(FrictionLaw law) {
  Case c = load_case(std::string(CASKDEM_SOURCE_DIR) + "/cases/model-1-3-sine.toml");
  c.model.friction_law = law;
  return c;
}

// 1.0 cm at 2.5 Hz, the shipped sine case: the cask rocks, with impacts and some slip.
inline std::vector<double> table_acceleration(double dt, int steps) {
  std::vector<double> a(steps);
  const double omega = 2.0 * 3.141592653589793 * 2.5;
  for (int n = 0; n < steps; ++n) a[n] = 0.01 * omega * omega * std::sin(omega * n * dt);
  return a;
}

// A block whose lanes differ in friction and damping, as an ensemble's do.
inline LaneBlock make_block(const Model& model, const RealisationParameters& nominal, int lanes) {
  LaneBlock block(lanes, model.corner_count);
  for (int l = 0; l < lanes; ++l) {
    RealisationParameters p = nominal;
    p.friction_static = 0.5 + 0.2 * l / lanes;
    p.friction_kinetic = 0.4 + 0.15 * l / lanes;
    p.damping_ratio = 0.01 + 0.05 * l / lanes;
    const LaneParameters<double> lane = lane_parameters(model, p);
    const BodyState<double> body = rest_state(model, lane);
    const CornerState<double> corners[kMaxCorners] = {};
    block.set_lane(l, lane, body, corners, initial_response(lane, body));
  }
  return block;
}

// The clock this machine reports (MHz), for the fraction of peak.
inline double reported_clock_mhz() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("cpu MHz", 0) == 0) return std::stod(line.substr(line.find(':') + 1));
  }
  return 0.0;
}

// Peak double-precision flops per second of one core: two FMA pipes, each a vector of
// `width` doubles doing a multiply and an add per cycle.
inline double core_peak(int width) { return 2.0 * width * 2.0 * reported_clock_mhz() * 1e6; }

inline int width_of(InstructionSet isa) {
  switch (isa) {
    case InstructionSet::avx512f: return 8;
    case InstructionSet::avx2: return 4;
    case InstructionSet::sse2: return 2;
    default: return 1;
  }
}

}  // namespace caskdem::bench
