// Fragility fits and site risk from Python: the ensemble's estimators (ensemble/fragility.h,
// ensemble/fit_test.h) on a caller's outcomes, and the risk command's convolution
// (risk/annual_frequency.h) of a lognormal curve with a hazard curve from a file or arrays.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ensemble/analysis.h"
#include "ensemble/fit_test.h"
#include "ensemble/fragility.h"
#include "ensemble/measures.h"
#include "ensemble/results.h"
#include "python/bindings.h"
#include "python/convert.h"
#include "risk/annual_frequency.h"
#include "risk/hazard_curve.h"

namespace caskdem::python {

namespace {

std::vector<std::int64_t> integers(const py::handle& values, const std::string& name) {
  const std::vector<double> v = column(values, name);
  std::vector<std::int64_t> out;
  for (double x : v) {
    if (!(x == std::floor(x)) || !(x >= 0.0) || x > 9e15) {
      throw py::value_error(name + ": expected non-negative whole numbers, got " + std::to_string(x));
    }
    out.push_back(static_cast<std::int64_t>(x));
  }
  return out;
}

// A lognormal curve fitted to realisations: each at an intensity (a stripe is a level that
// several share), exceeded or not, of a motion (the unit the bootstrap resamples and the fit
// test clusters; one motion when not given).
py::dict fit_fragility(const py::handle& level_values, const py::handle& exceeded_values,
                       const py::handle& motion_values, double confidence, int bootstrap, std::uint64_t seed) {
  const std::vector<double> level = column(level_values, "level");
  const std::vector<std::int64_t> exceeded = integers(exceeded_values, "exceeded");
  const std::vector<std::int64_t> motion =
      motion_values.is_none() ? std::vector<std::int64_t>(level.size(), 0) : integers(motion_values, "motion");
  if (level.size() != exceeded.size() || level.size() != motion.size()) {
    throw py::value_error("level, exceeded and motion: expected one value each per realisation, got " +
                          std::to_string(level.size()) + ", " + std::to_string(exceeded.size()) + " and " +
                          std::to_string(motion.size()));
  }
  if (level.empty()) throw py::value_error("level: expected at least one realisation");
  for (std::size_t i = 0; i < level.size(); ++i) {
    if (!(level[i] > 0.0) || !std::isfinite(level[i])) throw py::value_error("level: expected positive intensities");
    if (exceeded[i] > 1) throw py::value_error("exceeded: expected 0 or 1 (or booleans)");
  }
  if (!(confidence > 0.0 && confidence < 1.0)) throw py::value_error("confidence: expected a number in (0, 1)");
  if (bootstrap < 0) throw py::value_error("bootstrap: expected a non-negative number of replicates");

  std::vector<double> levels = level;
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  std::map<std::int64_t, std::size_t> motions;
  for (std::int64_t m : motion) motions.emplace(m, 0);
  std::size_t next = 0;
  for (auto& [id, k] : motions) k = next++;
  fragility::StripeData data;
  data.levels = levels;
  data.trials.assign(motions.size(), std::vector<std::int64_t>(levels.size(), 0));
  data.counts = data.trials;
  for (std::size_t i = 0; i < level.size(); ++i) {
    const std::size_t j =
        static_cast<std::size_t>(std::lower_bound(levels.begin(), levels.end(), level[i]) - levels.begin());
    const std::size_t m = motions[motion[i]];
    ++data.trials[m][j];
    data.counts[m][j] += exceeded[i];
  }

  std::vector<fragility::StripeProbability> stripes;
  std::vector<std::int64_t> trials, counts;
  fragility::LognormalFit fit;
  fragility::Band band;
  fragility::FitTest test;
  fragility::Misfit misfit;
  {
    py::gil_scoped_release release;  // the bootstraps refit hundreds of times
    stripes = fragility::stripe_probabilities(data, confidence);
    for (const auto& s : stripes) trials.push_back(s.trials), counts.push_back(s.count);
    fit = fragility::fit_lognormal(levels, trials, counts);
    if (fit.fitted) {
      std::vector<double> grid;
      const double low = 0.1 * levels.front(), high = 2.0 * levels.back();
      for (int k = 0; k <= 200; ++k) grid.push_back(low * std::pow(high / low, k / 200.0));
      // The streams an ensemble gives its first limit state (ensemble/analysis.cpp): with the
      // ensemble file's seed, its band and test come out as the result file has them.
      band = fragility::bootstrap_band(data, grid, bootstrap, confidence, band_seed(seed, 0));
      misfit = fragility::misfit(fit, stripes);
      std::vector<fragility::Cell> cells;
      for (std::size_t m = 0; m < data.trials.size(); ++m) {
        for (std::size_t j = 0; j < levels.size(); ++j) {
          if (data.trials[m][j] > 0)
            cells.push_back({static_cast<int>(j), levels[j], data.trials[m][j], data.counts[m][j]});
        }
      }
      // The test as fit_measures makes it for the ensemble's own measure: the curve over the cells.
      test = fragility::test_fit(fragility::fit_cells(cells), cells, fragility::kFitTestReplicates,
                                 measure_seed(fit_test_seed(seed), 0));
    }
  }

  py::dict out;
  out["fitted"] = fit.fitted;
  out["reason"] = fit.reason;
  out["median"] = fit.fitted ? py::object(py::float_(fit.median)) : py::object(py::none());
  out["beta"] = fit.fitted ? py::object(py::float_(fit.log_std)) : py::object(py::none());
  out["log_likelihood"] = fit.log_likelihood;
  std::vector<double> p, lower, upper;
  for (const auto& s : stripes) p.push_back(s.probability), lower.push_back(s.lower), upper.push_back(s.upper);
  py::dict stripe_table;
  stripe_table["level"] = array(levels);
  stripe_table["trials"] = array(trials);
  stripe_table["count"] = array(counts);
  stripe_table["probability"] = array(p);
  stripe_table["lower"] = array(lower);
  stripe_table["upper"] = array(upper);
  out["stripes"] = stripe_table;
  if (fit.fitted) {
    py::dict b;
    b["intensity"] = array(band.im);
    b["lower"] = array(band.lower);
    b["upper"] = array(band.upper);
    b["replicates"] = band.replicates;
    b["failed_replicates"] = band.failed_replicates;
    b["resampled"] = band.resampled;
    out["band"] = b;
    py::dict t;
    t["p_value"] = test.p_value;
    t["binomial_p"] = test.binomial_p;
    t["chi_square"] = test.chi_square;
    t["degrees_of_freedom"] = test.degrees_of_freedom;
    t["record_to_record"] = test.record_to_record;
    t["record_to_record_estimated"] = test.record_to_record_estimated;
    t["design_effect"] = test.design_effect;
    t["replicates"] = test.replicates;
    t["rejected"] = test.rejected;
    t["text"] = fragility::fit_test_text(test);
    out["test"] = t;
    out["rejected"] = test.rejected;
    out["max_abs_difference"] = misfit.max_abs_difference;
  } else {
    out["band"] = py::none();
    out["test"] = py::none();
    out["rejected"] = false;
  }
  out["confidence"] = confidence;
  return out;
}

risk::IntensityMeasure measure_of(const std::string& text) {
  const auto measure = risk::parse_intensity_measure(text);
  if (!measure) throw py::value_error("measure: expected PGA, PGV or SA(T) (T in s), got '" + text + "'");
  return *measure;
}

py::dict annual_frequency(double median, double beta_r, double beta_u, const std::string& measure_text,
                          const py::object& hazard, const py::object& intensity, const py::object& frequency) {
  const risk::IntensityMeasure measure = measure_of(measure_text);
  risk::HazardCurve curve;
  if (!hazard.is_none()) {
    if (!intensity.is_none() || !frequency.is_none()) {
      throw py::value_error("hazard: give a hazard file or the arrays intensity and frequency, not both");
    }
    risk::HazardReadOptions options;
    options.measure = measure;  // a file of another measure is refused
    curve = risk::read_hazard_curve(py::str(hazard).cast<std::string>(), options);
  } else {
    if (intensity.is_none() || frequency.is_none()) {
      throw py::value_error("hazard: expected a hazard file, or both intensity (SI) and frequency (1/year) arrays");
    }
    curve.source = "arrays";
    curve.measure = measure;
    curve.intensity = column(intensity, "intensity");
    curve.annual_frequency = column(frequency, "frequency");
    risk::check_hazard_curve(curve);
  }
  risk::LognormalFragility fragility{median, beta_r, beta_u};
  risk::check_fragility(fragility);
  const risk::SiteRisk r = risk::site_risk(curve, fragility);
  py::dict out;
  out["measure"] = risk::intensity_measure_name(curve.measure);
  out["unit"] = curve.measure.is_acceleration() ? "m/s^2" : "m/s";
  out["mean"] = r.mean;
  out["median"] = r.median;
  // Without an epistemic spread every fractile is the median: nothing was sampled.
  out["fractile_05"] = beta_u > 0.0 ? py::object(py::float_(r.fractile_05)) : py::object(py::none());
  out["fractile_95"] = beta_u > 0.0 ? py::object(py::float_(r.fractile_95)) : py::object(py::none());
  out["hclpf_conservative"] = r.hclpf_conservative;
  out["hclpf_composite"] = r.hclpf_composite;
  out["hclpf_lower"] = std::min(r.hclpf_conservative, r.hclpf_composite);
  out["below_curve"] = r.mean_integral.below_curve;
  out["above_curve"] = r.mean_integral.above_curve;
  out["undetermined_above"] = r.mean_integral.undetermined_above;
  out["segment_frequency"] = array(r.mean_integral.segment_frequency);
  out["hazard_intensity"] = array(curve.intensity);
  out["hazard_frequency"] = array(curve.annual_frequency);
  out["hazard_source"] = curve.source;
  return out;
}

}  // namespace

void bind_statistics(py::module_& m) {
  m.def("fit_fragility", &fit_fragility, py::arg("level"), py::arg("exceeded"), py::arg("motion") = py::none(),
        py::arg("confidence") = 0.95, py::arg("bootstrap") = 200, py::arg("seed") = 1);
  m.def("annual_frequency", &annual_frequency, py::arg("median"), py::arg("beta_r"), py::arg("beta_u") = 0.0,
        py::arg("measure") = "PGA", py::arg("hazard") = py::none(), py::arg("intensity") = py::none(),
        py::arg("frequency") = py::none());
  m.def(
      "verify_result", [](const std::filesystem::path& file) { verify_ensemble_file(file); }, py::arg("file"));
}

}  // namespace caskdem::python
