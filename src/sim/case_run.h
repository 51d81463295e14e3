#pragma once
// Running a case file's analysis: build the model and motions, choose the duration, run.

#include <memory>

#include "casefile/case_file.h"
#include "io/run_output.h"

namespace caskdem {

struct CaseMotions {
  std::unique_ptr<motion::TableMotion> horizontal;
  std::unique_ptr<motion::TableMotion> vertical;  // null when the case has none
  Excitation excitation() const { return {horizontal.get(), vertical.get()}; }
};

// A run longer than kLongestRun (s), or of more than kMostSteps steps, is a time step,
// similarity scale or stiffness in the wrong unit: no test or earthquake lasts a day, and 1e10
// steps take hours. Case runs and every realisation of an ensemble are held to both.
inline constexpr double kLongestRun = 1e5;
inline constexpr double kMostSteps = 1e10;

CaseMotions make_case_motions(const Case& c);
// Model from the case; a geometry or stability problem becomes an InputError naming the file.
Model build_case_model(const Case& c);
// Motion duration plus the settle time, unless the case gives a duration.
double case_duration(const Case& c, const CaseMotions& motions);

// Runs the case with histories at the case's output interval (0: none).
RunReport run_case(const Case& c, double output_interval);

}  // namespace caskdem
