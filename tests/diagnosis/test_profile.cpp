// A mechanism's profile (src/diagnosis/profile.h) on objectives whose profile is known in
// closed form: J_p(theta) at every grid point, the likelihood-ratio statistic and the interval
// against the exact values; a narrow basin of the mechanism that a fit from the baseline's
// values misses and the profile finds; and the best of several baseline starts at each point.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "diagnosis/fitting.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/profile.h"
#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

// The baseline plus a velocity-dependent friction (kinetic ratio r, a switch off at 1; decay
// speed, a shape) on a synthetic specimen.
ModelVariant friction_variant() {
  const testing::TestDirectory directory;
  SyntheticSpec spec;
  spec.seed = 3;
  write_synthetic_measured_set(directory.path(), spec);
  const MeasuredSet set = read_measured_set(directory.path());
  return ModelVariant(set.specimen, {Mechanism::velocity_dependent_friction}, true);
}

// J = 100 |u_b - c(r)|^2 + B(r) in the baseline's unit coordinates u_b: the best baseline moves
// with r (its friction by 0.2 (1 - r) of its range), so the profile is exactly B(r).
struct Coupled {
  const std::vector<Parameter>& space;
  double (*bowl)(double r);
  std::vector<double> operator()(const std::vector<std::vector<double>>& points) const {
    std::vector<double> j;
    for (const std::vector<double>& x : points) {
      const double r = x[3];
      const double centre[3] = {0.4 + 0.2 * (1.0 - r), 0.5, 0.5};
      double sum = 0.0;
      for (int i = 0; i < 3; ++i) sum += 100.0 * std::pow(to_unit(space[i], x[i]) - centre[i], 2);
      j.push_back(sum + bowl(r));
    }
    return j;
  }
};

TEST(Profile, MatchesAProfileKnownInClosedForm) {
  const ModelVariant variant = friction_variant();
  const std::vector<Parameter>& space = variant.parameters();
  ASSERT_EQ(space.size(), 5u);
  ASSERT_EQ(space[3].name, "kinetic_ratio");
  const auto bowl = [](double r) { return 50.0 * (r - 0.6) * (r - 0.6); };
  const Coupled coupled{space, bowl};
  const PopulationObjective objective = [&](const std::vector<std::vector<double>>& points) { return coupled(points); };
  const std::vector<double> baseline = variant.reference();  // a start away from every grid point's optimum
  const Profile p = profile_mechanism(variant, {baseline}, {}, objective);

  // The off point first (r = 1, the decay speed at its reference), then 9 kinetic ratios from
  // 0.3 to 1.5 (1 not among them) and 3 on either side of 1 (1/16, 1/32 and 1/64 of the way to
  // each edge), times 4 decay speeds.
  EXPECT_EQ(p.off, 0u);
  EXPECT_EQ(p.grid.size(), 1u + 15u * 4u);
  int near_off = 0;
  for (const ProfilePoint& point : p.grid) near_off += std::abs(point.values[0] - (1.0 - 0.7 / 64.0)) < 1e-9;
  EXPECT_EQ(near_off, 4);
  for (const ProfilePoint& point : p.grid) {
    EXPECT_NEAR(point.objective, bowl(point.values[0]), 1e-3) << "r " << point.values[0] << ", v0 " << point.values[1];
  }
  EXPECT_NEAR(p.grid[p.minimum].values[0], 0.6, 1e-12);
  EXPECT_NEAR(p.likelihood_ratio, bowl(1.0), 1e-3);                     // 8
  EXPECT_NEAR(p.p_value, std::erfc(std::sqrt(bowl(1.0) / 2.0)), 1e-5);  // chi2_1's tail
  // J_p within 3.841 of its minimum: |r - 0.6| <= 0.277, the grid's 0.45 to 0.75.
  EXPECT_NEAR(p.interval_low[0], 0.45, 1e-12);
  EXPECT_NEAR(p.interval_high[0], 0.75, 1e-12);
  // The decay speed does nothing here: its interval is its whole range.
  EXPECT_NEAR(p.interval_low[1], space[4].low, 1e-12);
  EXPECT_NEAR(p.interval_high[1], space[4].high, 1e-12);
}

TEST(Profile, FindsANarrowBasinAFitFromTheBaselineMisses) {
  const ModelVariant variant = friction_variant();
  const std::vector<Parameter>& space = variant.parameters();
  // Off (r = 1) J_p = 10; a basin 0.08 wide at r = 0.45 down to 2; a shallow rise between.
  const auto bowl = [](double r) {
    return 10.0 + 2.0 * (1.0 - r) * (1.0 - r) - 8.0 * std::exp(-std::pow((r - 0.45) / 0.04, 2));
  };
  const Coupled coupled{space, bowl};
  const PopulationObjective objective = [&](const std::vector<std::vector<double>>& points) { return coupled(points); };
  std::vector<double> start = variant.reference();
  start[0] = from_unit(space[0], 0.4);  // the baseline at its off-value optimum
  start[1] = from_unit(space[1], 0.5);
  start[2] = from_unit(space[2], 0.5);

  // A local search from the baseline's fit, the mechanism off, stays near r = 1.
  FitResult tally;
  std::vector<bool> free(space.size(), true);
  const std::vector<SearchEnd> local = search_from_each(space, {start}, free, objective, 60, 0.1, tally);
  ASSERT_EQ(local.size(), 1u);
  EXPECT_GT(local[0].objective, 9.0) << "r " << local[0].best[3];

  const Profile p = profile_mechanism(variant, {start}, {}, objective);
  EXPECT_NEAR(p.grid[p.minimum].values[0], 0.45, 1e-12);
  EXPECT_NEAR(p.grid[p.minimum].objective, bowl(0.45), 1e-3);
  EXPECT_NEAR(p.likelihood_ratio, 10.0 - bowl(0.45), 1e-3);
}

TEST(Profile, EachPointStartsFromTheBestBaselineThere) {
  // Two baseline basins, the second deeper, and a search budget too small to cross between
  // them: the profile reaches the deeper one because it is among the starts.
  const ModelVariant variant = friction_variant();
  const std::vector<Parameter>& space = variant.parameters();
  const PopulationObjective objective = [&](const std::vector<std::vector<double>>& points) {
    std::vector<double> j;
    for (const std::vector<double>& x : points) {
      const double u = to_unit(space[0], x[0]);
      const double near = 5.0 + 400.0 * (u - 0.2) * (u - 0.2), far = 1.0 + 400.0 * (u - 0.8) * (u - 0.8);
      j.push_back(std::min(near, far) + 10.0 * std::pow(x[3] - 0.9, 2));
    }
    return j;
  };
  std::vector<double> first = variant.reference(), second = first;
  first[0] = from_unit(space[0], 0.2);
  second[0] = from_unit(space[0], 0.8);
  ProfileOptions options;
  options.evaluations = 10;
  const Profile alone = profile_mechanism(variant, {first}, {}, objective, options);
  const Profile both = profile_mechanism(variant, {first, second}, {}, objective, options);
  EXPECT_GT(alone.grid[alone.off].objective, 4.9);
  for (const ProfilePoint& point : both.grid) EXPECT_LT(point.objective, 1.0 + 10.0 * 0.49 + 1e-6);
  // A fitted point given is kept as it is, and the minimum is never above it.
  std::vector<double> fitted = second;
  fitted[3] = 0.9;
  const Profile with_fit = profile_mechanism(variant, {first}, {fitted}, objective, options);
  EXPECT_LE(with_fit.grid[with_fit.minimum].objective, 1.0 + 1e-9);
}

}  // namespace
}  // namespace caskdem::diagnosis
