#pragma once
// The shipped case files, loaded for tests, and small helpers around a run.

#include <cstdint>
#include <string>

#include "casefile/case_file.h"
#include "model/build.h"
#include "sim/case_run.h"
#include "sim/simulate.h"

namespace caskdem::testing {

inline std::string case_path(const std::string& name) { return std::string(CASKDEM_SOURCE_DIR) + "/cases/" + name; }
inline std::string motion_path(const std::string& name) { return std::string(CASKDEM_SHARED_DIR) + "/motions/" + name; }

// The source paper's 1/3 model cask, as shipped.
inline Case one_third_model() { return load_case(case_path("model-1-3-sine.toml")); }

// The slider schemes a validation runs with: the source paper's half-step one and the whole-step
// one (kernels/slider.h); each check holds for both, with the same tolerance.
inline constexpr std::int32_t kBothSliders[] = {0, kWholeStepSlider};

struct Prepared {
  Model model;
  LaneParameters<double> lane;
};

inline Prepared prepare(const Case& c) {
  Prepared p{build_model(c.model, c.parameters), {}};
  p.lane = lane_parameters(p.model, c.parameters);
  return p;
}

}  // namespace caskdem::testing
