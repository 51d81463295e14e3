// `caskdem risk` as a user runs it: a given fragility against a power-law hazard table gives
// the closed-form annual frequency and the published HCLPF in its JSON, the lower HCLPF named;
// an ensemble's result file gives one annual frequency per fitted limit state, refused against a
// hazard of another intensity measure, a 1/N model's taken to full size by itself, and an answer
// resting on a rejected fit says so; a given fragility names its measure; a curve that stops
// short of the fragility is refused in one line.

#include <cmath>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/hdf5_file.h"
#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;
using testing::Outcome;
using testing::run_caskdem;

class RiskCommand : public testing::TemporaryFiles {
 protected:
  // H = 1e-4 a^-k (a in g) from 0.002 to 50 g.
  std::filesystem::path power_law(const std::string& name, double k, double low = 0.002, double high = 50.0) const {
    std::ostringstream text;
    text.precision(17);
    text << "PGA [g], annual frequency\n";
    for (int i = 0; i <= 40; ++i) {
      const double a = low * std::pow(high / low, i / 40.0);
      text << a << ", " << 1e-4 * std::pow(a, -k) << "\n";
    }
    return write(name, text.str());
  }
};

TEST_F(RiskCommand, AGivenFragilityGivesTheClosedFormAndThePublishedHclpf) {
  const double k = 2.0;
  const auto hazard = power_law("site.csv", k);
  const auto json = dir_ / "risk.json";
  const Outcome o = run_caskdem("risk --hazard " + hazard.string() +
                                " --median \"0.9 g\" --measure PGA --beta-r 0.25 --beta-u 0.30 --design-basis \"0.3 g\" --json " +
                                json.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("annual frequency"));
  const nlohmann::json r = nlohmann::json::parse(testing::file_text(json));
  const auto& state = r["limit_states"][0];
  const double at_median = 1e-4 * std::pow(0.9, -k);
  const double beta_c2 = 0.25 * 0.25 + 0.30 * 0.30;
  EXPECT_NEAR(state["mean_annual_frequency"].get<double>() / (at_median * std::exp(k * k * beta_c2 / 2.0)), 1.0, 1e-7);
  EXPECT_NEAR(state["median_annual_frequency"].get<double>() / (at_median * std::exp(k * k * 0.0625 / 2.0)), 1.0, 1e-7);
  EXPECT_NEAR(state["hclpf_conservative"].get<double>(), 0.3642, 5e-5);
  EXPECT_NEAR(state["hclpf_composite"].get<double>(), 0.3628, 5e-5);
  // The lower of the two is the one named, and the one set against the design basis.
  EXPECT_NEAR(state["hclpf_lower"].get<double>(), 0.3628, 5e-5);
  EXPECT_THAT(o.output, HasSubstr("(the lower: 1 % of the composite curve)"));
  EXPECT_NEAR(state["hclpf_to_design_basis"].get<double>(), 0.3628 / 0.3, 2e-4);
  EXPECT_TRUE(state["fractiles_sampled"].get<bool>());
  const double mean = state["mean_annual_frequency"].get<double>();
  EXPECT_NEAR(state["probability_in_years"].get<double>(), -std::expm1(-50.0 * mean), 1e-15);
  EXPECT_NEAR(state["ratio_to_target"].get<double>(), mean / 1e-5, 1e-9);
}

TEST_F(RiskCommand, AnEnsembleResultGivesEachFittedLimitStateItsFrequencyInItsOwnMeasure) {
  const std::string source = CASKDEM_SOURCE_DIR;
  const auto result = dir_ / "mixed.h5";
  ASSERT_EQ(run_caskdem("ensemble " + source + "/tests/ensemble/data/mixed-outcomes.toml --out " + result.string() +
                        " --threads 1 --quiet --no-plot")
                .status,
            0);
  // The test ensemble's measure is PGA: a PGA hazard is read, a PGV one refused.
  const Outcome ok = run_caskdem("risk " + result.string() + " --hazard " + power_law("pga.csv", 2.0).string() + " --no-plot");
  ASSERT_EQ(ok.status, 0) << ok.output;
  const nlohmann::json r = nlohmann::json::parse(testing::file_text(dir_ / "mixed-risk.json"));
  ASSERT_FALSE(r["limit_states"].empty());
  const hdf5::Group root = hdf5::open_file(result);
  for (const auto& state : r["limit_states"]) {
    // The median as the file holds it (PGA in m/s^2), in g.
    const hdf5::Group fit = root.open_group("limit_states").open_group(state["name"].get<std::string>());
    EXPECT_NEAR(state["median"].get<double>(), fit.double_attribute("median") / 9.80665, 1e-12);
    EXPECT_DOUBLE_EQ(state["beta_r"].get<double>(), fit.double_attribute("log_std"));
    // And the answer in the file's /risk group, which leaves the file sealed and whole.
    const hdf5::Group written = root.open_group("risk").open_group(state["name"].get<std::string>());
    EXPECT_DOUBLE_EQ(written.double_attribute("mean_annual_frequency"), state["mean_annual_frequency"].get<double>());
    // Against H = 1e-4 a^-2 with beta_U = 0: H(A_m) exp(2 beta^2), from the file's own fit.
    const double m = state["median"].get<double>(), beta = state["beta_r"].get<double>();
    EXPECT_NEAR(state["mean_annual_frequency"].get<double>() / (1e-4 * std::pow(m, -2.0) * std::exp(2.0 * beta * beta)), 1.0,
                1e-6)
        << state["name"];
  }
  const auto pgv = write("pgv.csv", "PGV [cm/s], annual frequency\n1, 1e-2\n1000, 1e-8\n");
  const Outcome refused = run_caskdem("risk " + result.string() + " --hazard " + pgv.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_THAT(refused.output, HasSubstr("its fragility curves are of PGA but the hazard curve " + pgv.string() + " is of PGV"));
}

TEST_F(RiskCommand, AModelsFragilityIsSetAgainstTheSiteAsThePrototypes) {
  // A 1/3 model's PGV capacity of 40 cm/s is a prototype's 40 sqrt(3) cm/s (lengths 1/3,
  // times 1/sqrt(3)); against H = 1e-4 (v / 1 cm/s)^-2 its frequency is H(40 sqrt 3) e^(2 beta^2).
  std::ostringstream text;
  text.precision(17);
  text << "PGV [cm/s], annual frequency\n";
  for (int i = 0; i <= 40; ++i) {
    const double v = 0.1 * std::pow(1e5, i / 40.0);
    text << v << ", " << 1e-4 * std::pow(v, -2.0) << "\n";
  }
  const auto hazard = write("pgv.csv", text.str());
  const auto json = dir_ / "model.json";
  const Outcome o = run_caskdem("risk --hazard " + hazard.string() +
                                " --median \"40 cm/s\" --measure PGV --beta 0.3 --similarity 3 --json " + json.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const nlohmann::json report = nlohmann::json::parse(testing::file_text(json));
  const auto& state = report["limit_states"][0];
  EXPECT_NEAR(state["median"].get<double>(), 40.0 * std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(state["mean_annual_frequency"].get<double>() / (1e-4 * std::pow(40.0 * std::sqrt(3.0), -2.0) * std::exp(2.0 * 0.09)),
              1.0, 1e-7);
  // Without beta_U nothing epistemic was sampled: no range of fractiles, said so.
  EXPECT_TRUE(state["fractile_05_annual_frequency"].is_null());
  EXPECT_FALSE(state["fractiles_sampled"].get<bool>());
  EXPECT_THAT(o.output, HasSubstr("fractiles not sampled"));
}

// The main job's ensemble, fewer realisations: a 1/3 model's result file. risk takes its curves
// to full size by itself; --similarity 3 gives the same answer and --similarity 1 the model's.
TEST_F(RiskCommand, AModelsResultFileIsTakenToFullSizeByItself) {
  const auto ensemble = variant_of(std::string(CASKDEM_SOURCE_DIR) + "/ensembles/model-1-3-builtin.toml", "small.toml",
                                   "realisations = 80", "realisations = 16");
  const auto result = dir_ / "small.h5";
  ASSERT_EQ(run_caskdem("ensemble " + ensemble.string() + " --out " + result.string() + " --quiet --no-plot").status, 0);
  EXPECT_DOUBLE_EQ(hdf5::open_file(result).double_attribute("model_scale"), 3.0);
  const std::string hazard = std::string(CASKDEM_SOURCE_DIR) + "/hazard/example-site-pgv.csv";
  const auto frequency = [&](const std::string& option, const std::string& json) {
    const Outcome o = run_caskdem("risk " + result.string() + " --hazard " + hazard + option + " --no-plot --json " +
                                  (dir_ / json).string());
    EXPECT_EQ(o.status, 0) << o.output;
    const nlohmann::json r = nlohmann::json::parse(testing::file_text(dir_ / json));
    return std::pair{r["limit_states"][0]["mean_annual_frequency"].get<double>(), o.output};
  };
  const auto [by_itself, said] = frequency("", "itself.json");
  EXPECT_THAT(said, HasSubstr("the fragility is a 1/3 model's (the result file's motions are prototype motions on it)"));
  EXPECT_EQ(frequency(" --similarity 3", "three.json").first, by_itself);
  EXPECT_GT(frequency(" --similarity 1", "one.json").first, 1.5 * by_itself) << "the model's curves, a weaker cask";
}

// A curve whose fit failed its test: the answer says what it rests on.
TEST_F(RiskCommand, AnAnswerOnARejectedFitSaysSo) {
  const auto ensemble = variant_of(std::string(CASKDEM_SOURCE_DIR) + "/ensembles/model-1-3-builtin.toml", "small.toml",
                                   "realisations = 80", "realisations = 16");
  const auto result = dir_ / "small.h5";
  ASSERT_EQ(run_caskdem("ensemble " + ensemble.string() + " --out " + result.string() + " --quiet --no-plot").status, 0);
  // The tip-over curve marked rejected, as its test would mark it, and the file sealed again.
  hdf5::Group root = hdf5::open_sealed_in_memory(result, "a result file of caskdem ensemble");
  hdf5::Group tip = root.open_group("limit_states").open_group("tip_over");
  tip.attribute("fit_rejected", std::int64_t(1));
  tip.attribute("fit_test_p_value", 0.001);
  hdf5::replace_sealed(result, [&] { return hdf5::file_image(root); });
  const Outcome o = run_caskdem("risk " + result.string() + " --hazard " + std::string(CASKDEM_SOURCE_DIR) +
                                "/hazard/example-site-pgv.csv --no-plot --json " + (dir_ / "r.json").string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("rests on a REJECTED fit: the ensemble's curve fails its test at 5 % (p 0.001"));
  const nlohmann::json r = nlohmann::json::parse(testing::file_text(dir_ / "r.json"));
  for (const auto& state : r["limit_states"]) {
    if (state["name"] == "tip_over") {
      EXPECT_TRUE(state["fit_rejected"].get<bool>());
    }
  }
}

// A given fragility names its measure; a hazard of another is refused, as is none given.
TEST_F(RiskCommand, AGivenFragilityOfAnotherMeasureThanTheHazardIsRefused) {
  const auto sa = write("SA1.csv", "SA(1.0) [g], annual frequency\n0.001, 1e-1\n10, 1e-7\n");
  const Outcome pga = run_caskdem("risk --hazard " + sa.string() + " --median \"0.9 g\" --measure PGA --beta 0.4");
  EXPECT_EQ(pga.status, 2) << pga.output;
  EXPECT_THAT(pga.output, HasSubstr("--measure PGA: the fragility is of PGA but the hazard curve " + sa.string() +
                                    " is of SA(1); expected a hazard curve of PGA"));
  const Outcome none = run_caskdem("risk --hazard " + sa.string() + " --median \"0.9 g\" --beta 0.4");
  EXPECT_EQ(none.status, 2) << none.output;
  EXPECT_THAT(none.output, HasSubstr("--measure: a given fragility needs its intensity measure"));
  const Outcome same = run_caskdem("risk --hazard " + sa.string() + " --median \"0.9 g\" --measure \"SA(1.0)\" --beta 0.4 "
                                   "--no-plot --json " + (dir_ / "sa.json").string());
  EXPECT_EQ(same.status, 0) << same.output;
}

TEST_F(RiskCommand, ACurveThatStopsShortIsRefusedInOneLine) {
  const auto hazard = power_law("short.csv", 2.0, 0.002, 1.0);
  const Outcome o = run_caskdem("risk --hazard " + hazard.string() + " --median \"0.9 g\" --measure PGA --beta 0.4");
  EXPECT_EQ(o.status, 2);
  EXPECT_THAT(o.output, HasSubstr(hazard.string() + ": given: the hazard curve ends at 1 g"));
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  const Outcome both =
      run_caskdem("risk --hazard " + hazard.string() + " --median \"0.9 g\" --measure PGA --beta 0.4 --beta-r 0.3");
  EXPECT_EQ(both.status, 2);
  EXPECT_THAT(both.output, HasSubstr("--beta: give either --beta"));
  const Outcome unit =
      run_caskdem("risk --hazard " + hazard.string() + " --median \"0.9 cm/s\" --measure PGA --beta 0.4");
  EXPECT_EQ(unit.status, 2);
  EXPECT_THAT(unit.output, HasSubstr("--median: \"0.9 cm/s\"; expected an acceleration"));
}

}  // namespace
}  // namespace caskdem
