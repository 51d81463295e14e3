// An ensemble with epistemic parameters, run end to end: each outer point holds its epistemic
// values fixed (one per stratum of a Latin hypercube over the outer points) and draws its
// aleatory values afresh (outer point 0 as the same ensemble without epistemic parameters
// would, the others their own Latin hypercube per stripe); the result file
// carries each limit state's family (A_m, beta_R, beta_U with their intervals), and
// `caskdem risk` takes beta_U from it.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ensemble/plan.h"
#include "io/hdf5_file.h"
#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;

class EpistemicEnsemble : public testing::TemporaryFiles {
 protected:
  // The test ensemble with `parameter` epistemic at `points` outer points of `per_stripe`
  // realisations per stripe.
  std::filesystem::path nested(const std::string& parameter, int points, int per_stripe) const {
    std::string text = testing::file_text(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
    text = std::regex_replace(text, std::regex("\\[uncertain." + parameter + "\\]\n"),
                              "[uncertain." + parameter + "]\nkind = \"epistemic\"\n");
    text = std::regex_replace(text, std::regex("seed = 7\n"), "seed = 7\nepistemic_points = " + std::to_string(points) + "\n");
    text = std::regex_replace(text, std::regex("realisations = 64"), "realisations = " + std::to_string(per_stripe));
    return write("nested.toml", text);
  }
};

TEST_F(EpistemicEnsemble, EachOuterPointHoldsItsEpistemicValuesAndDrawsItsOwnAleatorySample) {
  const EnsemblePlan plan(load_ensemble(nested("friction_static", 5, 16)), InstructionSet::scalar);
  std::string flat_text = testing::file_text(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
  flat_text = std::regex_replace(flat_text, std::regex("realisations = 64"), "realisations = 16");
  const EnsemblePlan flat(load_ensemble(write("flat.toml", flat_text)), InstructionSet::scalar);
  const EnsembleSpec& spec = plan.spec();
  ASSERT_EQ(spec.outer_count(), 5);
  ASSERT_EQ(plan.size(), 5 * 4 * 16);
  const std::int64_t per_outer = spec.realisations_per_outer_point();
  std::vector<double> outer_friction;
  for (int o = 0; o < 5; ++o) {
    const double friction = plan.realisation(o * per_outer).parameters.friction_static;
    outer_friction.push_back(friction);
    for (std::int64_t i = 0; i < per_outer; ++i) {
      const RealisationInput in = plan.realisation(o * per_outer + i);
      EXPECT_EQ(in.outer, o);
      EXPECT_EQ(in.parameters.friction_static, friction) << "outer point " << o << ", realisation " << i;
      // The same stripe and motion as at outer point 0, but an aleatory sample of its own.
      const RealisationInput first = plan.realisation(i);
      EXPECT_EQ(in.stripe, first.stripe);
      EXPECT_EQ(in.motion, first.motion);
      if (o == 0) {
        EXPECT_EQ(in.parameters.friction_kinetic, flat.realisation(i).parameters.friction_kinetic);
        EXPECT_EQ(in.restitution, flat.realisation(i).restitution);
      } else {
        EXPECT_NE(in.parameters.friction_kinetic, first.parameters.friction_kinetic) << "outer point " << o;
      }
    }
    // Within each stripe of each outer point a Latin hypercube: the 16 kinetic frictions of
    // U(0.06, 0.6) fall one in each sixteenth.
    for (int s = 0; s < 4; ++s) {
      std::set<int> cells;
      for (int j = 0; j < 16; ++j) {
        const double mu = plan.realisation(o * per_outer + s * 16 + j).parameters.friction_kinetic;
        cells.insert(static_cast<int>((mu - 0.06) / (0.54 / 16.0)));
      }
      EXPECT_EQ(cells.size(), 16u) << "outer point " << o << ", stripe " << s;
    }
  }
  // A Latin hypercube over the outer points: one value in each fifth of U(0.08, 0.8).
  std::set<int> strata;
  for (double f : outer_friction) strata.insert(static_cast<int>((f - 0.08) / (0.72 / 5.0)));
  EXPECT_EQ(strata.size(), 5u);
}

TEST_F(EpistemicEnsemble, TheResultCarriesTheFamilyAndRiskTakesBetaUFromIt) {
  // The restitution moves each outer point's curve a little: every outer point's stripes
  // still span its capacity.
  const auto file = nested("restitution", 4, 64);
  const auto result = dir_ / "nested.h5";
  const testing::Outcome run =
      testing::run_caskdem("ensemble " + file.string() + " --out " + result.string() + " --threads 1 --no-plot");
  ASSERT_EQ(run.status, 0) << run.output;
  const hdf5::Group root = hdf5::open_file(result);
  EXPECT_EQ(root.integer_attribute("epistemic_points"), 4);
  EXPECT_EQ(root.string_attribute("epistemic_parameters"), "restitution");
  int families = 0;
  for (const std::string& name : root.open_group("limit_states").member_names()) {
    const hdf5::Group e = root.open_group("limit_states").open_group(name).open_group("epistemic");
    EXPECT_EQ(e.read_doubles("outer_median").size(), 4u);
    if (e.integer_attribute("fitted") == 0) {
      EXPECT_THAT(run.output, HasSubstr("no family: " + e.string_attribute("not_fitted_because")));
      continue;
    }
    ++families;
    const double median = e.double_attribute("median"), beta_u = e.double_attribute("beta_u");
    EXPECT_LE(e.double_attribute("median_low"), median);
    EXPECT_GE(e.double_attribute("median_high"), median);
    EXPECT_LE(e.double_attribute("beta_u_low"), beta_u);
    EXPECT_GE(e.double_attribute("beta_u_high"), beta_u);
    // The family's median is the geometric mean of the outer points' medians.
    double log_sum = 0.0;
    for (double m : e.read_doubles("outer_median")) log_sum += std::log(m);
    EXPECT_NEAR(std::log(median), log_sum / 4.0, 1e-12);
    EXPECT_NEAR(e.double_attribute("beta_c"), std::hypot(e.double_attribute("beta_r"), beta_u), 1e-12);
  }
  ASSERT_GT(families, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("family"));
  // The PNG draws the family from the same groups (src/plots/plot_fragility.py).
  const testing::Outcome plot = testing::run_caskdem("plot " + result.string() + " --out " + (dir_ / "family.png").string());
  ASSERT_EQ(plot.status, 0) << plot.output;
  EXPECT_GT(std::filesystem::file_size(dir_ / "family.png"), 0u);

  const auto hazard = write("pga.csv", [] {
    std::string t = "PGA [g], annual frequency\n";
    for (int i = 0; i <= 40; ++i) {
      const double a = 0.002 * std::pow(25000.0, i / 40.0);
      t += std::to_string(a) + ", " + std::to_string(1e-4 * std::pow(a, -2.0)) + "\n";
    }
    return t;
  }());
  const testing::Outcome risk = testing::run_caskdem("risk " + result.string() + " --hazard " + hazard.string() + " --no-plot");
  ASSERT_EQ(risk.status, 0) << risk.output;
  const nlohmann::json r = nlohmann::json::parse(testing::file_text(dir_ / "nested-risk.json"));
  for (const auto& state : r["limit_states"]) {
    const hdf5::Group e = root.open_group("limit_states").open_group(state["name"].get<std::string>()).open_group("epistemic");
    if (e.integer_attribute("fitted") == 0) continue;
    EXPECT_DOUBLE_EQ(state["beta_u"].get<double>(), e.double_attribute("beta_u"));
    EXPECT_DOUBLE_EQ(state["beta_r"].get<double>(), e.double_attribute("beta_r"));
  }
  const testing::Outcome both =
      testing::run_caskdem("risk " + result.string() + " --hazard " + hazard.string() + " --beta-u 0.2 --no-plot");
  EXPECT_EQ(both.status, 2);
  EXPECT_THAT(both.output, HasSubstr("separates beta_U already"));
}

TEST_F(EpistemicEnsemble, EpistemicPointsWithoutAnEpistemicParameterAreRefused) {
  std::string text = testing::file_text(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml");
  text = std::regex_replace(text, std::regex("seed = 7\n"), "seed = 7\nepistemic_points = 10\n");
  const auto file = write("flat.toml", text);
  const std::string message = testing::input_error_of([&] { load_ensemble(file); }, "epistemic_points alone");
  EXPECT_THAT(message, HasSubstr("key sampling.epistemic_points: no [uncertain] parameter has kind = \"epistemic\""));
  text = std::regex_replace(testing::file_text(file), std::regex("distribution = \"uniform\"\nlow = 0.08"),
                            "kind = \"sometimes\"\ndistribution = \"uniform\"\nlow = 0.08");
  const std::string kind = testing::input_error_of([&] { load_ensemble(write("kind.toml", text)); }, "a bad kind");
  EXPECT_THAT(kind, HasSubstr("kind"));
}

}  // namespace
}  // namespace caskdem
