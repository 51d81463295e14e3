#include "ensemble/lane_io.h"

#include <cmath>

#include "kernels/step.h"
#include "sim/simulate3d.h"

namespace caskdem {

LaneStart lane_start(const EnsemblePlan& plan, std::int64_t index) {
  const Model& model = plan.model();
  const RealisationInput in = plan.realisation(index);
  LaneStart s;
  s.parameters = lane_parameters(model, in.parameters);
  s.body = rest_state(model, s.parameters);
  s.response = initial_response(s.parameters, s.body);
  s.motion = in.motion;
  return s;
}

LaneStart3D lane_start3d(const EnsemblePlan& plan, std::int64_t index) {
  const Model3D& model = plan.model3d();
  const RealisationInput in = plan.realisation(index);
  LaneStart3D s;
  s.parameters = lane_parameters3d(model, in.parameters);
  s.body = rest_state3d(model, s.parameters);
  s.response = initial_response3d(s.parameters, s.body);
  s.incidence = in.incidence;
  s.incidence_cos = std::cos(in.incidence);
  s.incidence_sin = std::sin(in.incidence);
  s.motion = in.motion;
  return s;
}

RealisationOutcome lane_outcome(const EnsemblePlan& plan, const LaneParameters<double>& parameters,
                                const BodyState<double>& body, Response<double> response, std::int64_t steps) {
  const Model& model = plan.model();
  kernels::finish(model, parameters, body, static_cast<double>(steps) * model.time_step, response);
  RealisationOutcome o;
  o.status = static_cast<LaneStatus>(static_cast<int>(response.status));
  o.max_abs_rotation = response.max_abs_rotation;
  o.max_abs_slide = response.max_abs_slide;
  o.residual_slide = response.final_slide;
  o.max_uplift = response.max_uplift;
  o.impacts = response.impacts;
  o.end_time = response.end_time;
  o.instability_time = o.status == LaneStatus::tipped_over ? response.instability_time : -1.0;
  return o;
}

// As the deterministic run sums it up (sim/simulate3d.h); the lanes count no impacts (-1).
RealisationOutcome lane_outcome3d(const EnsemblePlan& plan, const LaneParameters<double>& parameters,
                                  const BodyState3D<double>& body, const Response3D<double>& response,
                                  std::int64_t steps) {
  const RunSummary3D s =
      summarise3d(plan.model3d(), parameters, body, response, static_cast<double>(steps) * plan.model().time_step);
  RealisationOutcome o;
  o.status = s.status;
  o.max_abs_rotation = s.max_tilt;
  o.max_abs_slide = s.max_slide;
  o.residual_slide = s.residual_slide;
  o.max_uplift = s.max_uplift;
  o.impacts = -1.0;
  o.end_time = s.end_time;
  o.instability_time = s.instability_time;
  o.spin = s.spin;
  o.max_slip = s.max_slip;
  o.residual_slip = s.residual_slip;
  return o;
}

}  // namespace caskdem
