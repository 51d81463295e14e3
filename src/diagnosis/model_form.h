#pragma once
// The model form a diagnosis calibrates on: the footprint rule of a cylindrical specimen
// (footprint.h) and, with DiagnosisOptions::compare_normal_laws, the contact's normal law
// (model.md, "The normal law as a model form"). The baseline is calibrated on each form; the
// forms' held-out tests are judged at common tolerances (the stated form's references, each
// held-out tolerance the largest of the forms' own), and another form replaces the stated one
// only when it predicts them by at least minimum_gain better: the analyst's form stands unless
// the data speak against it. Shared by the diagnosis's steps (diagnose.cpp), not a user's API.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "diagnosis/diagnose.h"
#include "diagnosis/footprint.h"
#include "diagnosis/judging.h"

namespace caskdem::diagnosis {

struct ModelForm {
  std::optional<Footprint> footprint;  // none: a polygon section, as stated
  NormalLaw normal_law = NormalLaw::linear;
};

struct ModelFormChoice {
  std::vector<MeasuredSet> sets;  // the data on each form tried
  std::vector<Yardstick> yardsticks;
  std::vector<ModelFit> fits;  // the baseline calibrated on each
  std::vector<ModelForm> tried;
  std::size_t stated = 0, chosen = 0;
  std::vector<FootprintScore> scores;
};

// The baseline's calibration on one form's data, searched also from `also_from` (another
// form's fit of the same cask).
using BaselineCalibration =
    std::function<ModelFit(const MeasuredSet&, const Yardstick&, const std::vector<std::vector<double>>& also_from)>;

// Every form tried (the footprint rules where options.choose_footprint and the section is a
// cylinder, times the normal laws where options.compare_normal_laws), each calibrated and
// scored; a form this cask cannot stand on is skipped, said in the log.
ModelFormChoice choose_model_form(const MeasuredSet& given, const DiagnosisOptions& options,
                                  const BaselineCalibration& calibrate);

// Each form's calibration judged on the held-out tests at tolerances common to every form, and
// its gain over the stated form.
std::vector<FootprintScore> model_form_scores(const MeasuredSet& given, const ModelFormChoice& choice,
                                              const DiagnosisOptions& options);

}  // namespace caskdem::diagnosis
