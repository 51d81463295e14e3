#include "diagnosis/model_form.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace caskdem::diagnosis {

std::string form_label(const FootprintScore& score, bool laws_compared) {
  if (!laws_compared) return score.footprint;
  return (score.footprint.empty() ? std::string() : score.footprint + ", ") + score.normal_law + " law";
}

bool laws_compared(const std::vector<FootprintScore>& forms) {
  return std::any_of(forms.begin(), forms.end(),
                     [&](const FootprintScore& f) { return f.normal_law != forms.front().normal_law; });
}

namespace {

void say(const DiagnosisOptions& options, const std::string& line) {
  if (options.log) options.log(line);
}

std::string form_name(const ModelForm& form) {
  return (form.footprint ? "footprint " + footprint_name(*form.footprint) + ", " : std::string()) +
         normal_law_name(form.normal_law) + " normal law";
}

// The forms to try: every footprint rule of a cylinder (else the section as stated) times every
// normal law where asked (else the stated one), each rule's laws one after the other.
std::vector<ModelForm> forms_to_try(const Case& specimen, const DiagnosisOptions& options) {
  std::vector<std::optional<Footprint>> footprints = {footprint_of(specimen)};
  if (options.choose_footprint && footprint_of(specimen)) footprints.assign(all_footprints().begin(), all_footprints().end());
  std::vector<NormalLaw> laws = {specimen.model.normal_law};
  if (options.compare_normal_laws) laws = {NormalLaw::linear, NormalLaw::hunt_crossley};
  std::vector<ModelForm> forms;
  for (const std::optional<Footprint>& f : footprints) {
    for (NormalLaw law : laws) forms.push_back({f, law});
  }
  return forms;
}

}  // namespace

std::vector<FootprintScore> model_form_scores(const MeasuredSet& given, const ModelFormChoice& c,
                                              const DiagnosisOptions& options) {
  Yardstick common = c.yardsticks[c.stated];
  for (int t : given.heldout) {
    for (const ModelFit& fit : c.fits) {
      for (std::size_t m = 0; m < fit.heldout_tolerance[t].size(); ++m) {
        common.references[t].tolerance[m] = std::max(common.references[t].tolerance[m], fit.heldout_tolerance[t][m]);
      }
    }
  }
  std::vector<FootprintScore> scores;
  for (std::size_t i = 0; i < c.fits.size(); ++i) {
    const ModelVariant variant(c.sets[i].specimen, {}, c.sets[i].vertical_measured);
    Judged judged;
    (void)objective_over(c.sets[i], common, variant, given.heldout, {c.fits[i].fit.best}, options, &judged);
    FootprintScore score;
    score.footprint = c.tried[i].footprint ? footprint_name(*c.tried[i].footprint) : "";
    score.normal_law = normal_law_name(c.tried[i].normal_law);
    score.stated = i == c.stated;
    score.heldout_error = error_of(judged.loss, common, given.heldout);
    score.baseline = c.fits[i];
    scores.push_back(std::move(score));
  }
  const double stated_error = scores[c.stated].heldout_error;
  for (FootprintScore& score : scores) {
    score.heldout_gain = stated_error > 0.0 ? 1.0 - score.heldout_error / stated_error : 0.0;
  }
  return scores;
}

ModelFormChoice choose_model_form(const MeasuredSet& given, const DiagnosisOptions& options,
                                  const BaselineCalibration& calibrate) {
  const ModelForm stated{footprint_of(given.specimen), given.specimen.model.normal_law};
  ModelFormChoice choice;
  for (const ModelForm& form : forms_to_try(given.specimen, options)) {
    MeasuredSet s = given;
    const std::string name = form_name(form);
    try {
      if (form.footprint) s.specimen = with_footprint(given.specimen, *form.footprint);
      s.specimen.model.normal_law = form.normal_law;
      (void)ModelVariant(s.specimen, {}, s.vertical_measured);
    } catch (const std::invalid_argument& e) {  // a rule this cask cannot stand on (its centre of mass beyond r/2)
      say(options, name + " not tried: " + e.what());
      continue;
    }
    if (form.footprint == stated.footprint && form.normal_law == stated.normal_law) choice.stated = choice.sets.size();
    choice.tried.push_back(form);
    say(options, name + ": judging how predictable each test is");
    choice.yardsticks.push_back(yardstick_of(s, options));
    say(options, name + ": fitting the baseline");
    // The second law on a footprint is searched also from the first law's fit there: both
    // calibrate the same cask, and the search from the nominal values alone may end in
    // another basin.
    std::vector<std::vector<double>> also_from;
    if (choice.tried.size() >= 2 &&
        choice.tried[choice.tried.size() - 2].footprint == form.footprint) {
      also_from.push_back(choice.fits.back().fit.best);
    }
    choice.fits.push_back(calibrate(s, choice.yardsticks.back(), also_from));
    choice.sets.push_back(std::move(s));
  }
  choice.scores = model_form_scores(given, choice, options);
  choice.chosen = choice.stated;
  for (std::size_t i = 0; i < choice.scores.size(); ++i) {
    const FootprintScore& score = choice.scores[i];
    if (score.heldout_gain >= options.minimum_gain &&
        score.heldout_error < choice.scores[choice.chosen].heldout_error) {
      choice.chosen = i;
    }
  }
  choice.scores[choice.chosen].chosen = true;
  return choice;
}

}  // namespace caskdem::diagnosis
