#pragma once
// The similarity law of the source paper's shaking-table tests (a 1/N model of a prototype
// cask), stated so that every ratio follows from three choices (model / prototype):
//   acceleration 1 (gravity cannot be scaled), length 1/N, stress 1
// (the same materials carry the same stresses; the paper's models reach it by adding lead:
// density ratio N). From these, time = sqrt(length / acceleration) = 1/sqrt(N) and
// mass = stress * length^2 / acceleration = 1/N^2. A quantity of dimension
// M^a L^b T^c then scales by N^-(2a + b + c/2):
//   velocity 1/sqrt(N), frequency sqrt(N), force 1/N^2, mass 1/N^2, density N,
//   moment of inertia 1/N^4, spring constant 1/N, distributed stiffness (N/m^3) N,
//   damping coefficient beta (s) 1/sqrt(N); angles, friction and restitution 1.
// The paper's Tab. 1 prints weight 1/N^3 in its general form but 1/9 for N = 3; the 12.6 t
// 1/3 model of a ~113 t prototype matches 1/N^2, the law above.
// A prototype motion is applied to the model with its time axis compressed by sqrt(N).

#include <string>
#include <vector>

namespace caskdem {

struct DimensionExponents {
  double mass = 0.0;
  double length = 0.0;
  double time = 0.0;
};

// model / prototype ratio of a quantity with these dimensions, for a 1/N model. Throws
// std::invalid_argument unless N is positive and the ratio is finite and non-zero.
double similarity_ratio(double scale_n, DimensionExponents dimensions);

struct SimilarityRow {
  std::string quantity;
  DimensionExponents dimensions;
};
// The quantities docs/model.md ("Similarity law") and `caskdem similarity` list.
const std::vector<SimilarityRow>& similarity_table();

}  // namespace caskdem
