#pragma once
// The test that would settle it. Where a diagnosis leaves candidates standing (the baseline
// and mechanisms the data support but cannot single out), a table test on which their
// predictions differ by more than the noise and the test's predictability allow tells them
// apart. Each feasible test is simulated with every candidate at its fitted values; for each
// ordered pair (a, b) the test is judged as the diagnosis judges a measured one, with a's
// response (plus the set's sensor noise) as the measurement and b's as the model:
//   J_ab = sum_m rho((f_m(b) - f_m(a)) / tol_m(a)),
// the tolerances those of a measurement at the set's noise levels, widened by the test's
// predictability under a's model and by the spread of a's prediction over its parameters'
// standard errors (measures.h: add_predictability, add_fit_spread). J_ab is the loss b would
// take beyond a's own were a the truth: the expected log-likelihood ratio of the two models on
// that test, up to the factor 1/2 (Box & Hill 1967 rank experiments for model discrimination by
// it). A test separates a pair by min(J_ab, J_ba), and the candidates by the smallest over
// pairs: the test must tell every pair apart. Above chi2_1's 10.83 (the adequacy level, 1e-3)
// one such test would decide between the closest pair on its own.
//
// The feasible tests: sines over frequency and amplitude within the table's limits
// (specimen.toml [table]: peak acceleration, velocity, displacement and a frequency range; where
// the file states none, the largest acceleration, velocity and displacement the tests' table
// records reached, and 0.5 to 10 Hz, said so in the plan), and each measured test's table record
// scaled within the acceleration limit.

#include <string>
#include <vector>

#include "diagnosis/diagnose.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/measures.h"

namespace caskdem::diagnosis {

struct PlanCandidate {
  std::string name;  // "baseline" or a mechanism's name
  std::vector<Mechanism> mechanisms;
  std::vector<double> point;           // fitted values, the model's parameter order
  std::vector<double> standard_error;  // empty: the point alone
};

struct ProposedTest {
  std::string kind;                            // "sine" or "record"
  std::string description;                     // what to run, in the table operator's terms
  double frequency = 0.0;                      // Hz (sines)
  double peak_acceleration = 0.0;              // m/s^2
  double peak_velocity = 0.0;                  // m/s (sines)
  double peak_displacement = 0.0;              // m (sines)
  double scale = 0.0;                          // of the record (records)
  std::vector<double> drive;                   // m/s^2: the table drive at input.time_step (a sine's noise-free,
                                               // a record's the measured channel scaled)
  MeasuredTest input;                          // time and table acceleration (the drive plus the set's table noise)
  std::vector<std::vector<double>> pair_loss;  // J_ab, [a][b] (0 on the diagonal)
  double separation = 0.0;                     // min over pairs of min(J_ab, J_ba)
  std::string closest_pair;
  std::vector<SimulatedHistory> predicted;  // per candidate, at its fitted values
};

struct TestPlan {
  std::vector<PlanCandidate> candidates;
  std::vector<std::vector<Parameter>> parameters;  // per candidate, in its point's order
  TableLimits limits;
  std::string limits_source;        // "specimen.toml [table]" or how they were taken from the tests
  std::vector<ProposedTest> tests;  // every feasible test tried, best first (none with fewer than two candidates)
  double wall_seconds = 0.0;
};

// The leading candidates of a diagnosis: the baseline; the cause, if any; then the mechanisms
// whose profile gives the data's support against the baseline (likelihood ratio at least
// kProfileBound) and whose fit leaves the off value, largest ratio first; `count` in all at most.
std::vector<PlanCandidate> leading_candidates(const Diagnosis& d, int count = 4);

// Every feasible test simulated with every candidate and ranked by separation (the set's
// specimen on the footprint the candidates were fitted on: `specimen`).
TestPlan plan_tests(const MeasuredSet& set, const Case& specimen, const std::vector<PlanCandidate>& candidates,
                    const DiagnosisOptions& options);

}  // namespace caskdem::diagnosis
