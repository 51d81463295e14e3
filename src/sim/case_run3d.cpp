#include "sim/case_run3d.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"
#include "sim/case_run.h"

namespace caskdem {

Excitation3D CaseMotions3D::excitation() const { return {h1.get(), h2.get(), vertical.get(), incidence}; }

namespace {

double pair_measure(const motion::PairIntensity& p, const MotionSpec& spec) {
  const bool velocity = spec.scaling == MotionSpec::Scaling::target_pgv;
  switch (spec.pair_measure) {
    case MotionSpec::PairMeasure::rotd100: return velocity ? p.pgv_rotd100 : p.pga_rotd100;
    case MotionSpec::PairMeasure::geometric_mean: return velocity ? p.pgv_geometric_mean : p.pga_geometric_mean;
    case MotionSpec::PairMeasure::rotd50: break;
  }
  return velocity ? p.pgv_rotd50 : p.pga_rotd50;
}

// The set as one motion: one factor for every component, then the similarity's time scale.
void make_set(const MotionSpec& spec, const std::filesystem::path& owner, CaseMotions3D& m) {
  const std::optional<std::filesystem::path> vertical =
      spec.vertical_file.empty() ? std::nullopt : std::optional<std::filesystem::path>(spec.vertical_file);
  motion::ComponentSet set = motion::read_component_set(spec.file, spec.pair, vertical, spec.read, spec.tails);
  m.time_base = set.time_base;
  if (spec.scaling == MotionSpec::Scaling::factor) {
    m.scale_factor = spec.scale;
  } else {
    const double measure = pair_measure(motion::pair_intensity(set.h1, set.h2), spec);
    if (!(measure > 0.0)) throw InputError(located(spec.file, 0, "the horizontal pair is all zeros: it cannot be scaled to a target"));
    m.scale_factor = spec.scale / measure;
  }
  const double time_factor = 1.0 / std::sqrt(spec.similarity_scale);
  const auto prepare = [&](const motion::Record& record) {
    try {
      motion::Record r = motion::scaled(record, m.scale_factor);
      if (spec.similarity_scale != 1.0) r = motion::time_scaled(r, time_factor);
      return r;
    } catch (const std::invalid_argument& e) {
      throw InputError(located(owner, 0, std::string(e.what()) + " (the motion at " + spec.where + ")"));
    }
  };
  motion::Record h1 = prepare(set.h1), h2 = prepare(set.h2);
  m.pair = motion::pair_intensity(h1, h2);
  m.h1 = motion::make_record_motion(std::move(h1));
  m.h2 = motion::make_record_motion(std::move(h2));
  if (set.vertical) m.vertical = motion::make_record_motion(prepare(*set.vertical));
}

}  // namespace

CaseMotions3D make_motions3d(const MotionSpec& spec, const std::filesystem::path& owner) {
  CaseMotions3D m;
  m.incidence = spec.incidence;
  if (!spec.pair.empty()) {
    make_set(spec, owner, m);
  } else {
    m.h1 = make_motion(spec, &m.scale_factor);
  }
  return m;
}

CaseMotions3D make_case_motions3d(const Case& c) {
  if (c.horizontal.kind == MotionSpec::Kind::none && !c.vertical) {
    throw InputError(located(c.file, 0, "the case has no [motion]; `run` needs one"));
  }
  CaseMotions3D m = make_motions3d(c.horizontal, c.file);
  if (c.vertical) m.vertical = make_motion(*c.vertical);
  return m;
}

RunReport3D run_case3d(const Case& c, double output_interval) {
  RunReport3D report;
  report.source = &c;
  const Cylinder& cylinder = c.cask.cylinder;
  report.cask = cask_spec3d(cylinder, c.model.section.rounding, c.parameters.mass);
  report.parameters = nominal_parameters3d(report.cask, c.parameters);
  LaneParameters<double> lane;
  try {
    report.model = build_model3d(c.model, report.cask, report.parameters);
    lane = lane_parameters3d(report.model, report.parameters);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(c.file, 0, e.what()));
  }
  report.motions = make_case_motions3d(c);
  double duration = c.duration;
  RunSettings settings{0.0, output_interval};
  if (!(duration > 0.0)) {
    double motion_end = report.motions.h1->duration();
    if (report.motions.h2) motion_end = std::max(motion_end, report.motions.h2->duration());
    if (report.motions.vertical) motion_end = std::max(motion_end, report.motions.vertical->duration());
    if (c.settle_time_given) {
      duration = motion_end + c.settle_time;
    } else {
      // Until the cask is at rest (a rolling or wobbling cask goes on long after the table has
      // stopped), at most rest_cap after the motion.
      duration = motion_end + c.rest_cap;
      settings.rest_from = motion_end;
      settings.rest_energy = kRestEnergy * report.parameters.mass * report.model.model.gravity * report.cask.height;
      settings.rest_hold = kRestHold;
    }
  }
  settings.duration = duration;
  const double steps = duration / report.model.model.time_step;
  if (!(duration <= kLongestRun) || !(steps >= 1.0) || !(steps <= kMostSteps)) {
    throw InputError(located(c.file, 0, "the run would last " + number_text(duration) + " s in " + number_text(steps) +
                                        " steps; expected at most " + number_text(kLongestRun) + " s and 1 to " +
                                        number_text(kMostSteps) + " steps: a unit wrong somewhere?"));
  }
  const auto start = std::chrono::steady_clock::now();
  report.result = simulate3d(report.model, lane, rest_state3d(report.model, lane), report.motions.excitation(), settings);
  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace caskdem
