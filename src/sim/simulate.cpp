#include "sim/simulate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/step.h"
#include "model/build.h"

namespace caskdem {

namespace {

constexpr int kChunk = 4096;  // steps of table motion sampled at a time

template <FrictionLaw Law>
std::int64_t run_steps(const Model& model, const LaneParameters<double>& lane, BodyState<double>& body,
                       CornerState<double>* corners, Response<double>& response, const Excitation& excitation,
                       std::int64_t step_count, std::int64_t output_every, TimeHistory* history) {
  std::vector<double> horizontal(kChunk), vertical(kChunk, 0.0);
  ContactForces<double> forces{};
  for (std::int64_t first = 0; first < step_count; first += kChunk) {
    const int count = static_cast<int>(std::min<std::int64_t>(kChunk, step_count - first));
    motion::sample_acceleration(*excitation.horizontal, model.time_step, first, count, horizontal.data());
    if (excitation.vertical) motion::sample_acceleration(*excitation.vertical, model.time_step, first, count, vertical.data());
    for (int i = 0; i < count; ++i) {
      const std::int64_t n = first + i;
      const double time = static_cast<double>(n) * model.time_step;
      const BodyState<double> before = body;  // the state at t_n (velocities at t_{n-1/2})
      kernels::step<Law>(model, lane, horizontal[i], vertical[i], time, body, corners, response, &forces);
      if (history && n % output_every == 0) {
        history->time.push_back(time);
        history->rotation.push_back(before.theta);
        // Velocities live at half steps; their mean around t_n is the second-order value at t_n.
        history->angular_velocity.push_back(0.5 * (before.omega + body.omega));
        history->slide.push_back(forces.slide);
        history->uplift.push_back(std::max(0.0, forces.uplift));
        history->centre_x.push_back(before.x);
        history->centre_y.push_back(before.y);
        history->table_acceleration.push_back(horizontal[i]);
        history->table_velocity.push_back(excitation.horizontal->velocity(time));
        history->table_displacement.push_back(excitation.horizontal->displacement(time));
        history->table_vertical_acceleration.push_back(vertical[i]);
        for (int k = 0; k < model.corner_count; ++k) {
          history->normal_force[k].push_back(forces.normal[k]);
          history->shear_force[k].push_back(forces.shear[k]);
        }
      }
      if (response.status != 0.0) return n + 1;
    }
  }
  return step_count;
}

}  // namespace

std::string status_name(LaneStatus status) {
  switch (status) {
    case LaneStatus::running: return "completed";
    case LaneStatus::tipped_over: return "tipped_over";
    case LaneStatus::left_floor: return "left_floor";
    case LaneStatus::slid_off_pad: return "slid_off_pad";
    case LaneStatus::non_finite: return "non_finite";
  }
  return "unknown";
}

RunSummary summarise(const Model& model, const Response<double>& r, std::int64_t steps) {
  RunSummary s;
  s.max_abs_rotation = r.max_abs_rotation;
  s.stability_angle = model.stability_angle;
  s.max_rotation_ratio = r.max_abs_rotation / model.stability_angle;
  s.max_abs_slide = r.max_abs_slide;
  s.residual_slide = r.final_slide;
  s.max_uplift = r.max_uplift;
  s.status = static_cast<LaneStatus>(static_cast<int>(r.status));
  s.tipped_over = s.status == LaneStatus::tipped_over;
  s.tip_over_time = s.tipped_over ? r.end_time : -1.0;
  s.instability_time = s.tipped_over ? r.instability_time : -1.0;
  s.impacts = static_cast<int>(r.impacts);
  s.end_time = r.end_time;
  s.steps = steps;
  s.time_step = model.time_step;
  for (int j = 0; j < kPeakCount && j < s.impacts; ++j) s.half_cycle_peaks.push_back(r.peak[j]);
  return s;
}

RunResult simulate(const Model& model, const LaneParameters<double>& lane, const BodyState<double>& initial,
                   const Excitation& excitation, const RunSettings& settings) {
  if (!excitation.horizontal) throw std::invalid_argument("a run needs a horizontal table motion");
  if (!(settings.duration > 0.0)) throw std::invalid_argument("the run duration must be positive");
  const auto step_count = static_cast<std::int64_t>(std::ceil(settings.duration / model.time_step));
  std::int64_t output_every = 0;
  RunResult result;
  TimeHistory* history = nullptr;
  if (settings.output_interval > 0.0) {
    output_every = std::max<std::int64_t>(1, std::llround(settings.output_interval / model.time_step));
    history = &result.history;
    history->normal_force.assign(model.corner_count, {});
    history->shear_force.assign(model.corner_count, {});
  }
  BodyState<double> body = initial;
  CornerState<double> corners[kMaxCorners] = {};
  Response<double> response = initial_response(lane, body);
  std::int64_t steps = 0;
  switch (model.friction_law) {
    case FrictionLaw::constant:
      steps = run_steps<FrictionLaw::constant>(model, lane, body, corners, response, excitation, step_count, output_every, history);
      break;
    case FrictionLaw::static_kinetic:
      steps = run_steps<FrictionLaw::static_kinetic>(model, lane, body, corners, response, excitation, step_count, output_every, history);
      break;
    case FrictionLaw::exponential:
      steps = run_steps<FrictionLaw::exponential>(model, lane, body, corners, response, excitation, step_count, output_every, history);
      break;
    case FrictionLaw::tabulated:
      steps = run_steps<FrictionLaw::tabulated>(model, lane, body, corners, response, excitation, step_count, output_every, history);
      break;
  }
  kernels::finish(model, lane, body, static_cast<double>(steps) * model.time_step, response);
  result.summary = summarise(model, response, steps);
  return result;
}

}  // namespace caskdem
