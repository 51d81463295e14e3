#pragma once
// What `caskdem diagnose` writes (docs/measured-data.md, "Outputs"):
//   diagnosis.json  cause, second_cause, ranking (each mechanism's heldout_gain,
//                   information_criterion_delta, fitted parameters with standard errors, gain
//                   per error measure), baseline, residual structure, data issues
//   report.md       the same for people, with the plots
//   histories.h5    measured, baseline and extended rotation and sliding of every test
//   histories.png, residuals.png, ranking.png (src/plots/plot_diagnosis.py)
//   plan.json, plan.md, plan-histories.h5, plan.png  the tests that would tell the candidates
//                   apart (plan_report.h), when a plan is given; report.md ends with its best three

#include <filesystem>

#include "diagnosis/diagnose.h"
#include "diagnosis/plan_test.h"

namespace caskdem::diagnosis {

void write_diagnosis(const std::filesystem::path& directory, const MeasuredSet& set, const Diagnosis& diagnosis,
                     InstructionSet isa, bool plots, const TestPlan* plan = nullptr);

// "yes", "no", or "no (at its off value)": a ranked mechanism's significance in words.
std::string significance_text(const CandidateScore& candidate);

// The baseline calibration alone (`caskdem calibrate-measured`): calibration.json. `started_from`:
// the earlier result whose fit joined the starts (empty: none).
void write_calibration(const std::filesystem::path& directory, const MeasuredSet& set, const ModelFit& baseline,
                       const std::string& started_from = "");

}  // namespace caskdem::diagnosis
