#include "ensemble/limit_state_file.h"

#include <cmath>
#include <fstream>
#include <iomanip>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "model/build.h"

namespace caskdem {

namespace {

std::string kind_name(LimitState::Kind kind) {
  switch (kind) {
    case LimitState::Kind::tip_over: return "tip_over";
    case LimitState::Kind::rotation_ratio: return "rotation_ratio";
    case LimitState::Kind::sliding: return "sliding";
  }
  return "tip_over";
}

// A threshold's unit: sliding in m, a rotation ratio dimensionless (tip-over has none).
std::string threshold_unit(LimitState::Kind kind) { return kind == LimitState::Kind::sliding ? "m" : "1"; }

// The largest double for an infinite chi-square (a fit that says impossible where it happened).
double finite(double value) { return std::isfinite(value) ? value : 1.7976931348623157e308; }

void write_test(hdf5::Group& g, const fragility::FitTest& t) {
  g.attribute("fit_test_p_value", t.p_value);
  g.attribute("fit_rejected", std::int64_t(t.rejected));
  g.attribute("fit_test_level", fragility::kRejectionLevel);
  g.attribute("fit_test_replicates", std::int64_t(t.replicates));
  g.attribute("record_to_record", t.record_to_record);
  g.attribute("record_to_record_estimated", std::int64_t(t.record_to_record_estimated));
  g.attribute("design_effect", t.design_effect);
  g.attribute("binomial_p_value", t.binomial_p);
}

void write_measures(hdf5::Group& g, const std::vector<MeasureFit>& measures) {
  hdf5::Group all = g.group("measures");
  for (std::size_t k = 0; k < measures.size(); ++k) {
    const MeasureFit& m = measures[k];
    // Named by their order (a measure's name may hold a '/'), the ensemble's own first.
    hdf5::Group h = all.group(std::to_string(k));
    h.attribute("name", m.name);
    h.attribute("design", std::int64_t(m.design));
    h.attribute("display_unit", m.unit);
    h.attribute("display_unit_to_si", m.unit_to_si);
    h.attribute("intensity_unit", std::string(m.unit == "g" ? "m/s^2" : m.unit == "cm/s" ? "m/s" : "1"));
    h.attribute("fitted", std::int64_t(m.fit.fitted));
    if (!m.fit.fitted) {
      h.attribute("not_fitted_because", m.fit.reason);
      continue;
    }
    h.attribute("median", m.fit.median);
    h.attribute("log_std", m.fit.log_std);
    write_test(h, m.test);
  }
}

nlohmann::json test_json(const fragility::FitTest& t) {
  return {{"evaluated", t.evaluated},
          {"p_value", t.p_value},
          {"rejected", t.rejected},
          {"level", fragility::kRejectionLevel},
          {"replicates", t.replicates},
          {"record_to_record", t.record_to_record},
          {"record_to_record_estimated", t.record_to_record_estimated},
          {"design_effect", t.design_effect},
          {"binomial_p_value", t.binomial_p},
          {"chi_square", finite(t.chi_square)},
          {"degrees_of_freedom", t.degrees_of_freedom}};
}

}  // namespace

std::string intensity_si_unit(IntensityMeasure measure) {
  switch (measure) {
    case IntensityMeasure::pga:
    case IntensityMeasure::sa: return "m/s^2";
    case IntensityMeasure::pgv: return "m/s";
    case IntensityMeasure::pga_ratio:
    case IntensityMeasure::pgv_ratio: return "1";
  }
  return "1";
}

void write_limit_states(hdf5::Group& root, const EnsemblePlan& plan, const std::vector<LimitStateSummary>& summaries) {
  const EnsembleSpec& spec = plan.spec();
  const std::string unit = intensity_si_unit(spec.measure);
  hdf5::Group all = root.group("limit_states");
  for (std::size_t k = 0; k < summaries.size(); ++k) {
    const LimitStateSummary& s = summaries[k];
    hdf5::Group g = all.group(s.limit_state.name);
    g.attribute("order", std::int64_t(k));  // the ensemble file's order (the group lists names alphabetically)
    g.attribute("kind", kind_name(s.limit_state.kind));
    g.attribute("threshold", s.limit_state.threshold);
    g.attribute("threshold_unit", threshold_unit(s.limit_state.kind));
    g.attribute("intensity_unit", unit);
    std::vector<double> level, probability, lower, upper;
    std::vector<std::int64_t> trials, count;
    for (const auto& p : s.stripes) {
      level.push_back(p.level);
      trials.push_back(p.trials);
      count.push_back(p.count);
      probability.push_back(p.probability);
      lower.push_back(p.lower);
      upper.push_back(p.upper);
    }
    g.write("level", level, unit);
    g.write("trials", trials, "1");
    g.write("count", count, "1");
    g.write("probability", probability, "1");
    g.write("probability_lower", lower, "1");
    g.write("probability_upper", upper, "1");
    // The stripes split by motion: [motion][stripe], rows in the order of /motions/name.
    std::vector<double> motion_trials, motion_count;
    for (std::size_t m = 0; m < s.by_motion.trials.size(); ++m) {
      for (std::size_t j = 0; j < s.stripes.size(); ++j) {
        motion_trials.push_back(double(s.by_motion.trials[m][j]));
        motion_count.push_back(double(s.by_motion.counts[m][j]));
      }
    }
    g.write_matrix("motion_trials", motion_trials, s.by_motion.trials.size(), s.stripes.size(), "1");
    g.write_matrix("motion_count", motion_count, s.by_motion.trials.size(), s.stripes.size(), "1");
    if (s.limit_state.kind != LimitState::Kind::tip_over) {
      g.write("standing_count", s.standing_count, "1");
      g.attribute("largest_standing", s.largest_standing);  // in threshold_unit
    }
    g.attribute("same_as", s.same_as);
    g.attribute("fitted", std::int64_t(s.fit.fitted));
    if (s.fit.fitted) {
      g.attribute("median", s.fit.median);
      g.attribute("log_std", s.fit.log_std);
      g.attribute("log_likelihood", s.fit.log_likelihood);
      write_test(g, s.test);
      g.attribute("misfit_max_abs_difference", s.misfit.max_abs_difference);
      g.attribute("misfit_stripes_outside_interval", std::int64_t(s.misfit.stripes_outside_interval));
      g.attribute("misfit_chi_square", finite(s.misfit.chi_square));
      g.attribute("misfit_degrees_of_freedom", std::int64_t(s.misfit.degrees_of_freedom));
      g.attribute("misfit_p_value", s.misfit.p_value);
      g.write("band_im", s.band.im, unit);
      g.write("band_lower", s.band.lower, "1");
      g.write("band_upper", s.band.upper, "1");
      g.attribute("band_replicates", std::int64_t(s.band.replicates));
      g.attribute("band_failed_replicates", std::int64_t(s.band.failed_replicates));
      g.attribute("band_resampled", s.band.resampled);
      write_measures(g, s.measures);
    } else {
      g.attribute("not_fitted_because", s.fit.reason);
    }
    if (spec.outer_count() > 1) {
      const fragility::NestedFit& n = s.nested;
      hdf5::Group e = g.group("epistemic");
      e.attribute("fitted", std::int64_t(n.fitted));
      e.attribute("intensity_unit", unit);
      if (!n.fitted) e.attribute("not_fitted_because", n.reason);
      if (n.fitted) {
        e.attribute("median", n.median);
        e.attribute("beta_r", n.beta_r);
        e.attribute("beta_u", n.beta_u);
        e.attribute("beta_c", n.beta_c());
        e.attribute("log_median_spread", n.log_median_spread);
        e.attribute("fit_noise", n.fit_noise);
        e.attribute("confidence", n.confidence);
        e.attribute("median_low", n.median_low);
        e.attribute("median_high", n.median_high);
        e.attribute("beta_r_low", n.beta_r_low);
        e.attribute("beta_r_high", n.beta_r_high);
        e.attribute("beta_u_low", n.beta_u_low);
        e.attribute("beta_u_high", n.beta_u_high);
      }
      e.write("outer_median", n.outer_median, unit);
      e.write("outer_log_std", n.outer_log_std, "1");
    }
  }
}

std::vector<std::filesystem::path> write_fragility_tables(const std::filesystem::path& result_file,
                                                          const EnsemblePlan& plan,
                                                          const std::vector<LimitStateSummary>& summaries) {
  const EnsembleSpec& spec = plan.spec();
  const std::string unit = intensity_display_unit(spec.measure);
  const double to_unit = 1.0 / intensity_display_unit_to_si(spec.measure);
  const double scale = plan.model_scale();
  // Full size: PGV grows by sqrt(N), the other measures keep their values (at sqrt(N) times Sa's period).
  const double full_size = spec.measure == IntensityMeasure::pgv && scale > 1.0 ? std::sqrt(scale) : 1.0;
  const std::string stem = (result_file.parent_path() / result_file.stem()).string();
  const std::filesystem::path json_file = stem + "-fragility.json", csv_file = stem + "-fragility.csv";

  nlohmann::json report;
  report["result_file"] = result_file.string();
  report["title"] = spec.title;
  // The step the curves were computed at, so that a table read apart from its result file says it.
  report["time_step_s"] = plan.model().time_step;
  report["slider"] = slider_name_of(plan.model().whole_step_terms);
  report["intensity"] = {{"measure", intensity_name(spec.measure)},
                         {"unit", unit},
                         {"model_scale", scale},
                         {"of", scale > 1.0 ? "the table of the 1/" + std::to_string(int(std::lround(scale))) +
                                                  " model (median_full_size: the full-size cask's)"
                                            : scale == 1.0 ? "the table" : "the tables of models of several scales"}};
  if (spec.measure == IntensityMeasure::sa) report["intensity"]["period_s"] = spec.spectral_period;
  report["limit_states"] = nlohmann::json::array();
  std::ofstream csv(csv_file);
  // Column names that pandas and numpy both keep as they are: the unit spelt into the name.
  const std::string suffix = unit == "cm/s" ? "_cm_per_s" : unit.empty() ? "" : "_" + unit;
  csv << "limit_state,kind,threshold,threshold_unit,stripe,level" << suffix
      << ",trials,count,probability,probability_lower,probability_upper,standing_count,fitted,median" << suffix
      << ",log_std,fit_test_p_value,fit_rejected,record_to_record,binomial_p_value,fitted_probability\n";
  csv << std::setprecision(10);
  for (const LimitStateSummary& s : summaries) {
    nlohmann::json j = {{"name", s.limit_state.name},
                        {"kind", kind_name(s.limit_state.kind)},
                        {"threshold", s.limit_state.threshold},
                        {"threshold_unit", threshold_unit(s.limit_state.kind)},
                        {"fitted", s.fit.fitted},
                        {"same_as", s.same_as}};
    if (s.fit.fitted) {
      j["median"] = s.fit.median * to_unit;
      if (scale > 1.0) j["median_full_size"] = s.fit.median * to_unit * full_size;
      j["log_std"] = s.fit.log_std;
      j["rejected"] = s.test.rejected;
      j["test"] = test_json(s.test);
      j["measures"] = nlohmann::json::array();
      for (const MeasureFit& m : s.measures) {
        nlohmann::json mj = {{"name", m.name}, {"unit", m.unit}, {"design", m.design}, {"fitted", m.fit.fitted}};
        if (m.fit.fitted) {
          mj["median"] = m.fit.median / m.unit_to_si;
          mj["log_std"] = m.fit.log_std;
          mj["test"] = test_json(m.test);
        }
        j["measures"].push_back(mj);
      }
    } else {
      j["not_fitted_because"] = s.fit.reason;
    }
    if (s.limit_state.kind != LimitState::Kind::tip_over) {
      j["standing_count"] = s.standing_count;
      j["largest_standing"] = s.largest_standing;
    }
    j["stripes"] = nlohmann::json::array();
    for (std::size_t k = 0; k < s.stripes.size(); ++k) {
      const fragility::StripeProbability& p = s.stripes[k];
      j["stripes"].push_back({{"level", p.level * to_unit},
                              {"trials", p.trials},
                              {"count", p.count},
                              {"probability", p.probability},
                              {"lower", p.lower},
                              {"upper", p.upper}});
      const double fitted = fragility::fragility_probability(s.fit, p.level);
      csv << s.limit_state.name << "," << kind_name(s.limit_state.kind) << "," << s.limit_state.threshold << ","
          << threshold_unit(s.limit_state.kind) << "," << k << "," << p.level * to_unit << "," << p.trials << ","
          << p.count << "," << p.probability << "," << p.lower << "," << p.upper << ","
          << (s.limit_state.kind == LimitState::Kind::tip_over ? std::string() : std::to_string(s.standing_count[k])) << ","
          << int(s.fit.fitted) << ",";
      if (s.fit.fitted) {
        csv << s.fit.median * to_unit << "," << s.fit.log_std << "," << s.test.p_value << "," << int(s.test.rejected)
            << "," << s.test.record_to_record << "," << s.test.binomial_p << "," << fitted << "\n";
      } else {
        csv << ",,,,,,\n";
      }
    }
    report["limit_states"].push_back(j);
  }
  std::ofstream(json_file) << report.dump(2) << "\n";
  if (!csv) throw InputError(located(csv_file, 0, "could not be written"));
  return {json_file, csv_file};
}

}  // namespace caskdem
