#include "sim/rigid_equivalent.h"

#include <algorithm>
#include <cmath>

namespace caskdem {

theory::RigidBlock rigid_equivalent(const Model& model, const RealisationParameters& p) {
  // A corner of rounding radius r rolls like a pivot at its arc centre: the centre of mass's
  // height above the floor is R cos(alpha - theta) + r, the rigid block's plus a constant.
  double left = 1e300, right = -1e300, pivot_height = 0.0;
  for (int k = 0; k < model.corner_count; ++k) {
    if (model.corner_rest_gap[k] > 1e-12) continue;
    left = std::min(left, model.corner_x[k]);
    right = std::max(right, model.corner_x[k]);
    pivot_height = model.corner_y[k];
  }
  theory::RigidBlock block;
  block.half_width = 0.5 * (right - left);
  block.centre_height = p.centre_of_mass.y - pivot_height;
  block.inertia_about_pivot_per_mass =
      p.inertia / p.mass + block.half_width * block.half_width + block.centre_height * block.centre_height;
  block.gravity = model.gravity;
  return block;
}

}  // namespace caskdem
