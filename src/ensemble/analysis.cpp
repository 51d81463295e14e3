#include "ensemble/analysis.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace caskdem {

namespace {

bool standing(const EnsembleResults& r, std::int64_t i) {
  return static_cast<LaneStatus>(r.status[i]) == LaneStatus::running;
}

// The quantity a rocking or sliding limit state compares with its threshold.
double measured(const LimitState& limit_state, const EnsembleResults& r, std::int64_t i) {
  return limit_state.kind == LimitState::Kind::sliding ? r.max_abs_slide[i] : r.max_rotation_ratio[i];
}

// Why a state's stripes equal another's: the same casks exceed both.
std::string same_stripes_reason(const LimitStateSummary& s, const LimitStateSummary& other) {
  std::ostringstream out;
  out << std::setprecision(3) << "the same stripes as " << other.limit_state.name;
  const bool by_tipping = std::all_of(s.standing_count.begin(), s.standing_count.end(), [](std::int64_t c) { return c == 0; });
  if (by_tipping && s.limit_state.kind != LimitState::Kind::tip_over) {
    out << ": no cask that stayed standing reached it (the largest, ";
    if (s.limit_state.kind == LimitState::Kind::sliding) {
      out << s.largest_standing * 100.0 << " cm of slide";
    } else {
      out << s.largest_standing << " alpha of rotation";
    }
    out << "), so it counts the casks that tipped over, which exceed every limit state";
  } else {
    out << ": the same casks exceed both";
  }
  return out.str();
}

}  // namespace

bool exceeds(const LimitState& limit_state, const EnsembleResults& r, std::int64_t i) {
  const auto status = static_cast<LaneStatus>(r.status[i]);
  if (status == LaneStatus::tipped_over || status == LaneStatus::left_floor || status == LaneStatus::slid_off_pad) {
    return true;  // a cask that is down or gone exceeds every limit state
  }
  switch (limit_state.kind) {
    case LimitState::Kind::tip_over: return false;
    case LimitState::Kind::rotation_ratio: return r.max_rotation_ratio[i] >= limit_state.threshold;
    case LimitState::Kind::sliding: return r.max_abs_slide[i] >= limit_state.threshold;
  }
  return false;
}

std::vector<LimitStateSummary> analyse(const EnsemblePlan& plan, const EnsembleResults& r) {
  const EnsembleSpec& spec = plan.spec();
  const int stripes = static_cast<int>(spec.levels.size());
  const int motions = plan.motion_count();
  // Intensity grid for the fitted curves and bands: from a tenth of the lowest level to
  // twice the highest, log-spaced.
  std::vector<double> grid;
  const double low = 0.1 * spec.levels.front(), high = 2.0 * spec.levels.back();
  for (int k = 0; k <= 200; ++k) grid.push_back(low * std::pow(high / low, k / 200.0));

  const MeasureSet measures = measure_set(plan);
  std::vector<LimitStateSummary> summaries;
  for (std::size_t l = 0; l < spec.limit_states.size(); ++l) {
    const LimitState& limit_state = spec.limit_states[l];
    fragility::StripeData data;
    data.levels = spec.levels;
    data.trials.assign(motions, std::vector<std::int64_t>(stripes, 0));
    data.counts.assign(motions, std::vector<std::int64_t>(stripes, 0));
    for (std::int64_t i = 0; i < r.size; ++i) {
      if (!r.completed[i] || static_cast<LaneStatus>(r.status[i]) == LaneStatus::non_finite) continue;
      ++data.trials[r.motion[i]][r.stripe[i]];
      if (exceeds(limit_state, r, i)) ++data.counts[r.motion[i]][r.stripe[i]];
    }
    LimitStateSummary s;
    s.limit_state = limit_state;
    s.standing_count.assign(stripes, 0);
    if (limit_state.kind != LimitState::Kind::tip_over) {
      for (std::int64_t i = 0; i < r.size; ++i) {
        if (!r.completed[i] || !standing(r, i)) continue;
        s.largest_standing = std::max(s.largest_standing, measured(limit_state, r, i));
        if (exceeds(limit_state, r, i)) ++s.standing_count[r.stripe[i]];
      }
    }
    s.stripes = fragility::stripe_probabilities(data, spec.confidence);
    std::vector<std::int64_t> trials, counts;
    for (const auto& p : s.stripes) {
      trials.push_back(p.trials);
      counts.push_back(p.count);
    }
    s.fit = fragility::fit_lognormal(spec.levels, trials, counts,
                                     [&](double level) { return intensity_text(spec.measure, level); });
    if (s.fit.fitted) {
      // Each limit state gets its own stream of bootstrap numbers.
      s.band =
          fragility::bootstrap_band(data, grid, spec.bootstrap_replicates, spec.confidence, band_seed(spec.seed, l));
      s.misfit = fragility::misfit(s.fit, s.stripes);
      // The measures in turn, the ensemble's own first: its test is the curve's.
      // One bootstrap stream for every limit state: two states with the same stripes get the same test.
      s.measures = fit_measures(plan, measures, data, fragility::kFitTestReplicates, fit_test_seed(spec.seed));
      s.test = s.measures.front().test;
    }
    s.by_motion = data;
    if (spec.outer_count() > 1) {
      std::vector<std::vector<std::int64_t>> outer_trials(spec.outer_count(), std::vector<std::int64_t>(stripes, 0));
      std::vector<std::vector<std::int64_t>> outer_counts = outer_trials;
      for (std::int64_t i = 0; i < r.size; ++i) {
        if (!r.completed[i] || static_cast<LaneStatus>(r.status[i]) == LaneStatus::non_finite) continue;
        const int o = plan.outer_of(i);
        ++outer_trials[o][r.stripe[i]];
        if (exceeds(limit_state, r, i)) ++outer_counts[o][r.stripe[i]];
      }
      s.nested = fragility::fit_nested(spec.levels, outer_trials, outer_counts, spec.confidence,
                                       spec.seed + 104729 * (l + 1));
    }
    summaries.push_back(std::move(s));
  }
  // A state whose stripes repeat an earlier one's says so.
  for (std::size_t l = 1; l < summaries.size(); ++l) {
    for (std::size_t k = 0; k < l; ++k) {
      const auto counts = [](const LimitStateSummary& s) {
        std::vector<std::int64_t> c;
        for (const auto& p : s.stripes) c.push_back(p.count);
        return c;
      };
      if (counts(summaries[l]) != counts(summaries[k])) continue;
      summaries[l].same_as = same_stripes_reason(summaries[l], summaries[k]);
      break;
    }
  }
  return summaries;
}

}  // namespace caskdem
