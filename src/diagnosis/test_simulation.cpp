#include "diagnosis/test_simulation.h"

#include <algorithm>
#include <cmath>

#include "kernels/portable_math.h"
#include "motion/table_motion.h"

namespace caskdem::diagnosis {

namespace {

std::unique_ptr<motion::TableMotion> channel_motion(const std::vector<double>& samples, double dt, const char* name) {
  motion::Record record;
  record.source = name;
  record.time_step = dt;
  record.acceleration = samples;
  return motion::make_record_motion(std::move(record));
}

}  // namespace

std::vector<SimulatedHistory> simulate_test(const ModelVariant& variant, const MeasuredTest& test,
                                            const std::vector<std::vector<double>>& points, InstructionSet isa) {
  const Model& model = variant.model();
  const auto lanes = static_cast<std::int64_t>(points.size());
  const auto horizontal = channel_motion(test.table_acceleration, test.time_step, "table_acc");
  std::unique_ptr<motion::TableMotion> vertical;
  switch (variant.vertical_source()) {
    case VerticalSource::measured: vertical = channel_motion(test.vertical_table_acceleration, test.time_step, "table_acc_v"); break;
    case VerticalSource::from_horizontal: vertical = channel_motion(test.table_acceleration, test.time_step, "table_acc"); break;
    case VerticalSource::none: break;
  }

  LaneBlock block(lanes, model.corner_count);
  std::vector<LaneParameters<double>> parameters(lanes);
  for (std::int64_t l = 0; l < lanes; ++l) {
    parameters[l] = lane_parameters(model, variant.realisation(points[l]));
    const BodyState<double> body = rest_state(model, parameters[l]);
    const CornerState<double> corners[kMaxCorners] = {};
    block.set_lane(l, parameters[l], body, corners, initial_response(parameters[l], body));
  }
  if (block.lane_count() > lanes) block.pad_from(0);

  std::vector<SimulatedHistory> histories(lanes);
  for (auto& h : histories) {
    h.rotation.reserve(test.time.size());
    h.slide.reserve(test.time.size());
  }
  auto record = [&] {
    for (std::int64_t l = 0; l < lanes; ++l) {
      BodyState<double> body;
      Response<double> response;
      block.get_lane(l, nullptr, &body, nullptr, &response);
      const kernels::SinCos<double> r = kernels::sin_cos(body.theta);
      // The step's own expression for the base centre's sliding.
      const double slide = body.x - r.cos * parameters[l].centre_x + r.sin * parameters[l].centre_y - response.base_x0;
      histories[l].rotation.push_back(body.theta);
      histories[l].slide.push_back(slide);
      histories[l].tipped_over = response.status == double(LaneStatus::tipped_over);
    }
  };
  std::vector<double> a_h, a_v;
  std::int64_t step = 0;
  record();  // t = 0
  for (std::size_t k = 1; k < test.time.size(); ++k) {
    // Advance to the model step nearest the sample time (half a model step is ~1e-5 s).
    const auto target = static_cast<std::int64_t>(std::llround(test.time[k] / model.time_step));
    const int count = static_cast<int>(target - step);
    if (count > 0) {
      a_h.resize(count);
      a_v.assign(count, 0.0);
      motion::sample_acceleration(*horizontal, model.time_step, step, count, a_h.data());
      if (vertical) motion::sample_acceleration(*vertical, model.time_step, step, count, a_v.data());
      advance_block(isa, model, block, a_h.data(), a_v.data(), step, count);
      step = target;
    }
    record();
  }
  return histories;
}

}  // namespace caskdem::diagnosis
