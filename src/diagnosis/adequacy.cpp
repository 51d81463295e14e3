#include "diagnosis/adequacy.h"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/chi_squared.hpp>

#include "diagnosis/measures.h"

namespace caskdem::diagnosis {

double chi_square_survival(double x, int degrees_of_freedom) {
  if (degrees_of_freedom < 1) return 1.0;
  if (!(x > 0.0)) return 1.0;
  const boost::math::chi_squared_distribution<double> chi2(degrees_of_freedom);
  return boost::math::cdf(boost::math::complement(chi2, x));
}

const std::vector<MeasureFamily>& measure_families() {
  // Which mechanisms act on what: the friction law and the vertical table load set how far a
  // cask slides, and a soft floor how soon it starts; the loss per impact and its growth with
  // amplitude set how high and how long it rocks; the pivot's position and the channels'
  // timing set the rocking's rhythm and phase; an off-axis mass or a curved base tilt it to
  // one side (mechanisms.h).
  static const std::vector<MeasureFamily> families = {
      {"sliding",
       "how far the cask slides",
       {"max_sliding", "residual_sliding", "sliding_history"},
       {"max_sliding"},
       {"velocity_dependent_friction", "vertical_excitation", "floor_compliance"}},
      {"rocking_amplitude",
       "how high and how long the cask rocks",
       {"peak_rotation", "rms_rotation", "rocking_duration"},
       {"peak_rotation", "rms_rotation", "rocking_duration"},
       {"amplitude_dependent_restitution", "out_of_plane_loss", "vertical_excitation", "floor_compliance",
        "base_imperfection"}},
      {"rocking_timing",
       "the rocking's rhythm and phase",
       {"rocking_rate", "rotation_history", "rotation_lag"},
       {"rocking_rate"},
       {"sensor_delay", "base_imperfection", "floor_compliance"}},
      {"asymmetry", "rocking further to one side", {"rotation_asymmetry"}, {}, {"eccentric_mass", "base_imperfection"}},
  };
  return families;
}

std::vector<FamilyFit> judge_families(const std::vector<std::vector<double>>& residuals,
                                      const std::vector<std::vector<std::uint8_t>>& compared) {
  const std::vector<MeasureFamily>& families = measure_families();
  std::vector<FamilyFit> fits;
  for (const MeasureFamily& family : families) {
    FamilyFit f;
    f.family = family.name;
    double magnitude_sum = 0.0;
    for (std::size_t t = 0; t < residuals.size(); ++t) {
      for (const std::string& measure : family.measures) {
        const std::size_t m = measure_index(measure);
        if (m >= residuals[t].size() || !compared[t][m]) continue;
        f.statistic += robust_loss({residuals[t][m]});
        ++f.residuals;
        if (std::find(family.magnitudes.begin(), family.magnitudes.end(), measure) != family.magnitudes.end()) {
          magnitude_sum += residuals[t][m];
          ++f.magnitude_residuals;
        }
      }
    }
    f.p_value = f.residuals > 0 ? chi_square_survival(f.statistic, f.residuals) : 1.0;
    f.mean_magnitude_residual = f.magnitude_residuals > 0 ? magnitude_sum / f.magnitude_residuals : 0.0;
    fits.push_back(f);
  }
  // Holm's step-down: the k-th smallest p-value (from 0) against level / (F - k), stopping at
  // the first that passes; ties keep the families' order, so the verdict is deterministic.
  std::vector<std::size_t> order(fits.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return fits[a].p_value < fits[b].p_value; });
  bool rejecting = true;
  for (std::size_t k = 0; k < order.size(); ++k) {
    FamilyFit& f = fits[order[k]];
    f.holm_level = kAdequacyLevel / double(order.size() - k);
    rejecting = rejecting && f.p_value < f.holm_level;
    f.misfits = rejecting;
  }
  return fits;
}

namespace {

void add_check(std::vector<std::string>& checks, const std::string& check) {
  if (std::find(checks.begin(), checks.end(), check) == checks.end()) checks.push_back(check);
}

const char* kGeometryCheck =
    "the contact geometry: the half-width rule (gyration or radius) or a distributed base ([cask] footprint), "
    "and the contact stiffness's units";

}  // namespace

Adequacy judge_adequacy(const MeasuredSet& set, const std::vector<Parameter>& parameters, const FitResult& fit,
                        const std::vector<double>& nominal, const std::vector<double>& loss,
                        const std::vector<std::vector<double>>& residuals,
                        const std::vector<std::vector<std::uint8_t>>& compared,
                        const PointObjective& training_objective) {
  Adequacy a;
  const std::size_t tests = set.tests.size();
  const double test_level = kAdequacyLevel / double(tests);
  for (std::size_t t = 0; t < tests; ++t) {
    const int test_compared = static_cast<int>(std::count(compared[t].begin(), compared[t].end(), std::uint8_t{1}));
    a.statistic += loss[t];
    a.residuals += test_compared;
    if (chi_square_survival(loss[t], test_compared) < test_level) a.misfitting_tests.push_back(set.tests[t].name);
    for (std::size_t m = 0; m < residuals[t].size(); ++m) {
      if (std::abs(residuals[t][m]) > kMisfitResidual) {
        a.misfits.push_back({set.tests[t].name, measure_names()[m], residuals[t][m]});
      }
    }
  }
  a.degrees_of_freedom = std::max(1, a.residuals - static_cast<int>(parameters.size()));
  a.p_value = chi_square_survival(a.statistic, a.degrees_of_freedom);
  a.rms_residual = a.residuals > 0 ? std::sqrt(a.statistic / a.residuals) : 0.0;
  a.global_fits = a.p_value >= kAdequacyLevel;
  a.families = judge_families(residuals, compared);
  for (const FamilyFit& f : a.families) {
    if (f.misfits) a.misfitting_families.push_back(f.family);
  }
  a.fits_within_noise = a.global_fits && a.misfitting_families.empty();

  for (std::size_t i = 0; i < parameters.size() && i < nominal.size(); ++i) {
    const Parameter& p = parameters[i];
    const double value = fit.best[i];
    auto implausible = [&](const std::string& why) { a.implausible.push_back({p.name, value, nominal[i], why}); };
    // Far from the stated value, and the data exclude the stated value.
    auto excluded = [&]() {
      std::vector<double> stated = fit.best;
      stated[i] = nominal[i];
      const double ratio = training_objective(stated) - fit.objective;
      if (ratio <= kLikelihoodRatioBound) return false;
      implausible("");
      a.implausible.back().likelihood_ratio = ratio;
      return true;
    };
    if (at_search_bound(p, value)) {
      implausible("on its search bound [" + std::to_string(p.low) + ", " + std::to_string(p.high) +
                  "]: the tests pull it beyond the range searched");
    } else if (p.name == "stiffness_scale" && (value > kStiffnessFactor || value < 1.0 / kStiffnessFactor) && excluded()) {
      a.implausible.back().why = "the contact stiffness is more than " + std::to_string(int(kStiffnessFactor)) +
                                 " times off the nominal, and the data exclude the nominal: the contact's geometry, "
                                 "not its stiffness, is likely wrong";
    } else if (p.name == "friction" && nominal[i] > 0.0 &&
               (value > kFrictionFactor * nominal[i] || value < nominal[i] / kFrictionFactor) && excluded()) {
      a.implausible.back().why = "far from the stated coefficient (more than a factor 1.5 off), and the data exclude the "
                                 "stated one";
    }
  }
  for (const ImplausibleValue& v : a.implausible) {
    if (v.parameter == "stiffness_scale") add_check(a.checks, kGeometryCheck);
    if (v.parameter == "friction") {
      add_check(a.checks, "the friction coefficient stated in specimen.toml, and the contact geometry (a cask that "
                          "pivots at the wrong place slides where it should rock)");
    }
    if (v.parameter == "damping_ratio") add_check(a.checks, kGeometryCheck);
  }
  for (const Misfit& m : a.misfits) {
    if (m.measure == "rotation_lag" || m.measure == "rotation_history") {
      add_check(a.checks, "the channels' timing: a delay between the table and response channels, the sampling clock");
    }
    if (m.measure == "max_sliding" || m.measure == "residual_sliding" || m.measure == "sliding_history") {
      add_check(a.checks, "the sliding channel's units, sign and datum");
    }
    if (m.measure == "peak_rotation" || m.measure == "rms_rotation" || m.measure == "rocking_rate") {
      add_check(a.checks, "the rotation channel's units and sign");
      add_check(a.checks, kGeometryCheck);
    }
  }
  for (const FamilyFit& f : a.families) {
    if (!f.misfits) continue;
    for (const MeasureFamily& family : measure_families()) {
      if (family.name != f.family) continue;
      std::string mechanisms;
      for (const std::string& m : family.mechanisms) mechanisms += (mechanisms.empty() ? "" : ", ") + m;
      add_check(a.checks,
                family.what + " misfits (" + family.name + "): the mechanisms that act on it are " + mechanisms);
    }
  }
  a.adequate = a.fits_within_noise && a.implausible.empty();
  if (!a.adequate && a.checks.empty()) add_check(a.checks, "sensor units and timing, and " + std::string(kGeometryCheck));
  return a;
}

}  // namespace caskdem::diagnosis
