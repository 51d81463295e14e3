// An earlier diagnosis as starts (src/diagnosis/earlier_fits.h): which fits of a diagnosis.json
// are read and where each is used, what a malformed file gets, and the promise the option makes:
// a fit searched also from an earlier point ends no higher than that point's J on the present
// tests, and is the fit made without it wherever that point's search does not end lowest (that it
// never ends above the fit made without it is tested on a known objective, test_fitting.cpp).

#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/fitting.h"
#include "diagnosis/footprint.h"
#include "diagnosis/synthesize.h"
#include "small_search_set.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

// The set test_decision_invariants.cpp runs on, its search cut to a few points: the promise holds
// at any search size.
MeasuredSet small_set(const testing::TestDirectory& directory,
                      const std::string& search_settings = "starts = 1\nevaluations = 10\nexploration = 16") {
  EXPECT_TRUE(write_small_search_set(directory.path(), search_settings)) << "specimen.toml's [diagnosis] keys changed";
  return read_measured_set(directory.path());
}

nlohmann::json fit_object(const std::string& model, const std::vector<std::pair<std::string, double>>& values) {
  nlohmann::json fit{{"model", model}};
  fit["parameters"] = nlohmann::json::object();
  for (const auto& [name, value] : values) fit["parameters"][name] = {{"value", value}, {"units", ""}};
  return fit;
}

std::vector<std::pair<std::string, double>> values_of(const ModelVariant& variant, const std::vector<double>& x) {
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t i = 0; i < x.size(); ++i) out.emplace_back(variant.parameters()[i].name, x[i]);
  return out;
}

std::string error_of(const std::filesystem::path& file, const MeasuredSet& set) {
  try {
    (void)read_earlier_fits(file, set);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(EarlierFits, EachFitStartsTheFitOfItsOwnModelAndForm) {
  const testing::TestDirectory directory;
  const MeasuredSet set = small_set(directory);
  const ModelVariant baseline(set.specimen, {}, set.vertical_measured);
  const ModelVariant eccentric(set.specimen, {Mechanism::eccentric_mass}, set.vertical_measured);
  const Footprint stated_rule = *footprint_of(set.specimen);
  const Footprint other_rule = stated_rule == Footprint::distributed ? Footprint::radius : Footprint::distributed;
  const std::string stated = footprint_name(stated_rule), other = footprint_name(other_rule);

  std::vector<double> b = baseline.reference(), e = eccentric.reference(&b);
  b[0] *= 1.1;
  e[0] *= 0.9;
  e.back() = eccentric.parameters().back().high * 10.0;  // beyond its box: moved onto the bound
  std::vector<double> other_form = b;
  other_form[0] *= 1.2;
  nlohmann::json j;
  j["footprint"] = stated;
  j["normal_law"] = "linear";
  j["baseline"] = fit_object("baseline", values_of(baseline, b));
  const auto row = [&](const std::string& rule, const std::vector<double>& x) {
    return nlohmann::json{{"footprint", rule}, {"normal_law", "linear"},
                          {"baseline", fit_object("baseline", values_of(baseline, x))}};
  };
  j["footprints"] = {row(other, other_form), row(stated, b)};
  j["ranking"] = {
      {{"mechanism", "eccentric_mass"}, {"fit", fit_object("baseline + eccentric_mass", values_of(eccentric, e))}}};
  j["second_ranking"] = nlohmann::json::array();
  j["cause_refitted"] = nullptr;
  const std::filesystem::path file = directory / "earlier.json";
  std::ofstream(file) << j.dump(2);

  const EarlierFits earlier = read_earlier_fits(file, set);
  EXPECT_EQ(earlier.fits.size(), 4u);
  // The stated form's baseline appears twice in the file (reported and in its row): one start.
  const std::vector<std::vector<double>> baseline_starts = earlier_starts(earlier, set.specimen, baseline);
  ASSERT_EQ(baseline_starts.size(), 1u);
  EXPECT_EQ(baseline_starts[0], b);
  const std::vector<std::vector<double>> eccentric_starts = earlier_starts(earlier, set.specimen, eccentric);
  ASSERT_EQ(eccentric_starts.size(), 1u);
  std::vector<double> in_box = e;
  in_box.back() = eccentric.parameters().back().high;
  EXPECT_EQ(eccentric_starts[0], in_box);
  // The other rule's row starts only a fit on that rule.
  const Case on_other = with_footprint(set.specimen, other_rule);
  const std::vector<std::vector<double>> other_starts =
      earlier_starts(earlier, on_other, ModelVariant(on_other, {}, set.vertical_measured));
  ASSERT_EQ(other_starts.size(), 1u);
  EXPECT_EQ(other_starts[0], other_form);
  // A model the file has no fit of gets none.
  const ModelVariant delayed(set.specimen, {Mechanism::sensor_delay}, set.vertical_measured);
  EXPECT_TRUE(earlier_starts(earlier, set.specimen, delayed).empty());
}

TEST(EarlierFits, AFileThatIsNotADiagnosisIsRefusedNamingTheKey) {
  const testing::TestDirectory directory;
  const MeasuredSet set = small_set(directory);
  const ModelVariant baseline(set.specimen, {}, set.vertical_measured);
  const std::filesystem::path file = directory / "earlier.json";
  const auto refusal = [&](const std::string& text) {
    std::ofstream(file) << text;
    return error_of(file, set);
  };
  EXPECT_NE(refusal("{ not json").find("not JSON"), std::string::npos);
  EXPECT_NE(refusal("{\"cause\": \"none\"}").find("expected the diagnosis.json"), std::string::npos);

  nlohmann::json j;
  j["baseline"] = fit_object("baseline", values_of(baseline, baseline.reference()));
  j["ranking"] = {{{"fit", fit_object("baseline + no_such_effect", {})}}};
  EXPECT_NE(refusal(j.dump()).find("unknown mechanism \"no_such_effect\""), std::string::npos);

  std::vector<std::pair<std::string, double>> missing = values_of(baseline, baseline.reference());
  missing.pop_back();
  j["ranking"] = {{{"fit", fit_object("baseline", missing)}}};
  const std::string message = refusal(j.dump());
  const std::string key = "ranking[0].fit.parameters." + baseline.parameters().back().name + ".value";
  EXPECT_NE(message.find(key), std::string::npos) << message;
  EXPECT_EQ(message.rfind(file.string(), 0), 0u) << "names the file first: " << message;

  EXPECT_NE(error_of(directory / "absent.json", set).find("cannot be read"), std::string::npos);
}

// The promise: with an earlier point among its starts, a fit ends at or below that point's J on
// the present tests, however small its search. The earlier point is a larger search's fit of the
// same set, which the small search alone does not reach.
TEST(EarlierFits, AFitEndsNoHigherThanTheEarlierPoint) {
  const testing::TestDirectory directory, larger_directory;
  const MeasuredSet set = small_set(directory);
  const MeasuredSet larger = small_set(larger_directory, "starts = 4\nevaluations = 30\nexploration = 64");
  DiagnosisOptions options;
  options.threads = 2;
  const ModelFit earlier = calibrate_baseline(larger, options);
  const ModelFit alone = calibrate_baseline(set, options);
  // The earlier point as a search reads a start (through its unit coordinates).
  const ModelVariant baseline(set.specimen, {}, set.vertical_measured);
  std::vector<double> point;
  for (std::size_t i = 0; i < earlier.fit.best.size(); ++i) {
    const Parameter& p = baseline.parameters()[i];
    point.push_back(from_unit(p, to_unit(p, earlier.fit.best[i])));
  }
  const double earlier_objective = evaluate_point(set, {}, point, {}, options).training_objective;
  RecordProperty("J at the earlier point", std::to_string(earlier_objective));
  RecordProperty("J of the fit without it", std::to_string(alone.fit.objective));
  ASSERT_GT(alone.fit.objective, earlier_objective) << "the small search alone must miss the earlier point's basin";

  const std::filesystem::path file = directory / "calibration.json";
  std::ofstream(file) << fit_object("baseline", values_of(baseline, point)).dump(2);
  options.earlier = read_earlier_fits(file, set);
  const ModelFit started = calibrate_baseline(set, options);
  RecordProperty("J of the fit started from it", std::to_string(started.fit.objective));
  EXPECT_LE(started.fit.objective, earlier_objective);
}

// The other half: an earlier point whose search does not end lowest leaves the fit as it is
// without it, to the bit (the searches the exploration chooses are not displaced by it). The
// point is the search box's low corner, far from where these tests are fitted.
TEST(EarlierFits, APoorEarlierPointLeavesTheFitAsItWas) {
  const testing::TestDirectory directory;
  const MeasuredSet set = small_set(directory);
  DiagnosisOptions options;
  options.threads = 2;
  const ModelFit alone = calibrate_baseline(set, options);
  const ModelVariant baseline(set.specimen, {}, set.vertical_measured);
  std::vector<double> corner;
  for (const Parameter& p : baseline.parameters()) corner.push_back(p.low);
  const std::filesystem::path file = directory / "calibration.json";
  std::ofstream(file) << fit_object("baseline", values_of(baseline, corner)).dump(2);
  options.earlier = read_earlier_fits(file, set);
  const ModelFit started = calibrate_baseline(set, options);
  RecordProperty("J at the corner", std::to_string(evaluate_point(set, {}, corner, {}, options).training_objective));
  EXPECT_EQ(started.fit.best, alone.fit.best);
  EXPECT_EQ(started.fit.objective, alone.fit.objective);
  EXPECT_GT(started.fit.evaluations, alone.fit.evaluations) << "the corner was searched too";
}

}  // namespace
}  // namespace caskdem::diagnosis
