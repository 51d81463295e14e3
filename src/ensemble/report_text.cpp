#include "ensemble/report_text.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/text.h"

namespace caskdem {

std::string restitution_text(const EnsemblePlan& plan) {
  const CalibrationCurve& curve = plan.calibration();
  if (!plan.restitution_uncertain() || curve.restitution.empty()) return "";
  double lowest = curve.highest(), highest = curve.lowest();
  for (std::int64_t i = 0; i < plan.size(); ++i) {
    const double e = plan.realisation(i).restitution;
    lowest = std::min(lowest, e);
    highest = std::max(highest, e);
  }
  std::ostringstream out;
  // The highest restitution needs the least damping.
  out << std::setprecision(4) << std::fixed << lowest << " to " << highest << " -> damping ratio "
      << std::setprecision(3) << std::defaultfloat << curve.damping_for(lowest) << " to "
      << curve.damping_for(highest) << " (the nominal cask's free rocking at this step, which reaches "
      << std::setprecision(4) << std::fixed << curve.lowest() << " to " << curve.highest() << ")";
  return out.str();
}

namespace {

constexpr int kNameColumn = 20;

std::string lead(const std::string& name) {
  std::ostringstream out;
  out << std::left << std::setw(kNameColumn) << name;
  return out.str();
}

std::string number(double value, int digits = 3) {
  std::ostringstream out;
  out << std::setprecision(digits) << value;
  return out.str();
}

}  // namespace

std::string scaled_intensity_text(const EnsembleSpec& spec, double value, double model_scale) {
  const std::string text = intensity_text(spec.measure, value);
  if (!(model_scale > 1.0)) return text;
  const std::string model = " on the 1/" + number_text(model_scale) + " model";
  switch (spec.measure) {
    case IntensityMeasure::pgv:
      return text + model + " (" + intensity_text(spec.measure, value * std::sqrt(model_scale)) + " at full size)";
    case IntensityMeasure::sa:
      return text + model + " at " + number(spec.spectral_period) + " s (the same at " +
             number(spec.spectral_period * std::sqrt(model_scale)) + " s at full size)";
    default: return text + model + " (the same at full size)";
  }
}

std::vector<std::string> limit_state_lines(const EnsemblePlan& plan, const LimitStateSummary& s) {
  const EnsembleSpec& spec = plan.spec();
  std::vector<std::string> lines;
  const std::string indent(kNameColumn, ' ');
  if (s.fit.fitted) {
    lines.push_back(lead(s.limit_state.name) + "median " + scaled_intensity_text(spec, s.fit.median, plan.model_scale()) +
                    ", log-std " + number(s.fit.log_std));
    lines.push_back(indent + fragility::fit_test_text(s.test));
    std::string measures = indent + "by measure:";
    for (const MeasureFit& m : s.measures) {
      measures += " " + m.name + " ";
      if (!m.fit.fitted) {
        measures += "no curve;";
        continue;
      }
      measures += "beta " + number(m.fit.log_std) + " p " + number(m.test.p_value, 2) +
                  (m.test.rejected ? " rejected" : "") + ";";
    }
    measures.pop_back();
    lines.push_back(measures);
  } else {
    lines.push_back(lead(s.limit_state.name) + "no curve: " + s.fit.reason);
  }
  if (!s.same_as.empty()) {
    lines.push_back(indent + s.same_as);
  } else if (s.limit_state.kind != LimitState::Kind::tip_over) {
    std::string standing = indent + "exceeded while standing, by stripe:";
    for (std::int64_t c : s.standing_count) standing.append(" ").append(std::to_string(c));
    lines.push_back(standing);
  }
  return lines;
}

}  // namespace caskdem
