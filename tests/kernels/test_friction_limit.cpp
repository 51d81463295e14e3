// The contact laws skip the costly friction coefficient (an exp, or a table search) when no lane
// of a batch can slip or be clipped (friction_limit in kernels/friction_law.h). That must change
// no bit. Here the 2D corner contact and the 3D spring-slider are set against the law written
// from its equations, with the exact coefficient every time, at contact states placed on both
// sides of the floor and of the exact limit, one lane at a time and in batches whose lanes
// hold or not. The 3D slider also skips the square roots and divisions that lane::root_not_above
// decides from squares, and the division of a stiffness that did not change: the same test holds
// it to the bits of the law that always takes them.

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

// Tables: one that falls and rises again (its lowest row inside), one that falls to 1e-5 (beyond
// 0.3 m/s its interpolation rounds to 1e-5 - 4.5e-17), one with a row of zero friction (no
// floor), and one that ends at zero, where the interpolation rounds to -2.8e-17.
constexpr int kTables = 4;
Model model_with(FrictionLaw law, int table = 0) {
  Model m;
  m.corner_count = 1;
  m.corner_normal_stiffness[0] = 4.0e8;
  m.corner_shear_stiffness[0] = 3.5e8;
  m.time_step = 1.7e-5;
  m.friction_law = law;
  const std::vector<std::array<double, 2>> tables[] = {
      {{0.0, 0.6}, {0.02, 0.5}, {0.1, 0.42}, {1.0, 0.5}},
      {{0.0, 0.6}, {0.3, 1e-5}},
      {{0.0, 0.5}, {0.05, 0.0}, {1.0, 0.3}},
      {{0.0, 0.19}, {0.3, 0.0}},
  };
  m.friction_table_size = static_cast<int>(tables[table].size());
  for (int i = 0; i < m.friction_table_size; ++i) {
    m.friction_table_speed[i] = tables[table][i][0];
    m.friction_table_coefficient[i] = tables[table][i][1];
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
std::vector<Situation> situations(const Model& m, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double offsets[] = {-1e-3, -1e-9, -2e-12, -1e-12, -1e-13, 0.0, 1e-13, 1e-12, 2e-12, 1e-9, 1e-3};
  // Coefficients far apart, where the law's rounding is largest against the lower one, and zero.
  const double extremes[][2] = {{1e-6, 0.5}, {0.5, 1e-6}, {0.5, 0.0}, {0.0, 0.4}};
  std::vector<Situation> all;
  for (int i = 0; i < 20000; ++i) {
    Situation s{};
    // Both orders of mu_s and mu_k: a falling and a rising law.
    s.p = unit(random) < 0.7 ? parameters(0.45 + 0.3 * unit(random), 0.45 + 0.3 * unit(random))
                             : parameters(extremes[i % 4][0], extremes[i % 4][1]);
    // Some lanes without the dashpot, whose force would otherwise hide a fast-slipping contact
    // from the floor.
    if (unit(random) < 0.3) s.p.damping_beta = 0.0;
    s.gap = unit(random) < 0.15 ? 1e-4 * unit(random) : -2e-4 * unit(random);
    s.normal_velocity = 0.05 * (unit(random) - 0.5);
    // Also the speeds where mu(v) is its lowest, exactly or to the last bits: at rest (a rising
    // law), far beyond the decay speed (a falling one), the table's lowest row.
    const double special[] = {0.0, 5.0, 0.1, 0.3, 0.05, 2.0};
    const double speed = unit(random) < 0.3 ? special[i % 6] : std::pow(10.0, -6.0 + 6.0 * unit(random));
    s.slip_velocity = speed * (unit(random) < 0.5 ? -1.0 : 1.0);
    s.slipping = unit(random) < 0.3 ? 1.0 : 0.0;
    const double normal = normal_force(m, m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
    const double floor = lowest_friction<Law>(m, s.p) * normal;
    const double exact = friction_coefficient<Law>(m, s.p, std::abs(s.slip_velocity), s.slipping > 0.5) * normal;
    const double at = unit(random) < 0.5 ? floor : exact;
    const double target = unit(random) < 0.2 ? 2.0 * exact * unit(random) : at * (1.0 + offsets[i % 11]);
    const double sign = unit(random) < 0.5 ? -1.0 : 1.0;
    s.shear_spring = sign * target + m.corner_shear_stiffness[0] * s.slip_velocity * m.time_step;
    s.slip_z = 0.01 * (unit(random) - 0.5) * (unit(random) < 0.5 ? 1e-4 : 1.0);
    s.shear_z = 0.1 * target * (unit(random) - 0.5);
    // Untouched before, or touching at the same stiffness (the centre, a rim pressed all round:
    // the 3D slider then skips its division), or at another (an arc that narrows or widens).
    const double stiffness_draw = unit(random);
    s.stiffness = stiffness_draw < 0.2   ? 0.0
                  : stiffness_draw < 0.5 ? m.corner_shear_stiffness[0]
                                         : m.corner_shear_stiffness[0] * (0.8 + 0.4 * unit(random));
    // A spring at -0 that does not slip: its force stays -0, which a zero limit would clamp to +0.
    if (unit(random) < 0.05) s.shear_spring = -0.0, s.slip_velocity = 0.0, s.slip_z = 0.0, s.shear_z = -0.0;
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
  const double normal = normal_force(m, kn, s.p, s.gap, s.normal_velocity);
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
  const double normal = normal_force(m, m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
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

// Which way friction_limit went for a batch: its answer must be the floor's bits in every lane
// or the evaluated mu F_n's (+1 floor, -1 evaluated, 0 when the two agree in every lane).
template <FrictionLaw Law, class HoldsWithin>
int way_taken(const Model& m, const LaneParameters<Wide>& p, const Wide& slip_speed, const Wide& slipping,
              const Wide& normal, HoldsWithin&& holds_within) {
  const Wide floor = lowest_friction<Law>(m, p) * normal;
  const Wide evaluated = friction_coefficient<Law>(m, p, slip_speed, slipping > Wide(0.5)) * normal;
  const Wide got = friction_limit<Law>(m, p, slip_speed, slipping > Wide(0.5), normal, holds_within);
  bool is_floor = true, is_evaluated = true;
  for (std::size_t l = 0; l < kWidth; ++l) {
    is_floor = is_floor && same_bits(lane_of(got, l), lane_of(floor, l));
    is_evaluated = is_evaluated && same_bits(lane_of(got, l), lane_of(evaluated, l));
  }
  EXPECT_TRUE(is_floor || is_evaluated);
  return is_evaluated ? (is_floor ? 0 : -1) : 1;
}

// The source paper's slider: every term reads the half-step velocity.
template <class T>
SliderVelocities<T> half_step(const T& normal_velocity, const T& slip_velocity, const T& slip_z = T(0.0)) {
  const ContactVelocity<T> half{normal_velocity, slip_velocity, slip_z};
  return slider_velocities(0, half, half);
}

// The test's situations must send many batches each way through friction_limit (of 10,000:
// 230 to 2,400 take the floor, depending on the law and table).
void expect_both_ways(const int (&ways)[2]) {
  EXPECT_GT(ways[0], 100) << "batches given the floor";
  EXPECT_GT(ways[1], 100) << "batches that evaluated mu";
}

template <FrictionLaw Law>
void expect_the_law_2d(int table) {
  std::mt19937_64 random(7);
  const Model m = model_with(Law, table);
  const std::vector<Situation> all = situations<Law>(m, random);
  int ways[2] = {0, 0};
  for (std::size_t i = 0; i + kWidth <= all.size(); i += kWidth) {
    std::array<const Situation*, kWidth> lanes;
    for (std::size_t l = 0; l < kWidth; ++l) {
      lanes[l] = &all[i + l];
      // One lane alone.
      const Situation& s = *lanes[l];
      const CornerContact<double> got = corner_contact<Law>(
          m, s.p, 0, s.gap, half_step(s.normal_velocity, s.slip_velocity), {s.shear_spring, s.slipping});
      const CornerContact<double> want = law_2d<Law>(m, s);
      ASSERT_TRUE(same_bits(got.normal_force, want.normal_force));
      ASSERT_TRUE(same_bits(got.shear_force, want.shear_force)) << got.shear_force << " vs " << want.shear_force;
      ASSERT_TRUE(same_bits(got.next.shear_spring, want.next.shear_spring));
      ASSERT_TRUE(same_bits(got.next.slipping, want.next.slipping));
    }
    // The lanes in one batch.
    const LaneParameters<Wide> p = gather_parameters<Wide>(lanes);
    const Wide gap = wide_of(lanes, [](const Situation& s) { return s.gap; });
    const Wide normal_velocity = wide_of(lanes, [](const Situation& s) { return s.normal_velocity; });
    const Wide slip = wide_of(lanes, [](const Situation& s) { return s.slip_velocity; });
    const CornerState<Wide> previous{wide_of(lanes, [](const Situation& s) { return s.shear_spring; }),
                                     wide_of(lanes, [](const Situation& s) { return s.slipping; })};
    const CornerContact<Wide> got = corner_contact<Law>(m, p, 0, gap, half_step(normal_velocity, slip), previous);
    for (std::size_t l = 0; l < kWidth; ++l) {
      const CornerContact<double> want = law_2d<Law>(m, *lanes[l]);
      ASSERT_TRUE(same_bits(lane_of(got.normal_force, l), want.normal_force));
      ASSERT_TRUE(same_bits(lane_of(got.shear_force, l), want.shear_force));
      ASSERT_TRUE(same_bits(lane_of(got.next.shear_spring, l), want.next.shear_spring));
      ASSERT_TRUE(same_bits(lane_of(got.next.slipping, l), want.next.slipping));
    }
    // Which way the batch went, with the 2D law's own test of its forces.
    const Wide ks(m.corner_shear_stiffness[0]);
    const Wide trial = previous.shear_spring - ks * slip * Wide(m.time_step);
    const Wide sticking = trial + -p.damping_beta * ks * slip;
    const int way = way_taken<Law>(m, p, xsimd::abs(slip), previous.slipping, got.normal_force, [&](const Wide& floor) {
      return xsimd::abs(trial) <= floor && xsimd::abs(sticking) <= floor;
    });
    if (way != 0) ways[way > 0 ? 0 : 1]++;
  }
  if (table < 2) expect_both_ways(ways);  // the tables with a zero row have no floor
}

TEST(FrictionLimit, TheFloorChangesNoBitOfTheExponentialLaw2D) { expect_the_law_2d<FrictionLaw::exponential>(0); }
TEST(FrictionLimit, TheFloorChangesNoBitOfTheTabulatedLaw2D) {
  for (int table = 0; table < kTables; ++table) expect_the_law_2d<FrictionLaw::tabulated>(table);
}

template <FrictionLaw Law>
void expect_the_law_3d(int table) {
  std::mt19937_64 random(11);
  const Model m = model_with(Law, table);
  const std::vector<Situation> all = situations<Law>(m, random);
  int ways[2] = {0, 0};
  // Batches whose every lane skips (index 0) or not (1): the division of the stiffness kept, the
  // trial force's root, the transmitted force's root (shear_contact's shortcuts, as it decides
  // them at the exact limit).
  int kept_ways[2] = {0, 0}, trial_ways[2] = {0, 0}, magnitude_ways[2] = {0, 0};
  for (std::size_t i = 0; i + kWidth <= all.size(); i += kWidth) {
    std::array<const Situation*, kWidth> lanes;
    for (std::size_t l = 0; l < kWidth; ++l) {
      lanes[l] = &all[i + l];
      const Situation& s = *lanes[l];
      const double normal = normal_force(m, m.corner_normal_stiffness[0], s.p, s.gap, s.normal_velocity);
      ContactState3D<double> got_state = state_3d(s), want_state = state_3d(s);
      const Vector3<double> got =
          shear_contact<Law>(m, s.p, s.gap < 0.0, true, normal, m.corner_shear_stiffness[0], std::max(-s.gap, 0.0),
                             half_step(s.normal_velocity, s.slip_velocity, s.slip_z), got_state);
      const Vector3<double> want = law_3d<Law>(m, s, want_state);
      ASSERT_TRUE(same_bits(got.x, want.x)) << got.x << " vs " << want.x;
      ASSERT_TRUE(same_bits(got.z, want.z));
      ASSERT_TRUE(same_bits(got_state.shear_x, want_state.shear_x));
      ASSERT_TRUE(same_bits(got_state.shear_z, want_state.shear_z));
      ASSERT_TRUE(same_bits(got_state.stiffness, want_state.stiffness));
      ASSERT_TRUE(same_bits(got_state.slipping, want_state.slipping));
    }
    const LaneParameters<Wide> p = gather_parameters<Wide>(lanes);
    const Wide gap = wide_of(lanes, [](const Situation& s) { return s.gap; });
    const Wide normal = normal_force(m, Wide(m.corner_normal_stiffness[0]), p, gap,
                                     wide_of(lanes, [](const Situation& s) { return s.normal_velocity; }));
    const Wide slip_x = wide_of(lanes, [](const Situation& s) { return s.slip_velocity; });
    const Wide slip_z = wide_of(lanes, [](const Situation& s) { return s.slip_z; });
    const ContactState3D<Wide> before{wide_of(lanes, [](const Situation& s) { return s.shear_spring; }),
                                      wide_of(lanes, [](const Situation& s) { return s.shear_z; }),
                                      wide_of(lanes, [](const Situation& s) { return s.stiffness; }),
                                      wide_of(lanes, [](const Situation& s) { return s.slipping; })};
    ContactState3D<Wide> state = before;
    const Wide ks(m.corner_shear_stiffness[0]);
    const Vector3<Wide> got = shear_contact<Law>(m, p, gap < Wide(0.0), Wide(0.0) == Wide(0.0), normal, ks,
                                                 lane::max(-gap, Wide(0.0)), half_step(Wide(0.0), slip_x, slip_z), state);
    for (std::size_t l = 0; l < kWidth; ++l) {
      ContactState3D<double> want_state = state_3d(*lanes[l]);
      const Vector3<double> want = law_3d<Law>(m, *lanes[l], want_state);
      ASSERT_TRUE(same_bits(lane_of(got.x, l), want.x));
      ASSERT_TRUE(same_bits(lane_of(got.z, l), want.z));
      ASSERT_TRUE(same_bits(lane_of(state.shear_x, l), want_state.shear_x));
      ASSERT_TRUE(same_bits(lane_of(state.shear_z, l), want_state.shear_z));
      ASSERT_TRUE(same_bits(lane_of(state.stiffness, l), want_state.stiffness));
      ASSERT_TRUE(same_bits(lane_of(state.slipping, l), want_state.slipping));
    }
    // Which way the batch went, with the 3D spring-slider's own test of its forces.
    const Wide one(1.0);
    const auto had = before.stiffness > Wide(0.0);
    kept_ways[xsimd::all(!had || before.stiffness == ks) ? 0 : 1]++;
    const Wide kept = xsimd::select(had, xsimd::min(one, ks / xsimd::select(had, before.stiffness, one)), Wide(0.0));
    const Wide trial_x = before.shear_x * kept - ks * slip_x * Wide(m.time_step);
    const Wide trial_z = before.shear_z * kept - ks * slip_z * Wide(m.time_step);
    const Wide sticking_x = trial_x + -p.damping_beta * ks * slip_x;
    const Wide sticking_z = trial_z + -p.damping_beta * ks * slip_z;
    const Wide speed = xsimd::sqrt(slip_x * slip_x + slip_z * slip_z);
    const int way = way_taken<Law>(m, p, speed, before.slipping, normal, [&](const Wide& floor) {
      const Wide inside = floor * Wide(1.0 - 1e-12);
      return trial_x * trial_x + trial_z * trial_z <= inside * inside &&
             sticking_x * sticking_x + sticking_z * sticking_z <= inside * inside;
    });
    if (way != 0) ways[way > 0 ? 0 : 1]++;
    const Wide exact = friction_coefficient<Law>(m, p, speed, before.slipping > Wide(0.5)) * normal;
    trial_ways[xsimd::all(lane::root_not_above(trial_x * trial_x + trial_z * trial_z, exact)) ? 0 : 1]++;
    // The force transmitted equals the force before the clip where that is decided within the
    // limit, and is the limit itself (not decided within it) where the clip acted.
    magnitude_ways[xsimd::all(lane::root_not_above(got.x * got.x + got.z * got.z, exact)) ? 0 : 1]++;
  }
  if (table < 2) expect_both_ways(ways);
  for (const int* w : {kept_ways, trial_ways, magnitude_ways}) {
    EXPECT_GT(w[0], 100) << "batches that skip a root or a division";
    EXPECT_GT(w[1], 100) << "batches that take it";
  }
}

TEST(FrictionLimit, TheFloorChangesNoBitOfTheExponentialLaw3D) { expect_the_law_3d<FrictionLaw::exponential>(0); }
TEST(FrictionLimit, TheFloorChangesNoBitOfTheTabulatedLaw3D) {
  for (int table = 0; table < kTables; ++table) expect_the_law_3d<FrictionLaw::tabulated>(table);
}

}  // namespace
}  // namespace caskdem::kernels
