#include "sim/simulate3d.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include "kernels/step3d.h"

namespace caskdem {

namespace {

struct Run {
  const Model3D& model;
  const LaneParameters<double>& lane;
  const Excitation3D& excitation;
};

double acceleration(const motion::TableMotion* m, double t) { return m ? m->acceleration(t) : 0.0; }

// ½ m |v|^2 + ½ sum pi_j^2 / I_j: the cask's kinetic energy (velocities at the half step).
double kinetic_energy(const LaneParameters<double>& lane, const BodyState3D<double>& b) {
  return 0.5 * (b.vx * b.vx + b.vy * b.vy + b.vz * b.vz) / lane.inverse_mass +
         0.5 * ((b.pi_x * b.pi_x + b.pi_z * b.pi_z) * lane.inverse_inertia + b.pi_y * b.pi_y * lane.inverse_axial_inertia);
}

template <FrictionLaw Law>
std::int64_t run_steps(const Run& run, const RunSettings& settings, BodyState3D<double>& body,
                       ContactState3D<double>* points, Response3D<double>& response, std::int64_t step_count,
                       std::int64_t output_every, TimeHistory3D* history, double& rim_turn, bool& at_rest) {
  // Rolling on the rim turns the place where it touches: the turn of the touching arc's
  // direction, summed while the cask rides on its rim (the arc short of the whole ring) from one
  // step to the next. Rocking in a plane adds nothing: its arc flips sides through upright,
  // where the whole ring touches.
  double last_azimuth = 0.0;
  bool riding = false;
  double quiet = 0.0;  // s the kinetic energy has stayed below the rest tolerance
  const double dt = run.model.model.time_step;
  const double c = std::cos(run.excitation.incidence), s = std::sin(run.excitation.incidence);
  for (std::int64_t n = 0; n < step_count; ++n) {
    const double time = static_cast<double>(n) * dt;
    const double a1 = acceleration(run.excitation.h1, time), a2 = acceleration(run.excitation.h2, time);
    const double table_x = c * a1 - s * a2, table_z = s * a1 + c * a2;
    const double table_vertical = acceleration(run.excitation.vertical, time);
    if (history && n % output_every == 0) {
      const double tilt = axis_tilt(body);
      const double ex = 2.0 * (body.qx * body.qy - body.qw * body.qz), ez = 2.0 * (body.qy * body.qz + body.qw * body.qx);
      const kernels::Rotation<double> r = kernels::rotation_of(kernels::Quaternion<double>{body.qw, body.qx, body.qy, body.qz});
      const kernels::Vector3<double> to_base = r.apply({-run.lane.centre_x, -run.lane.centre_y, 0.0});
      const kernels::RimTouch<double> rim = kernels::rim_touch(run.model.contacts, run.lane, r, body.y);
      const double uplift = rim.centre_gap + rim.amplitude;  // the ring's highest point
      history->time.push_back(time);
      history->tilt.push_back(tilt);
      history->tilt_azimuth.push_back(std::atan2(ez, ex));
      history->spin.push_back(response.spin);
      history->rim_azimuth.push_back(std::atan2(rim.arc.towards_sin, rim.arc.towards_cos));
      history->slide_x.push_back(body.x + to_base.x - response.base_x0);
      history->slide_z.push_back(body.z + to_base.z - response.base_z0);
      history->slip_x.push_back(response.slip_x);
      history->slip_z.push_back(response.slip_z);
      history->uplift.push_back(std::max(0.0, uplift));
      history->centre_x.push_back(body.x);
      history->centre_y.push_back(body.y);
      history->centre_z.push_back(body.z);
      history->table_x.push_back(table_x);
      history->table_z.push_back(table_z);
      history->table_vertical.push_back(table_vertical);
    }
    {
      const kernels::Rotation<double> r = kernels::rotation_of(kernels::Quaternion<double>{body.qw, body.qx, body.qy, body.qz});
      const kernels::RimTouch<double> rim = kernels::rim_touch(run.model.contacts, run.lane, r, body.y);
      const bool on_rim = rim.arc.half_width > 0.0 && rim.arc.half_width < 1.0;
      const double azimuth = std::atan2(rim.arc.towards_sin, rim.arc.towards_cos);
      // A jump of more than a quarter turn in one step is the arc changing sides through upright
      // between two steps, not rolling (which turns it by |w_s| dt, far less).
      const double turn = std::abs(std::remainder(azimuth - last_azimuth, 2.0 * std::numbers::pi));
      if (on_rim && riding && turn < 0.5 * std::numbers::pi) rim_turn += turn;
      riding = on_rim;
      last_azimuth = azimuth;
    }
    kernels::step3d<Law>(run.model.model, run.model.contacts, run.lane, table_x, table_vertical, table_z, time, body,
                         points, response);
    if (response.status != 0.0) return n + 1;
    if (settings.rest_from >= 0.0 && time >= settings.rest_from) {
      quiet = kinetic_energy(run.lane, body) < settings.rest_energy ? quiet + dt : 0.0;
      if (quiet >= settings.rest_hold) {
        at_rest = true;
        return n + 1;
      }
    }
  }
  return step_count;
}

}  // namespace

RunResult3D simulate3d(const Model3D& model, const LaneParameters<double>& lane, const BodyState3D<double>& initial,
                       const Excitation3D& excitation, const RunSettings& settings) {
  if (!excitation.h1) throw std::invalid_argument("a 3D run needs at least its first horizontal component");
  const double dt = model.model.time_step;
  const auto steps = static_cast<std::int64_t>(std::ceil(settings.duration / dt));
  const std::int64_t every = settings.output_interval > 0.0
                                 ? std::max<std::int64_t>(1, std::llround(settings.output_interval / dt))
                                 : steps + 1;
  RunResult3D result;
  BodyState3D<double> body = initial;
  std::vector<ContactState3D<double>> points(kContactSliders3D, ContactState3D<double>{});
  Response3D<double> response = initial_response3d(lane, initial);
  TimeHistory3D* history = settings.output_interval > 0.0 ? &result.history : nullptr;
  const Run run{model, lane, excitation};
  std::int64_t done = 0;
  double rim_turn = 0.0;
  bool at_rest = false;
  const auto run_with = [&](auto law) {
    return run_steps<decltype(law)::value>(run, settings, body, points.data(), response, steps, every, history, rim_turn,
                                           at_rest);
  };
  switch (model.model.friction_law) {
    case FrictionLaw::constant: done = run_with(std::integral_constant<FrictionLaw, FrictionLaw::constant>{}); break;
    case FrictionLaw::static_kinetic:
      done = run_with(std::integral_constant<FrictionLaw, FrictionLaw::static_kinetic>{});
      break;
    case FrictionLaw::exponential: done = run_with(std::integral_constant<FrictionLaw, FrictionLaw::exponential>{}); break;
    case FrictionLaw::tabulated: done = run_with(std::integral_constant<FrictionLaw, FrictionLaw::tabulated>{}); break;
  }
  result.summary = summarise3d(model, lane, body, response, static_cast<double>(done) * dt);
  RunSummary3D& s = result.summary;
  s.rim_revolutions = rim_turn / (2.0 * std::numbers::pi);
  s.rest_criterion = settings.rest_from >= 0.0;
  s.came_to_rest = at_rest;
  s.kinetic_energy_at_end = kinetic_energy(lane, body);
  result.final_state = body;
  return result;
}

RunSummary3D summarise3d(const Model3D& model, const LaneParameters<double>& lane, const BodyState3D<double>& body,
                         const Response3D<double>& response, double run_time) {
  RunSummary3D s;
  s.max_tilt = 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(response.max_axis_departure)));
  s.stability_angle = model.model.stability_angle;
  s.max_tilt_ratio = s.max_tilt / s.stability_angle;
  s.max_slide = response.max_slide;
  const kernels::Rotation<double> r = kernels::rotation_of(kernels::Quaternion<double>{body.qw, body.qx, body.qy, body.qz});
  const kernels::Vector3<double> to_base = r.apply({-lane.centre_x, -lane.centre_y, 0.0});
  s.residual_slide = std::hypot(body.x + to_base.x - response.base_x0, body.z + to_base.z - response.base_z0);
  s.max_uplift = std::max(0.0, response.max_uplift);
  s.max_slip = response.max_slip;
  s.residual_slip = std::hypot(response.slip_x, response.slip_z);
  s.spin = response.spin;
  s.status = static_cast<LaneStatus>(static_cast<int>(response.status));
  s.end_time = s.status == LaneStatus::running ? run_time : response.end_time;
  s.instability_time = s.status == LaneStatus::tipped_over ? response.instability_time : -1.0;
  s.time_step = model.model.time_step;
  // A lane that went non-finite is frozen and flagged by its status; no NaN reaches a result.
  for (double* v : {&s.max_tilt, &s.max_tilt_ratio, &s.max_slide, &s.residual_slide, &s.max_slip, &s.residual_slip,
                    &s.max_uplift, &s.spin}) {
    if (!std::isfinite(*v)) *v = 0.0;
  }
  return s;
}

}  // namespace caskdem
