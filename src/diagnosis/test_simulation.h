#pragma once
// A measured test simulated for many candidate parameter vectors at once: one SIMD lane per
// candidate, the table acceleration of the test (and its vertical channel, when the model
// uses one) as the shared input, rotation and sliding recorded at the test's sample times.

#include <vector>

#include "diagnosis/measured_test.h"
#include "diagnosis/mechanisms.h"
#include "kernels/block.h"

namespace caskdem::diagnosis {

struct SimulatedHistory {
  std::vector<double> rotation;  // rad, at the test's sample times
  std::vector<double> slide;     // m, base centre relative to the floor
  bool tipped_over = false;
};

std::vector<SimulatedHistory> simulate_test(const ModelVariant& variant, const MeasuredTest& test,
                                            const std::vector<std::vector<double>>& points, InstructionSet isa);

}  // namespace caskdem::diagnosis
