// The diagnosis's answer on whole data sets at the shipped search settings (ctest label
// diagnosis-full, in the gate): data from the baseline model plus noise give "none", whatever
// normal law is compared; with one effect hidden it is named and no second effect is reported;
// and on data its own model did not make (the independent generator), the null gives "none"
// and a hidden convex base, which the model cannot fit, is not called "none". The other full
// diagnoses (every other mechanism named where it is hidden, Hunt-Crossley data, two effects,
// a wrong footprint rule, the profiles on independent data) are test_more_diagnoses.cpp (label
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
// linear law keep it (test_more_diagnoses.cpp has the Hunt-Crossley data).
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
// test_more_diagnoses.cpp.
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

TEST(IndependentData, BaselineDataGiveNone) {
  const Diagnosis d = diagnose_independent("none", 301, "distributed");
  RecordProperty("cause", d.cause);
  RecordProperty("p_value", std::to_string(d.baseline.adequacy.p_value));
  EXPECT_EQ(d.cause, "none") << "top: " << mechanism_name(d.ranking.front().mechanism) << " gain "
                             << d.ranking.front().heldout_gain << ", adequate " << d.baseline.adequacy.adequate;
  EXPECT_EQ(d.footprint, "distributed");
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

}  // namespace
}  // namespace caskdem::diagnosis
