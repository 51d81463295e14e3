#pragma once
// Does the calibrated model fit the data at all? Judged before any mechanism is ranked, so
// that "no mechanism helps" can tell "the model fits within noise" (`none`) from "the model
// misfits and nothing in the library explains it" (`unexplained`).
//
// Goodness of fit. Each residual r is a measure's error over its tolerance (the measurement's
// noise and the test's own predictability; measures.h), so a model that fits within noise has
// |r| of order 1 or less, and the loss J = sum of pseudo-Huber(r) (r^2 within three
// tolerances, growing like 6 |r| beyond) over N residuals with k fitted parameters is at most
// about a chi-square variable with N - k degrees of freedom (Pearson's statistic; the
// tolerances are at least the noise, so the reference is conservative). The p-value
// P(chi2_{N-k} >= J) is small when many residuals exceed their tolerances at once: a history
// that drifts out of phase, sliding off by centimetres. A single chaotic miss cannot make it
// small alone, as pseudo-Huber grows only linearly. Each test is judged the same way
// (chi2 with its own number of measures; Bonferroni over the tests), and every measure
// beyond kMisfitResidual tolerances is named.
//
// Plausibility. A fit can reach the data with values no specimen has: a contact stiffness
// several times the nominal (the contact's geometry is wrong, not its stiffness), a
// friction coefficient far from what the experimenter stated, a value on its search bound (the
// tests pull it beyond the range searched). Any of these makes the model inadequate too,
// whatever its residuals say, and is named with what to check. A value far from the stated
// one counts only where the data exclude the stated one: the training objective at the stated
// value (the other parameters at the fit) exceeds the fit's by more than the likelihood-ratio
// bound, chi2 with one degree of freedom at the same level (Wilks 1938). A friction the
// tests barely determine (a cask that slides only millimetres) can end anywhere a search
// stops; that is not a misfit of the model.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "diagnosis/fitting.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

// A model fits within noise when its goodness-of-fit p-value is at least this.
inline constexpr double kAdequacyLevel = 1e-3;
// A measure is named as a misfit beyond this many tolerances.
inline constexpr double kMisfitResidual = 3.0;
// A calibrated contact stiffness this many times above or below the nominal is implausible.
inline constexpr double kStiffnessFactor = 3.0;
// A calibrated friction coefficient this many times above or below the stated one is implausible.
inline constexpr double kFrictionFactor = 1.5;
// chi2_1 exceeds this with probability kAdequacyLevel: the stated value is excluded when the
// training objective there exceeds the fit's by more.
inline constexpr double kLikelihoodRatioBound = 10.83;

struct Misfit {
  std::string test, measure;
  double residual = 0.0;  // in tolerances
};

// Measures grouped by what they measure (measures.h), and the mechanisms (mechanisms.h) that
// act on it: where a family misfits, these are the candidates.
struct MeasureFamily {
  std::string name;
  std::string what;  // in words, for the report
  std::vector<std::string> measures;
  std::vector<std::string> magnitudes;  // its measures whose sign says over- (+) or under-prediction (-)
  std::vector<std::string> mechanisms;
};
const std::vector<MeasureFamily>& measure_families();

// One family's goodness of fit.
struct FamilyFit {
  std::string family;
  double statistic = 0.0;   // J_f: the robust loss of its residuals over every test
  int residuals = 0;        // N_f
  double p_value = 1.0;     // P(chi2_{N_f} >= J_f)
  double holm_level = 0.0;  // the level Holm's step-down compared it with
  bool misfits = false;
  double mean_magnitude_residual = 0.0;  // mean signed residual of its magnitude measures (< 0: under-predicted)
  int magnitude_residuals = 0;
};

struct ImplausibleValue {
  std::string parameter;
  double value = 0.0, nominal = 0.0;
  std::string why;
  double likelihood_ratio = 0.0;  // J at the nominal value minus J at the fit (0: not asked, a value on its bound)
};

struct Adequacy {
  double statistic = 0.0;        // J over every test (training and held-out)
  int residuals = 0;             // N
  int degrees_of_freedom = 0;    // N - k
  double p_value = 1.0;          // P(chi2_{N-k} >= statistic)
  double rms_residual = 0.0;     // sqrt(J / N)
  bool global_fits = true;       // p_value >= kAdequacyLevel
  std::vector<FamilyFit> families;               // in measure_families() order
  std::vector<std::string> misfitting_families;  // rejected by Holm's step-down
  std::vector<std::string> misfitting_tests;  // each test's own p-value below kAdequacyLevel / tests
  std::vector<Misfit> misfits;                // |r| > kMisfitResidual
  std::vector<ImplausibleValue> implausible;
  bool fits_within_noise = true;  // the global test and every family pass
  bool adequate = true;           // fits within noise with plausible values
  std::vector<std::string> checks;  // what to check when it is not
};

// `loss`, `residuals` and `compared` per test (all tests; `compared` per measure, 1 where it is
// compared: TestReference::compared); `nominal` the values the specimen states for the
// baseline's parameters (friction, damping ratio, stiffness scale); `training_objective` the J
// the fit minimised, at any point.
using PointObjective = std::function<double(const std::vector<double>&)>;
Adequacy judge_adequacy(const MeasuredSet& set, const std::vector<Parameter>& parameters, const FitResult& fit,
                        const std::vector<double>& nominal, const std::vector<double>& loss,
                        const std::vector<std::vector<double>>& residuals,
                        const std::vector<std::vector<std::uint8_t>>& compared,
                        const PointObjective& training_objective);

// Each family's goodness of fit and Holm's verdict, from every test's residuals.
std::vector<FamilyFit> judge_families(const std::vector<std::vector<double>>& residuals,
                                      const std::vector<std::vector<std::uint8_t>>& compared);

// P(chi2_nu >= x).
double chi_square_survival(double x, int degrees_of_freedom);

}  // namespace caskdem::diagnosis
