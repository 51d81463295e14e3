#pragma once
// The deterministic run: one realisation, one motion, the scalar instantiation of the
// kernel's step (kernels/step.h), with time histories. This is the reference the ensemble
// engine is checked against lane by lane.

#include <cstdint>
#include <string>
#include <vector>

#include "kernels/lane_state.h"
#include "kernels/model.h"
#include "motion/table_motion.h"

namespace caskdem {

struct Excitation {
  const motion::TableMotion* horizontal = nullptr;
  const motion::TableMotion* vertical = nullptr;  // optional
};

struct RunSettings {
  double duration = 0.0;         // s (with a rest criterion: the most the run lasts)
  double output_interval = 0.0;  // s; 0 records no history
  // The rest criterion (3D case runs, sim/simulate3d.h): from rest_from (s; < 0: none) the run
  // ends once the cask's kinetic energy has stayed below rest_energy (J) for rest_hold (s).
  double rest_from = -1.0;
  double rest_energy = 0.0;
  double rest_hold = 1.0;
};

struct TimeHistory {
  std::vector<double> time;                  // s
  std::vector<double> rotation;              // rad
  std::vector<double> angular_velocity;      // rad/s
  std::vector<double> slide;                 // m, base centre relative to the floor
  std::vector<double> uplift;                // m, largest corner rise above rest
  std::vector<double> centre_x, centre_y;    // m, centre of mass in the floor frame
  std::vector<double> table_acceleration;    // m/s^2
  std::vector<double> table_velocity;        // m/s
  std::vector<double> table_displacement;    // m
  std::vector<double> table_vertical_acceleration;  // m/s^2
  std::vector<std::vector<double>> normal_force;    // [corner][sample], N
  std::vector<std::vector<double>> shear_force;     // [corner][sample], N
};

struct RunSummary {
  double max_abs_rotation = 0.0;       // rad
  double stability_angle = 0.0;        // alpha, rad
  double max_rotation_ratio = 0.0;     // max |theta| / alpha
  double max_abs_slide = 0.0;          // m
  double residual_slide = 0.0;         // m, at the end
  double max_uplift = 0.0;             // m
  LaneStatus status = LaneStatus::running;
  bool tipped_over = false;
  double tip_over_time = -1.0;         // s, when |theta| reached the tip-over angle (-1: not tipped)
  double instability_time = -1.0;      // s, when it last rose past alpha before tipping (-1: never)
  int impacts = 0;
  double end_time = 0.0;               // s, last observed time
  std::int64_t steps = 0;
  double time_step = 0.0;              // s
  std::vector<double> half_cycle_peaks;  // max |omega| of the first rocking half-cycles, rad/s
};

struct RunResult {
  RunSummary summary;
  TimeHistory history;
};

RunSummary summarise(const Model& model, const Response<double>& response, std::int64_t steps);

RunResult simulate(const Model& model, const LaneParameters<double>& lane, const BodyState<double>& initial,
                   const Excitation& excitation, const RunSettings& settings);

std::string status_name(LaneStatus status);

}  // namespace caskdem
