#pragma once
// What an analyst tries when a fragility curve does not fit: another intensity measure. The
// ensemble's realisations are set against each measure in turn, every cell (one motion's runs at
// one stripe, ensemble/fit_test.h) at that measure's value of the motion as scaled for the
// stripe, scale = level / (the ensemble's measure of the unscaled motion); the curve is fitted
// over the cells and tested with the motions clustered. A better measure orders the motions as
// the cask feels them: its curve is steeper (smaller beta), its record-to-record share rho
// smaller, and its fit holds. The ensemble's own measure is one of them, so the numbers stand
// side by side.
//
// The measures, of the table motion as the cask felt it (the model's, for a 1/N model): PGA and
// PGV (in 3D, of the horizontal pair by the ensemble's pair measure), and for a planar cask the
// 5 %-damped pseudo-spectral acceleration at the rocking period T_p = 2 pi / p and at half of it
// (p the frequency parameter of the rigid cask, sqrt(m g R / I_O)), and the ensemble's own Sa(T)
// when that is its measure. The dimensionless measures PGA / (g tan alpha) and PGV p /
// (g tan alpha) are PGA and PGV times one number for the whole ensemble: they order the cells
// alike and give the same beta, test and rho, so they are not repeated.

#include <cstdint>
#include <string>
#include <vector>

#include "ensemble/fit_test.h"
#include "ensemble/fragility.h"
#include "ensemble/plan.h"

namespace caskdem {

// Each motion's value (unscaled) of each measure.
struct MeasureSet {
  std::vector<std::string> names;          // "PGA", "PGV", "Sa(2.72 s)"
  std::vector<std::string> units;          // the unit users read it in: "g", "cm/s"
  std::vector<double> unit_to_si;          // SI per display unit
  std::vector<bool> design;                // the ensemble's own measure
  std::vector<std::vector<double>> value;  // [measure][motion], SI
};
MeasureSet measure_set(const EnsemblePlan& plan);

struct MeasureFit {
  std::string name, unit;
  double unit_to_si = 1.0;
  bool design = false;
  fragility::LognormalFit fit;  // median in SI
  fragility::FitTest test;
};

// One limit state's stripes split by motion (trials[m][j], counts[m][j]) under every measure of
// the set; `seed` keys the tests' bootstraps.
std::vector<MeasureFit> fit_measures(const EnsemblePlan& plan, const MeasureSet& set,
                                     const fragility::StripeData& data, int replicates, std::uint64_t seed);
// Measure k's stream among those keyed by `seed`.
inline std::uint64_t measure_seed(std::uint64_t seed, int k) { return seed + 31 * static_cast<std::uint64_t>(k + 1); }

// The cells of one measure (index in the set).
std::vector<fragility::Cell> cells_of(const EnsemblePlan& plan, const MeasureSet& set, int measure,
                                      const fragility::StripeData& data);

}  // namespace caskdem
