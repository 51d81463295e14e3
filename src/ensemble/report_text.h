#pragma once
// What the ensemble command prints about its answer: each limit state's curve with the scale it
// is at (a 1/N model's intensities, and the full-size cask's beside them), the fit's test with
// the motions clustered, the curve's dispersion under the other intensity measures, the casks that
// exceeded while standing, and a state that repeats another's stripes said to, with why; and,
// before the run, the damping ratios its sampled restitutions were calibrated to.

#include <string>
#include <vector>

#include "ensemble/analysis.h"
#include "ensemble/plan.h"

namespace caskdem {

// A level of the ensemble's measure as the user reads it, with its scale: "57.4 cm/s on the 1/3
// model (99.5 cm/s at full size)", "0.6 g (the same at full size)" (accelerations and the
// dimensionless measures keep their values under the similarity law; PGV grows by sqrt(N) and
// Sa's period by sqrt(N)), or as intensity_text for a full-size cask (scale 1) and for motions on
// models of several scales (0).
std::string scaled_intensity_text(const EnsembleSpec& spec, double value, double model_scale);

// Where restitution is uncertain: the sampled range, the damping ratios it calibrates to at the
// ensemble's step and the range the nominal cask's free rocking can reach ("0.9400 to 0.9699 ->
// damping ratio 0.119 to 0.00239 ..."). The top of a range near the undamped limit means nearly
// undamped contacts, which ring between impacts (docs/time-step.md). Empty without uncertain
// restitution.
std::string restitution_text(const EnsemblePlan& plan);

// The lines for one limit state, the first led by its name in a column of 20.
std::vector<std::string> limit_state_lines(const EnsemblePlan& plan, const LimitStateSummary& summary);

}  // namespace caskdem
