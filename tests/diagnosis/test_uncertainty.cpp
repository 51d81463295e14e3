// The jackknife's standard errors (fitting.h, DiagnosisOptions::jackknife) refit the model
// without each training test in turn. Its arithmetic is checked on clusters with a known answer
// in test_fitting.cpp; here, that each refit's objective leaves out exactly one training test
// and keeps every other, summed as the fits sum them: at any point, J without test k equals the
// sum of the other training tests' losses as evaluate_point judges them one by one. How often
// the errors cover the true values is measured outside CI (bench/parameter_coverage.py;
// docs/diagnosis-accuracy.md, "Are the uncertainties right?").

#include <string>

#include <gtest/gtest.h>

#include "diagnosis/diagnose.h"
#include "diagnosis/synthesize.h"
#include "support/temporary_files.h"

namespace caskdem::diagnosis {
namespace {

TEST(Uncertainty, EachJackknifeRefitLeavesOutOneTrainingTest) {
  const testing::TestDirectory directory;
  SyntheticSpec spec;
  spec.seed = 4;
  write_synthetic_measured_set(directory.path(), spec);
  const MeasuredSet set = read_measured_set(directory.path());
  DiagnosisOptions options;
  options.threads = 2;
  const std::vector<double> point = {0.33, 0.05, 1.2};
  const PointEvaluation e = evaluate_point(set, {}, point, {}, options);
  ASSERT_GE(set.training.size(), 3u);
  for (std::size_t k = 0; k < set.training.size(); ++k) {
    double others = 0.0;
    for (std::size_t s = 0; s < set.training.size(); ++s) {
      if (s != k) others += e.loss[set.training[s]];
    }
    const std::vector<double> without = training_objective_without(set, {}, {point}, static_cast<int>(k), options);
    ASSERT_EQ(without.size(), 1u);
    EXPECT_EQ(without[0], others) << "without " << set.tests[set.training[k]].name;
  }
  // Leaving out none gives the whole training objective.
  EXPECT_EQ(training_objective_without(set, {}, {point}, -1, options)[0], e.training_objective);
}

}  // namespace
}  // namespace caskdem::diagnosis
