#pragma once
// A mechanism's profile: the training objective J minimised over the baseline's parameters at
// each point of a grid across the mechanism's own parameters, their whole search range,
//   J_p(theta) = min over (mu, h, k) of J(mu, h, k, theta).
// A fit from a few starts can end at the mechanism's off value while some theta lowers J (the
// independent generator's Stribeck friction: the kinetic ratio back at 1, J unchanged, though
// the baseline under-predicts the sliding by 4 to 5 tolerances). The profile cannot miss such a
// theta to within its grid spacing and the baseline's basins the fits found, as every grid
// point has its own search over the baseline's parameters, from the best of those basins there;
// a fit that missed the mechanism is repeated from the profile's minimum (diagnose.cpp).
//
// It also gives what a point estimate does not (Venzon & Moolgavkar 1988; Pawitan, "In All
// Likelihood", 2001, ch. 3-4). The likelihood-ratio statistic against the model without the
// mechanism, Lambda = J_p(off) - min J_p, is chi2 with one degree of freedom per switch when
// the mechanism is absent (the loss is -2 ln L up to a constant where it is quadratic; a switch
// on its range's edge makes it a 50:50 mixture of chi2_0 and chi2_1, Self & Liang 1987, so the
// chi2_1 reference is conservative). The profile interval of each own parameter is the range of
// grid values whose J_p is within chi2_1(0.95) = 3.84 of the minimum, over the other own
// parameters (on the grid: its resolution is the grid's spacing).

#include <string>
#include <vector>

#include "diagnosis/fitting.h"
#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

// chi2_1's 95 % point: the profile interval's bound on J_p - min J_p.
inline constexpr double kProfileBound = 3.841;

struct ProfilePoint {
  std::vector<double> values;  // the mechanism's own parameters (the grid point)
  std::vector<double> best;    // the whole parameter vector at the re-optimised baseline
  double objective = 0.0;      // J_p
};

struct Profile {
  std::vector<std::string> parameters;  // the mechanism's own, in the model's order
  std::vector<std::string> units;
  std::vector<ProfilePoint> grid;
  std::size_t minimum = 0;                          // index into grid
  std::size_t off = 0;                              // the grid point at the mechanism's off value
  double likelihood_ratio = 0.0;                    // J_p(off) - min J_p (>= 0)
  double p_value = 1.0;                             // P(chi2_1 >= likelihood_ratio)
  std::vector<double> interval_low, interval_high;  // per own parameter
  int evaluations = 0, populations = 0;
};

struct ProfileOptions {
  int points_per_axis = 9;  // evenly spaced over a switch's range (its off value and points near it added)
  int shape_points = 4;     // evenly spaced over a shape parameter's range
  int evaluations = 30;       // per grid point's search over the baseline's parameters
  double initial_step = 0.1;  // of the unit box
};

// `variant`: the baseline plus one mechanism; `baselines`: values of the baseline's parameters
// the fits found (the baseline's own first): each grid point's search starts from the one that
// fits best there, all tried in one population, so that the profile sees every basin the fits
// found; `fitted`: points of the whole model (a fit's optimum) added to the grid as they are,
// so that the profile's minimum is never above a fit's; `objective`: J over the training tests.
Profile profile_mechanism(const ModelVariant& variant, const std::vector<std::vector<double>>& baselines,
                          const std::vector<std::vector<double>>& fitted, const PopulationObjective& objective,
                          const ProfileOptions& options = {});

// The minimum, the likelihood ratio and the intervals from the grid as it stands.
void summarise(Profile& profile, const ModelVariant& variant);

// A point of the whole model found otherwise (a fit started from the profile's minimum) added
// to the profile, its summary made again.
void add_point(Profile& profile, const ModelVariant& variant, const std::vector<double>& best, double objective);

}  // namespace caskdem::diagnosis
