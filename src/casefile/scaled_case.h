#pragma once
// A case transformed by the similarity law (src/model/similarity.h): scaled_case(c, N) is
// the 1/N model of c (N > 1 shrinks; N = 1/3 gives the prototype of a 1/3 model). Every
// dimensional input is multiplied by its ratio; angles, friction coefficients and damping
// ratios are unchanged; a motion's time axis is compressed by sqrt(N) (records through
// similarity_scale, sines and pulses directly).

#include "casefile/case_file.h"

namespace caskdem {

Case scaled_case(const Case& c, double scale_n);

}  // namespace caskdem
