// Validation 4, calibration: `calibrate` finds the damping ratio whose free vibration gives a
// target rocking restitution within 0.002, for targets 0.90 .. 0.97. Which targets a cask can
// reach is physics, not tuning: between Housner's rigid-impact value (heavy damping) and the
// undamped springs' elastic exchange. The source paper's 1/3 model reaches 0.93 .. 0.97 (its
// measured 0.963 among them); a stockier section of the same cask reaches 0.88 .. 0.94.

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "sim/free_vibration.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

Case stockier_cask() {
  Case c = testing::one_third_model();
  Cylinder cylinder = c.cask.cylinder;
  cylinder.height = 1.5;  // alpha 0.30 instead of 0.23
  cylinder.mass = 8743.0 * std::acos(-1.0) / 4.0 * cylinder.diameter * cylinder.diameter * cylinder.height;
  c.model.section = cylinder_section(cylinder, c.model.section.rounding);
  c.parameters = [&] {
    RealisationParameters p = c.parameters;
    const RealisationParameters mass = nominal_parameters(c.model);
    p.mass = mass.mass;
    p.inertia = mass.inertia;
    p.centre_of_mass = mass.centre_of_mass;
    return p;
  }();
  return c;
}

void expect_calibrated(const Case& c, double target) {
  const CalibrationResult result = calibrate_damping(c, target);
  // The reached value is a fresh free-vibration run at the returned h, not the solver's estimate.
  const Model model = build_model(c.model, c.parameters);
  RealisationParameters p = c.parameters;
  p.damping_ratio = result.damping_ratio;
  const double reached = free_vibration(model, p, c.free_vibration).restitution;
  EXPECT_NEAR(reached, target, 0.002) << "h = " << result.damping_ratio;
  EXPECT_NEAR(result.restitution, reached, 1e-15);
  ::testing::Test::RecordProperty("h_for_" + std::to_string(target), std::to_string(result.damping_ratio));
  ::testing::Test::RecordProperty("error_for_" + std::to_string(target), std::to_string(reached - target));
}

TEST(Calibration, PaperModelReachesTargetsUpTo097) {
  const Case c = testing::one_third_model();
  for (double target : {0.94, 0.95, 0.963, 0.97}) expect_calibrated(c, target);
}

TEST(Calibration, StockierCaskReachesTargetsDownTo090) {
  const Case c = stockier_cask();
  for (double target : {0.90, 0.91, 0.92}) expect_calibrated(c, target);
}

TEST(Calibration, UnreachableTargetIsRefusedWithTheRange) {
  const Case c = stockier_cask();
  try {
    (void)calibrate_damping(c, 0.99);
    FAIL() << "0.99 cannot be reached by this cask";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("out of reach"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("model-1-3-sine.toml"));
  }
}

}  // namespace
}  // namespace caskdem
