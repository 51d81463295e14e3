// The mechanisms beyond the source paper's model (kernels/contact_law.h, kernels/step.h),
// each against what it must do by construction, by statics, energy or momentum:
//   soft floor layer      settles where s K d0 + K (d - d0) = m g
//   vertical acceleration settles at m (g + a_v) / K
//   convex base           leans onto a side at the tilt c / a of its three corners
//   impact damper         restitution falls with impact speed, and not without it; however
//                         large, it cannot fall below the plastic impact's (Housner 1963)
//   wobble damper         the fall before the first impact matches the rigid block's equation
//                         of motion with the same couple, integrated independently
#include <cmath>

#include <gtest/gtest.h>

#include "sim/free_vibration.h"
#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

struct CaskSetup {
  Case c;
  Model model;
};

CaskSetup paper(bool base_centre_contact = false) {
  CaskSetup s{testing::one_third_model(), {}};
  s.c.model.base_centre_contact = base_centre_contact;
  s.c.model.friction_law = FrictionLaw::constant;
  s.c.parameters.friction_static = s.c.parameters.friction_kinetic = 2.0;
  s.model = build_model(s.c.model, s.c.parameters);
  return s;
}

double settled_penetration(const CaskSetup& s, const RealisationParameters& p, const motion::TableMotion& vertical) {
  const LaneParameters<double> lane = lane_parameters(s.model, p);
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const RunResult run = simulate(s.model, lane, rest_state(s.model, lane), {&still, &vertical}, {2.0, 1e-3});
  return p.centre_of_mass.y - run.history.centre_y.back();
}

TEST(Mechanisms, SoftFloorLayerSettlesWhereTheBilinearSpringCarriesTheWeight) {
  const CaskSetup s = paper();
  RealisationParameters p = s.c.parameters;
  p.floor_soft_ratio = 0.1;
  const double stiffness = total_standing_normal_stiffness(s.model);
  const double weight = p.mass * s.model.gravity;
  testing::FunctionMotion none([](double) { return 0.0; }, 0.0);
  for (double depth : {2e-5, 2e-4}) {  // the weight exceeds the layer's capacity, then it does not
    p.floor_soft_depth = depth;
    const double expected = weight > 0.1 * stiffness * depth ? depth + (weight - 0.1 * stiffness * depth) / stiffness
                                                             : weight / (0.1 * stiffness);
    EXPECT_NEAR(settled_penetration(s, p, none) / expected, 1.0, 1e-6) << "depth " << depth;
  }
}

TEST(Mechanisms, VerticalAccelerationChangesTheEffectiveWeight) {
  const CaskSetup s = paper();
  RealisationParameters p = s.c.parameters;
  const double stiffness = total_standing_normal_stiffness(s.model);
  testing::FunctionMotion downward([](double) { return -0.4 * 9.80665; }, 10.0);
  // The table accelerating downward at 0.4 g: the cask weighs 0.6 m g on its springs.
  EXPECT_NEAR(settled_penetration(s, p, downward) / (0.6 * p.mass * s.model.gravity / stiffness), 1.0, 1e-6);
  p.vertical_scale = 0.5;  // and the lane's scale on the vertical motion applies
  EXPECT_NEAR(settled_penetration(s, p, downward) / (0.8 * p.mass * s.model.gravity / stiffness), 1.0, 1e-6);
}

TEST(Mechanisms, ConvexBaseLeansOntoASideAtItsCamberTilt) {
  const CaskSetup s = paper(true);
  ASSERT_EQ(s.model.corner_count, 3);
  ASSERT_GE(s.model.camber_corner, 0);
  RealisationParameters p = s.c.parameters;
  p.base_camber = 1e-3;
  // A rocker on its middle corner: it cannot stand on it and settles onto a middle and an
  // end corner, tilted by c / a (a: from the middle to an end arc centre), less the tiny
  // difference of the two corners' spring compressions.
  p.centre_of_mass.x = 1e-6;  // decide the side
  // It falls off the middle corner slowly (from 1e-6 m off balance) and then rocks between the
  // middle and the end corner, losing energy only when the end corner lands: a high contact
  // damping lets it settle within the run.
  p.damping_ratio = 0.5;
  const LaneParameters<double> lane = lane_parameters(s.model, p);
  testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const RunResult run = simulate(s.model, lane, rest_state(s.model, lane), {&still, nullptr}, {10.0, 1e-3});
  const double a = s.model.corner_x[s.model.camber_corner] - s.model.corner_x[0];
  const double tilt = std::abs(run.history.rotation.back());
  EXPECT_NEAR(tilt / (p.base_camber / std::abs(a)), 1.0, 0.02);
  // Flat (camber 0), the same three-corner base stands upright.
  p.base_camber = 0.0;
  const LaneParameters<double> flat = lane_parameters(s.model, p);
  const RunResult upright = simulate(s.model, flat, rest_state(s.model, flat), {&still, nullptr}, {3.0, 1e-3});
  EXPECT_LT(std::abs(upright.history.rotation.back()), 1e-4);
}

double restitution(const CaskSetup& s, RealisationParameters p, double tilt_ratio) {
  FreeVibrationSpec fv = s.c.free_vibration;
  fv.initial_tilt_ratio = tilt_ratio;
  fv.ratios = 1;
  return free_vibration(s.model, p, fv).restitution;
}

TEST(Mechanisms, ImpactDamperMakesRestitutionFallWithImpactSpeed) {
  const CaskSetup s = paper();
  RealisationParameters p = s.c.parameters;
  // Without it, restitution hardly depends on the amplitude (linear contact).
  EXPECT_LT(std::abs(restitution(s, p, 0.05) - restitution(s, p, 0.8)), 0.002);
  // With it, each larger release (a faster impact) loses more.
  p.impact_damping = 10.0;  // s/m
  double previous = 1.0;
  for (double tilt_ratio : {0.05, 0.1, 0.3, 0.8}) {
    const double e = restitution(s, p, tilt_ratio);
    EXPECT_LT(e, previous) << "release at " << tilt_ratio << " alpha";
    previous = e;
  }
  EXPECT_GT(restitution(s, p, 0.05) - restitution(s, p, 0.8), 0.004);
  // More damper, more loss at the same amplitude.
  RealisationParameters less = p;
  less.impact_damping = 1.0;
  EXPECT_GT(restitution(s, less, 0.8), restitution(s, p, 0.8));
  // A rocking impact conserves angular momentum about the landing corner; the most it can lose
  // is a plastic impact's, e = 1 - 2 m R^2 sin^2(alpha) / I_O (Housner 1963), which a very
  // large damper approaches and no damper passes.
  const double b = 0.5 * (s.model.corner_x[1] - s.model.corner_x[0]);
  const double h = s.c.parameters.centre_of_mass.y - s.model.corner_y[0];
  const double size_squared = b * b + h * h, alpha = std::atan(b / h);
  const double inertia_about_pivot = s.c.parameters.inertia + s.c.parameters.mass * size_squared;
  const double plastic = 1.0 - 2.0 * s.c.parameters.mass * size_squared * std::sin(alpha) * std::sin(alpha) / inertia_about_pivot;
  RealisationParameters plastic_limit = p;
  plastic_limit.impact_damping = 2000.0;
  const double limit = restitution(s, plastic_limit, 0.8);
  EXPECT_GE(restitution(s, p, 0.8), limit);
  EXPECT_NEAR(limit, plastic, 0.002);  // rounded corners: the landing is not quite a point impact
}

// The rigid block's fall from rest at theta0 to its first impact with the wobble couple
// -I 2 zeta p (phi / alpha) phi' (phi = |theta|) about its pivot,
//   I_O phi'' = -m g R sin(alpha - phi) - I 2 zeta p (phi / alpha) phi',
// by fourth-order Runge-Kutta; returns |phi'| at phi = 0.
double rigid_impact_speed(double mass, double inertia, double size, double alpha, double p, double zeta,
                          double theta0, double gravity) {
  const double inertia_about_pivot = inertia + mass * size * size;
  auto acceleration = [&](double phi, double rate) {
    return (-mass * gravity * size * std::sin(alpha - phi) - inertia * 2.0 * zeta * p * (phi / alpha) * rate) /
           inertia_about_pivot;
  };
  double phi = theta0, rate = 0.0;
  const double dt = 1e-5;
  while (true) {
    const double k1p = rate, k1r = acceleration(phi, rate);
    const double k2p = rate + 0.5 * dt * k1r, k2r = acceleration(phi + 0.5 * dt * k1p, k2p);
    const double k3p = rate + 0.5 * dt * k2r, k3r = acceleration(phi + 0.5 * dt * k2p, k3p);
    const double k4p = rate + dt * k3r, k4r = acceleration(phi + dt * k3p, k4p);
    const double next_phi = phi + dt / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
    const double next_rate = rate + dt / 6.0 * (k1r + 2.0 * k2r + 2.0 * k3r + k4r);
    if (next_phi <= 0.0) return std::abs(rate + (next_rate - rate) * phi / (phi - next_phi));
    phi = next_phi;
    rate = next_rate;
  }
}

TEST(Mechanisms, WobbleDamperTakesTheEnergyOfTheRigidBlocksCouple) {
  const CaskSetup s = paper();
  auto first_peak = [&](double wobble) {
    RealisationParameters p = s.c.parameters;
    p.wobble_damping = wobble;
    p.damping_ratio = 0.0;
    FreeVibrationSpec fv = s.c.free_vibration;
    fv.initial_tilt_ratio = 0.7;
    fv.ratios = 1;
    return free_vibration(s.model, p, fv).peaks.at(0);
  };
  const RealisationParameters& nominal = s.c.parameters;
  const double b = 0.5 * (s.model.corner_x[1] - s.model.corner_x[0]);
  const double h = nominal.centre_of_mass.y - s.model.corner_y[0];
  const double size = std::hypot(b, h), alpha = std::atan(b / h);
  auto rigid = [&](double zeta) {
    return rigid_impact_speed(nominal.mass, nominal.inertia, size, alpha, s.model.rocking_frequency, zeta, 0.7 * alpha,
                              s.model.gravity);
  };
  // Without it: energy conservation (rolling on the rounded corner costs 0.5 %).
  EXPECT_NEAR(first_peak(0.0) / rigid(0.0), 1.0, 0.01);
  // With it: the fraction of the impact speed it takes is the rigid block's, which cancels the
  // rounded corner's small difference.
  for (double zeta : {0.2, 0.5}) {
    const double taken = 1.0 - first_peak(zeta) / first_peak(0.0);
    const double expected = 1.0 - rigid(zeta) / rigid(0.0);
    EXPECT_GT(taken, 0.005) << "zeta " << zeta;
    EXPECT_NEAR(taken / expected, 1.0, 0.05) << "zeta " << zeta;
  }
}

}  // namespace
}  // namespace caskdem
