#include "model/contact_stiffness.h"

#include <cmath>
#include <stdexcept>

namespace caskdem {

DistributedStiffness barkan_stiffness(const BarkanFloor& floor, double base_area) {
  if (!(floor.shear_modulus > 0.0)) throw std::invalid_argument("the shear modulus must be positive");
  if (!(floor.poisson_ratio >= 0.0 && floor.poisson_ratio < 0.5)) {
    throw std::invalid_argument("Poisson's ratio must be in [0, 0.5)");
  }
  if (!(base_area > 0.0)) throw std::invalid_argument("the base area must be positive");
  const double a = std::sqrt(base_area);
  const double normal_total = floor.shear_modulus * floor.beta_z * a / (1.0 - floor.poisson_ratio);
  const double shear_total = 2.0 * (1.0 + floor.poisson_ratio) * floor.shear_modulus * floor.beta_x * a;
  return {normal_total / base_area, shear_total / base_area};
}

}  // namespace caskdem
