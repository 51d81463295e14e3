// The Hunt-Crossley normal law (kernels/contact_law.h) against what it did not produce, in a
// normal impact: the cask, upright and level, meets the floor at speed u with gravity off, so
// that every contact shares one overlap d and the cask is a mass on the sum of their springs,
//   m d'' = -K_H d^(3/2) (1 + lambda d')            (d' > 0 into the floor)
//  - elastic (lambda = beta = 0): it rebounds at u (energy), its deepest overlap is
//    (5 m u^2 / (4 K_H))^(2/5) (the energy integral) and its contact lasts
//    t_c = 2 d_max / u * integral_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) B(2/5, 1/2) d_max / u
//    (Johnson, Contact Mechanics, ch. 11, for the Hertz exponent 3/2);
//  - damped: the rebound speed solves G(-u_out) = G(u) with G(v) = v/lambda - ln(1 + lambda v)/lambda^2,
//    whatever the stiffness (Hunt & Crossley 1975), on the 2D corners and on the 3D base's rim
//    and centre alike; the step's error falls as the step does; a damping ratio acts as its
//    share of lambda (beta K_t / (m g)) and the relation holds at the sum;
//  - at rest it carries the weight at (m g / K)^(2/3) d_H^(1/3), and the nominal cask at d_H;
//  - the linear law is unchanged by the model form's existence: a Hunt-Crossley cask at the
//    same K rocks differently, and the linear model gives the bits it gave.
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/tools/roots.hpp>
#include <gtest/gtest.h>

#include "model/build3d.h"
#include "sim/simulate3d.h"
#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

Case hunt_crossley_cask(double impact_damping, double damping_ratio = 0.0) {
  Case c = testing::one_third_model();
  c.model.normal_law = NormalLaw::hunt_crossley;
  c.model.friction_law = FrictionLaw::constant;
  c.parameters.friction_static = c.parameters.friction_kinetic = 2.0;
  c.parameters.impact_damping = impact_damping;
  c.parameters.damping_ratio = damping_ratio;
  return c;
}

// The exact rebound speed of the Hunt-Crossley impact at speed u.
double exact_rebound(double impact_damping, double u) {
  const double l = impact_damping;
  auto G = [l](double v) { return v / l - std::log1p(l * v) / (l * l); };
  auto f = [&](double w) { return G(-w) - G(u); };  // increasing in w on [0, min(u, 1/lambda))
  boost::math::tools::eps_tolerance<double> tolerance(50);
  std::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve(f, 0.0, std::min(u, (1.0 - 1e-15) / l), tolerance, iterations);
  return 0.5 * (root.first + root.second);
}

struct Impact {
  double rebound_speed = 0.0;  // m/s
  double max_overlap = 0.0;    // m
  double contact_time = 0.0;   // s
};

// The 2D cask dropped level at speed u onto the floor, gravity off, from first touch.
Impact drop2d(Model model, const LaneParameters<double>& lane, double u) {
  model.gravity = 0.0;
  BodyState<double> body{};
  body.x = lane.centre_x;
  body.y = lane.centre_y;  // the standing corners just touch
  body.vy = -u;
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const double dt = model.time_step;
  const RunResult run = simulate(model, lane, body, {&still, nullptr}, {0.05, dt});
  const std::vector<double>& y = run.history.centre_y;
  Impact impact;
  int touching = 0;
  for (double level : y) {
    impact.max_overlap = std::max(impact.max_overlap, lane.centre_y - level);
    if (level < lane.centre_y) ++touching;
  }
  impact.contact_time = touching * dt;
  impact.rebound_speed =
      (y[y.size() - 1] - y[y.size() - 2]) / (run.history.time.back() - run.history.time[y.size() - 2]);
  return impact;
}

TEST(HuntCrossley, ElasticImpactConservesEnergyAndFollowsHertzTheory) {
  const Case c = hunt_crossley_cask(0.0);
  const Model model = build_model(c.model, c.parameters);
  const LaneParameters<double> lane = lane_parameters(model, c.parameters);
  ASSERT_GT(model.hertz_overlap, 0.0);
  const double m = c.parameters.mass;
  const double hertz_stiffness = total_standing_normal_stiffness(model) / std::sqrt(model.hertz_overlap);  // K_H
  const double integral = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);                    // 1.4716
  for (double u : {0.05, 0.3}) {
    const Impact impact = drop2d(model, lane, u);
    const double deepest = std::pow(5.0 * m * u * u / (4.0 * hertz_stiffness), 0.4);
    // Central differences conserve a shadow energy: the rebound is elastic to O(dt^2).
    EXPECT_NEAR(impact.rebound_speed / u, 1.0, 1e-4) << u;
    EXPECT_NEAR(impact.max_overlap / deepest, 1.0, 1e-3) << u;
    // The contact time is counted in whole steps: within two of them.
    EXPECT_NEAR(impact.contact_time, 2.0 * integral * deepest / u, 2.0 * model.time_step) << u;
  }
}

TEST(HuntCrossley, DampedImpactReboundsAsTheLawsRestitutionRelationSays) {
  for (double impact_damping : {0.5, 3.0}) {
    for (double u : {0.05, 0.3}) {
      const double exact = exact_rebound(impact_damping, u);
      double previous_error = 1.0;
      for (double step_factor : {1.0, 0.25}) {
        Case c = hunt_crossley_cask(impact_damping);
        c.model.safety_factor *= step_factor;
        const Model model = build_model(c.model, c.parameters);
        const Impact impact = drop2d(model, lane_parameters(model, c.parameters), u);
        const double error = std::abs(impact.rebound_speed - exact) / u;
        // Some hundred steps a contact: the default step is within 1e-4 u of the exact rebound
        // (1.4e-5 u at most here), and the error falls at least 8-fold at a quarter of the step
        // (the half-step damper's local first-order errors cancel between approach and rebound:
        // 16 to 30-fold here).
        EXPECT_LT(error, 1e-4) << "lambda " << impact_damping << " u " << u << " f_s x " << step_factor;
        if (step_factor < 1.0) {
          EXPECT_LT(error, previous_error / 8.0) << "lambda " << impact_damping << " u " << u;
        }
        previous_error = error;
      }
    }
  }
  // The paper's damping ratio acts through the damper alone: its share, beta K_t / (m g) at rest,
  // adds to lambda, and the rebound is the relation's at the sum.
  Case damped = hunt_crossley_cask(0.5, 0.05);
  const Model damped_model = build_model(damped.model, damped.parameters);
  const LaneParameters<double> damped_lane = lane_parameters(damped_model, damped.parameters);
  const double weight = damped.parameters.mass * damped_model.gravity;
  const double tangent = 1.5 * total_standing_normal_stiffness(damped_model);  // at rest, d = d_H
  EXPECT_NEAR(damped_lane.impact_damping, 0.5 + damped_lane.damping_beta * tangent / weight, 1e-12);
  EXPECT_GT(damped_lane.impact_damping, 0.6) << "the damping ratio's share is not negligible here";
  EXPECT_NEAR(drop2d(damped_model, damped_lane, 0.3).rebound_speed / exact_rebound(damped_lane.impact_damping, 0.3),
              1.0, 1e-4);
  // Independent of the stiffness: a contact four times softer rebounds alike.
  Case soft = hunt_crossley_cask(3.0);
  soft.model.stiffness.normal *= 0.25;
  soft.model.stiffness.shear *= 0.25;
  const Model model = build_model(soft.model, soft.parameters);
  EXPECT_NEAR(drop2d(model, lane_parameters(model, soft.parameters), 0.3).rebound_speed / exact_rebound(3.0, 0.3), 1.0,
              1e-4);
}

TEST(HuntCrossley, ThreeDimensionalBaseReboundsAsTheRelationSays) {
  for (double impact_damping : {0.0, 3.0}) {
    Case c = hunt_crossley_cask(impact_damping);
    CaskSpec3D spec{0.5 * c.cask.cylinder.diameter, c.cask.cylinder.height, c.model.section.rounding,
                    c.parameters.mass};
    const RealisationParameters p = nominal_parameters3d(spec, c.parameters);
    Model3D model = build_model3d(c.model, spec, p);
    ASSERT_GT(model.model.hertz_overlap, 0.0);
    const LaneParameters<double> lane = lane_parameters3d(model, p);
    model.model.gravity = 0.0;
    BodyState3D<double> body = rest_state3d(model, lane);
    body.y = lane.centre_y;
    const double u = 0.3;
    body.vy = -u;
    testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
    const RunResult3D run = simulate3d(model, lane, body, {&still}, {0.05, 0.0});
    const double expected = impact_damping > 0.0 ? exact_rebound(impact_damping, u) : u;
    EXPECT_NEAR(run.final_state.vy / expected, 1.0, 1e-4) << impact_damping;
  }
}

TEST(HuntCrossley, CarriesTheWeightWhereTheSpringSays) {
  Case c = hunt_crossley_cask(0.0, 0.5);
  const Model model = build_model(c.model, c.parameters);
  // The nominal cask settles at d_H, where both laws push alike: its linear settlement.
  const double weight = c.parameters.mass * model.gravity;
  EXPECT_NEAR(model.hertz_overlap / (weight / total_standing_normal_stiffness(model)), 1.0, 1e-12);
  RealisationParameters heavier = c.parameters;
  heavier.mass *= 2.0;
  heavier.inertia *= 2.0;
  heavier.stiffness_scale = 0.5;
  const LaneParameters<double> lane = lane_parameters(model, heavier);
  // Released just touching, it settles on its damped springs to (m g / K)^(2/3) d_H^(1/3).
  BodyState<double> body{};
  body.x = lane.centre_x;
  body.y = lane.centre_y;
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const RunResult run = simulate(model, lane, body, {&still, nullptr}, {2.0, 1e-3});
  const double force_over_stiffness = 2.0 * weight / (0.5 * total_standing_normal_stiffness(model));
  const double expected = std::cbrt(force_over_stiffness * force_over_stiffness * model.hertz_overlap);
  EXPECT_NEAR((lane.centre_y - run.history.centre_y.back()) / expected, 1.0, 1e-6);
  EXPECT_NEAR((lane.centre_y - rest_state(model, lane).y) / expected, 1.0, 1e-9);
}

TEST(HuntCrossley, IsAModelFormOfItsOwnAndLeavesTheLinearLawAsItWas) {
  const Case linear = testing::one_third_model();
  Case hertz = linear;
  hertz.model.normal_law = NormalLaw::hunt_crossley;
  const Model linear_model = build_model(linear.model, linear.parameters);
  Model stray = linear_model;
  stray.hertz_overlap = 1e-3;  // read only under the Hunt-Crossley law
  const LaneParameters<double> lane = lane_parameters(linear_model, linear.parameters);
  // A sine at twice the rocking onset g tan(alpha): the cask rocks.
  const double onset = linear_model.gravity * std::tan(linear_model.stability_angle);
  testing::FunctionMotion sine([onset](double t) { return 2.0 * onset * std::sin(2.0 * std::numbers::pi * 3.0 * t); },
                               3.0);
  const RunSettings settings{3.0, 0.0};
  const RunSummary a = simulate(linear_model, lane, rest_state(linear_model, lane), {&sine, nullptr}, settings).summary;
  const RunSummary b = simulate(stray, lane, rest_state(stray, lane), {&sine, nullptr}, settings).summary;
  ASSERT_GT(a.max_rotation_ratio, 0.05);
  EXPECT_EQ(a.max_abs_rotation, b.max_abs_rotation);
  EXPECT_EQ(a.residual_slide, b.residual_slide);
  const Model hertz_model = build_model(hertz.model, hertz.parameters);
  const LaneParameters<double> hertz_lane = lane_parameters(hertz_model, hertz.parameters);
  const RunSummary h =
      simulate(hertz_model, hertz_lane, rest_state(hertz_model, hertz_lane), {&sine, nullptr}, settings).summary;
  EXPECT_GT(std::abs(h.max_abs_rotation / a.max_abs_rotation - 1.0), 1e-6);
}

}  // namespace
}  // namespace caskdem
