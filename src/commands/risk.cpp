// caskdem risk [RESULT.h5] --hazard FILE: the annual frequency of each limit state at a site,
// the fragility (an ensemble's fitted curves, or a median and betas given) convolved with the
// site's hazard curve (risk/annual_frequency.h), with HCLPF, the probability in N years, the
// ratio to a target and the intensities that contribute; a JSON and a PNG beside.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "core/quantity.h"
#include "core/text.h"
#include "core/units.h"
#include "ensemble/fit_test.h"
#include "ensemble/results.h"
#include "io/hdf5_file.h"
#include "io/output_paths.h"
#include "io/run_output.h"
#include "risk/annual_frequency.h"
#include "risk/hazard_curve.h"

namespace caskdem::commands {

namespace {

// The answer into the result file as a /risk group (replacing an earlier one), written back
// whole and sealed, as the ensemble writes it.
void write_risk_group(const std::string& file, const nlohmann::json& report) {
  hdf5::Group root = hdf5::open_sealed_in_memory(file, "a result file of caskdem ensemble");
  root.remove("risk");
  hdf5::Group risk = root.group("risk");
  const auto& hazard = report["hazard"];
  risk.attribute("hazard_source", hazard["source"].get<std::string>());
  risk.attribute("measure", hazard["measure"].get<std::string>());
  risk.attribute("unit", hazard["unit"].get<std::string>());
  risk.attribute("years", report["years"].get<double>());
  risk.attribute("target_annual_frequency", report["target_annual_frequency"].get<double>());
  if (report.contains("design_basis")) risk.attribute("design_basis", report["design_basis"].get<double>());
  // SI, as every intensity of the result file (the JSON has the user's unit).
  std::vector<double> intensity = hazard["intensity"].get<std::vector<double>>();
  for (double& a : intensity) a *= hazard["unit_to_si"].get<double>();
  risk.write("hazard_intensity", intensity, hazard["si_unit"].get<std::string>());
  risk.write("hazard_annual_frequency", hazard["annual_frequency"].get<std::vector<double>>(), "1/yr");
  for (const auto& state : report["limit_states"]) {
    hdf5::Group g = risk.group(state["name"].get<std::string>());
    for (const auto& [key, value] : state.items()) {
      if (value.is_number()) g.attribute(key, value.get<double>());
    }
    g.write("segment_annual_frequency", state["segment_annual_frequency"].get<std::vector<double>>(), "1/yr");
  }
  hdf5::replace_sealed(file, [&] { return hdf5::file_image(root); });
}

using risk::IntensityMeasure;

struct NamedFragility {
  std::string name;
  risk::LognormalFragility fragility;
  std::string same_as;    // a result file's note that another limit state has the same stripes
  bool tested = false;    // its fit was tested with the motions clustered (a result file's curve)
  bool rejected = false;  // and rejected
  double test_p = 1.0;
};

NamedFragility named(std::string name, const risk::LognormalFragility& fragility) {
  NamedFragility f;
  f.name = std::move(name);
  f.fragility = fragility;
  return f;
}

struct RiskOptions {
  std::string result, hazard, format = "automatic", imt, site, median, measure, design_basis, json, plot;
  double beta = 0.0, beta_r = 0.0, beta_u = 0.0, years = 50.0, target = 1e-5, similarity = 1.0;
  bool similarity_given = false;
  bool no_plot = false;
};

// "0.9 g" (or a bare SI number) in the dimension of the hazard's measure.
double intensity_option(const std::string& option, const std::string& text, const IntensityMeasure& measure) {
  std::string error;
  const auto value = parse_quantity(text, measure.is_acceleration() ? Dimension::acceleration : Dimension::velocity, error);
  if (!value || !std::isfinite(*value) || *value <= 0.0)
    throw InputError(option + ": \"" + text + "\"; expected " + (measure.is_acceleration() ? "an acceleration" : "a velocity") +
                     " above 0 such as \"" + (measure.is_acceleration() ? "0.9 g" : "80 cm/s") + "\" for a hazard of " +
                     intensity_measure_name(measure) + (error.empty() ? "" : " (" + error + ")"));
  return *value;
}

// A model's intensities as the prototype's, by the similarity law of a 1/N model (caskdem
// similarity): lengths 1/N, times 1/sqrt(N), so accelerations alike and velocities 1/sqrt(N);
// a spectral ordinate keeps its value at a period sqrt(N) times longer.
double prototype_factor(IntensityMeasure& measure, double n) {
  if (measure.kind == IntensityMeasure::Kind::sa) measure.period *= std::sqrt(n);
  return measure.kind == IntensityMeasure::Kind::pgv ? std::sqrt(n) : 1.0;
}

// The fitted lognormal of each limit state of an ensemble result, in the SI unit of PGA, PGV
// or SA(T) (the measure in `measure`), as prototype intensities when `similarity` is not 1.
// Limit states without a fitted curve are noted in `notes`, printed once every input is read.
// The model's scale the result file records (its motions' similarity_scale): 1 for a file that
// predates it, with a note.
double model_scale_of(const std::string& file, std::vector<std::string>& notes) {
  const hdf5::Group root = hdf5::open_file(file);
  if (!root.has_attribute("model_scale")) {
    notes.push_back("scale      " + file + " records no model scale (an older result file): its curves are taken as "
                    "the full-size cask's; --similarity N says otherwise");
    return 1.0;
  }
  return root.double_attribute("model_scale");
}

std::vector<NamedFragility> fragilities_of_result(const std::string& file, const IntensityMeasure& hazard_measure,
                                                  const std::string& hazard_file, double beta_u, double similarity,
                                                  std::vector<std::string>& notes) {
  std::vector<NamedFragility> out;
  try {
    verify_ensemble_file(file);
    const hdf5::Group root = hdf5::open_file(file);
    if (!root.has("limit_states"))
      throw InputError(located(file, 0, "has no limit_states group; expected the result file of a completed ensemble"));
    const std::string measure = root.string_attribute("intensity_measure");
    if (measure != "pga" && measure != "pga_ratio" && measure != "pgv" && measure != "pgv_ratio" && measure != "sa")
      throw InputError(located(file, 0, "intensity_measure \"" + measure + "\"; expected pga, pgv, pga_ratio, pgv_ratio or sa"));
    // Ratios to the uplift threshold g tan(alpha) (and p for PGV) convert to PGA and PGV.
    const double uplift = units::standard_gravity * std::tan(root.double_attribute("stability_angle_rad"));
    IntensityMeasure im{IntensityMeasure::Kind::pga, 0.0};
    double to_si = 1.0;
    if (measure == "pga_ratio") to_si = uplift;
    if (measure == "pgv" || measure == "pgv_ratio") im.kind = IntensityMeasure::Kind::pgv;
    if (measure == "pgv_ratio") to_si = uplift / root.double_attribute("frequency_parameter_rad_s");
    if (measure == "sa") {
      im = {IntensityMeasure::Kind::sa, root.double_attribute("intensity_period_s")};
      // Hazard curves are of 5 %-damped spectra.
      const double zeta = root.double_attribute("intensity_damping_ratio");
      if (std::abs(zeta - 0.05) > 1e-9)
        throw InputError(located(file, 0, "its fragility curves are of Sa at " + number_text(100.0 * zeta) +
                                              " % damping; expected 5 %, the damping of hazard curves"));
    }
    to_si *= prototype_factor(im, similarity);
    if (!(im == hazard_measure))
      throw InputError(located(file, 0, "its fragility curves are of " + intensity_measure_name(im) +
                                            (similarity != 1.0 ? " (as the prototype's)" : "") + " but the hazard curve " +
                                            hazard_file + " is of " + intensity_measure_name(hazard_measure) +
                                            "; expected a hazard curve of " + intensity_measure_name(im)));
    const hdf5::Group all = root.open_group("limit_states");
    // In the ensemble file's order where the file records it.
    std::vector<std::string> names = all.member_names();
    std::stable_sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
      const auto order = [&](const std::string& n) {
        const hdf5::Group g = all.open_group(n);
        return g.has_attribute("order") ? g.integer_attribute("order") : std::int64_t(0);
      };
      return order(a) < order(b);
    });
    for (const std::string& name : names) {
      const hdf5::Group g = all.open_group(name);
      if (g.integer_attribute("fitted") == 0) {
        notes.push_back("fragility  " + name + ": not fitted (" + g.string_attribute("not_fitted_because") +
                        "), no annual frequency");
        continue;
      }
      // An ensemble with epistemic parameters has the family's A_m, beta_R and beta_U.
      if (g.has("epistemic")) {
        const hdf5::Group e = g.open_group("epistemic");
        if (e.integer_attribute("fitted") != 0) {
          if (beta_u > 0.0)
            throw InputError("--beta-u: " + file + " separates beta_U already (its ensemble has epistemic parameters)");
          out.push_back(named(name, {e.double_attribute("median") * to_si, e.double_attribute("beta_r"),
                                     e.double_attribute("beta_u")}));
          continue;
        }
        notes.push_back("fragility  " + name + ": no epistemic family (" + e.string_attribute("not_fitted_because") +
                        "); the pooled curve, taken as aleatory");
      }
      out.push_back(named(name, {g.double_attribute("median") * to_si, g.double_attribute("log_std"), beta_u}));
    }
    // The pooled curve's test stands for the family too: the family is fitted to the same stripes.
    for (NamedFragility& f : out) {
      const hdf5::Group g = all.open_group(f.name);
      if (g.has_attribute("same_as")) f.same_as = g.string_attribute("same_as");
      if (!g.has_attribute("fit_rejected")) continue;
      f.tested = true;
      f.rejected = g.integer_attribute("fit_rejected") != 0;
      f.test_p = g.double_attribute("fit_test_p_value");
    }
    for (const NamedFragility& f : out) {
      try {
        risk::check_fragility(f.fragility);
      } catch (const std::invalid_argument& e) {
        throw InputError(located(file, 0, "limit state " + f.name + ": " + e.what()));
      }
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(located(file, 0, std::string(e.what()) + "; expected a result file of caskdem ensemble"));
  }
  if (out.empty()) throw InputError(located(file, 0, "has no fitted fragility curve; expected at least one"));
  return out;
}

// Four significant digits: a capacity or a hazard level is not known better.
std::string intensity_text(double si, const IntensityMeasure& m) {
  std::ostringstream out;
  out << std::setprecision(4) << si / risk::display_unit_to_si(m) << " " << risk::display_unit(m);
  return out.str();
}

void run_risk(const RiskOptions& o, bool beta_given, bool beta_r_given, bool beta_u_given) {
  risk::HazardReadOptions read;
  const auto format = risk::parse_hazard_format(o.format);
  if (!format) throw InputError("--hazard-format: \"" + o.format + "\"; expected automatic, openquake, nshmp or table");
  read.format = *format;
  if (!o.imt.empty()) {
    read.measure = risk::parse_intensity_measure(o.imt);
    if (!read.measure) throw InputError("--imt: \"" + o.imt + "\"; expected PGA, PGV or SA(T) with T in s");
  }
  if (!o.site.empty()) {
    const auto comma = o.site.find(',');
    const auto lon = parse_double(trim(std::string_view(o.site).substr(0, comma)));
    const auto lat = comma == std::string::npos ? std::nullopt : parse_double(trim(std::string_view(o.site).substr(comma + 1)));
    if (!lon || !lat || !std::isfinite(*lon) || !std::isfinite(*lat))
      throw InputError("--site: \"" + o.site + "\"; expected LON,LAT in degrees");
    read.site = std::pair{*lon, *lat};
  }
  const risk::HazardCurve hazard = risk::read_hazard_curve(o.hazard, read);
  const IntensityMeasure& im = hazard.measure;

  std::vector<NamedFragility> fragilities;
  std::vector<std::string> notes;
  double similarity = o.similarity;
  if (!o.result.empty()) {
    if (!o.median.empty() || beta_given || beta_r_given || !o.measure.empty())
      throw InputError("--median, --beta, --beta-r and --measure: give a fragility either by its parameters or by a "
                       "result file, not both");
    // A 1/N model's curves go to the full-size cask unless --similarity says otherwise.
    if (!o.similarity_given) {
      try {
        verify_ensemble_file(o.result);
        similarity = model_scale_of(o.result, notes);
      } catch (const std::runtime_error& e) {
        if (dynamic_cast<const InputError*>(&e)) throw;
        throw InputError(located(o.result, 0, std::string(e.what()) + "; expected a result file of caskdem ensemble"));
      }
      if (similarity == 0.0)
        throw InputError(located(o.result, 0, "its motions are applied to models of several scales (their "
                                              "similarity_scale differ); expected --similarity N to say which"));
    }
    fragilities = fragilities_of_result(o.result, im, o.hazard, o.beta_u, similarity, notes);
  } else {
    if (o.median.empty() || (!beta_given && !beta_r_given))
      throw InputError("risk: expected a result file, or --median with --measure and --beta (or --beta-r and --beta-u)");
    if (beta_given && (beta_r_given || beta_u_given))
      throw InputError("--beta: give either --beta (aleatory alone) or --beta-r with --beta-u, not both");
    // A given fragility names its measure, and a hazard of another is refused.
    if (o.measure.empty())
      throw InputError("--measure: a given fragility needs its intensity measure (PGA, PGV or SA(T) with T in s), "
                       "the measure of --median");
    const auto given = risk::parse_intensity_measure(o.measure);
    if (!given) throw InputError("--measure: \"" + o.measure + "\"; expected PGA, PGV or SA(T) with T in s");
    IntensityMeasure model = *given;
    if (similarity != 1.0 && model.kind == IntensityMeasure::Kind::sa)
      throw InputError("--similarity: a given SA fragility is at the model's period; give it at the prototype's instead");
    const double factor = prototype_factor(model, similarity);
    if (!(model == im))
      throw InputError("--measure " + o.measure + ": the fragility is of " + intensity_measure_name(model) +
                       (similarity != 1.0 ? " (as the prototype's)" : "") + " but the hazard curve " + o.hazard +
                       " is of " + intensity_measure_name(im) + "; expected a hazard curve of " +
                       intensity_measure_name(model));
    fragilities.push_back(named(
        "given", {intensity_option("--median", o.median, im) * factor, beta_given ? o.beta : o.beta_r, o.beta_u}));
    try {
      risk::check_fragility(fragilities.back().fragility);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string(beta_given ? "--beta" : "--beta-r and --beta-u") + ": " + e.what());
    }
  }
  const double design_basis = o.design_basis.empty() ? 0.0 : intensity_option("--design-basis", o.design_basis, im);

  // Every answer before any line is printed, so that a refusal is the only line.
  std::vector<risk::SiteRisk> risks;
  for (const NamedFragility& f : fragilities) {
    try {
      risks.push_back(risk::site_risk(hazard, f.fragility));
    } catch (const std::invalid_argument& e) {
      throw InputError(located(o.hazard, 0, f.name + ": " + e.what()));
    }
  }
  std::filesystem::path json = o.json, png = o.plot;
  if (!o.result.empty()) {
    const std::filesystem::path stem = std::filesystem::path(o.result).replace_extension("");
    if (json.empty()) json = stem.string() + "-risk.json";
    if (png.empty() && !o.no_plot) png = stem.string() + "-risk.png";
  }
  if (!png.empty() && o.no_plot) png.clear();
  if (!png.empty() && json.empty()) json = std::filesystem::path(png).replace_extension(".json");
  if (!json.empty()) prepare_output_file(json);
  if (!png.empty()) prepare_output_file(png);

  std::cout << "hazard     " << hazard.source << ": " << intensity_measure_name(im) << ", " << hazard.intensity.size()
            << " points from " << intensity_text(hazard.intensity.front(), im) << " to "
            << intensity_text(hazard.intensity.back(), im) << "\n";
  if (similarity != 1.0) {
    std::cout << "scale      the fragility is a 1/" << similarity << " model's"
              << (o.similarity_given ? " (--similarity)" : " (the result file's motions are prototype motions on it)")
              << ", set against the site as the full-size cask's (accelerations alike, PGV x sqrt(" << similarity
              << "), Sa at sqrt(" << similarity << ") times the period)" << (o.similarity_given ? "" : "; --similarity 1 keeps the model's")
              << "\n";
  }
  nlohmann::json report;
  report["hazard"] = {{"source", hazard.source},
                      {"measure", intensity_measure_name(im)},
                      {"unit", risk::display_unit(im)},
                      {"unit_to_si", risk::display_unit_to_si(im)},
                      {"si_unit", im.is_acceleration() ? "m/s^2" : "m/s"},
                      {"annual_frequency", hazard.annual_frequency}};
  std::vector<double> shown;
  for (double a : hazard.intensity) shown.push_back(a / risk::display_unit_to_si(im));
  report["hazard"]["intensity"] = shown;
  report["years"] = o.years;
  report["similarity"] = similarity;
  report["intensities"] = similarity > 1.0 ? "the full-size cask's (the 1/N model's curves taken to full size)"
                                           : "the cask's as given";
  report["target_annual_frequency"] = o.target;
  if (design_basis > 0.0) report["design_basis"] = design_basis / risk::display_unit_to_si(im);
  report["limit_states"] = nlohmann::json::array();

  for (const std::string& note : notes) std::cout << note << "\n";
  std::cout << std::setprecision(3);
  for (std::size_t k = 0; k < fragilities.size(); ++k) {
    const NamedFragility& f = fragilities[k];
    const risk::SiteRisk& r = risks[k];
    const double unit = risk::display_unit_to_si(im);
    const risk::FrequencyIntegral& mean = r.mean_integral;
    std::cout << "fragility  " << f.name << ": median " << intensity_text(f.fragility.median, im)
              << (similarity > 1.0 ? " at full size" : "") << ", beta_R " << f.fragility.beta_r << ", beta_U "
              << f.fragility.beta_u << " (beta_C " << f.fragility.beta_c() << ")\n";
    if (!f.same_as.empty()) std::cout << "  " << f.same_as << "\n";
    if (f.rejected) {
      std::cout << "  rests on a REJECTED fit: the ensemble's curve fails its test at "
                << 100.0 * fragility::kRejectionLevel << " % (p " << f.test_p
                << " with the motions clustered); the frequencies below are those of a curve the stripes do not bear "
                   "out (docs/ensemble-file.md, the fit test)\n";
    }
    std::cout << "  annual frequency  mean " << r.mean << " /yr; median " << r.median;
    if (f.fragility.beta_u > 0.0) {
      std::cout << ", 5 % " << r.fractile_05 << ", 95 % " << r.fractile_95 << "\n";
    } else {
      std::cout << "; fractiles not sampled (beta_U = 0: no epistemic uncertainty in this fragility)\n";
    }
    std::cout << "  in " << o.years << " years       " << risk::probability_in_years(r.mean, o.years) << " (mean)\n";
    std::cout << "  against target    " << r.mean / o.target << " x " << o.target << " /yr\n";
    // Both definitions, the lower one named: with a small beta_U the "conservative" one is the larger.
    const bool composite_lower = r.hclpf_composite <= r.hclpf_conservative;
    std::cout << "  HCLPF             " << intensity_text(std::min(r.hclpf_composite, r.hclpf_conservative), im)
              << " (the lower: " << (composite_lower ? "1 % of the composite curve" : "A_m exp(-1.645 (beta_R + beta_U))")
              << "); " << intensity_text(std::max(r.hclpf_composite, r.hclpf_conservative), im) << " by "
              << (composite_lower ? "A_m exp(-1.645 (beta_R + beta_U))" : "1 % of the composite curve");
    if (design_basis > 0.0)
      std::cout << "; the lower " << std::min(r.hclpf_composite, r.hclpf_conservative) / design_basis
                << " x the design basis";
    std::cout << "\n";
    // The segment that contributes most, and the share beyond the curve's ends.
    std::size_t modal = 0;
    for (std::size_t i = 0; i < mean.segment_frequency.size(); ++i)
      if (mean.segment_frequency[i] > mean.segment_frequency[modal]) modal = i;
    std::cout << "  contributes most  " << intensity_text(hazard.intensity[modal], im) << " to "
              << intensity_text(hazard.intensity[modal + 1], im) << " ("
              << 100.0 * mean.segment_frequency[modal] / r.mean << " %); beyond the curve "
              << 100.0 * (mean.below_curve + mean.above_curve) / r.mean << " %\n";
    nlohmann::json j = {{"name", f.name},
                        {"median", f.fragility.median / unit},
                        {"beta_r", f.fragility.beta_r},
                        {"beta_u", f.fragility.beta_u},
                        {"beta_c", f.fragility.beta_c()},
                        {"mean_annual_frequency", r.mean},
                        {"median_annual_frequency", r.median},
                        {"fractiles_sampled", f.fragility.beta_u > 0.0},
                        {"fit_tested", f.tested},
                        {"same_as", f.same_as},
                        {"fit_rejected", f.rejected},
                        {"probability_in_years", risk::probability_in_years(r.mean, o.years)},
                        {"ratio_to_target", r.mean / o.target},
                        {"hclpf_conservative", r.hclpf_conservative / unit},
                        {"hclpf_composite", r.hclpf_composite / unit},
                        {"hclpf_lower", std::min(r.hclpf_conservative, r.hclpf_composite) / unit},
                        {"below_curve", mean.below_curve},
                        {"above_curve", mean.above_curve},
                        {"undetermined_above", mean.undetermined_above},
                        {"segment_annual_frequency", mean.segment_frequency}};
    if (design_basis > 0.0) j["hclpf_to_design_basis"] = std::min(r.hclpf_conservative, r.hclpf_composite) / design_basis;
    // Fractiles only where an epistemic beta_U was sampled or given; null otherwise (not sampled).
    j["fractile_05_annual_frequency"] = f.fragility.beta_u > 0.0 ? nlohmann::json(r.fractile_05) : nlohmann::json();
    j["fractile_95_annual_frequency"] = f.fragility.beta_u > 0.0 ? nlohmann::json(r.fractile_95) : nlohmann::json();
    if (f.tested) j["fit_test_p_value"] = f.test_p;
    report["limit_states"].push_back(j);
  }

  if (!o.result.empty()) {
    write_risk_group(o.result, report);
    std::cout << "wrote " << o.result << " (its /risk group)\n";
  }
  if (!json.empty()) {
    std::ofstream(json) << report.dump(2) << "\n";
    std::cout << "wrote " << json.string() << "\n";
  }
  if (!png.empty()) {
    run_plot_script("plot_risk.py", {json.string(), png.string()});
    std::cout << "wrote " << png.string() << "\n";
  }
}

}  // namespace

void add_risk(CLI::App& app) {
  auto o = std::make_shared<RiskOptions>();
  CLI::App* cmd = app.add_subcommand(
      "risk", "Annual frequency of each limit state at a site: fragility x hazard curve, with HCLPF and fractiles");
  cmd->add_option("result", o->result, "Ensemble result file (HDF5) whose fitted fragility curves to use");
  cmd->add_option("--hazard", o->hazard, "Hazard curve: OpenQuake or nshmp-haz CSV, or a table")->required();
  cmd->add_option("--hazard-format", o->format, "automatic, openquake, nshmp or table");
  cmd->add_option("--imt", o->imt, "Intensity measure of a hazard file that does not say it: PGA, PGV or SA(T)");
  cmd->add_option("--site", o->site, "LON,LAT of the site in a hazard file of several");
  cmd->add_option("--median", o->median, "Median capacity of a given fragility, e.g. \"0.9 g\"");
  cmd->add_option("--measure", o->measure, "The intensity measure of a given fragility: PGA, PGV or SA(T) (required "
                                           "with --median; the hazard's must be the same)");
  auto* beta = cmd->add_option("--beta", o->beta, "Its log standard deviation (aleatory)")->check(positive_number());
  auto* beta_r = cmd->add_option("--beta-r", o->beta_r, "Aleatory log standard deviation beta_R")->check(positive_number());
  auto* beta_u = cmd->add_option("--beta-u", o->beta_u, "Epistemic log standard deviation beta_U (default 0)")
                     ->check(non_negative_number());
  auto* similarity = cmd->add_option("--similarity", o->similarity,
                  "The fragility is a 1/N model's: set its intensities against the site as the prototype's (PGV x "
                  "sqrt(N)); default: a result file's own model scale (1 keeps its curves as the model's), else 1")
      ->check(number_check("a scale N of at least 1", [](double x) { return x >= 1.0; }, "N"));
  cmd->add_option("--years", o->years, "Years for the probability of exceedance (default 50)")->check(positive_number());
  cmd->add_option("--target", o->target, "Target annual frequency (default 1e-5, ASCE 43 SDC-5)")->check(positive_number());
  cmd->add_option("--design-basis", o->design_basis, "Design-basis intensity, e.g. \"0.3 g\": HCLPF against it");
  cmd->add_option("--json", o->json, "JSON file of the numbers (default beside a result file)");
  cmd->add_option("--plot", o->plot, "PNG of the hazard, the fragility family and the contributions");
  cmd->add_flag("--no-plot", o->no_plot, "Write no PNG");
  cmd->callback([o, beta, beta_r, beta_u, similarity]() {
    o->similarity_given = similarity->count() > 0;
    run_risk(*o, beta->count() > 0, beta_r->count() > 0, beta_u->count() > 0);
  });
}

}  // namespace caskdem::commands
