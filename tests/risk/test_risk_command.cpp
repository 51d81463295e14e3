// `caskdem risk` as a user runs it: a given fragility against a power-law hazard table gives
// the closed-form annual frequency and the published HCLPF in its JSON; an ensemble's result
// file gives one annual frequency per fitted limit state, refused against a hazard of another
// intensity measure; a curve that stops short of the fragility is refused in one line.

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
                                " --median \"0.9 g\" --beta-r 0.25 --beta-u 0.30 --design-basis \"0.3 g\" --json " + json.string());
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
  EXPECT_NEAR(state["hclpf_to_design_basis"].get<double>(), 0.3642 / 0.3, 2e-4);
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
  const Outcome o = run_caskdem("risk --hazard " + hazard.string() + " --median \"40 cm/s\" --beta 0.3 --similarity 3 --json " +
                                json.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const nlohmann::json report = nlohmann::json::parse(testing::file_text(json));
  const auto& state = report["limit_states"][0];
  EXPECT_NEAR(state["median"].get<double>(), 40.0 * std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(state["mean_annual_frequency"].get<double>() / (1e-4 * std::pow(40.0 * std::sqrt(3.0), -2.0) * std::exp(2.0 * 0.09)),
              1.0, 1e-7);
}

TEST_F(RiskCommand, ACurveThatStopsShortIsRefusedInOneLine) {
  const auto hazard = power_law("short.csv", 2.0, 0.002, 1.0);
  const Outcome o = run_caskdem("risk --hazard " + hazard.string() + " --median \"0.9 g\" --beta 0.4");
  EXPECT_EQ(o.status, 2);
  EXPECT_THAT(o.output, HasSubstr(hazard.string() + ": given: the hazard curve ends at 1 g"));
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  const Outcome both = run_caskdem("risk --hazard " + hazard.string() + " --median \"0.9 g\" --beta 0.4 --beta-r 0.3");
  EXPECT_EQ(both.status, 2);
  EXPECT_THAT(both.output, HasSubstr("--beta: give either --beta"));
  const Outcome unit = run_caskdem("risk --hazard " + hazard.string() + " --median \"0.9 cm/s\" --beta 0.4");
  EXPECT_EQ(unit.status, 2);
  EXPECT_THAT(unit.output, HasSubstr("--median: \"0.9 cm/s\"; expected an acceleration"));
}

}  // namespace
}  // namespace caskdem
