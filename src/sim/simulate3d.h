#pragma once
// One deterministic run of the 3D cask (kernels/step3d.h, the scalar instantiation of the step
// SIMD lanes run): the table's two horizontal components, applied at an incidence angle, and
// its vertical; the time histories and the summary. A case run ends when the cask is at rest
// (RunSettings' rest criterion: its kinetic energy, translation and rotation, below a tolerance
// for a held time after the motion), within a cap.

#include <vector>

#include "kernels/lane_state3d.h"
#include "model/build3d.h"
#include "motion/table_motion.h"
#include "sim/simulate.h"

namespace caskdem {

struct Excitation3D {
  const motion::TableMotion* h1 = nullptr;        // along (cos a, 0, sin a) of the floor frame
  const motion::TableMotion* h2 = nullptr;        // along (-sin a, 0, cos a); may be null
  const motion::TableMotion* vertical = nullptr;  // may be null
  double incidence = 0.0;                         // a, rad
};

struct TimeHistory3D {
  std::vector<double> time;                     // s
  std::vector<double> tilt;                     // rad, of the axis from vertical
  std::vector<double> tilt_azimuth;             // rad, direction the axis leans to, from +x towards +z
  std::vector<double> spin;                     // rad, about the cask's axis, accumulated
  std::vector<double> rim_azimuth;              // rad, where on its rim the cask is lowest (body frame): rolling turns it
  std::vector<double> slide_x, slide_z;         // m, base centre relative to the floor
  std::vector<double> slip_x, slip_z;           // m, the slip accumulated where the cask bears (kernels/lane_state3d.h)
  std::vector<double> uplift;                   // m, the highest contact point's gap
  std::vector<double> centre_x, centre_y, centre_z;  // m, centre of mass
  std::vector<double> table_x, table_z, table_vertical;  // m/s^2
};

struct RunSummary3D {
  double max_tilt = 0.0;        // rad
  double stability_angle = 0.0;  // alpha, rad
  double max_tilt_ratio = 0.0;  // max tilt / alpha
  double max_slide = 0.0;       // m, the base centre's walk from where it stood (sliding and rolling)
  double residual_slide = 0.0;  // m, at the end
  double max_slip = 0.0;        // m, the material's sliding where the cask bears on the floor (rolling excluded)
  double residual_slip = 0.0;   // m, at the end
  double max_uplift = 0.0;      // m
  double spin = 0.0;            // rad, at the end
  double rim_revolutions = 0.0; // turns of the place on its rim where it touches, while riding on the rim (rolling)
  LaneStatus status = LaneStatus::running;
  double end_time = 0.0;        // s
  double instability_time = -1.0;
  double time_step = 0.0;
  // With a rest criterion (RunSettings): whether the cask came to rest, and when the criterion
  // was met (the end of the run); false when the run reached its end still moving.
  bool rest_criterion = false;
  bool came_to_rest = false;
  double kinetic_energy_at_end = 0.0;  // J
};

struct RunResult3D {
  RunSummary3D summary;
  TimeHistory3D history;
  BodyState3D<double> final_state;
};

// The summary of a run from its final state and response (rim_revolutions, which only the
// deterministic run follows, left 0); run_time is where a lane still running stopped.
RunSummary3D summarise3d(const Model3D& model, const LaneParameters<double>& lane, const BodyState3D<double>& body,
                         const Response3D<double>& response, double run_time);

// Throws std::invalid_argument without a first horizontal component.
RunResult3D simulate3d(const Model3D& model, const LaneParameters<double>& lane, const BodyState3D<double>& initial,
                       const Excitation3D& excitation, const RunSettings& settings);

}  // namespace caskdem
