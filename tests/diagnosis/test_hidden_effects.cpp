// The diagnosis's answer on whole data sets at the shipped search settings (ctest label
// diagnosis-full, in the gate): data from the baseline model plus noise give "none", whatever
// normal law is compared; with one effect hidden it is named and no second effect is reported;
// and on data its own model did not make (the independent generator), the null, a wrong
// footprint rule, a hidden convex base and the profiles. Every other mechanism named where it is
// hidden, Hunt-Crossley data, and two effects hidden are test_every_mechanism.cpp (label
// diagnosis-more, left out of the gate for its time). Seeds differ from test to test; success
// rates over more seeds are measured outside CI (bench/diagnosis_success.sh,
// docs/diagnosis-accuracy.md).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "diagnosis/diagnose.h"
#include "measured_set.h"  // tests/independent
#include "support/temporary_files.h"
#include "synthetic_diagnosis.h"

namespace caskdem::diagnosis {
namespace {

// The normal laws are compared too (DiagnosisOptions::compare_normal_laws): data made with the
// linear law keep it (test_every_mechanism.cpp has the Hunt-Crossley data).
// Also: a mechanism at its off value is reported with no gain in diagnosis.json (its ratio as
// fitted kept beside it); on these data most mechanisms end there.
TEST(HiddenEffect, BaselineDataGiveNone) {
  const testing::TestDirectory report("report");
  const Diagnosis d = diagnose_synthetic({}, 109, false, "gyration", report.path(), NormalLaw::linear, true);
  RecordProperty("top_gain", std::to_string(d.ranking.front().heldout_gain));
  EXPECT_EQ(d.cause, "none") << "top: " << mechanism_name(d.ranking.front().mechanism) << " gain "
                             << d.ranking.front().heldout_gain;
  EXPECT_EQ(d.footprint, "gyration") << "the stated rule, which made the data, is kept";
  EXPECT_EQ(d.normal_law, "linear") << "the stated law, which made the data, is kept";
  EXPECT_FALSE(d.normal_law_changed);
  EXPECT_TRUE(d.baseline.adequacy.adequate) << "p " << d.baseline.adequacy.p_value;

  std::ifstream in(report.path() / "diagnosis.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  int off = 0;
  for (const nlohmann::json& c : j.at("ranking")) {
    if (!c.at("at_off_value").get<bool>()) continue;
    ++off;
    EXPECT_EQ(c.at("heldout_gain").get<double>(), 0.0) << c.at("mechanism");
    EXPECT_FALSE(c.at("significant").get<bool>()) << c.at("mechanism");
    ASSERT_TRUE(c.contains("heldout_gain_as_fitted")) << c.at("mechanism");
  }
  EXPECT_GT(off, 0) << "no mechanism at its off value: the check above checked nothing";
}

// One effect hidden, so no second one to find. Fitted from the cause's point, the pair with
// out-of-plane loss found a better region of the cause's own parameters (J 2.9 of the
// vertical excitation alone against 1.1 refitted from the pairs) and passed for a second
// effect (held-out gain 0.41); scored against the cause refitted from the pairs' values, no
// pair is significant. Over 41 right single-cause diagnoses (bench/results/
// second-effect-refit.csv) false second effects fell from 15 to 3.
// The hidden vertical excitation is also named as the cause, as every other mechanism is in
// test_every_mechanism.cpp.
TEST(HiddenEffect, OneEffectGivesNoSecondEffect) {
  const Diagnosis d = diagnose_synthetic({Mechanism::vertical_excitation}, 105, true);
  const CandidateScore& found = score_of(d, Mechanism::vertical_excitation);
  RecordProperty("cause", d.cause);
  RecordProperty("second", d.second_cause);
  RecordProperty("heldout_gain", std::to_string(found.heldout_gain));
  EXPECT_EQ(d.cause, "vertical_excitation");
  EXPECT_GT(found.heldout_gain, 0.0);
  EXPECT_TRUE(found.significant) << "held-out gain " << found.heldout_gain << ", BIC delta " << found.bic_delta;
  EXPECT_EQ(d.second_cause, "") << "a second effect where none is hidden";
  EXPECT_EQ(d.second_ranking.size(), all_mechanisms().size() - 1) << "every other mechanism tried on top of the cause";
}

// Data its own model did not make: the independent generator (tests/independent: a cylinder on
// a distributed Hunt-Crossley footprint, tanh-regularised friction, Boost.Odeint's adaptive
// Runge-Kutta; six tests of 10 mm sines and time-compressed records), its effects written apart
// from src/diagnosis/mechanisms. Rates over more seeds are in docs/diagnosis-accuracy.md.
Diagnosis diagnose_independent(const std::string& effect, std::uint64_t seed, const std::string& stated_footprint) {
  const testing::TestDirectory directory;
  independent::MeasuredSetOptions options;
  options.footprint = stated_footprint;
  independent::write_independent_measured_set(directory.path(), effect, seed, options);
  const MeasuredSet set = read_measured_set(directory.path());
  DiagnosisOptions diagnosis_options;
  diagnosis_options.threads = 2;
  diagnosis_options.look_for_second_effect = false;
  return diagnose(set, diagnosis_options);
}

TEST(IndependentData, BaselineDataGiveNone) {
  const Diagnosis d = diagnose_independent("none", 301, "distributed");
  RecordProperty("cause", d.cause);
  RecordProperty("p_value", std::to_string(d.baseline.adequacy.p_value));
  EXPECT_EQ(d.cause, "none") << "top: " << mechanism_name(d.ranking.front().mechanism) << " gain "
                             << d.ranking.front().heldout_gain << ", adequate " << d.baseline.adequacy.adequate;
  EXPECT_EQ(d.footprint, "distributed");
}

// The same kind of data, the specimen file stating the source paper's two-corner rule: never
// "none"; the footprint the data come from is named.
TEST(IndependentData, AWrongFootprintRuleIsNamed) {
  const Diagnosis d = diagnose_independent("none", 301, "gyration");
  RecordProperty("cause", d.cause);
  EXPECT_NE(d.cause, "none");
  EXPECT_EQ(d.footprint, "distributed");
  EXPECT_EQ(d.cause, "footprint");
}

// A convex base hidden in these data (seed 302) is not named: the camber caskdem's mechanism
// adds lowers one contact at the base centre, while the generator curves the whole footprint,
// and the fit does not reach the held-out gain asked. The answer must then not be "none": the
// baseline misfits beyond noise, and the report says so.
TEST(IndependentData, AHiddenConvexBaseIsNotCalledNone) {
  const Diagnosis d = diagnose_independent("base_imperfection", 302, "distributed");
  RecordProperty("cause", d.cause);
  EXPECT_NE(d.cause, "none");
  EXPECT_FALSE(d.baseline.adequacy.adequate);
}

// The profile cannot miss a mechanism the data support: for each effect hidden in the
// independent generator's data, where the mechanism at the generator's true values (mapped to
// caskdem's parameters) fits the training tests better than the calibrated baseline, by more
// than the profile's bound, the mechanism's profile must find a value that does too. The truth
// is judged with the baseline's parameters searched again (a profile point at the true values:
// the generator's contact and friction are not caskdem's, so its true friction, stiffness and
// damping put into caskdem's model miss by hundreds: J 450 against the baseline's 58 on the
// friction set here, as `caskdem evaluate-measured --from truth.json` shows). Where the two
// models differ in form (the generator's rocking damping couple, its curved footprint) the
// truth need not fit better, and nothing is asserted for that effect.
TEST(IndependentData, TheProfileFindsAMechanismWhereItsTruthLowersTheMisfit) {
  struct Mapped {
    Mechanism mechanism;
    std::vector<std::pair<std::string, std::string>> parameters;  // caskdem's, the generator's
    double factor = 1.0;                                           // on the generator's value
  };
  const std::vector<Mapped> effects = {
      {Mechanism::velocity_dependent_friction, {{"kinetic_ratio", "kinetic_ratio"}, {"decay_speed", "stribeck_speed_m_s"}}},
      {Mechanism::amplitude_dependent_restitution, {{"impact_damping", "extra_hunt_crossley_c_h_s_m"}}, 1.5},
      {Mechanism::eccentric_mass, {{"eccentricity", "eccentricity_m"}}},
      {Mechanism::base_imperfection, {{"base_camber", "camber_m"}}},
      {Mechanism::vertical_excitation, {}},
      {Mechanism::floor_compliance, {{"floor_soft_ratio", "soft_ratio"}, {"floor_soft_depth", "soft_depth_m"}}},
      {Mechanism::out_of_plane_loss, {{"wobble_damping", "rocking_damping_ratio"}}},
      {Mechanism::sensor_delay, {{"sensor_delay", "sensor_delay_s"}}},
  };
  DiagnosisOptions options;
  options.threads = 2;
  int checked = 0;
  for (std::size_t e = 0; e < effects.size(); ++e) {
    const Mapped& m = effects[e];
    const std::string name = mechanism_name(m.mechanism);
    const testing::TestDirectory directory;
    const independent::MeasuredSetResult made =
        independent::write_independent_measured_set(directory.path(), name, 401 + e);
    const MeasuredSet set = read_measured_set(directory.path());
    const ModelFit baseline = calibrate_baseline(set, options);
    const ModelVariant variant(set.specimen, {m.mechanism}, set.vertical_measured);
    std::vector<double> truth = variant.reference();
    const auto clamp_to = [&](const std::string& parameter, double value) {
      const Parameter& p = variant.parameters()[variant.index_of(parameter)];
      return std::clamp(value, p.low, p.high);
    };
    truth[0] = clamp_to("friction", made.truth.friction);
    truth[1] = clamp_to("damping_ratio", made.truth.damping_ratio);
    truth[2] = clamp_to("stiffness_scale", made.truth.stiffness_scale);
    if (m.mechanism == Mechanism::vertical_excitation) truth[variant.index_of("vertical_gain")] = 1.0;
    for (const auto& [ours, theirs] : m.parameters) {
      for (const auto& [key, value] : made.truth.effect_parameters) {
        if (key == theirs) truth[variant.index_of(ours)] = clamp_to(ours, m.factor * value);
      }
    }
    const double truth_alone = evaluate_point(set, {m.mechanism}, truth, {}, options).training_objective;
    std::copy(baseline.fit.best.begin(), baseline.fit.best.end(), truth.begin());
    const double at_truth = profile_on(set, m.mechanism, baseline.fit.best, options, {truth}).grid.back().objective;
    const Profile profile = profile_on(set, m.mechanism, baseline.fit.best, options);
    const double found = profile.grid[profile.minimum].objective;
    RecordProperty(name + "_baseline_J", std::to_string(baseline.fit.objective));
    RecordProperty(name + "_truth_J", std::to_string(at_truth));
    RecordProperty(name + "_profile_minimum_J", std::to_string(found));
    std::printf("%-32s baseline J %8.2f  truth J %8.2f (alone %8.2f)  profile minimum J %8.2f  likelihood ratio %7.2f\n",
                name.c_str(), baseline.fit.objective, at_truth, truth_alone, found, profile.likelihood_ratio);
    if (at_truth < baseline.fit.objective - kProfileBound) {
      ++checked;
      EXPECT_LT(found, baseline.fit.objective) << name << ": its truth lowers J to " << at_truth;
    }
  }
  RecordProperty("effects_checked", checked);
  EXPECT_GE(checked, 2) << "too few effects whose truth lowers the misfit: the check checked little";
}

}  // namespace
}  // namespace caskdem::diagnosis
