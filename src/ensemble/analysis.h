#pragma once
// From the realisations to the answer: for each limit state, the stripe probabilities
// with their binomial intervals, the lognormal fragility curve fitted by maximum
// likelihood, its bootstrap band over records, and its misfit to the stripes.
//
// A realisation exceeds a limit state when
//   tip_over        it tipped over;
//   rotation_ratio  max |theta| / alpha reached the threshold;
//   sliding         the base slid at least the threshold.
// A cask that tipped over, left the floor or slid off its pad exceeds every limit state; a
// realisation that went non-finite counts in none (it is reported, never silently kept).
// With epistemic parameters each outer point's stripes are also fitted on their own, and the
// family's A_m, beta_R and beta_U estimated from those fits.

#include <string>
#include <vector>

#include "ensemble/epistemic.h"
#include "ensemble/fragility.h"
#include "ensemble/results.h"

namespace caskdem {

struct LimitStateSummary {
  LimitState limit_state;
  std::vector<fragility::StripeProbability> stripes;
  fragility::LognormalFit fit;
  fragility::Band band;
  fragility::Misfit misfit;
  // With epistemic parameters: A_m, beta_R and beta_U from each outer point's own curve
  // (ensemble/epistemic.h); `fit` above is then the curve of all outer points pooled.
  fragility::NestedFit nested;
};

bool exceeds(const LimitState& limit_state, const EnsembleResults& results, std::int64_t index);

std::vector<LimitStateSummary> analyse(const EnsemblePlan& plan, const EnsembleResults& results);

}  // namespace caskdem
