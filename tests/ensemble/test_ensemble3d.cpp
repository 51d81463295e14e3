// The 3D cask in ensembles (ensemble/plan.h, ensemble/runner.h): every realisation run in SIMD
// lanes gives what the deterministic 3D run (sim/simulate3d.h, the scalar instantiation of the
// same step) gives for its parameters, motion and incidence, bit for bit, over realisations that
// stand still, rock, slide and tip over; the same bits on every instruction set, thread count,
// block size and schedule; the incidence drawn uniform over half a turn unless the file says
// otherwise; and the 3D ensemble file's own refusals.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "sim/simulate3d.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

const std::string kEnsemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes-3d.toml";

std::vector<RealisationOutcome> run(const EnsemblePlan& plan, const std::vector<std::int64_t>& indices, int lanes,
                                    InstructionSet isa, int threads, bool refill = true,
                                    std::int64_t budget = MotionTables::kDefaultBudgetBytes) {
  std::vector<RealisationOutcome> by_index(plan.size());
  RunOptions options;
  options.isa = isa;
  options.threads = threads;
  options.lanes = lanes;
  options.refill = refill;
  run_realisations(plan, MotionTables(plan, budget), indices, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) by_index[done[k]] = outcomes[k];
                   });
  std::vector<RealisationOutcome> selected;
  for (std::int64_t i : indices) selected.push_back(by_index[i]);
  return selected;
}

std::vector<double> bits_of(const std::vector<RealisationOutcome>& outcomes) {
  std::vector<double> v;
  for (const RealisationOutcome& o : outcomes) {
    v.insert(v.end(), {double(o.status), o.max_abs_rotation, o.max_abs_slide, o.residual_slide, o.max_uplift,
                       o.end_time, o.instability_time, o.spin});
  }
  return v;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(Ensemble3D, EveryLaneEqualsTheDeterministicRun) {
  const EnsemblePlan plan(load_ensemble(kEnsemble), InstructionSet::automatic);
  ASSERT_TRUE(plan.three_d());
  std::vector<std::int64_t> all(plan.size());
  for (std::int64_t i = 0; i < plan.size(); ++i) all[i] = i;
  const std::vector<RealisationOutcome> wide = run(plan, all, 64, InstructionSet::automatic, 2);

  int standing = 0, rocking = 0, sliding = 0, tipped = 0;
  for (std::int64_t i = 0; i < plan.size(); ++i) {
    const RealisationInput in = plan.realisation(i);
    const Model3D& model = plan.model3d();
    const LaneParameters<double> lane = lane_parameters3d(model, in.parameters);
    const Excitation3D excitation{plan.component(in.motion, 0), plan.component(in.motion, 1),
                                  plan.component(in.motion, 2), in.incidence};
    const RunSummary3D s =
        simulate3d(model, lane, rest_state3d(model, lane), excitation, {plan.run_duration(in.motion), 0.0}).summary;
    const RealisationOutcome reference{s.status, s.max_tilt, s.max_slide, s.residual_slide, s.max_uplift, -1.0,
                                       s.end_time, s.instability_time, s.spin};
    EXPECT_TRUE(same_bits(bits_of({wide[i]}), bits_of({reference})))
        << "realisation " << i << ": status " << int(wide[i].status) << " against " << int(s.status) << ", tilt "
        << wide[i].max_abs_rotation << " against " << s.max_tilt << ", spin " << wide[i].spin << " against " << s.spin;
    // Rocking and sliding overlap (a cask may do both); standing does neither.
    const bool tips = s.status == LaneStatus::tipped_over;
    tipped += tips;
    rocking += !tips && s.max_tilt_ratio > 0.1;
    sliding += !tips && s.max_slide > 0.02;
    standing += s.max_tilt_ratio < 0.01 && s.max_slide < 1e-3;
  }
  std::printf("of %lld: %d stood, %d rocked beyond 0.1 alpha and %d slid beyond 2 cm without tipping over, %d tipped over\n",
              static_cast<long long>(plan.size()), standing, rocking, sliding, tipped);
  // The ensemble must exercise every kind of outcome, or the comparison proves little.
  EXPECT_GE(standing, 10);
  EXPECT_GE(rocking, 10);
  EXPECT_GE(sliding, 10);
  EXPECT_GE(tipped, 10);
}

// Refilled lanes of three motions (one with no second horizontal and no vertical, one with no
// vertical) beside each other, blocks of one motion in lockstep, a table too large for its
// budget (sampled chunk by chunk), 1 or 2 threads, blocks of 8 or 24: the scalar lanes' bits.
TEST(Ensemble3D, SameBitsOnEveryInstructionSetThreadCountBlockSizeAndSchedule) {
  const EnsemblePlan plan(load_ensemble(kEnsemble), InstructionSet::automatic);
  std::vector<std::int64_t> some;
  for (std::int64_t i = 0; i < plan.size(); i += 8) some.push_back(i);
  const std::vector<double> reference = bits_of(run(plan, some, 16, InstructionSet::scalar, 1));
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) continue;
    for (int lanes : {8, 24}) {
      EXPECT_TRUE(same_bits(bits_of(run(plan, some, lanes, isa, 2, true)), reference)) << instruction_set_name(isa) << ", " << lanes;
      EXPECT_TRUE(same_bits(bits_of(run(plan, some, lanes, isa, 1, false)), reference)) << instruction_set_name(isa) << ", " << lanes;
    }
  }
  ASSERT_FALSE(MotionTables(plan, 0).whole());
  EXPECT_TRUE(same_bits(bits_of(run(plan, some, 16, InstructionSet::automatic, 2, true, 0)), reference));
}

// The source paper's half-step slider in 3D (an ensemble's default, the whole-step slider, is
// the test above's): the scalar lanes' bits on every instruction set, thread count, block size
// and schedule (refilled or in lockstep), and not the whole-step slider's.
TEST(Ensemble3D, PaperSchemeSameBitsOnEveryInstructionSetThreadCountBlockSizeAndSchedule) {
  EnsembleSpec spec = load_ensemble(kEnsemble);
  ASSERT_EQ(spec.base.model.whole_step_terms, kWholeStepSlider) << "an ensemble's default";
  spec.base.model.whole_step_terms = 0;
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  const EnsemblePlan whole_step(load_ensemble(kEnsemble), InstructionSet::automatic);
  std::vector<std::int64_t> some;
  for (std::int64_t i = 0; i < plan.size(); i += 8) some.push_back(i);
  const std::vector<double> reference = bits_of(run(plan, some, 16, InstructionSet::scalar, 1));
  EXPECT_FALSE(same_bits(bits_of(run(whole_step, some, 16, InstructionSet::scalar, 1)), reference));
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (!instruction_set_available(isa)) continue;
    for (int lanes : {8, 24}) {
      EXPECT_TRUE(same_bits(bits_of(run(plan, some, lanes, isa, 2, true)), reference)) << instruction_set_name(isa) << ", " << lanes;
      EXPECT_TRUE(same_bits(bits_of(run(plan, some, lanes, isa, 1, false)), reference)) << instruction_set_name(isa) << ", " << lanes;
    }
  }
}

// Without [uncertain.incidence], a 3D ensemble turns each realisation's pair uniformly over
// [0, 180) degrees: in each stripe of n (Latin hypercube) one incidence in each of n equal strata.
TEST(Ensemble3D, IncidenceIsUniformOverHalfATurnByDefault) {
  const EnsembleSpec spec = load_ensemble(kEnsemble);
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  const std::int64_t n = spec.realisations_per_stripe;
  for (int stripe = 0; stripe < static_cast<int>(spec.levels.size()); ++stripe) {
    std::vector<int> strata(n, 0);
    for (std::int64_t j = 0; j < n; ++j) {
      const double incidence = plan.realisation(stripe * n + j).incidence;
      ASSERT_GT(incidence, 0.0);
      ASSERT_LT(incidence, std::numbers::pi);
      strata[static_cast<std::size_t>(incidence / std::numbers::pi * double(n))] += 1;
    }
    EXPECT_EQ(std::count(strata.begin(), strata.end(), 1), n) << "stripe " << stripe;
  }
  // And the station's components are scaled together: the pair's RotD50 PGA to the level.
  const RealisationInput in = plan.realisation(n + 1);  // stripe 1, motion 1 (Rinaldi)
  ASSERT_EQ(in.motion, 1);
  EXPECT_NEAR(in.scale_factor * plan.intensity(1).pga, spec.levels[1], 1e-12 * spec.levels[1]);
  EXPECT_EQ(in.parameters.vertical_scale, in.parameters.horizontal_scale);
}

// The 3D test ensemble, its records named by absolute paths, with `find` replaced.
class Ensemble3DErrors : public testing::TemporaryFiles {
 protected:
  std::filesystem::path variant(const std::string& name, const std::string& find, const std::string& replace) const {
    std::string text = testing::file_text(kEnsemble);
    for (std::size_t at; (at = text.find("../../../../shared")) != std::string::npos;) {
      text.replace(at, std::string("../../../../shared").size(), CASKDEM_SHARED_DIR);
    }
    const auto at = text.find(find);
    EXPECT_NE(at, std::string::npos) << "no \"" << find << "\"";
    if (at != std::string::npos) text.replace(at, find.size(), replace);
    return write(name + ".toml", text);
  }
};

// The solid cylinder's I_1 = m (R^2 / 4 + H^2 / 12) and I_3 = m R^2 / 2 unless [cask] gives
// them, and with an uncertain mass both scale with it (the same shape); the eccentricity moves
// the centre of mass along the body's x.
TEST_F(Ensemble3DErrors, TheCylindersInertiasAndEccentricityAreTheFilesWhenGiven) {
  const EnsemblePlan solid(load_ensemble(kEnsemble), InstructionSet::automatic);
  const RealisationParameters p = solid.realisation(0).parameters;
  const double R = 0.475, H = 2.033;
  EXPECT_NEAR(p.inertia, p.mass * (R * R / 4.0 + H * H / 12.0), 1e-12 * p.inertia);
  EXPECT_NEAR(p.axial_inertia, p.mass * R * R / 2.0, 1e-12 * p.axial_inertia);
  const EnsemblePlan given(load_ensemble(variant("inertias", "rounding = \"0.5 cm\"",
                                                 "rounding = \"0.5 cm\"\ninertia = \"5000 kg m^2\"\n"
                                                 "axial_inertia = \"1500 kg m^2\"\neccentricity = \"2 cm\"")),
                           InstructionSet::automatic);
  const RealisationParameters q = given.realisation(0).parameters;
  const double nominal_mass = 8743.0 * std::numbers::pi * R * R * H;
  EXPECT_NEAR(q.inertia, 5000.0 * q.mass / nominal_mass, 1e-9 * q.inertia);
  EXPECT_NEAR(q.axial_inertia, 1500.0 * q.mass / nominal_mass, 1e-9 * q.axial_inertia);
  EXPECT_EQ(q.centre_of_mass.x, 0.02);
  EXPECT_LT(given.stability_angle(), solid.stability_angle());
}

// The InputError that reading and planning the ensemble file throws.
std::string error_of(const std::filesystem::path& file) {
  return testing::input_error_of([&] { const EnsemblePlan plan(load_ensemble(file), InstructionSet::automatic); },
                                 file.string());
}

TEST_F(Ensemble3DErrors, EachRefusalNamesItsKey) {
  using ::testing::HasSubstr;
  struct Case {
    const char* name;
    std::string find, replace, expected;
  };
  const std::vector<Case> cases = {
      {"incidence-in-motion", "similarity_scale = 3\n", "similarity_scale = 3\nincidence = \"30 deg\"\n",
       "key motions[1].incidence: an ensemble samples the incidence: give [uncertain] incidence instead"},
      {"intensity-in-motion", "similarity_scale = 3\n", "similarity_scale = 3\nintensity = \"rotd100\"\n",
       "key motions[1].intensity: an ensemble scales every pair by one measure: give [intensity] pair_measure instead"},
      {"restitution", "[intensity]", "[uncertain.restitution]\ndistribution = \"uniform\"\nlow = 0.9\nhigh = 0.95\n\n[intensity]",
       "key uncertain.restitution: the 3D cask's damping is the [damping] ratio"},
      {"sa", "measure = \"pga\"", "measure = \"sa\"\nperiod = \"0.5 s\"",
       "key intensity.measure: a 3D ensemble is scaled by its pairs' PGA or PGV"},
      {"pair-measure", "measure = \"pga\"", "measure = \"pga\"\npair_measure = \"rotd75\"", "key intensity.pair_measure"},
      {"incidence-range", "[intensity]", "[uncertain.incidence]\ndistribution = \"uniform\"\nlow = \"0 deg\"\nhigh = \"720 deg\"\n\n[intensity]",
       "key uncertain.incidence.low: expected incidence angles within [-360, 360] degrees"},
  };
  for (const Case& c : cases) {
    const auto file = variant(c.name, c.find, c.replace);
    const std::string e = error_of(file);
    EXPECT_THAT(e, HasSubstr(file.string() + ":")) << c.name;
    EXPECT_THAT(e, HasSubstr(c.expected)) << c.name;
  }
  // A planar ensemble has no incidence and no pairs.
  const std::string planar = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml";
  const auto incidence = variant_of(planar, "planar-incidence.toml", "[intensity]",
                                    "[uncertain.incidence]\ndistribution = \"uniform\"\nlow = 0\nhigh = 1\n\n[intensity]");
  EXPECT_THAT(error_of(incidence), HasSubstr("key uncertain.incidence: only a 3D cask ([cask] dimensions = 3) has an incidence"));
  const auto pair = variant_of(planar, "planar-pair.toml", "measure = \"pga\"", "measure = \"pga\"\npair_measure = \"rotd50\"");
  EXPECT_THAT(error_of(pair), HasSubstr("key intensity.pair_measure: only a 3D cask"));
}

}  // namespace
}  // namespace caskdem
