#include "sim/case_run.h"

#include <algorithm>
#include <chrono>

#include "core/error.h"
#include "core/text.h"

namespace caskdem {

CaseMotions make_case_motions(const Case& c) {
  if (c.horizontal.kind == MotionSpec::Kind::none && !c.vertical) {
    throw InputError(located(c.file, 0, "the case has no [motion]; `run` needs one (`calibrate` does not)"));
  }
  CaseMotions m;
  m.horizontal = make_motion(c.horizontal);
  if (c.vertical) m.vertical = make_motion(*c.vertical);
  return m;
}

Model build_case_model(const Case& c) {
  try {
    return build_model(c.model, c.parameters);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(c.file, 0, e.what()));
  }
}

double case_duration(const Case& c, const CaseMotions& motions) {
  if (c.duration > 0.0) return c.duration;
  double motion_end = motions.horizontal->duration();
  if (motions.vertical) motion_end = std::max(motion_end, motions.vertical->duration());
  const double duration = motion_end + c.settle_time;
  if (!(duration <= kLongestRun)) {
    throw InputError(located(c.file, 0, "the run would last " + number_text(duration) + " s (the motion and settle_time); "
                                        "expected at most " + number_text(kLongestRun) +
                                        " s: a record's time step or the similarity scale in the wrong unit?"));
  }
  return duration;
}

namespace {
void check_step_count(const Case& c, const Model& model, double duration) {
  const double steps = duration / model.time_step;
  if (!(steps >= 1.0) || !(steps <= kMostSteps)) {
    throw InputError(located(c.file, 0, "the time step " + number_text(model.time_step) + " s makes " +
                                        number_text(steps) + " steps of a " + number_text(duration) +
                                        " s run; expected 1 to " + number_text(kMostSteps) +
                                        ": a mass, density or contact stiffness in the wrong unit?"));
  }
}
}  // namespace

RunReport run_case(const Case& c, double output_interval) {
  require_planar(c, "run_case");  // a 3D case runs by run_case3d (sim/case_run3d.h)
  RunReport report;
  report.source = &c;
  report.model = build_case_model(c);
  report.facts = model_facts(report.model, c.model, c.parameters);
  const CaseMotions motions = make_case_motions(c);
  const LaneParameters<double> lane = lane_parameters(report.model, c.parameters);
  const double duration = case_duration(c, motions);
  check_step_count(c, report.model, duration);
  const auto start = std::chrono::steady_clock::now();
  report.result = simulate(report.model, lane, rest_state(report.model, lane), motions.excitation(),
                           {duration, output_interval});
  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace caskdem
