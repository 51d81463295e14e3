// The free rotation of the 3D cask (kernels/rigid_rotation.h): a turn's sine and cosine to a few
// ulp, each lane's bits its own, the torque-free top against an independent integration of
// Euler's equations, and its invariants (the floor-frame angular momentum, the kinetic energy, a
// unit quaternion) held to rounding over many steps.

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>
#include <xsimd/xsimd.hpp>

#include "kernels/rigid_rotation.h"
#include "support/ulps.h"

namespace caskdem::kernels {
namespace {

using testing::ulps_apart;

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

// cos a and sin(a)/a from a^2, on both sides of the small turn.
TEST(RigidRotation, AHalfTurnFromItsSquareMatchesLibm) {
  double worst_cos = 0.0, worst_ratio = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    for (double range : {0.04, 3.0}) {
      const double a = range * i / 200000.0;
      const HalfTurn<double> t = half_turn_of_squared(a * a);
      if (std::abs(std::cos(a)) > 1e-3) worst_cos = std::max(worst_cos, ulps_apart(t.cos, std::cos(a)));
      worst_ratio = std::max(worst_ratio, ulps_apart(t.sin_over_angle, a == 0.0 ? 1.0 : std::sin(a) / a));
    }
  }
  EXPECT_LE(worst_cos, 2.0);
  EXPECT_LE(worst_ratio, 4.0);  // sin(a)/a from sqrt(a^2) and a division beyond the small turn
}

// A torque-free symmetric top (the cask's inertias, I_1 = 2 I_3 as a squat cylinder's) turning at
// several rad/s about a tilted axis. Against an independent integration of Euler's equations and
// the quaternion's kinematics, q' = q (0, omega) / 2, by RK4 at a hundredth of the step: the same
// orientation and momentum after 2 s to 1e-10. And being the exact flow, it keeps L = R pi and the
// energy over 10^5 steps to their rounding, at most an epsilon a step (2.2e-11), and |q| to 1e-15
// (renormalised every step).
struct Top {
  Quaternion<double> q{std::cos(0.2), std::sin(0.2) * 0.6, 0.0, std::sin(0.2) * 0.8};
  Vector3<double> pi{4200.0 * 1.5, 2100.0 * 4.0, -4200.0 * 0.7};
};
constexpr double kTransverse = 1.0 / 4200.0, kAxial = 1.0 / 2100.0;  // 1/I, 1/(kg m^2)

double energy_of(const Vector3<double>& pi) {
  return 0.5 * (pi.x * pi.x * kTransverse + pi.y * pi.y * kAxial + pi.z * pi.z * kTransverse);
}

Top rk4(Top top, double step, long steps) {
  struct Rate {
    Quaternion<double> q;
    Vector3<double> pi;
  };
  auto rate = [](const Top& t) {
    const Vector3<double> omega{t.pi.x * kTransverse, t.pi.y * kAxial, t.pi.z * kTransverse};
    const Quaternion<double> dq = product(t.q, Quaternion<double>{0.0, omega.x, omega.y, omega.z});
    return Rate{{0.5 * dq.w, 0.5 * dq.x, 0.5 * dq.y, 0.5 * dq.z}, cross(t.pi, omega)};
  };
  auto add = [](const Top& t, const Rate& r, double h) {
    return Top{{t.q.w + h * r.q.w, t.q.x + h * r.q.x, t.q.y + h * r.q.y, t.q.z + h * r.q.z},
               {t.pi.x + h * r.pi.x, t.pi.y + h * r.pi.y, t.pi.z + h * r.pi.z}};
  };
  for (long n = 0; n < steps; ++n) {
    const Rate k1 = rate(top), k2 = rate(add(top, k1, step / 2)), k3 = rate(add(top, k2, step / 2)),
               k4 = rate(add(top, k3, step));
    const Rate sum{{k1.q.w + 2 * k2.q.w + 2 * k3.q.w + k4.q.w, k1.q.x + 2 * k2.q.x + 2 * k3.q.x + k4.q.x,
                    k1.q.y + 2 * k2.q.y + 2 * k3.q.y + k4.q.y, k1.q.z + 2 * k2.q.z + 2 * k3.q.z + k4.q.z},
                   {k1.pi.x + 2 * k2.pi.x + 2 * k3.pi.x + k4.pi.x, k1.pi.y + 2 * k2.pi.y + 2 * k3.pi.y + k4.pi.y,
                    k1.pi.z + 2 * k2.pi.z + 2 * k3.pi.z + k4.pi.z}};
    top = add(top, sum, step / 6);
  }
  return top;
}

TEST(RigidRotation, TheFreeTopFollowsEulersEquations) {
  Top exact;
  for (int n = 0; n < 2000; ++n) free_rotation(1e-3, kTransverse, kAxial, exact.q, exact.pi);
  const Top reference = rk4(Top{}, 1e-5, 200000);
  EXPECT_NEAR(exact.q.w, reference.q.w, 1e-10);
  EXPECT_NEAR(exact.q.x, reference.q.x, 1e-10);
  EXPECT_NEAR(exact.q.y, reference.q.y, 1e-10);
  EXPECT_NEAR(exact.q.z, reference.q.z, 1e-10);
  const double size = std::sqrt(energy_of(Top{}.pi) * 2.0 * 4200.0);  // |pi|, near enough
  EXPECT_NEAR(exact.pi.x / size, reference.pi.x / size, 1e-10);
  EXPECT_NEAR(exact.pi.y / size, reference.pi.y / size, 1e-10);
  EXPECT_NEAR(exact.pi.z / size, reference.pi.z / size, 1e-10);
}

TEST(RigidRotation, TheFreeTopKeepsItsInvariants) {
  const double rounding = 1e5 * std::numeric_limits<double>::epsilon();
  Top top;
  const Vector3<double> l0 = rotation_of(top.q).apply(top.pi);
  const double e0 = energy_of(top.pi);
  for (int n = 0; n < 100000; ++n) free_rotation(1e-4, kTransverse, kAxial, top.q, top.pi);
  const Vector3<double> l = rotation_of(top.q).apply(top.pi);
  const double size = std::sqrt(l0.x * l0.x + l0.y * l0.y + l0.z * l0.z);
  EXPECT_LT(std::abs(l.x - l0.x) / size, rounding);
  EXPECT_LT(std::abs(l.y - l0.y) / size, rounding);
  EXPECT_LT(std::abs(l.z - l0.z) / size, rounding);
  EXPECT_LT(std::abs(energy_of(top.pi) / e0 - 1.0), rounding);
  RecordProperty("energy_drift", std::to_string(energy_of(top.pi) / e0 - 1.0));
  EXPECT_LT(std::abs(top.q.w * top.q.w + top.q.x * top.q.x + top.q.y * top.q.y + top.q.z * top.q.z - 1.0), 1e-15);
}

}  // namespace
}  // namespace caskdem::kernels
