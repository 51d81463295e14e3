// The test that would settle it (src/diagnosis/plan_test.h), on synthetic measured data:
// candidates that predict alike are not separated by any test; two frictions a factor three
// apart are separated beyond the adequacy bound by a test strong enough to slide the cask under
// one of them and not the other (the onset of sliding is mu g, rigid-plastic theory); every
// proposed sine respects the table's stated limits; and a [table] that cannot be used is one
// clear error naming the file and key.

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/units.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/plan_test.h"
#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

void append(const std::filesystem::path& file, const std::string& text) { std::ofstream(file, std::ios::app) << text; }

struct Made {
  testing::TestDirectory directory;
  MeasuredSet set;
};

void make(Made& made, const std::string& table) {
  SyntheticSpec spec;
  spec.seed = 5;
  write_synthetic_measured_set(made.directory.path(), spec);
  append(made.directory.path() / "specimen.toml", table);
  made.set = read_measured_set(made.directory.path());
}

const std::string kTable =
    "\n[table]\npeak_acceleration = \"0.6 g\"\npeak_velocity = \"0.4 m/s\"\nstroke = \"5 cm\"\n"
    "frequencies = [\"1 Hz\", \"8 Hz\"]\n";

PlanCandidate baseline_at(const MeasuredSet& set, double friction) {
  const ModelVariant variant(set.specimen, {}, set.vertical_measured);
  PlanCandidate c{"friction " + std::to_string(friction), {}, variant.reference(), {}};
  c.point[0] = friction;
  return c;
}

TEST(PlanTest, SeparatesTwoFrictionsWithATestThatSlidesOnlyOne) {
  Made made;
  make(made, kTable);
  ASSERT_TRUE(made.set.settings.table.has_value());
  DiagnosisOptions options;
  options.threads = 2;
  const TestPlan plan =
      plan_tests(made.set, made.set.specimen, {baseline_at(made.set, 0.15), baseline_at(made.set, 0.45)}, options);
  ASSERT_FALSE(plan.tests.empty());
  EXPECT_EQ(plan.limits_source, "specimen.toml [table]");
  const TableLimits& limits = *made.set.settings.table;
  for (const ProposedTest& p : plan.tests) {
    EXPECT_TRUE(std::isfinite(p.separation)) << p.description;
    if (p.kind != "sine") continue;
    EXPECT_LE(p.peak_acceleration, limits.peak_acceleration * (1.0 + 1e-9)) << p.description;
    EXPECT_LE(p.peak_velocity, limits.peak_velocity * (1.0 + 1e-9)) << p.description;
    EXPECT_LE(p.peak_displacement, limits.stroke * (1.0 + 1e-9)) << p.description;
    EXPECT_GE(p.frequency, limits.min_frequency * (1.0 - 1e-9));
    EXPECT_LE(p.frequency, limits.max_frequency * (1.0 + 1e-9));
  }
  // Ranked best first; the best decides between the two on its own.
  for (std::size_t t = 1; t < plan.tests.size(); ++t) EXPECT_GE(plan.tests[t - 1].separation, plan.tests[t].separation);
  const ProposedTest& best = plan.tests.front();
  RecordProperty("best", best.description);
  RecordProperty("separation", std::to_string(best.separation));
  EXPECT_GT(best.separation, 10.83) << best.description;
  // A rigid block slides when the table exceeds mu g: the best test lies beyond the lower onset.
  EXPECT_GT(best.peak_acceleration, 0.15 * units::standard_gravity) << best.description;
  // Below both onsets neither candidate slides or rocks: those tests separate them least.
  for (const ProposedTest& p : plan.tests) {
    if (p.peak_acceleration < 0.1 * units::standard_gravity) {
      EXPECT_LT(p.separation, 1.0) << p.description;
    }
  }
}

TEST(PlanTest, CandidatesThatPredictAlikeAreNotSeparated) {
  Made made;
  make(made, kTable);
  DiagnosisOptions options;
  options.threads = 2;
  PlanCandidate a = baseline_at(made.set, 0.35), b = a;
  b.name = "the same model";
  const TestPlan plan = plan_tests(made.set, made.set.specimen, {a, b}, options);
  for (const ProposedTest& p : plan.tests) EXPECT_EQ(p.separation, 0.0) << p.description;
}

TEST(PlanTest, ATableThatCannotBeUsedIsOneClearError) {
  const struct {
    std::string table, expected;
  } cases[] = {
      {"\n[table]\npeak_velocity = \"0.4 m/s\"\nstroke = \"5 cm\"\nfrequencies = [\"1 Hz\", \"8 Hz\"]\n",
       "peak_acceleration"},
      {"\n[table]\npeak_acceleration = \"-1 g\"\npeak_velocity = \"0.4 m/s\"\nstroke = \"5 cm\"\n"
       "frequencies = [\"1 Hz\", \"8 Hz\"]\n",
       "table.peak_acceleration"},
      {"\n[table]\npeak_acceleration = \"1 g\"\npeak_velocity = \"0.4 m/s\"\nstroke = \"5 cm\"\n"
       "frequencies = [\"8 Hz\", \"1 Hz\"]\n",
       "the lower first"},
      {"\n[table]\npeak_acceleration = \"1 g\"\npeak_velocity = \"0.4 m/s\"\nstroke = \"5 cm\"\n"
       "frequencies = [\"1 Hz\", \"8 Hz\"]\npayload = 3\n",
       "payload"},
  };
  for (const auto& c : cases) {
    testing::TestDirectory directory;
    SyntheticSpec spec;
    write_synthetic_measured_set(directory.path(), spec);
    append(directory.path() / "specimen.toml", c.table);
    try {
      (void)read_measured_set(directory.path());
      ADD_FAILURE() << "accepted: " << c.table;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("specimen.toml"), std::string::npos) << message;
      EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace caskdem::diagnosis
