// The Hunt-Crossley law's shear spring, Mindlin's (kernels/contact_law.h), measured on the law
// itself (below), and the cylinder on a Hunt-Crossley footprint against the independent generator's
// (tests/independent: a continuous circular base of 64 strips with a friction that follows its
// pressure, integrated by Dormand-Prince with error control; it shares no code with caskdem).
// Both codes release the same 1/3-scale cylinder, on the same Hertz base with the same Hunt &
// Crossley damper and friction coefficient, from rest at half its slenderness about a rim, and
// rock freely. Each impact's restitution is read from the amplitudes on either side of it,
// Housner's energy relation cos(alpha - theta_(k+1)) - cos(alpha) = e^2 (cos(alpha - theta_k) - cos(alpha)),
// each code with its own alpha.
//
// What it checks: the rocking impact's energy loss, the sum of the normal damper's and of any
// slip at the base. The generator's base cannot store a tangential force, so with friction well
// above the impact's need (h (1 - e) / (r (1 + e)) = 0.13 of the normal impulse for a rigid
// block) its base does not slip; caskdem's spring-slider must not slip either, which holds
// when its shear spring stiffens with the Hertz contact as Mindlin's does
// (kernels/contact_law.h, mindlin_factor). With a linear shear spring beside the Hertz normal
// one, caskdem's restitutions were 2.2 to 2.7 % low here (0.862 against 0.885 at the first
// impact: a fifth more energy lost), and this test failed.
//
// The tolerance is what the two discretisations leave, measured once (caskdem's kMaxCorners
// raised for it): the generator's restitutions move by up to 1.0 % between 16 and 64 strips,
// caskdem's by up to 0.8 % between 16 and 64 points, and at 64 each the two agree within 0.4 %
// at every impact (within 1.9 % at caskdem's default 9 points). So at 16 points, agreement is
// asked within 1.5 %.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "cylinder_model.h"
#include "kernels/contact_law.h"
#include "simulate.h"
#include "support/function_motion.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

constexpr double kStiffness = 2.38e10;   // N/m^3: the generator's tangent pressure slope at rest
constexpr double kStandingDamping = 0.02;  // its standing vertical mode's damping ratio
constexpr double kFriction = 0.5;
constexpr double kTiltRatio = 0.5;
constexpr double kSampleStep = 5e-4;  // s
constexpr double kDuration = 4.5;     // s: six impacts

independent::CaskParameters generator_cask() {
  independent::CaskParameters p;
  p.mu_static = kFriction;
  independent::set_standing_stiffness(p, kStiffness, kStandingDamping);
  return p;
}

// The half-cycles' amplitudes of a free rocking history (the largest |theta| between zero
// crossings), the release first.
std::vector<double> amplitudes(const std::vector<double>& theta, double alpha) {
  std::vector<double> out;
  double largest = 0.0;
  for (std::size_t i = 0; i < theta.size(); ++i) {
    if (i > 0 && (theta[i] > 0.0) != (theta[i - 1] > 0.0)) {
      if (largest > 0.02 * alpha) out.push_back(largest);
      largest = 0.0;
    }
    largest = std::max(largest, std::abs(theta[i]));
  }
  return out;
}

std::vector<double> restitutions(const std::vector<double>& amplitude, double alpha) {
  std::vector<double> e;
  for (std::size_t k = 0; k + 1 < amplitude.size(); ++k) {
    e.push_back(std::sqrt((std::cos(alpha - amplitude[k + 1]) - std::cos(alpha)) /
                          (std::cos(alpha - amplitude[k]) - std::cos(alpha))));
  }
  return e;
}

std::vector<double> generator_restitutions() {
  const independent::CaskParameters p = generator_cask();
  const independent::CylinderModel model(p);
  independent::State s = model.equilibrium();
  // Turned counter-clockwise by theta0 about the left rim (-r, 0): the right side lifts.
  const double theta0 = kTiltRatio * p.slenderness(), height = s[1];
  s[0] = -p.radius + p.radius * std::cos(theta0) - height * std::sin(theta0);
  s[1] = p.radius * std::sin(theta0) + height * std::cos(theta0);
  s[2] = theta0;
  std::vector<double> times;
  for (int k = 1; k * kSampleStep <= kDuration; ++k) times.push_back(k * kSampleStep);
  const independent::Response r = independent::simulate(model, {}, s, times);
  return restitutions(amplitudes(r.rotation, p.slenderness()), p.slenderness());
}

// caskdem's case of the same cask: its per-area Hertz coefficient K / sqrt(d_H),
// d_H = m g / (K A), equal to the generator's k_h, so K = (k_h sqrt(m g / A))^(2/3); its
// damper lambda = 1.5 c_h (the generator writes p = k_h d^n (1 + 1.5 c_h d')).
std::vector<double> caskdem_restitutions(int footprint_points) {
  const independent::CaskParameters g = generator_cask();
  const double weight = g.mass() * g.gravity, area = g.footprint_area();
  const double hertz_stiffness = std::pow(g.k_h * std::sqrt(weight / area), 2.0 / 3.0);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("caskdem-independent-rocking-" + std::to_string(footprint_points) + ".toml");
  {
    std::ofstream out(file);
    out << std::setprecision(17);
    out << "title = \"the independent generator's cylinder\"\n"
        << "[cask]\nshape = \"cylinder\"\ndiameter = \"" << 2.0 * g.radius << " m\"\nheight = \"" << 2.0 * g.half_height
        << " m\"\ndensity = \"" << g.density << " kg/m^3\"\nfootprint = \"distributed\"\nfootprint_points = "
        << footprint_points << "\nrounding = \"0.5 cm\"\n"
        << "[contact]\nnormal_law = \"hunt-crossley\"\nnormal_stiffness = \"" << hertz_stiffness
        << " N/m^3\"\nshear_stiffness = \"" << hertz_stiffness * 2.21 / 2.38 << " N/m^3\"\nimpact_damping = \""
        << 1.5 * g.c_h << " s/m\"\n"
        << "[friction]\nlaw = \"constant\"\ncoefficient = " << kFriction << "\n"
        << "[damping]\nratio = 0.0\nfrequency = \"135 Hz\"\n"
        << "[integration]\nsafety_factor = 0.01\n";
  }
  const Case c = load_case(file);
  std::filesystem::remove(file);
  const testing::Prepared p = testing::prepare(c);
  const testing::FunctionMotion still([](double) { return 0.0; }, 0.0);
  const double alpha = p.model.stability_angle;
  const RunResult run = simulate(p.model, p.lane, tilted_state(p.model, p.lane, kTiltRatio * alpha), {&still, nullptr},
                                 {kDuration, kSampleStep});
  return restitutions(amplitudes(run.history.rotation, alpha), alpha);
}

// Mindlin's property, measured on the law: at every overlap the shear spring's stiffness (a
// small slip's force) stands to the normal spring's tangent stiffness (a finite difference of
// the normal force) as K_s to K_n; and at a fixed stretch the shear force falls with the
// contact's stiffness as it opens, as sqrt(d).
// A contact of the footprint moving along the floor at `slip` (m/s) for one step, not normally.
kernels::SliderVelocities<double> slipping_at(double slip) {
  const kernels::ContactVelocity<double> v{0.0, slip, 0.0};
  return kernels::slider_velocities(0, v, v);
}

TEST(IndependentRocking, TheHertzShearSpringKeepsMindlinsRatioToTheNormalTangent) {
  Case c = testing::one_third_model();
  c.model.normal_law = NormalLaw::hunt_crossley;
  c.model.friction_law = FrictionLaw::constant;
  c.parameters.friction_static = c.parameters.friction_kinetic = 10.0;  // sticks
  c.parameters.damping_ratio = 0.0;
  const testing::Prepared p = testing::prepare(c);
  const Model& m = p.model;
  const double kn = m.corner_normal_stiffness[0], ks = m.corner_shear_stiffness[0];
  const double slip = 1e-3;  // m/s for one step
  const CornerState<double> unstretched{0.0, 0.0};
  const auto contact = [&](double overlap, double slip_velocity, const CornerState<double>& before) {
    return kernels::corner_contact<FrictionLaw::constant>(m, p.lane, 0, -overlap, slipping_at(slip_velocity), before);
  };
  for (double ratio : {0.04, 0.25, 1.0, 4.0, 25.0}) {
    const double d = ratio * m.hertz_overlap, h = 1e-6 * d;
    const double normal_tangent =
        (contact(d + h, 0.0, unstretched).normal_force - contact(d - h, 0.0, unstretched).normal_force) / (2.0 * h);
    const double shear_stiffness = -contact(d, slip, unstretched).shear_force / (slip * m.time_step);
    EXPECT_NEAR((shear_stiffness / normal_tangent) / (ks / kn), 1.0, 1e-6) << "overlap " << ratio << " d_H";
  }
  // Stretched at 25 d_H and held, the spring at d_H pushes sqrt(1/25) of the force.
  const kernels::CornerContact<double> deep = contact(25.0 * m.hertz_overlap, slip, unstretched);
  const kernels::CornerContact<double> opened = contact(m.hertz_overlap, 0.0, deep.next);
  EXPECT_NEAR(opened.shear_force / deep.shear_force, 0.2, 1e-12);
}

TEST(IndependentRocking, HuntCrossleyFootprintLosesWhatTheGeneratorsLosesAtEachImpact) {
  const std::vector<double> generator = generator_restitutions();
  const std::vector<double> ours = caskdem_restitutions(16);
  ASSERT_GE(generator.size(), 5u);
  ASSERT_GE(ours.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    std::printf("impact %zu: restitution %.4f, the generator's %.4f (%+.2f %%)\n", k + 1, ours[k], generator[k],
                100.0 * (ours[k] / generator[k] - 1.0));
    EXPECT_NEAR(ours[k] / generator[k], 1.0, 0.015) << "impact " << k + 1;
  }
  // The restitution rises as the amplitude falls (the damper's loss grows with the impact
  // speed, e ~ 1 - c_h v), in both.
  EXPECT_LT(generator[0], generator[4]);
  EXPECT_LT(ours[0], ours[4]);
}

}  // namespace
}  // namespace caskdem
