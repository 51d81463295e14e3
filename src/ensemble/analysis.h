#pragma once
// From the realisations to the answer: for each limit state, the stripe probabilities
// with their binomial intervals, the lognormal fragility curve fitted by maximum
// likelihood, its bootstrap band over records, and its misfit to the stripes.
//
// A realisation exceeds a limit state when
//   tip_over        it tipped over;
//   rotation_ratio  max |theta| / alpha reached the threshold;
//   sliding         the base slid at least the threshold.
// A cask that tipped over, left the floor or slid off its pad exceeds every limit state (the
// convention of fragility analyses: a cask on its side has also slid and rocked beyond any
// limit); a realisation that went non-finite counts in none (it is reported, never silently
// kept). Beside the convention each rocking and sliding state counts, stripe by stripe, the
// casks that exceeded it while standing (still upright, on the floor and pad at the end), and
// names the largest value a standing cask reached; two limit states with the same stripes are
// said to be the same, and why.
//
// Each fitted curve is tested with the motions clustered (ensemble/fit_test.h), the
// record-to-record share beside it, and fitted again under other intensity measures
// (ensemble/measures.h), so that a rejected curve comes with what to try next.
// With epistemic parameters each outer point's stripes are also fitted on their own, and the
// family's A_m, beta_R and beta_U estimated from those fits.

#include <string>
#include <vector>

#include "ensemble/epistemic.h"
#include "ensemble/fit_test.h"
#include "ensemble/fragility.h"
#include "ensemble/measures.h"
#include "ensemble/results.h"

namespace caskdem {

struct LimitStateSummary {
  LimitState limit_state;
  std::vector<fragility::StripeProbability> stripes;
  fragility::LognormalFit fit;
  fragility::Band band;
  fragility::Misfit misfit;       // as if every run were independent (the binomial test)
  fragility::FitTest test;        // motions clustered: what decides whether the curve is rejected
  fragility::StripeData by_motion;  // the stripes split by motion
  std::vector<MeasureFit> measures;  // the curve under each intensity measure, the ensemble's first
  // Rocking and sliding states: per stripe the casks that exceeded while standing, and the largest
  // value (rotation ratio, or slide in m) a standing cask reached in the whole ensemble.
  std::vector<std::int64_t> standing_count;
  double largest_standing = 0.0;
  std::string same_as;  // "tip_over: ..." when another limit state has the same stripes, and why
  // With epistemic parameters: A_m, beta_R and beta_U from each outer point's own curve
  // (ensemble/epistemic.h); `fit` above is then the curve of all outer points pooled.
  fragility::NestedFit nested;
};

bool exceeds(const LimitState& limit_state, const EnsembleResults& results, std::int64_t index);

// The bootstrap streams of the analysis, keyed by the ensemble's seed: limit state l's band, and
// the fit tests (one stream for every limit state, so that two states with the same stripes get
// the same test; measure k's test then its own, fit_measures).
inline std::uint64_t band_seed(std::uint64_t seed, std::size_t limit_state) { return seed + 7919 * (limit_state + 1); }
inline std::uint64_t fit_test_seed(std::uint64_t seed) { return seed + 6151; }

std::vector<LimitStateSummary> analyse(const EnsemblePlan& plan, const EnsembleResults& results);

}  // namespace caskdem
