#pragma once
// What `caskdem plan-test` and `caskdem diagnose` write about the proposed tests: plan.json (every
// feasible test tried, ranked, with the candidates and the table limits), plan.md (the best
// three, what each candidate predicts for them, and how to read the separation),
// plan-histories.h5 and plan.png (the candidates' predicted histories of the best three).

#include <filesystem>
#include <string>

#include "diagnosis/plan_test.h"

namespace caskdem::diagnosis {

// How many of the ranked tests the report, the histories and the plot show.
inline constexpr int kProposedTests = 3;

void write_plan(const std::filesystem::path& directory, const TestPlan& plan, bool plots);

// The plan's Markdown section ("## The test that would settle it"), for plan.md and the end of
// the diagnosis report.
std::string plan_markdown(const TestPlan& plan);

}  // namespace caskdem::diagnosis
