#include "diagnosis/earlier_fits.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "diagnosis/footprint.h"
#include "model/build.h"

namespace caskdem::diagnosis {

namespace {

std::string form_footprint(const Case& specimen) {
  const std::optional<Footprint> f = footprint_of(specimen);
  return f ? footprint_name(*f) : std::string();
}

// One fit object ("model", "parameters": {name: {"value": x}}) at `key`, on the given form.
EarlierFit fit_at(const nlohmann::json& fit, const std::string& key, const std::string& footprint,
                  const std::string& normal_law, const MeasuredSet& set, const std::filesystem::path& file) {
  if (!fit.is_object() || !fit.contains("model") || !fit["model"].is_string() || !fit.contains("parameters") ||
      !fit["parameters"].is_object()) {
    fail_at(file, 0, key + ": expected a fit (a \"model\" name and its \"parameters\")");
  }
  EarlierFit e{footprint, normal_law, fit["model"].get<std::string>(), {}};
  const std::vector<Mechanism> mechanisms = parse_mechanism_list(e.model, file.string() + ": " + key + ".model");
  std::optional<ModelVariant> checked;
  try {
    checked.emplace(set.specimen, mechanisms, set.vertical_measured);
  } catch (const std::invalid_argument& error) {  // a model this cask's set cannot have
    fail_at(file, 0, key + ".model: " + error.what());
  }
  const ModelVariant& variant = *checked;
  for (const Parameter& p : variant.parameters()) {
    const nlohmann::json& parameters = fit["parameters"];
    const nlohmann::json* value = nullptr;
    if (parameters.contains(p.name) && parameters[p.name].is_object() && parameters[p.name].contains("value")) {
      value = &parameters[p.name]["value"];
    }
    if (!value || !value->is_number() || !std::isfinite(value->get<double>())) {
      fail_at(file, 0, key + ".parameters." + p.name + ".value: expected a finite number (the fit of \"" + e.model +
                           "\")");
    }
    e.values.emplace_back(p.name, value->get<double>());
  }
  return e;
}

std::string string_or_empty(const nlohmann::json& j, const std::string& key, const std::filesystem::path& file) {
  if (!j.contains(key) || j[key].is_null()) return {};
  if (!j[key].is_string()) fail_at(file, 0, key + ": expected a name or null");
  return j[key].get<std::string>();
}

}  // namespace

EarlierFits read_earlier_fits(const std::filesystem::path& file, const MeasuredSet& set) {
  std::ifstream in(file);
  if (!in || std::filesystem::is_directory(file)) {
    fail_at(file, 0, "cannot be read (expected the diagnosis.json of an earlier `caskdem diagnose` of this cask)");
  }
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // a syntax error, or a number beyond a double
    fail_at(file, 0, std::string("not JSON: ") + e.what());
  }
  EarlierFits out;
  out.source = file;
  if (j.is_object() && j.contains("model") && !j.contains("baseline")) {  // a calibration.json: the stated form
    out.fits.push_back(fit_at(j, "model", form_footprint(set.specimen), normal_law_name(set.specimen.model.normal_law),
                              set, file));
    return out;
  }
  if (!j.is_object() || !j.contains("baseline") || !j.contains("ranking") || !j["ranking"].is_array()) {
    fail_at(file, 0, "expected the diagnosis.json of `caskdem diagnose` (a \"baseline\" and a \"ranking\") or a "
                     "calibration.json");
  }
  // The mechanisms were fitted on the form the diagnosis kept; each form's row has its own.
  const std::string footprint = string_or_empty(j, "footprint", file);
  const std::string law = j.contains("normal_law") ? string_or_empty(j, "normal_law", file)
                                                   : normal_law_name(set.specimen.model.normal_law);
  out.fits.push_back(fit_at(j["baseline"], "baseline", footprint, law, set, file));
  if (j.contains("footprints") && j["footprints"].is_array()) {
    for (std::size_t i = 0; i < j["footprints"].size(); ++i) {
      const nlohmann::json& row = j["footprints"][i];
      const std::string key = "footprints[" + std::to_string(i) + "]";
      if (!row.is_object()) fail_at(file, 0, key + ": expected a model form's row");
      out.fits.push_back(fit_at(row.value("baseline", nlohmann::json()), key + ".baseline",
                                string_or_empty(row, "footprint", file), string_or_empty(row, "normal_law", file),
                                set, file));
    }
  }
  for (const char* list : {"ranking", "second_ranking"}) {
    if (!j.contains(list) || !j[list].is_array()) continue;
    for (std::size_t i = 0; i < j[list].size(); ++i) {
      const std::string key = std::string(list) + "[" + std::to_string(i) + "]";
      const nlohmann::json& entry = j[list][i];
      out.fits.push_back(fit_at(entry.is_object() ? entry.value("fit", nlohmann::json()) : nlohmann::json(),
                                key + ".fit", footprint, law, set, file));
    }
  }
  if (j.contains("cause_refitted") && !j["cause_refitted"].is_null()) {
    out.fits.push_back(fit_at(j["cause_refitted"], "cause_refitted", footprint, law, set, file));
  }
  return out;
}

std::vector<std::vector<double>> earlier_starts(const EarlierFits& earlier, const Case& specimen,
                                                const ModelVariant& variant) {
  const std::string footprint = form_footprint(specimen), law = normal_law_name(specimen.model.normal_law);
  const std::string model = variant.name();
  std::vector<std::vector<double>> starts;
  for (const EarlierFit& e : earlier.fits) {
    if (e.model != model || e.footprint != footprint || e.normal_law != law) continue;
    std::vector<double> start;
    for (const Parameter& p : variant.parameters()) {
      const auto named = [&](const auto& v) { return v.first == p.name; };
      const auto found = std::find_if(e.values.begin(), e.values.end(), named);
      if (found == e.values.end()) break;  // read_earlier_fits checked every name on this specimen
      start.push_back(std::clamp(found->second, p.low, p.high));
    }
    if (start.size() == variant.parameters().size() && std::find(starts.begin(), starts.end(), start) == starts.end()) {
      starts.push_back(std::move(start));
    }
  }
  return starts;
}

}  // namespace caskdem::diagnosis
