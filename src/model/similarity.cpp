#include "model/similarity.h"

#include <cmath>
#include <stdexcept>

#include "core/text.h"

namespace caskdem {

double similarity_ratio(double scale_n, DimensionExponents d) {
  if (!(scale_n > 0.0)) throw std::invalid_argument("the similarity scale N must be positive");
  const double exponent = -(2.0 * d.mass + d.length + 0.5 * d.time);
  const double ratio = std::pow(scale_n, exponent);
  if (!(std::isfinite(ratio) && ratio > 0.0))
    throw std::invalid_argument("the similarity scale N = " + number_text(scale_n) + " makes the ratio N^" +
                                number_text(exponent) + " overflow or vanish; expected N nearer 1");
  return ratio;
}

const std::vector<SimilarityRow>& similarity_table() {
  static const std::vector<SimilarityRow> rows = {
      {"length", {0, 1, 0}},
      {"time", {0, 0, 1}},
      {"acceleration", {0, 1, -2}},
      {"velocity", {0, 1, -1}},
      {"frequency", {0, 0, -1}},
      {"stress", {1, -1, -2}},
      {"mass", {1, 0, 0}},
      {"density", {1, -3, 0}},
      {"force", {1, 1, -2}},
      {"moment of inertia", {1, 2, 0}},
      {"spring constant (N/m)", {1, 0, -2}},
      {"distributed stiffness (N/m^3)", {1, -2, -2}},
      {"damping coefficient beta (s)", {0, 0, 1}},
      {"angle, friction, restitution", {0, 0, 0}},
      {"angular velocity", {0, 0, -1}},
  };
  return rows;
}

}  // namespace caskdem
