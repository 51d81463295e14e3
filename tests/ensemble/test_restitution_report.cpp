// The restitution line of the ensemble's header: the damping ratios it prints for the sampled
// restitutions are checked against free rocking run afresh at those ratios (the source paper's
// restitution, eq. 1), not against the calibration curve that produced them.

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "ensemble/report_text.h"
#include "sim/free_vibration.h"

namespace caskdem {
namespace {

std::string data_file(const std::string& name) {
  return std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/" + name;
}

TEST(RestitutionReport, ThePrintedDampingRatiosGiveThePrintedRestitutionsInFreeRocking) {
  const EnsembleSpec spec = load_ensemble(data_file("mixed-outcomes.toml"));  // uniform 0.94 to 0.97
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  const std::string text = restitution_text(plan);
  double low = 0.0, high = 0.0, damping_low = 0.0, damping_high = 0.0, reach_low = 0.0, reach_high = 0.0;
  ASSERT_EQ(std::sscanf(text.c_str(),
                        "%lf to %lf -> damping ratio %lf to %lf (the nominal cask's free rocking at this step, which "
                        "reaches %lf to %lf)",
                        &low, &high, &damping_low, &damping_high, &reach_low, &reach_high),
            6)
      << text;
  // 256 draws from 0.94 to 0.97 (a fixed stream): the extremes lie inside, within 1 % of the range
  // of its ends (a uniform sample misses that by chance with probability 2 x 0.99^256 = 0.15; this
  // stream's does not, and it cannot change).
  EXPECT_GE(low, 0.94);
  EXPECT_LE(high, 0.97);
  EXPECT_LT(low, 0.94 + 0.01 * 0.03);
  EXPECT_GT(high, 0.97 - 0.01 * 0.03);
  EXPECT_GT(damping_low, damping_high) << "the highest restitution needs the least damping";
  EXPECT_LE(reach_low, low);
  EXPECT_GE(reach_high, high);
  for (const auto& [restitution, damping] : {std::pair{low, damping_low}, std::pair{high, damping_high}}) {
    RealisationParameters p = plan.nominal();
    p.damping_ratio = damping;
    const double reached = free_vibration(plan.model(), p, spec.base.free_vibration).restitution;
    // The curve is interpolated between 48 damping ratios and made monotone where the undamped
    // springs' exchange makes free rocking wander by a few 1e-4 (ensemble/plan.cpp); the printed
    // ratio has 3 digits: 1e-3 leaves room for that wander (measured: 4e-5 and 2.6e-4).
    EXPECT_NEAR(reached, restitution, 1e-3) << "damping ratio " << damping;
    RecordProperty("error_at_" + std::to_string(restitution), std::to_string(reached - restitution));
  }
}

TEST(RestitutionReport, AnEnsembleWithoutUncertainRestitutionPrintsNone) {
  const EnsembleSpec spec = load_ensemble(data_file("resume.toml"));
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  EXPECT_EQ(restitution_text(plan), "");
}

}  // namespace
}  // namespace caskdem
