// The free rotation of the 3D cask (kernels/rigid_rotation.h): a turn's sine and cosine to a few
// ulp, each lane's bits its own, one axis's rotation the exact one, and the torque-free top's
// invariants (the floor-frame angular momentum, the kinetic energy, a unit quaternion) held to
// rounding over many steps.

#include <cmath>
#include <cstring>
#include <numbers>

#include <gtest/gtest.h>
#include <xsimd/xsimd.hpp>

#include "kernels/rigid_rotation.h"

namespace caskdem::kernels {
namespace {

double ulps_apart(double a, double b) {
  if (a == b) return 0.0;
  return std::abs(a - b) / std::abs(std::nextafter(b, 2.0 * b + 1.0) - b);
}

TEST(RigidRotation, ATurnsSineAndCosineMatchLibmToTwoUlp) {
  double worst_sin = 0.0, worst_cos = 0.0;
  for (int i = -200000; i <= 200000; ++i) {
    for (double range : {0.04, 3.0}) {  // the polynomial's range and beyond it
      const double a = range * i / 200000.0;
      const SinCos<double> r = sin_cos_of_turn(a);
      if (a != 0.0) worst_sin = std::max(worst_sin, ulps_apart(r.sin, std::sin(a)));
      if (std::abs(std::cos(a)) > 1e-3) worst_cos = std::max(worst_cos, ulps_apart(r.cos, std::cos(a)));
    }
  }
  EXPECT_LE(worst_sin, 2.0);
  EXPECT_LE(worst_cos, 2.0);
}

// A small angle beside a large one in a batch gets the bits it gets alone.
TEST(RigidRotation, EachLanesTurnIsItsOwn) {
  using Batch = xsimd::batch<double, xsimd::sse2>;
  alignas(16) double input[2], wide_sin[2], wide_cos[2];
  for (int i = -20000; i <= 20000; ++i) {
    input[0] = 0.04 * i / 20000.0;
    input[1] = 1.0;
    const SinCos<Batch> together = sin_cos_of_turn(Batch::load_aligned(input));
    together.sin.store_aligned(wide_sin);
    together.cos.store_aligned(wide_cos);
    const SinCos<double> alone = sin_cos_of_turn(input[0]);
    ASSERT_EQ(std::memcmp(&alone.sin, &wide_sin[0], sizeof(double)), 0) << input[0];
    ASSERT_EQ(std::memcmp(&alone.cos, &wide_cos[0], sizeof(double)), 0) << input[0];
  }
}

// From upright, a turn by theta about body axis y is the quaternion (cos theta/2, 0, sin theta/2, 0),
// and the body-frame momentum turns backwards by theta.
TEST(RigidRotation, OneAxisIsTheExactRotation) {
  for (double theta : {1e-6, 0.01, 0.5, 2.0}) {
    Quaternion<double> q{1.0, 0.0, 0.0, 0.0};
    Vector3<double> pi{1.0, theta, 0.5};  // h pi_y / I_y = theta with h = I_y = 1
    rotate_about_body_axis(1, 1.0, 1.0, q, pi);
    EXPECT_NEAR(q.w, std::cos(0.5 * theta), 2e-16);
    EXPECT_NEAR(q.y, std::sin(0.5 * theta), 2e-16);
    EXPECT_EQ(q.x, 0.0);
    EXPECT_EQ(q.z, 0.0);
    EXPECT_NEAR(pi.x, std::cos(theta) * 1.0 - std::sin(theta) * 0.5, 4e-16);
    EXPECT_NEAR(pi.z, std::sin(theta) * 1.0 + std::cos(theta) * 0.5, 4e-16);
    EXPECT_EQ(pi.y, theta);
  }
}

// A torque-free symmetric top (the cask's inertias) turning at several rad/s about a tilted axis
// for 10 s: each factor of the splitting conserves L = R pi exactly, so it stays to rounding
// (1e-12), and |q| stays 1 to 1e-15; the energy is the splitting's, second order and bounded:
// its error falls by 4 when the step halves.
double free_top_energy_error(double step) {
  const double transverse = 1.0 / 4200.0, axial = 1.0 / 2100.0;  // 1/I, kg m^2
  Quaternion<double> q{std::cos(0.2), std::sin(0.2) * 0.6, 0.0, std::sin(0.2) * 0.8};
  Vector3<double> pi{4200.0 * 1.5, 2100.0 * 4.0, -4200.0 * 0.7};
  auto energy = [&] { return 0.5 * (pi.x * pi.x * transverse + pi.y * pi.y * axial + pi.z * pi.z * transverse); };
  const Vector3<double> l0 = rotation_of(q).apply(pi);
  const double e0 = energy();
  double worst = 0.0;
  for (long n = 0; n < std::lround(10.0 / step); ++n) {
    free_rotation(step, transverse, axial, q, pi);
    worst = std::max(worst, std::abs(energy() / e0 - 1.0));
  }
  const Vector3<double> l = rotation_of(q).apply(pi);
  const double size = std::sqrt(l0.x * l0.x + l0.y * l0.y + l0.z * l0.z);
  EXPECT_LT(std::abs(l.x - l0.x) / size, 1e-12);
  EXPECT_LT(std::abs(l.y - l0.y) / size, 1e-12);
  EXPECT_LT(std::abs(l.z - l0.z) / size, 1e-12);
  EXPECT_LT(std::abs(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z - 1.0), 1e-15);
  return worst;
}

TEST(RigidRotation, TheFreeTopKeepsItsInvariants) {
  const double coarse = free_top_energy_error(2e-4), fine = free_top_energy_error(1e-4);
  RecordProperty("energy_error_1e-4", std::to_string(fine));
  EXPECT_LT(fine, 1e-8);
  EXPECT_GT(coarse / fine, 3.5);
  EXPECT_LT(coarse / fine, 4.5);
}

}  // namespace
}  // namespace caskdem::kernels
