// The shear spring at a touch (kernels/slider.h, "The spring at a touch") against a convergence
// study. The cask, level and with gravity off, lands at 0.3 m/s with 0.3 m/s of slip on a floor
// whose friction holds (mu = 10: the contact sticks until its normal force fades as it leaves),
// and flies off again; its rotation rate after the impact is the impact's alone (the flight
// exerts nothing), so each step's answer can be set against the finest's. A touch falls anywhere
// within a step: each step lands from 16 heights spread over one step's approach, and the mean of
// its error over them, its bias, is what adds up over the many contacts of an ensemble's rocking
// (docs/time-step.md, "The spring at a touch"); the rest of the error changes sign with where the
// touch falls and averages out.
//  - the whole-step slider's bias is second order in the step;
//  - without the touch rule (the paper's scheme, or the whole-step velocities alone) it is first
//    order and twenty times larger at f_s = 0.02: what the rule removes;
//  - where the contact slips throughout (mu = 0.3) the cap sets the force and the rule changes
//    nothing;
// and the same for the 3D cask's base (its rim and centre). Landing tilted by 0.01 rad, the 3D
// cask first touches on a point of its rim, and the touching arc then widens through the impact:
// the springs that join it within a step take half the step's slip (the trapezoidal rule on the
// arc's stiffness), and the bias falls with the step at order 1.6 (the arc's stiffness grows like
// the square root of the overlap near the touch, which the trapezoid follows less closely); without
// the rule, first order.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/build3d.h"
#include "sim/simulate3d.h"
#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

constexpr double kSpeed = 0.3;   // m/s, towards the floor and along it
constexpr int kHeights = 16;     // touches spread over one step
constexpr double kFinest = 0.0003125;
const std::vector<double> kSteps = {0.04, 0.02, 0.01, 0.005};
constexpr std::int32_t kVelocitiesOnly = kWholeStepSlider & ~kSpringSinceTouch;

Case landing_cask(double safety_factor, std::int32_t slider, double friction) {
  Case c = testing::one_third_model();
  c.model.friction_law = FrictionLaw::constant;
  c.parameters.friction_static = c.parameters.friction_kinetic = friction;
  c.parameters.damping_ratio = 0.02;
  c.model.safety_factor = safety_factor;
  c.model.whole_step_terms = slider;
  return c;
}

// The planar cask's rotation rate after it left the floor, landing from `height` steps' approach.
double planar_spin(double safety_factor, std::int32_t slider, double friction, double height) {
  const Case c = landing_cask(safety_factor, slider, friction);
  Model model = build_model(c.model, c.parameters);
  const LaneParameters<double> lane = lane_parameters(model, c.parameters);
  model.gravity = 0.0;
  BodyState<double> body{};
  body.x = lane.centre_x;
  body.y = lane.centre_y + height * kSpeed * model.time_step;
  body.vx = kSpeed;
  body.vy = -kSpeed;
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const RunResult run = simulate(model, lane, body, {&still, nullptr}, {0.03, model.time_step});
  const std::vector<double>& rotation = run.history.rotation;
  const std::vector<double>& time = run.history.time;
  const std::size_t n = time.size();
  return (rotation[n - 1] - rotation[n - 2]) / (time[n - 1] - time[n - 2]);
}

// The 3D cask's angular momentum about the axis across its slide, likewise, landing level or
// tilted (towards +x, on its rim).
double cylinder_spin_tilted(double safety_factor, std::int32_t slider, double friction, double height, double tilt) {
  const Case c = landing_cask(safety_factor, slider, friction);
  const CaskSpec3D spec{0.5 * c.cask.cylinder.diameter, c.cask.cylinder.height, c.model.section.rounding,
                        c.parameters.mass};
  const RealisationParameters p = nominal_parameters3d(spec, c.parameters);
  Model3D model = build_model3d(c.model, spec, p);
  const LaneParameters<double> lane = lane_parameters3d(model, p);
  model.model.gravity = 0.0;
  BodyState3D<double> body = tilt > 0.0 ? tilted_state3d(model, lane, tilt, 0.0) : rest_state3d(model, lane);
  if (tilt == 0.0) body.y = lane.centre_y;
  body.y += height * kSpeed * model.model.time_step;
  body.vx = kSpeed;
  body.vy = -kSpeed;
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  return simulate3d(model, lane, body, {&still}, {0.03, 0.0}).final_state.pi_z;
}

double cylinder_spin(double safety_factor, std::int32_t slider, double friction, double height) {
  return cylinder_spin_tilted(safety_factor, slider, friction, height, 0.0);
}

double cylinder_spin_on_rim(double safety_factor, std::int32_t slider, double friction, double height) {
  return cylinder_spin_tilted(safety_factor, slider, friction, height, 0.01);
}

using Spin = double (*)(double, std::int32_t, double, double);

// The mean over the touch's place in a step of the spin after the impact.
double mean_spin(Spin spin, double safety_factor, std::int32_t slider, double friction) {
  double sum = 0.0;
  for (int j = 0; j < kHeights; ++j) sum += spin(safety_factor, slider, friction, (j + 0.5) / kHeights);
  return sum / kHeights;
}

// The least-squares slope of log |bias| against log f_s over kSteps, and the biases.
struct Convergence {
  std::vector<double> bias;  // relative to the finest step's spin
  double order = 0.0;
};

Convergence convergence(Spin spin, std::int32_t slider, double friction, double reference) {
  Convergence c;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (double f : kSteps) {
    const double bias = (mean_spin(spin, f, slider, friction) - reference) / std::abs(reference);
    c.bias.push_back(bias);
    const double x = std::log(f), y = std::log(std::abs(bias));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double n = static_cast<double>(kSteps.size());
  c.order = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return c;
}

void expect_touch_rule_converges(Spin spin, const std::string& cask, double least_order = 1.8) {
  const double reference = mean_spin(spin, kFinest, kWholeStepSlider, 10.0);
  ASSERT_GT(std::abs(reference), 0.0);
  const Convergence whole = convergence(spin, kWholeStepSlider, 10.0, reference);
  const Convergence velocities = convergence(spin, kVelocitiesOnly, 10.0, reference);
  const Convergence paper = convergence(spin, 0, 10.0, reference);
  ::testing::Test::RecordProperty(cask + " order whole-step", std::to_string(whole.order));
  ::testing::Test::RecordProperty(cask + " order whole-step-velocities", std::to_string(velocities.order));
  ::testing::Test::RecordProperty(cask + " order half-step", std::to_string(paper.order));
  ::testing::Test::RecordProperty(cask + " bias at f_s 0.02 whole-step", std::to_string(whole.bias[1]));
  ::testing::Test::RecordProperty(cask + " bias at f_s 0.02 half-step", std::to_string(paper.bias[1]));
  EXPECT_GE(whole.order, least_order) << cask;
  EXPECT_LE(velocities.order, 1.2) << cask;
  EXPECT_LE(paper.order, 1.2) << cask;
  const double gain = least_order >= 1.8 ? 10.0 : 4.0;  // at f_s = 0.02
  EXPECT_GT(std::abs(paper.bias[1]), gain * std::abs(whole.bias[1])) << cask;
  EXPECT_GT(std::abs(velocities.bias[1]), gain * std::abs(whole.bias[1])) << cask;
}

TEST(SpringAtTouch, StickingLandingsBiasIsSecondOrderWithTheRule) {
  expect_touch_rule_converges(planar_spin, "planar");
}

TEST(SpringAtTouch, CylinderBaseLandsAsThePlanarCaskDoes) {
  expect_touch_rule_converges(cylinder_spin, "3D");
}

TEST(SpringAtTouch, CylinderLandingOnItsRimAsTheArcWidens) {
  expect_touch_rule_converges(cylinder_spin_on_rim, "3D on its rim", 1.5);
}

TEST(SpringAtTouch, ChangesNothingWhereTheContactSlipsThroughout) {
  for (double f : {0.04, 0.01}) {
    for (double height : {0.25, 0.75}) {
      EXPECT_EQ(planar_spin(f, kWholeStepSlider, 0.3, height), planar_spin(f, kVelocitiesOnly, 0.3, height))
          << "f_s " << f << ", touch at " << height << " of a step";
    }
  }
}

}  // namespace
}  // namespace caskdem
