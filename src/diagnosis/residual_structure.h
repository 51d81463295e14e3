#pragma once
// Where the calibrated baseline disagrees: its residuals set against what each mechanism
// would change (amplitude, sliding speed, impact speed, rotation sign, vertical
// acceleration, a lag in time), each row pointing to the mechanisms it suggests. A pointer
// for people reading the report, not a test: the ranking decides.

#include <vector>

#include "diagnosis/diagnose.h"

namespace caskdem::diagnosis {

std::vector<StructureRow> residual_structure(const MeasuredSet& set, const std::vector<TestReference>& references,
                                             const ModelFit& baseline, const Model& model,
                                             const std::vector<SimulatedHistory>& histories);

}  // namespace caskdem::diagnosis
