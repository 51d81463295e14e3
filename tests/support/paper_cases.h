#pragma once
// The shipped case files, loaded for tests, and small helpers around a run.

#include <cstdint>
#include <cstdio>
#include <string>

#include "casefile/case_file.h"
#include "ensemble/ensemble_file.h"
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

// The schemes a validation against theory runs with: a case's default, the source paper's
// half-step slider at f_s = 0.01; the whole-step slider at the same step; and an ensemble's
// default, the whole-step slider at f_s = 0.05 (ensemble/ensemble_file.h), the step the
// fragilities are computed at. Each check holds for every one, with the same tolerance.
struct Scheme {
  std::int32_t slider = 0;
  double safety_factor = 0.01;
  void apply(Case& c) const {
    c.model.whole_step_terms = slider;
    c.model.safety_factor = safety_factor;
  }
  std::string name() const {
    char step[32];
    std::snprintf(step, sizeof step, "%g", safety_factor);
    return slider_name_of(slider) + " slider at f_s " + step;
  }
};
inline constexpr Scheme kSchemes[] = {{0, 0.01}, {kWholeStepSlider, 0.01}, {kEnsembleSlider, kEnsembleSafetyFactor}};

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
