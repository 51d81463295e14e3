#include "ensemble/measures.h"

#include <cmath>
#include <exception>
#include <iomanip>
#include <numbers>
#include <sstream>

#include <omp.h>

#include "core/units.h"

namespace caskdem {

namespace {

std::string period_text(double period) {
  std::ostringstream out;
  out << "Sa(" << std::setprecision(3) << period << " s)";
  return out.str();
}

void add(MeasureSet& set, const std::string& name, const std::string& unit, double unit_to_si, bool design,
         std::vector<double> value) {
  set.names.push_back(name);
  set.units.push_back(unit);
  set.unit_to_si.push_back(unit_to_si);
  set.design.push_back(design);
  set.value.push_back(std::move(value));
}

}  // namespace

MeasureSet measure_set(const EnsemblePlan& plan) {
  const EnsembleSpec& spec = plan.spec();
  const int motions = plan.motion_count();
  const double g = units::standard_gravity, cm = 0.01;
  std::vector<double> design(motions), pga(motions), pgv(motions);
  for (int m = 0; m < motions; ++m) {
    design[m] = plan.intensity_of(m, 1.0);
    pga[m] = plan.intensity(m).pga;
    pgv[m] = plan.intensity(m).pgv;
  }
  MeasureSet set;
  switch (spec.measure) {
    case IntensityMeasure::pga: add(set, "PGA", "g", g, true, design); break;
    case IntensityMeasure::pgv: add(set, "PGV", "cm/s", cm, true, design); break;
    case IntensityMeasure::pga_ratio: add(set, "PGA / (g tan alpha)", "", 1.0, true, design); break;
    case IntensityMeasure::pgv_ratio: add(set, "PGV p / (g tan alpha)", "", 1.0, true, design); break;
    case IntensityMeasure::sa: add(set, period_text(spec.spectral_period), "g", g, true, design); break;
  }
  // The others, but one the design measure is a constant multiple of.
  const bool acceleration = spec.measure == IntensityMeasure::pga || spec.measure == IntensityMeasure::pga_ratio;
  const bool velocity = spec.measure == IntensityMeasure::pgv || spec.measure == IntensityMeasure::pgv_ratio;
  if (!acceleration) add(set, "PGA", "g", g, false, pga);
  if (!velocity) add(set, "PGV", "cm/s", cm, false, pgv);
  if (!plan.three_d()) {
    const double rocking_period = 2.0 * std::numbers::pi / plan.frequency_parameter();
    for (double period : {0.5 * rocking_period, rocking_period}) {
      if (spec.measure == IntensityMeasure::sa && std::abs(period / spec.spectral_period - 1.0) < 1e-3) continue;
      std::vector<double> sa(motions);
      for (int m = 0; m < motions; ++m) {
        sa[m] = motion::spectral_acceleration(plan.motion(m), period, 0.05, plan.model().time_step);
      }
      add(set, period_text(period), "g", g, false, sa);
    }
  }
  return set;
}

std::vector<fragility::Cell> cells_of(const EnsemblePlan& plan, const MeasureSet& set, int measure,
                                      const fragility::StripeData& data) {
  std::vector<fragility::Cell> cells;
  for (std::size_t m = 0; m < data.trials.size(); ++m) {
    // The motion's scale at a stripe is level / (its unscaled design value); every measure is
    // linear in the scale.
    const double ratio = set.value[measure][m] / plan.intensity_of(static_cast<int>(m), 1.0);
    for (std::size_t j = 0; j < data.levels.size(); ++j) {
      if (data.trials[m][j] == 0) continue;
      cells.push_back({static_cast<int>(j), data.levels[j] * ratio, data.trials[m][j], data.counts[m][j]});
    }
  }
  return cells;
}

std::vector<MeasureFit> fit_measures(const EnsemblePlan& plan, const MeasureSet& set,
                                     const fragility::StripeData& data, int replicates, std::uint64_t seed) {
  std::vector<MeasureFit> fits(set.names.size());
  std::exception_ptr failure;
  // Independent measures, each with its own bootstrap stream: the same numbers on any thread count.
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < static_cast<int>(set.names.size()); ++k) {
    try {
      MeasureFit& f = fits[static_cast<std::size_t>(k)];
      f.name = set.names[k];
      f.unit = set.units[k];
      f.unit_to_si = set.unit_to_si[k];
      f.design = set.design[k];
      const std::vector<fragility::Cell> cells = cells_of(plan, set, k, data);
      f.fit = fragility::fit_cells(cells);
      f.test = fragility::test_fit(f.fit, cells, replicates, measure_seed(seed, k));
    } catch (...) {
#pragma omp critical
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return fits;
}

}  // namespace caskdem
