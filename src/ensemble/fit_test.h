#pragma once
// Does a fitted fragility curve describe the stripes? A test whose null respects how an ensemble
// is sampled: a stripe's realisations come as groups, one per motion (the motion scaled to the
// stripe's level, then the cask's uncertain parameters drawn), and the outcomes of one motion
// move together. Record-to-record variability (the intensity measure's insufficiency: two
// records of the same PGV do not shake the cask alike) makes the stripe fractions scatter more
// than independent trials would, so a binomial test rejects a curve that may be right.
//
// Cells. The unit is a cell: one motion's realisations at one stripe, n_c runs of which z_c
// exceed, all at the same value x_c of any intensity measure (the motion as scaled). The curve
// F(x) = Phi(ln(x / median) / beta) is fitted by maximum likelihood over the cells
// (fragility::fit_lognormal; for the ensemble's own measure the cells of a stripe share one level
// and this is the stripe fit).
//
// Record to record. rho, the intraclass correlation of the outcomes within a cell: the share of
// a single outcome's variance that lies between motions at the same stripe once the curve's own
// change across the stripe (other measures) is taken out. The ANOVA estimator for binary data
// (Fleiss 1981, Statistical Methods for Rates and Proportions, ch. 13), pooled over stripes, on
// the residuals r_c = z_c / n_c - F(x_c) centred in each stripe:
//   MSB = sum_c n_c (r_c - rbar_j)^2 / (K - J),   MSW = sum_c z_c (n_c - z_c) / n_c / (N - K),
//   n0 = (N - sum_j sum_c n_c^2 / N_j) / (K - J),  rho = (MSB - MSW) / (MSB + (n0 - 1) MSW),
// clipped to [0, 0.99] (K cells, J stripes, N runs). rho = 0: the motions of a stripe do not
// differ beyond chance; a stripe fraction's variance is then the binomial one times the design
// effect 1 + (n0 - 1) rho.
//
// The test. T = sum_j (Z_j - E_j)^2 / V_j over stripes, Z_j the stripe's exceedances,
// E_j = sum_c n_c F(x_c), V_j = sum_c n_c F (1 - F): Pearson's chi-square of the stripe totals.
// Its null distribution by a parametric bootstrap that keeps the design: each cell's probability
// is drawn from the beta distribution of mean F(x_c) and intraclass correlation rho
// (a = F (1 - rho) / rho, b = (1 - F)(1 - rho) / rho: a beta-binomial cell), its count from the
// binomial, the curve refitted to the replicate and T recomputed; p = (1 + #{T* >= T}) /
// (1 + replicates). Random numbers from Philox (ensemble/sampling.h), so the p-value is
// reproducible. Beside it, the binomial p of T against chi-square(J - 2), the test that takes
// every run as independent. A curve whose p is below kRejectionLevel is rejected.

#include <cstdint>
#include <string>
#include <vector>

#include "ensemble/fragility.h"

namespace caskdem::fragility {

inline constexpr double kRejectionLevel = 0.05;
inline constexpr int kFitTestReplicates = 400;

struct Cell {
  int stripe = 0;        // the stripe the cell's runs were made for
  double level = 0.0;    // the cell's value of the measure, > 0
  std::int64_t trials = 0;
  std::int64_t count = 0;
};

struct FitTest {
  bool evaluated = false;           // false when the curve was not fitted or no stripe has runs
  double chi_square = 0.0;          // T
  int degrees_of_freedom = 0;       // stripes with runs - 2 (at least 1)
  double binomial_p = 1.0;          // T against chi-square(df): every run independent
  double record_to_record = 0.0;    // rho
  bool record_to_record_estimated = false;  // false with one motion (nothing to compare)
  double design_effect = 1.0;       // 1 + (n0 - 1) rho
  double p_value = 1.0;             // the bootstrap's, motions clustered
  int replicates = 0;               // bootstrap replicates that could be refitted
  bool rejected = false;            // p_value < kRejectionLevel
};

// The curve over cells (fit_lognormal; level_text names a level in a reason, as there).
LognormalFit fit_cells(const std::vector<Cell>& cells, const LevelText& level_text = nullptr);

// Throws std::invalid_argument for a cell with a level that is not finite and > 0, a count
// outside [0, trials] or a negative stripe.
FitTest test_fit(const LognormalFit& fit, const std::vector<Cell>& cells, int replicates, std::uint64_t seed);

// One line for a printout: "fit holds (p 0.31 with motions clustered; record to record 0.24)" or
// "fit REJECTED at 5 % (p 0.002 ...)".
std::string fit_test_text(const FitTest& test);

}  // namespace caskdem::fragility
