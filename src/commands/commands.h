#pragma once
// The subcommands of `caskdem`, one file each; main.cpp registers them.

#include <CLI/CLI.hpp>

namespace caskdem::commands {

void add_run(CLI::App& app);
void add_calibrate(CLI::App& app);
void add_sweep(CLI::App& app);
void add_motion(CLI::App& app);
void add_similarity(CLI::App& app);
void add_ensemble(CLI::App& app);
void add_plot(CLI::App& app);
void add_diagnose(CLI::App& app);
void add_evaluate_measured(CLI::App& app);
void add_risk(CLI::App& app);
void add_plan_test(CLI::App& app);

}  // namespace caskdem::commands

namespace caskdem::diagnosis {
struct MeasuredSet;
struct TestPlan;
}

namespace caskdem::commands {

// The imperfections found in the data (gaps, clipping, dead channels, unknown columns), one
// "data" line each, as every command that reads measured data prints them.
void print_data_issues(const diagnosis::MeasuredSet& set);

// The candidates, the table limits and the best proposed tests (plan-test, diagnose).
void print_plan(const diagnosis::TestPlan& plan);

}  // namespace caskdem::commands
