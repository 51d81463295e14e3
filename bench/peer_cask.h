#pragma once
// The peer benchmarks' cask (bench/bench_peer.cpp, bench/bench_peer_fragility.cpp): the source
// paper's 1/3 model (12.6 t, the section of cases/model-1-3-sine.toml) on caskdem's constant
// friction law, under Kobe Takatori 090 compressed in time by sqrt(3) (the 1/3 model's
// similarity), and the same cask in MuJoCo (Debian's libmujoco-dev): a box of the same section
// (2b x H) and mass on a plane, planar (slide x, slide z, hinge y), in the table's frame like
// caskdem: the table acceleration enters as the force -m a(t) at the centre of mass. MuJoCo's
// contact is its own (soft constraints, default solref), so the two codes' answers are each
// converged on their own, not compared with each other.

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <mujoco/mujoco.h>

#include "casefile/case_file.h"
#include "core/units.h"
#include "model/build.h"

namespace caskdem::bench {

inline constexpr double kPeerFriction = 0.6;
inline const double kSimilarity = std::getenv("PEER_SIMILARITY") ? std::atof(std::getenv("PEER_SIMILARITY")) : 3.0;

inline MotionSpec kobe() {
  MotionSpec record;
  record.kind = MotionSpec::Kind::record;
  record.file = std::string(CASKDEM_SHARED_DIR) + "/motions/kobe1995_takatori090.csv";
  record.read.format = motion::RecordFormat::columns;
  record.read.unit = motion::AccelerationUnit::g;
  record.similarity_scale = kSimilarity;
  return record;
}

struct Peer {
  Case cask;
  std::unique_ptr<motion::TableMotion> motion;  // the compressed record, unscaled
  double pga = 0.0;                             // m/s^2, of the compressed record
  double duration = 0.0;                        // s: record + 2 s
  double half_width = 0.0, height = 0.0, mass = 0.0;
};

inline const Peer& peer() {
  static const Peer p = [] {
    Peer q;
    q.cask = load_case(std::string(CASKDEM_SOURCE_DIR) + "/cases/model-1-3-sine.toml");
    q.cask.model.friction_law = FrictionLaw::constant;
    q.cask.parameters.friction_static = kPeerFriction;
    q.cask.parameters.friction_kinetic = kPeerFriction;
    q.motion = make_motion(kobe());
    q.pga = motion::peak_acceleration(*q.motion, 1e-3);
    q.duration = q.motion->duration() + 2.0;
    const Model model = build_model(q.cask.model, q.cask.parameters);
    double corner = 0.0;
    for (int k = 0; k < model.corner_count; ++k) corner = std::max(corner, model.corner_x[k]);
    q.half_width = corner + model.rounding_radius;
    q.height = q.cask.cask.cylinder.height;
    q.mass = q.cask.parameters.mass;
    return q;
  }();
  return p;
}

// ---- MuJoCo ----------------------------------------------------------------------------
struct MujocoModel {
  mjModel* model = nullptr;
  ~MujocoModel() { mj_deleteModel(model); }
};

// integrator: MuJoCo's own name, "Euler" (its default, semi-implicit) or "RK4".
inline std::unique_ptr<MujocoModel> mujoco_model(double time_step, double friction, const char* integrator = "Euler") {
  const Peer& p = peer();
  char xml[2048];
  std::snprintf(xml, sizeof xml,
                "<mujoco model='cask'>"
                "<option timestep='%.17g' gravity='0 0 -9.80665' integrator='%s'/>"
                "<worldbody>"
                "<geom type='plane' size='10 10 0.1' friction='%g 0.005 0.0001'/>"
                "<body name='cask' pos='0 0 %.17g'>"
                "<joint name='x' type='slide' axis='1 0 0'/>"
                "<joint name='z' type='slide' axis='0 0 1'/>"
                "<joint name='rocking' type='hinge' axis='0 1 0'/>"
                "<geom type='box' size='%.17g %.17g %.17g' mass='%.17g' friction='%g 0.005 0.0001'/>"
                "</body></worldbody></mujoco>",
                time_step, integrator, friction, 0.5 * p.height, p.half_width, p.half_width, 0.5 * p.height, p.mass, friction);
  // A file of its own per call: threads may load models side by side.
  static std::atomic<long> serial{0};
  const auto path = std::filesystem::temp_directory_path() /
                    ("caskdem-peer-cask-" + std::to_string(::getpid()) + "-" + std::to_string(serial++) + ".xml");
  std::ofstream(path) << xml;
  char error[1000] = "";
  auto m = std::make_unique<MujocoModel>();
  m->model = mj_loadXML(path.string().c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(path);
  if (!m->model) throw std::runtime_error(std::string("MuJoCo: ") + error);
  return m;
}

// One realisation: max |rotation| over the run, stopping where caskdem does (tipped over),
// and the simulated time. scale: the factor on the record, the peer's compressed Kobe for its
// duration and 2 s unless another record and duration are given.
struct MujocoRun {
  double max_rotation = 0.0;
  double simulated = 0.0;  // s
};

inline MujocoRun mujoco_run(const mjModel* model, double scale, const motion::TableMotion* record = nullptr,
                            double duration = 0.0) {
  const Peer& p = peer();
  const motion::TableMotion& table = record ? *record : *p.motion;
  if (duration <= 0.0) duration = p.duration;
  mjData* data = mj_makeData(model);
  mj_forward(model, data);
  const int body = mj_name2id(model, mjOBJ_BODY, "cask");
  const int rocking = model->jnt_qposadr[mj_name2id(model, mjOBJ_JOINT, "rocking")];
  double max_rotation = 0.0;
  const auto steps = static_cast<long>(std::ceil(duration / model->opt.timestep));
  for (long n = 0; n < steps; ++n) {
    data->xfrc_applied[6 * body + 0] = -p.mass * scale * table.acceleration(data->time);
    mj_step(model, data);
    const double rotation = std::abs(data->qpos[rocking]);
    max_rotation = std::max(max_rotation, rotation);
    if (rotation >= 0.5 * std::acos(-1.0)) break;
  }
  const MujocoRun run{max_rotation, data->time};
  mj_deleteData(data);
  return run;
}


// A model's friction, on both geoms (MuJoCo takes the larger of the two), changed in place.
inline void set_mujoco_friction(mjModel* model, double friction) {
  for (int g = 0; g < model->ngeom; ++g) model->geom_friction[3 * g] = friction;
}

}  // namespace caskdem::bench
