#include "casefile/scaled_case.h"

#include "model/similarity.h"

namespace caskdem {

namespace {

MotionSpec scaled_motion(MotionSpec m, double n) {
  const double length = similarity_ratio(n, {0, 1, 0});
  const double time = similarity_ratio(n, {0, 0, 1});
  switch (m.kind) {
    case MotionSpec::Kind::sine:
      m.amplitude *= length;
      m.frequency /= time;
      break;
    case MotionSpec::Kind::pulse:
      m.pulse_duration *= time;  // accelerations are unchanged
      break;
    case MotionSpec::Kind::synthetic:
    case MotionSpec::Kind::record:
      // PGA targets and factors are accelerations (ratio 1); a PGV target applies to the
      // record before its time compression, so it stays as it is too.
      m.similarity_scale *= n;
      break;
    case MotionSpec::Kind::none:
      break;
  }
  return m;
}

}  // namespace

Case scaled_case(const Case& c, double n) {
  const double length = similarity_ratio(n, {0, 1, 0});
  const double time = similarity_ratio(n, {0, 0, 1});
  const double mass = similarity_ratio(n, {1, 0, 0});
  const double inertia = similarity_ratio(n, {1, 2, 0});
  const double velocity = similarity_ratio(n, {0, 1, -1});
  const double distributed_stiffness = similarity_ratio(n, {1, -2, -2});

  Case s = c;
  Section& section = s.model.section;
  for (Point& p : section.outline) p = {p.x * length, p.y * length};
  section.centre_of_mass = {section.centre_of_mass.x * length, section.centre_of_mass.y * length};
  section.depth *= length;
  section.rounding *= length;
  section.base_area *= length * length;
  section.mass *= mass;
  section.inertia *= inertia;
  s.cask.cylinder.diameter *= length;
  s.cask.cylinder.height *= length;
  s.cask.cylinder.mass *= mass;
  if (s.cask.cylinder.inertia) *s.cask.cylinder.inertia *= inertia;
  s.cask.cylinder.eccentricity *= length;

  s.model.stiffness.normal *= distributed_stiffness;
  s.model.stiffness.shear *= distributed_stiffness;
  for (auto& row : s.model.friction_table) row.first *= velocity;
  s.model.time_step *= time;
  s.model.lift_off_height *= length;
  s.model.pad_half_width *= length;

  RealisationParameters& p = s.parameters;
  p.mass *= mass;
  p.inertia *= inertia;
  p.centre_of_mass = {p.centre_of_mass.x * length, p.centre_of_mass.y * length};
  p.friction_decay_speed *= velocity;
  p.damping_frequency /= time;

  s.horizontal = scaled_motion(s.horizontal, n);
  if (s.vertical) s.vertical = scaled_motion(*s.vertical, n);
  s.duration *= time;
  s.settle_time *= time;
  s.output.interval *= time;
  s.free_vibration.duration *= time;
  return s;
}

}  // namespace caskdem
