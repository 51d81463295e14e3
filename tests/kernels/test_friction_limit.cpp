// The contact laws skip the costly friction coefficient (an exp, or a table search) when no lane
// of a batch can slip or be clipped (friction_limit in kernels/friction_law.h). That must change
// no bit. Here the 2D corner contact and the 3D spring-slider are set against the law written
// from its equations, with the exact coefficient every time, at contact states placed on both
// sides of the floor and of the exact limit, one lane at a time and in batches whose lanes
// hold or not.

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <xsimd/xsimd.hpp>

#include "kernels/contact_law.h"
#include "kernels/friction_law.h"
#include "kernels/step3d.h"

namespace caskdem::kernels {
namespace {

using Wide = xsimd::batch<double, xsimd::sse2>;
constexpr std::size_t kWidth = Wide::size;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

Model model_with(FrictionLaw law) {
  Model m;
  m.corner_count = 1;
  m.corner_normal_stiffness[0] = 4.0e8;
  m.corner_shear_stiffness[0] = 3.5e8;
  m.time_step = 1.7e-5;
  m.friction_law = law;
  // A table that falls and rises again, its lowest row inside.
  const double speed[] = {0.0, 0.02, 0.1, 1.0};
  const double coefficient[] = {0.6, 0.5, 0.42, 0.5};
  m.friction_table_size = 4;
  for (int i = 0; i < 4; ++i) {
    m.friction_table_speed[i] = speed[i];
    m.friction_table_coefficient[i] = coefficient[i];
  }
  return m;
}

LaneParameters<double> parameters(double mu_static, double mu_kinetic) {
  LaneParameters<double> p{};
  p.inverse_mass = 1.0 / 12600.0;
  p.friction_static = mu_static;
  p.friction_kinetic = mu_kinetic;
  p.inverse_decay_speed = 1.0 / 0.05;
  p.damping_beta = 1.3e-4;
  p.stiffness_scale = 1.0;
  p.floor_soft_ratio = 1.0;
  return p;
}

// One contact situation: the lane's parameters, the gap and velocities, the spring's state.
struct Situation {
  LaneParameters<double> p;
  double gap, normal_velocity, slip_velocity, shear_spring, slipping;
  double slip_z, shear_z, stiffness;  // the 3D spring-slider's out-of-plane parts
};

// States placed around the floor (lowest mu x F_n) and the exact limit: the trial force at
// (1 + u) of one of them, u from -1e-3 to 1e-3 through +-1e-13, or anywhere.
template <FrictionLaw Law>
std::vector<Situation> situations(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Model m = model_with(Law);
  const double offsets[] = {-1e-3, -1e-9, -2e-12, -1e-12, -1e-13, 0.0, 1e-13, 1e-12, 2e-12, 1e-9, 1e-3};
  std::vector<Situation> all;
  for (int i = 0; i < 20000; ++i) {
    Situation s{};
    // Both orders of mu_s and mu_k: a falling and a rising law.
    s.p = parameters(0.45 + 0.3 * unit(random), 0.45 + 0.3 * unit(random));
    s.gap = unit(random) < 0.15 ? 1e-4 * unit(random) : -2e-4 * unit(random);
    s.normal_velocity = 0.05 * (unit(random) - 0.5);
    // Also the speeds where mu(v) is its lowest, exactly or to the last bits: at rest (a rising
    // law), far beyond the decay speed (a falling one), the table's lowest row.
    const double special[] = {0.0, 5.0, 0.1};
    const double speed = unit(random) < 0.3 ? special[i % 3] : std::pow(10.0, -6.0 + 6.0 * unit(random));
    s.slip_velocity = speed * (unit(random) < 0.5 ? -1.0 : 1.0);
    s.slipping = unit(random) < 0.3 ? 1.0 : 0.0;
    const double normal = normal_force(m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
    const double floor = lowest_friction<Law>(m, s.p) * normal;
    const double exact = friction_coefficient<Law>(m, s.p, std::abs(s.slip_velocity), s.slipping > 0.5) * normal;
    const double at = unit(random) < 0.5 ? floor : exact;
    const double target = unit(random) < 0.2 ? 2.0 * exact * unit(random) : at * (1.0 + offsets[i % 11]);
    const double sign = unit(random) < 0.5 ? -1.0 : 1.0;
    s.shear_spring = sign * target + m.corner_shear_stiffness[0] * s.slip_velocity * m.time_step;
    s.slip_z = 0.01 * (unit(random) - 0.5) * (unit(random) < 0.5 ? 1e-4 : 1.0);
    s.shear_z = 0.1 * target * (unit(random) - 0.5);
    s.stiffness = unit(random) < 0.2 ? 0.0 : m.corner_shear_stiffness[0] * (0.8 + 0.4 * unit(random));
    all.push_back(s);
  }
  return all;
}

// The 2D law from its equations (kernels/contact_law.h's header), the coefficient always evaluated.
template <FrictionLaw Law>
CornerContact<double> law_2d(const Model& m, const Situation& s) {
  const double kn = m.corner_normal_stiffness[0] * s.p.stiffness_scale;
  const double ks = m.corner_shear_stiffness[0] * s.p.stiffness_scale;
  const bool touching = s.gap < 0.0;
  const double normal = normal_force(kn, s.p, s.gap, s.normal_velocity);
  const double mu = friction_coefficient<Law>(m, s.p, std::abs(s.slip_velocity), s.slipping > 0.5);
  const double limit = mu * normal;
  const double trial = s.shear_spring - ks * s.slip_velocity * m.time_step;
  const bool slipping = touching && std::abs(trial) > limit;
  const double spring = slipping ? std::copysign(limit, trial) : (touching ? trial : 0.0);
  const double dashpot = touching && !slipping ? -s.p.damping_beta * ks * s.slip_velocity : 0.0;
  return {normal, lane::clamp(spring + dashpot, -limit, limit), {spring, slipping ? 1.0 : 0.0}};
}

// The 3D spring-slider from its equations (kernels/step3d.h, shear_contact), the coefficient always evaluated.
template <FrictionLaw Law>
Vector3<double> law_3d(const Model& m, const Situation& s, ContactState3D<double>& state) {
  const double ks = m.corner_shear_stiffness[0];
  const bool touching = s.gap < 0.0;
  const double normal = normal_force(m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
  const double slip_speed = std::sqrt(s.slip_velocity * s.slip_velocity + s.slip_z * s.slip_z);
  const double limit = friction_coefficient<Law>(m, s.p, slip_speed, state.slipping > 0.5) * normal;
  const bool had = state.stiffness > 0.0;
  const double kept = had ? std::min(1.0, ks / state.stiffness) : 0.0;
  const double trial_x = state.shear_x * kept - ks * s.slip_velocity * m.time_step;
  const double trial_z = state.shear_z * kept - ks * s.slip_z * m.time_step;
  const double trial = std::sqrt(trial_x * trial_x + trial_z * trial_z);
  const bool slipping = touching && trial > limit;
  const double cap = slipping ? limit / trial : 1.0;
  const double spring_x = touching ? trial_x * cap : 0.0, spring_z = touching ? trial_z * cap : 0.0;
  const bool sticking = touching && !slipping;
  const double shear_x = spring_x + (sticking ? -s.p.damping_beta * ks * s.slip_velocity : 0.0);
  const double shear_z = spring_z + (sticking ? -s.p.damping_beta * ks * s.slip_z : 0.0);
  const double magnitude = std::sqrt(shear_x * shear_x + shear_z * shear_z);
  const double clip = magnitude > limit ? limit / magnitude : 1.0;
  state = {spring_x, spring_z, touching ? ks : 0.0, slipping ? 1.0 : 0.0};
  return {shear_x * clip, 0.0, shear_z * clip};
}

ContactState3D<double> state_3d(const Situation& s) { return {s.shear_spring, s.shear_z, s.stiffness, s.slipping}; }

template <class T>
LaneParameters<T> gather_parameters(const std::array<const Situation*, kWidth>& lanes) {
  LaneParameters<T> p;
  int field = 0;
  p.for_each_field([&](T& value) {
    alignas(64) double v[kWidth];
    for (std::size_t l = 0; l < kWidth; ++l) {
      LaneParameters<double> q = lanes[l]->p;
      int f = 0;
      q.for_each_field([&](double& x) {
        if (f++ == field) v[l] = x;
      });
    }
    value = T::load_aligned(v);
    ++field;
  });
  return p;
}

template <class F>
Wide wide_of(const std::array<const Situation*, kWidth>& lanes, F&& field) {
  alignas(64) double v[kWidth];
  for (std::size_t l = 0; l < kWidth; ++l) v[l] = field(*lanes[l]);
  return Wide::load_aligned(v);
}

double lane_of(const Wide& w, std::size_t l) {
  alignas(64) double v[kWidth];
  w.store_aligned(v);
  return v[l];
}

// Whether the lane's forces stay within the floor: then the kernel may take the floor.
template <FrictionLaw Law>
bool holds_at_floor(const Model& m, const Situation& s) {
  const double ks = m.corner_shear_stiffness[0];
  const double normal = normal_force(m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
  const double floor = lowest_friction<Law>(m, s.p) * normal;
  const double trial = s.shear_spring - ks * s.slip_velocity * m.time_step;
  const double sticking = trial + -s.p.damping_beta * ks * s.slip_velocity;
  return normal == 0.0 || (std::abs(trial) <= floor && std::abs(sticking) <= floor);
}

template <FrictionLaw Law>
void expect_the_law_2d() {
  std::mt19937_64 random(7);
  const Model m = model_with(Law);
  const std::vector<Situation> all = situations<Law>(random);
  int batches_at_floor = 0, batches_evaluated = 0;
  for (std::size_t i = 0; i + kWidth <= all.size(); i += kWidth) {
    std::array<const Situation*, kWidth> lanes;
    bool floor_for_all = true;
    for (std::size_t l = 0; l < kWidth; ++l) {
      lanes[l] = &all[i + l];
      floor_for_all = floor_for_all && holds_at_floor<Law>(m, *lanes[l]);
      // One lane alone.
      const Situation& s = *lanes[l];
      const CornerContact<double> got =
          corner_contact<Law>(m, s.p, 0, s.gap, s.normal_velocity, s.slip_velocity, {s.shear_spring, s.slipping});
      const CornerContact<double> want = law_2d<Law>(m, s);
      ASSERT_TRUE(same_bits(got.normal_force, want.normal_force));
      ASSERT_TRUE(same_bits(got.shear_force, want.shear_force)) << got.shear_force << " vs " << want.shear_force;
      ASSERT_TRUE(same_bits(got.next.shear_spring, want.next.shear_spring));
      ASSERT_TRUE(same_bits(got.next.slipping, want.next.slipping));
    }
    (floor_for_all ? batches_at_floor : batches_evaluated)++;
    // The lanes in one batch.
    const LaneParameters<Wide> p = gather_parameters<Wide>(lanes);
    const CornerState<Wide> previous{wide_of(lanes, [](const Situation& s) { return s.shear_spring; }),
                                     wide_of(lanes, [](const Situation& s) { return s.slipping; })};
    const CornerContact<Wide> got = corner_contact<Law>(
        m, p, 0, wide_of(lanes, [](const Situation& s) { return s.gap; }),
        wide_of(lanes, [](const Situation& s) { return s.normal_velocity; }),
        wide_of(lanes, [](const Situation& s) { return s.slip_velocity; }), previous);
    for (std::size_t l = 0; l < kWidth; ++l) {
      const CornerContact<double> want = law_2d<Law>(m, *lanes[l]);
      ASSERT_TRUE(same_bits(lane_of(got.normal_force, l), want.normal_force));
      ASSERT_TRUE(same_bits(lane_of(got.shear_force, l), want.shear_force));
      ASSERT_TRUE(same_bits(lane_of(got.next.shear_spring, l), want.next.shear_spring));
      ASSERT_TRUE(same_bits(lane_of(got.next.slipping, l), want.next.slipping));
    }
  }
  // Both ways through friction_limit were taken, many times.
  EXPECT_GT(batches_at_floor, 500);
  EXPECT_GT(batches_evaluated, 500);
}

TEST(FrictionLimit, TheFloorChangesNoBitOfTheExponentialLaw2D) { expect_the_law_2d<FrictionLaw::exponential>(); }
TEST(FrictionLimit, TheFloorChangesNoBitOfTheTabulatedLaw2D) { expect_the_law_2d<FrictionLaw::tabulated>(); }

template <FrictionLaw Law>
void expect_the_law_3d() {
  std::mt19937_64 random(11);
  const Model m = model_with(Law);
  const std::vector<Situation> all = situations<Law>(random);
  for (std::size_t i = 0; i + kWidth <= all.size(); i += kWidth) {
    std::array<const Situation*, kWidth> lanes;
    for (std::size_t l = 0; l < kWidth; ++l) {
      lanes[l] = &all[i + l];
      const Situation& s = *lanes[l];
      const double normal = normal_force(m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
      ContactState3D<double> got_state = state_3d(s), want_state = state_3d(s);
      const Vector3<double> got = shear_contact<Law>(m, s.p, s.gap < 0.0, true, normal, m.corner_shear_stiffness[0],
                                                     s.slip_velocity, s.slip_z, got_state);
      const Vector3<double> want = law_3d<Law>(m, s, want_state);
      ASSERT_TRUE(same_bits(got.x, want.x)) << got.x << " vs " << want.x;
      ASSERT_TRUE(same_bits(got.z, want.z));
      ASSERT_TRUE(same_bits(got_state.shear_x, want_state.shear_x));
      ASSERT_TRUE(same_bits(got_state.shear_z, want_state.shear_z));
      ASSERT_TRUE(same_bits(got_state.slipping, want_state.slipping));
    }
    const LaneParameters<Wide> p = gather_parameters<Wide>(lanes);
    const Wide gap = wide_of(lanes, [](const Situation& s) { return s.gap; });
    const Wide normal = normal_force(Wide(m.corner_normal_stiffness[0]), p, gap,
                                     wide_of(lanes, [](const Situation& s) { return s.normal_velocity; }));
    ContactState3D<Wide> state{wide_of(lanes, [](const Situation& s) { return s.shear_spring; }),
                               wide_of(lanes, [](const Situation& s) { return s.shear_z; }),
                               wide_of(lanes, [](const Situation& s) { return s.stiffness; }),
                               wide_of(lanes, [](const Situation& s) { return s.slipping; })};
    const Vector3<Wide> got = shear_contact<Law>(m, p, gap < Wide(0.0), Wide(0.0) == Wide(0.0), normal,
                                                 Wide(m.corner_shear_stiffness[0]),
                                                 wide_of(lanes, [](const Situation& s) { return s.slip_velocity; }),
                                                 wide_of(lanes, [](const Situation& s) { return s.slip_z; }), state);
    for (std::size_t l = 0; l < kWidth; ++l) {
      ContactState3D<double> want_state = state_3d(*lanes[l]);
      const Vector3<double> want = law_3d<Law>(m, *lanes[l], want_state);
      ASSERT_TRUE(same_bits(lane_of(got.x, l), want.x));
      ASSERT_TRUE(same_bits(lane_of(got.z, l), want.z));
      ASSERT_TRUE(same_bits(lane_of(state.shear_x, l), want_state.shear_x));
      ASSERT_TRUE(same_bits(lane_of(state.slipping, l), want_state.slipping));
    }
  }
}

TEST(FrictionLimit, TheFloorChangesNoBitOfTheExponentialLaw3D) { expect_the_law_3d<FrictionLaw::exponential>(); }
TEST(FrictionLimit, TheFloorChangesNoBitOfTheTabulatedLaw3D) { expect_the_law_3d<FrictionLaw::tabulated>(); }

}  // namespace
}  // namespace caskdem::kernels
