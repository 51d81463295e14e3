#pragma once
// Fitting model parameters to measured tests with NLopt, a population at a time.
//
// A first population explores the parameter box (one lockstep run): the reference points,
// a Latin hypercube of the whole box, and a Latin hypercube near the references (their
// baseline parameters moved a little, a mechanism's parameters over their whole range:
// a mechanism that matters changes the best baseline parameters only a little, and the
// region where it fits can be too small for a global sample of a 5-D box to hit). Each local
// search starts from the best explored point that has no better one within basin_radius (unit
// coordinates), so that the starts spread over the basins the sample found instead of crowding
// into the broadest (multi-level single linkage, Rinnooy Kan & Timmer 1987); the best points
// left fill the remaining starts. The local searches (NLopt's BOBYQA,
// Powell 2009, bounded, derivative-free), which run side by side, each in its own thread:
// whenever all of them are waiting for an objective value, their points are evaluated together
// as lanes of one lockstep simulation (the ensemble kernel), so a population costs one run.
// Rocking is chaotic and the objective rugged, so a local search started from the reference
// alone can settle in a far basin; exploring first finds the basins. A second, tighter round
// explores around the best end point (every parameter moved a little) and searches again,
// so that the result depends less on one draw. The searches work on unit coordinates (linear
// or logarithmic in each parameter) and the best end point wins.
//
// Uncertainty, two ways. The curvature: the objective J is a sum of N squared scaled
// residuals; near the optimum J(x) ~ J* + (x - x*)' H (x - x*) / 2, and with the residual
// variance estimated as s^2 = J* / (N - k) the covariance of the estimate is 2 s^2 H^-1
// (Gauss-Newton, Bates & Watts 1988). H comes from central finite differences, evaluated as one
// more population. It assumes independent residuals and a smooth J; on rocking tests neither
// holds (a test's residuals move together, and a test on a knife edge pulls the fit by more
// than its curvature says), and it understates the error by an order of magnitude (docs/diagnosis-accuracy.md,
// "Are the uncertainties right?"). The jackknife over clusters (the tests): the fit repeated
// with each cluster left out, x_(t), and var x_i = (G - 1)/G sum_t (x_(t),i - mean)^2 (Efron &
// Stein 1981; Efron & Tibshirani 1993, ch. 11), in unit coordinates, then scaled to physical
// units at the optimum as the curvature's are. It costs G fits, and it has its own blind spot:
// along a direction the tests hardly determine, refits started from the optimum need not move
// (measured on an eccentric-mass fit: a stiffness scale 15 % off, the jackknife's error 0.07 %
// of it, the curvature's 8 %). Each misses what the other sees, so the larger is reported.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlopt.hpp>

#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

// Objective values of a population of parameter vectors (physical values), in one run.
using PopulationObjective = std::function<std::vector<double>(const std::vector<std::vector<double>>& points)>;

struct FitOptions {
  int exploration = 192;      // points of the first population (the references, then half global, half local)
  double local_spread = 0.05; // of the unit box: how far local exploration moves a reference's baseline parameters
  int starts = 8;             // parallel local searches, from the explored basins (basin_radius)
  double basin_radius = 0.5;  // of the unit box: a start has no better explored point this near (0: the best points)
  int evaluations = 60;       // per search
  int refinement = 96;        // points of a second exploration around the best end point (0: none)
  double initial_step = 0.1;  // of the unit box, the searches' first steps
  nlopt::algorithm method = nlopt::LN_BOBYQA;
  std::uint64_t seed = 1;     // Latin hypercube
  bool standard_errors = true; // the curvature population (off for a fit that only finds a start)
};

struct FitResult {
  std::vector<double> best;        // physical values
  double objective = 0.0;
  int evaluations = 0;             // points evaluated, all searches
  int populations = 0;             // lockstep runs
  std::vector<double> standard_error;  // physical units; empty when the curvature is not positive definite
  std::string uncertainty_method;      // "curvature", or "larger of the jackknife over G tests and the curvature"
  std::string uncertainty_note;        // why there is none, when there is none
};

// `references`: points every search family starts from (the first is always searched).
// `searched_also`: points (an earlier fit's) each evaluated in the first population and searched
// from, beside the searches the exploration chooses, which stay as they would be without them.
// The second round runs around the first round's best without them, as it would without them,
// and, where one of their searches ended lowest, around that end too. So the fit ends at or
// below both the lowest of these points' J and the fit without them, and where none of their
// searches ends below every other in the first round it is the fit without them, to the bit.
FitResult fit_parameters(const std::vector<Parameter>& space, const std::vector<std::vector<double>>& references,
                         const PopulationObjective& objective, const FitOptions& options, int residual_count,
                         const std::vector<std::vector<double>>& searched_also = {});

// Local searches side by side (BOBYQA), one from each start (physical values), each over the
// parameters `free` marks while the others keep their start's values: every search's points
// are evaluated together, one population per round. A profile's shape: a grid over some
// parameters, the others re-optimised at each grid point (diagnosis/profile.h). Each end is
// the best point its search saw; `tally` counts the evaluations and populations.
struct SearchEnd {
  std::vector<double> best;  // physical values
  double objective = 0.0;
};
std::vector<SearchEnd> search_from_each(const std::vector<Parameter>& space,
                                        const std::vector<std::vector<double>>& starts, const std::vector<bool>& free,
                                        const PopulationObjective& objective, int evaluations, double initial_step,
                                        FitResult& tally);

double to_unit(const Parameter& p, double value);
double from_unit(const Parameter& p, double unit);

// J over every cluster (a test) but `left_out` (0 to G - 1), for a population of points.
using LeaveOneOutObjective =
    std::function<std::vector<double>(const std::vector<std::vector<double>>& points, int left_out)>;

// Raises each of `fit`'s curvature standard errors to the jackknife's over `clusters` clusters
// where that is larger: each refit with `options` (no curvature), from the fit's optimum and
// `references`. A fit without curvature errors (not positive definite) is left without.
void jackknife_errors(const std::vector<Parameter>& space, FitResult& fit,
                      const std::vector<std::vector<double>>& references, const LeaveOneOutObjective& objective,
                      int clusters, FitOptions options);

// Whether a fitted value ended on an edge of its search box: the tests pull it further than the
// box allows, so the curvature there says nothing about its uncertainty.
bool at_search_bound(const Parameter& p, double value);

// Parameter i's standard error, where the fit has one: none when the curvature was not positive
// definite or the value ended on a search bound.
std::optional<double> standard_error_of(const FitResult& fit, const std::vector<Parameter>& space, std::size_t i);

}  // namespace caskdem::diagnosis
