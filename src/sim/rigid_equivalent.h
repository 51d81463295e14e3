#pragma once
// The rigid block that the DEM section tends to as its contact stiffens: pivots at the
// rounding-arc centres of the outermost standing corners, the section's mass properties.
// Used to compare the DEM with Housner's theory on the same geometry.

#include "kernels/model.h"
#include "model/build.h"
#include "theory/rocking.h"

namespace caskdem {

theory::RigidBlock rigid_equivalent(const Model& model, const RealisationParameters& parameters);

}  // namespace caskdem
