#pragma once
// What `caskdem plan-test` and `caskdem diagnose` write about the proposed tests: plan.json (every
// feasible test tried, ranked, with the candidates and the table limits), plan.md (the best
// three, what each candidate predicts for them, and how to read the separation),
// plan-histories.h5 and plan.png (the candidates' predicted histories of the best three), and
// drive-1.csv ... drive-3.csv (the best three's table drives: what the laboratory runs).
// read_drive reads a drive back (synthesize-measured --drive: the loop closed).

#include <filesystem>
#include <string>
#include <vector>

#include "diagnosis/plan_test.h"

namespace caskdem::diagnosis {

// How many of the ranked tests the report, the histories and the plot show.
inline constexpr int kProposedTests = 3;

void write_plan(const std::filesystem::path& directory, const TestPlan& plan, bool plots);

// The plan's Markdown section ("## The test that would settle it"), for plan.md and the end of
// the diagnosis report.
std::string plan_markdown(const TestPlan& plan);

// The decimals a time is printed with in a drive or a synthetic test: whole milliseconds (the
// programme's 200 Hz) to the millisecond, any other step to the nanosecond, so that a reader
// recovers the step from the span.
int time_decimals(double time_step);

// A table drive file: "# " comment lines (the first says what the test is), the header
// "t,table_acc", then samples evenly spaced from t = 0, in s and m/s^2.
struct TableDrive {
  std::string description;
  double time_step = 0.0;            // s
  std::vector<double> acceleration;  // m/s^2
};

// Throws InputError naming the file and line, and what was expected.
TableDrive read_drive(const std::filesystem::path& file);

}  // namespace caskdem::diagnosis
