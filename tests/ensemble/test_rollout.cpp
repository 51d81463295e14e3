// Realisations a caller chooses (ensemble/rollout.h): the file's own, given back as columns, are
// the plan's to the bit, planar and 3D; they run to the file's outcomes on the CPU and on queued
// lanes in a GPU's place; a caller's rows are checked against what the plan can run. The
// Python module's tests (tests/python/test_rollout.py) compare with the command line's file.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "core/error.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/execute.h"
#include "ensemble/rollout.h"
#include "kernels/lane_device.h"

namespace caskdem {
namespace {

const std::string kData = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/";

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

class RolloutTest : public testing::TestWithParam<std::string> {};

TEST_P(RolloutTest, TheFilesColumnsGiveThePlansRealisations) {
  EnsemblePlan plan(load_ensemble(kData + GetParam()), InstructionSet::automatic);
  const ParameterColumns columns = plan_columns(plan);
  const std::vector<RealisationInput> chosen =
      realisations_from_columns(plan, columns, plan.size(), InstructionSet::automatic);
  ASSERT_EQ(static_cast<std::int64_t>(chosen.size()), plan.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) {
    const RealisationInput a = plan.realisation(i), &b = chosen[static_cast<std::size_t>(i)];
    ASSERT_EQ(a.motion, b.motion) << i;
    const RealisationParameters &p = a.parameters, &q = b.parameters;
    for (auto [x, y] : {std::pair{p.friction_static, q.friction_static},
                        {p.friction_kinetic, q.friction_kinetic},
                        {p.friction_decay_speed, q.friction_decay_speed},
                        {p.damping_ratio, q.damping_ratio},
                        {p.mass, q.mass},
                        {p.inertia, q.inertia},
                        {p.axial_inertia, q.axial_inertia},
                        {p.centre_of_mass.x, q.centre_of_mass.x},
                        {p.centre_of_mass.y, q.centre_of_mass.y},
                        {p.horizontal_scale, q.horizontal_scale},
                        {p.vertical_scale, q.vertical_scale},
                        {a.incidence, b.incidence},
                        {a.restitution, b.restitution}}) {
      ASSERT_TRUE(same_bits(x, y)) << GetParam() << " realisation " << i << ": " << x << " against " << y;
    }
  }
}

TEST_P(RolloutTest, ChosenRealisationsRunToTheFilesOutcomesOnTheCpuAndOnQueuedLanes) {
  EnsemblePlan plan(load_ensemble(kData + GetParam()), InstructionSet::automatic);
  const MotionTables tables(plan, MotionTables::kDeviceBudgetBytes);
  RolloutOptions cpu;
  cpu.threads = 2;
  const EnsembleResults file = rollout(plan, tables, cpu);  // the plan's own realisations

  // Every fifth of the file's realisations, last first: row r is realisation picked[r].
  std::vector<std::int64_t> picked;
  for (std::int64_t i = plan.size() - 1; i >= 0; i -= 5) picked.push_back(i);
  ParameterColumns columns = plan_columns(plan);
  for (auto& [name, values] : columns) {
    std::vector<double> rows;
    for (std::int64_t i : picked) rows.push_back(values[static_cast<std::size_t>(i)]);
    values = rows;
  }
  const auto count = static_cast<std::int64_t>(picked.size());
  EnsemblePlan chosen = plan;
  chosen.set_realisations(realisations_from_columns(plan, columns, count, InstructionSet::automatic));
  const std::unique_ptr<LaneDevice> lanes = open_host_lane_device(16);
  RolloutOptions device;
  device.device = lanes.get();
  std::int64_t last = 0;
  device.on_progress = [&](std::int64_t done) {
    EXPECT_GT(done, last);
    last = done;
  };
  for (const EnsembleResults& ran : {rollout(chosen, tables, cpu), rollout(chosen, tables, device)}) {
    ASSERT_EQ(ran.completed_count(), count);
    const auto a = file.columns(), b = ran.columns();
    for (std::size_t c = 0; c < a.size(); ++c) {
      if (a[c].name == "level" || a[c].name == "stripe") continue;  // a chosen row has no stripe
      for (std::int64_t r = 0; r < count; ++r) {
        const auto i = static_cast<std::size_t>(picked[static_cast<std::size_t>(r)]);
        if (a[c].real) {
          ASSERT_TRUE(same_bits((*a[c].real)[i], (*b[c].real)[r])) << a[c].name << " row " << r;
        } else {
          ASSERT_EQ((*a[c].integer)[i], (*b[c].integer)[r]) << a[c].name << " row " << r;
        }
      }
    }
  }
  EXPECT_EQ(last, count);
}

INSTANTIATE_TEST_SUITE_P(PlanarAnd3D, RolloutTest, testing::Values("mixed-outcomes.toml", "mixed-outcomes-3d.toml"),
                         [](const auto& info) {
                           return info.param.find("3d") != std::string::npos ? "spatial" : "planar";
                         });

TEST(Rollout, RowsThePlanCannotRunAreRefusedByColumnAndRow) {
  EnsemblePlan plan(load_ensemble(kData + "mixed-outcomes.toml"), InstructionSet::automatic);
  const auto refused = [&](const ParameterColumns& columns, std::int64_t count, const std::string& words) {
    try {
      (void)realisations_from_columns(plan, columns, count, InstructionSet::automatic);
      ADD_FAILURE() << "accepted; expected " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused({{"motion", {0, 1}}, {"scale_factor", {1.0}}, {"mass", {plan.lightest_mass(), 0.5 * plan.lightest_mass()}}},
          2, "mass, row 1");
  refused({{"motion", {0}}, {"level", {-1.0}}}, 1, "level, row 0");
  refused({{"motion", {0}}, {"scale_factor", {1.0}}, {"incidence", {0.1}}}, 1, "incidence");
  refused({{"motion", {0}}, {"scale_factor", {1.0}}, {"friction", {0.1}}}, 1, "friction: not a parameter");
  refused({{"motion", {0}}, {"scale_factor", {1.0}}}, 0, "at least one realisation");
  // The lightest mass the time step was chosen for is accepted, and its inertia scales with it.
  const auto rows = realisations_from_columns(
      plan, {{"motion", {1}}, {"scale_factor", {2.0}}, {"mass", {plan.lightest_mass()}}}, 1, InstructionSet::automatic);
  EXPECT_DOUBLE_EQ(rows[0].parameters.inertia / rows[0].parameters.mass, plan.nominal().inertia / plan.nominal().mass);
  EXPECT_DOUBLE_EQ(rows[0].level, plan.intensity_of(1, 2.0));
}

}  // namespace
}  // namespace caskdem
