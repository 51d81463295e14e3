#pragma once
// Fragility statistics of a multiple-stripe analysis (Baker 2015, "Efficient analytical
// fragility function fitting using dynamic structural analysis", Earthquake Spectra 31(1)):
//
//   P(limit state exceeded | IM = x) = Phi(ln(x / median) / log_std)
//
// fitted by maximum likelihood to the stripes (n_j runs at IM level x_j, z_j exceeding):
//   max over (median, log_std) of sum_j [ln C(n_j, z_j) + z_j ln Phi_j + (n_j - z_j) ln(1 - Phi_j)],
// with NLopt; each stripe's probability z_j / n_j gets a Clopper-Pearson interval; a
// bootstrap that resamples records (not single runs; record-to-record variability is the
// larger part of the uncertainty) and refits gives a confidence band; and the fit is
// checked against the binned Monte Carlo values.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace caskdem::fragility {

// The data of one limit state. counts[m][j] and trials[m][j] split stripe j by motion m
// (the unit the bootstrap resamples); a stripe's totals are the sums over motions.
struct StripeData {
  std::vector<double> levels;                     // IM level of each stripe, increasing, > 0
  std::vector<std::vector<std::int64_t>> trials;  // [motion][stripe]
  std::vector<std::vector<std::int64_t>> counts;  // [motion][stripe], 0 <= count <= trials
};

struct StripeProbability {
  double level = 0.0;
  std::int64_t trials = 0;
  std::int64_t count = 0;
  double probability = 0.0;  // count / trials (0 when no trials)
  double lower = 0.0;        // Clopper-Pearson interval at the given confidence
  double upper = 0.0;
};

// Throws std::invalid_argument for a malformed StripeData (a motion without one entry per stripe,
// a count outside [0, trials]) or a confidence outside (0, 1). A stripe without runs gets [0, 1].
std::vector<StripeProbability> stripe_probabilities(const StripeData& data, double confidence);

// Clopper-Pearson ("exact") binomial interval for `count` successes in `trials`; [0, 1] when
// trials = 0. Throws std::invalid_argument unless 0 <= count <= trials and 0 < confidence < 1.
void clopper_pearson(std::int64_t count, std::int64_t trials, double confidence, double& lower, double& upper);

struct LognormalFit {
  bool fitted = false;       // false when the data cannot identify the curve (all zero, all one, ...)
  std::string reason;        // why not, when not
  double median = 0.0;       // theta, in IM units
  double log_std = 0.0;      // beta
  double log_likelihood = 0.0;
};

// Maximum-likelihood fit over stripe totals. Not fitted when no stripe has a count, when
// every stripe is all-exceeding, or when the optimum runs to log_std outside [1e-3, 5].
// Also not fitted when the stripes are perfectly separated (zeros below, all-exceeding above, at
// most one partial stripe between: the MLE is then a step, log_std -> 0) or when the median runs
// to the search bound. Stripes may come in any order; equal levels are pooled; stripes without
// runs are ignored. Throws std::invalid_argument for mismatched sizes, a level that is not finite
// and > 0, or a count outside [0, trials]. median, log_std and log_likelihood are never NaN (they
// hold the rejected optimum when the optimiser ran, else 0).
// level_text writes a level as the user reads it (its unit) in the reason a curve is not fitted;
// without it, a level is written as the number given ("IM 5.88").
using LevelText = std::function<std::string(double)>;
LognormalFit fit_lognormal(const std::vector<double>& levels, const std::vector<std::int64_t>& trials,
                           const std::vector<std::int64_t>& counts, const LevelText& level_text = nullptr);

double fragility_probability(const LognormalFit& fit, double im);  // Phi(ln(im/median)/log_std)
                                                                    // (0 if !fit.fitted or im <= 0)

struct Band {
  std::vector<double> im;      // grid of IM values
  std::vector<double> lower;   // (1 - confidence)/2 quantile of the bootstrap curves at each im
  std::vector<double> upper;   // (1 + confidence)/2 quantile
  int replicates = 0;          // bootstrap fits that succeeded
  std::string resampled;       // "records", or "realisations" when there is a single motion
  int failed_replicates = 0;   // bootstrap resamples that could not be fitted (skipped)
};

// Bootstrap band: `replicates` resamples of the motions with replacement (or of each
// stripe's realisations, when there is only one motion), refit each; random numbers from
// Philox keyed by `seed`, so the band is reproducible. Motions without any run are left out of
// the resampling ("only one motion" means one with runs). With no successful replicate,
// lower = 0 and upper = 1 at every im (no information). Throws std::invalid_argument for a
// malformed StripeData, replicates < 0 or a confidence outside (0, 1).
Band bootstrap_band(const StripeData& data, const std::vector<double>& im_grid, int replicates, double confidence,
                    std::uint64_t seed);

struct Misfit {
  double max_abs_difference = 0.0;  // max over stripes of |P_fit(x_j) - z_j / n_j|
  int stripes_outside_interval = 0;  // stripes whose Clopper-Pearson interval misses the fit
  double chi_square = 0.0;           // Pearson: sum (z - n P)^2 / (n P (1 - P))
  int degrees_of_freedom = 0;        // informative stripes - 2 (at least 1)
  double p_value = 1.0;              // of chi_square under the fitted model
};

// Over the stripes with trials > 0. An unfitted fit, or no such stripe, gives the default Misfit
// with degrees_of_freedom = 0 ("not evaluated"). chi_square is +infinity (p_value 0) only when
// the fit gives a stripe probability that underflows to exactly 0 or 1 and the data disagree.
Misfit misfit(const LognormalFit& fit, const std::vector<StripeProbability>& stripes);

}  // namespace caskdem::fragility
