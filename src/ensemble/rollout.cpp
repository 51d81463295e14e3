#include "ensemble/rollout.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"
#include "ensemble/device_runner.h"
#include "ensemble/execute.h"
#include "sim/free_vibration.h"

namespace caskdem {

const std::vector<RolloutParameter>& rollout_parameters() {
  static const std::vector<RolloutParameter> parameters = {
      {"motion", "1", "index of the ensemble's motion (0 to M - 1, in the file's order)"},
      {"scale_factor", "1", "factor on the motion's accelerations (give it or level)"},
      {"level", "SI", "the motion's intensity in the ensemble's measure, SI (m/s^2, m/s or the ratio)"},
      {"friction_static", "1", "static friction coefficient"},
      {"friction_kinetic", "1", "kinetic friction coefficient (static_kinetic and exponential laws)"},
      {"friction_decay_speed", "m/s", "the exponential law's decay speed v0"},
      {"restitution", "1", "rocking restitution, made a damping ratio by the cask's calibration curve"},
      {"damping_ratio", "1", "the contacts' damping ratio h (instead of restitution)"},
      {"mass", "kg", "mass (inertia scales with it); no lighter than the ensemble's lightest"},
      {"centre_height", "m", "height of the centre of mass above the base"},
      {"eccentricity", "m", "horizontal offset of the centre of mass from the axis"},
      {"base_camber", "m", "rise of the base's edges above its middle (a convex base)"},
      {"incidence", "rad", "direction of the motion's first horizontal in the floor plane (3D)"},
  };
  return parameters;
}

namespace {

[[noreturn]] void fail(const std::string& name, std::int64_t row, const std::string& message) {
  throw InputError("rollout parameter " + name + (row >= 0 ? ", row " + std::to_string(row) : std::string()) + ": " +
                   message);
}

// The column's value for a row (a column of one value holds for every row), or none.
class Columns {
 public:
  Columns(const ParameterColumns& columns, std::int64_t count) : columns_(columns) {
    const auto& known = rollout_parameters();
    for (const auto& column : columns) {
      const std::string& name = column.first;
      const std::vector<double>& values = column.second;
      if (std::none_of(known.begin(), known.end(), [&](const RolloutParameter& p) { return p.name == name; })) {
        std::string names;
        std::vector<std::string> candidates;
        for (const RolloutParameter& p : known)
          names += (names.empty() ? "" : ", ") + p.name, candidates.push_back(p.name);
        const auto meant = likely_meant(name, candidates);
        fail(name, -1,
             "not a parameter" + (meant ? "; did you mean " + *meant + "?" : std::string()) + " (expected one of " +
                 names + ")");
      }
      if (values.size() != 1 && static_cast<std::int64_t>(values.size()) != count) {
        fail(name, -1,
             "expected " + std::to_string(count) + " values (one per realisation) or one, got " +
                 std::to_string(values.size()));
      }
      for (std::size_t k = 0; k < values.size(); ++k) {
        if (!std::isfinite(values[k]))
          fail(name, static_cast<std::int64_t>(k), "expected a finite number, got " + number_text(values[k]));
      }
    }
  }
  bool has(const std::string& name) const { return columns_.count(name) > 0; }
  std::optional<double> at(const std::string& name, std::int64_t row) const {
    const auto it = columns_.find(name);
    if (it == columns_.end()) return std::nullopt;
    return it->second.size() == 1 ? it->second[0] : it->second[static_cast<std::size_t>(row)];
  }

 private:
  const ParameterColumns& columns_;
};

// The base corners' extent in x (the body frame): the centre of mass must lie over it.
std::pair<double, double> base_extent(const EnsemblePlan& plan) {
  if (plan.three_d()) {
    const double ring = plan.model3d().contacts.ring_radius;
    return {-ring, ring};
  }
  const Model& m = plan.model();
  double lowest = m.corner_rest_gap[0];
  for (int c = 1; c < m.corner_count; ++c) lowest = std::min(lowest, m.corner_rest_gap[c]);
  double left = INFINITY, right = -INFINITY;
  for (int c = 0; c < m.corner_count; ++c) {
    if (m.corner_rest_gap[c] <= lowest + 1e-12 * (1.0 + std::abs(lowest))) {
      left = std::min(left, m.corner_x[c]);
      right = std::max(right, m.corner_x[c]);
    }
  }
  return {left, right};
}

double section_top(const EnsemblePlan& plan) {
  double top = 0.0;
  for (const Point& p : plan.model_spec().section.outline) top = std::max(top, p.y);
  return plan.three_d() ? plan.spec().base.cask.cylinder.height : top;
}

}  // namespace

std::vector<RealisationInput> realisations_from_columns(EnsemblePlan& plan, const ParameterColumns& parameters,
                                                        std::int64_t count, InstructionSet isa) {
  if (count < 1) throw InputError("rollout: expected at least one realisation, got " + std::to_string(count));
  const Columns columns(parameters, count);
  const FrictionLaw law = plan.model().friction_law;
  if (columns.has("scale_factor") == columns.has("level")) {
    fail(columns.has("level") ? "level" : "scale_factor", -1,
         std::string(columns.has("level") ? "given with scale_factor; expected" : "not given; expected") +
             " scale_factor or level, one of the two (a factor on the motion's accelerations, or the intensity in "
             "the ensemble's measure, SI)");
  }
  if (!columns.has("motion") && plan.motion_count() > 1) {
    fail("motion", -1,
         "the ensemble has " + std::to_string(plan.motion_count()) + " motions: give each realisation's (0 to " +
             std::to_string(plan.motion_count() - 1) + ")");
  }
  if (columns.has("restitution") && columns.has("damping_ratio")) {
    fail("damping_ratio", -1, "give restitution or damping_ratio, not both (restitution sets the damping ratio)");
  }
  if (columns.has("friction_kinetic") && law != FrictionLaw::static_kinetic && law != FrictionLaw::exponential) {
    fail("friction_kinetic", -1,
         "the ensemble's friction law has no kinetic coefficient (static_kinetic or exponential have)");
  }
  if (columns.has("friction_decay_speed") && law != FrictionLaw::exponential) {
    fail("friction_decay_speed", -1, "only the exponential friction law has a decay speed");
  }
  if (columns.has("friction_static") && law == FrictionLaw::tabulated) {
    fail("friction_static", -1, "a tabulated friction law cannot vary its coefficient");
  }
  if (columns.has("incidence") && !plan.three_d()) {
    fail("incidence", -1,
         "only a 3D cask ([cask] dimensions = 3) has an incidence: the planar model has one direction");
  }
  if (columns.has("restitution")) plan.calibrate(isa);
  const double stable_damping = columns.has("damping_ratio")
                                    ? largest_stable_damping_ratio(plan.model(), plan.model_spec(), plan.nominal())
                                    : 0.0;
  const auto [left, right] = base_extent(plan);
  const double top = section_top(plan);
  const RealisationParameters& nominal = plan.nominal();

  std::vector<RealisationInput> inputs(static_cast<std::size_t>(count));
  for (std::int64_t row = 0; row < count; ++row) {
    RealisationInput& in = inputs[static_cast<std::size_t>(row)];
    in.index = row;
    const double motion = columns.at("motion", row).value_or(0.0);
    if (!(motion >= 0.0 && motion < plan.motion_count() && motion == std::floor(motion))) {
      fail("motion", row,
           "expected an index 0 to " + std::to_string(plan.motion_count() - 1) + ", got " + number_text(motion));
    }
    in.motion = static_cast<int>(motion);
    if (const auto level = columns.at("level", row)) {
      if (!(*level > 0.0)) fail("level", row, "expected a positive intensity, got " + number_text(*level));
      in.level = *level;
      in.scale_factor = *level / plan.intensity_of(in.motion, 1.0);  // as the plan scales a stripe's motion
    } else {
      in.scale_factor = *columns.at("scale_factor", row);
      if (!(in.scale_factor > 0.0))
        fail("scale_factor", row, "expected a positive factor, got " + number_text(in.scale_factor));
      in.level = plan.intensity_of(in.motion, in.scale_factor);
    }
    in.parameters = nominal;
    RealisationParameters& p = in.parameters;
    if (const auto v = columns.at("friction_static", row)) {
      p.friction_static = *v;
      if (law == FrictionLaw::constant) p.friction_kinetic = *v;  // one coefficient, as the ensemble file's
    }
    if (const auto v = columns.at("friction_kinetic", row)) p.friction_kinetic = *v;
    if (const auto v = columns.at("friction_decay_speed", row)) p.friction_decay_speed = *v;
    if (const auto v = columns.at("restitution", row)) {
      in.restitution = *v;
      try {
        p.damping_ratio = plan.calibration().damping_for(*v);
      } catch (const std::out_of_range& e) {
        fail("restitution", row, std::string(e.what()) + " of this cask's free vibration");
      }
    }
    if (const auto v = columns.at("damping_ratio", row)) {
      if (!(*v >= 0.0 && *v <= stable_damping)) {
        fail("damping_ratio", row,
             "expected 0 to " + number_text(stable_damping) +
                 " (the most the ensemble's time step keeps stable), got " + number_text(*v));
      }
      p.damping_ratio = *v;
    }
    if (const auto v = columns.at("mass", row)) {
      if (!(*v >= plan.lightest_mass())) {
        fail("mass", row,
             "expected at least " + number_text(plan.lightest_mass()) +
                 " kg, the lightest the ensemble's time step was chosen for (lower [uncertain.mass] in "
                 "the file to run lighter casks), got " +
                 number_text(*v));
      }
      p.inertia = nominal.inertia * *v / nominal.mass;  // same shape, so inertia scales with mass
      p.axial_inertia = nominal.axial_inertia * *v / nominal.mass;
      p.mass = *v;
    }
    if (const auto v = columns.at("centre_height", row)) {
      if (!(*v > 0.0 && *v < top)) {
        fail("centre_height", row,
             "expected a height inside the cask, 0 to " + number_text(top) + " m, got " + number_text(*v));
      }
      p.centre_of_mass.y = *v;
    }
    if (const auto v = columns.at("eccentricity", row)) {
      if (!(*v > left && *v < right)) {
        fail("eccentricity", row,
             "expected the centre of mass over the base, " + number_text(left) + " to " + number_text(right) +
                 " m, got " + number_text(*v));
      }
      p.centre_of_mass.x = *v;
    }
    if (const auto v = columns.at("base_camber", row)) p.base_camber = *v;
    if (const auto v = columns.at("incidence", row)) in.incidence = *v;
    p.horizontal_scale = in.scale_factor;
    if (plan.three_d()) p.vertical_scale = in.scale_factor;  // the station's components scale together
    try {
      (void)lane_parameters(plan.model(), p);  // the checks every lane's parameters pass
    } catch (const std::invalid_argument& e) {
      fail("parameters", row, e.what());
    }
  }
  return inputs;
}

ParameterColumns plan_columns(const EnsemblePlan& plan) {
  ParameterColumns columns;
  auto& motion = columns["motion"];
  auto& scale = columns["scale_factor"];
  for (const auto& [name, distribution] : plan.spec().uncertain) columns[name];
  for (std::int64_t i = 0; i < plan.size(); ++i) {
    const RealisationInput in = plan.realisation(i);
    motion.push_back(in.motion);
    scale.push_back(in.scale_factor);
    const RealisationParameters& p = in.parameters;
    for (auto& [name, values] : columns) {
      if (name == "friction_static")
        values.push_back(p.friction_static);
      else if (name == "friction_kinetic")
        values.push_back(p.friction_kinetic);
      else if (name == "friction_decay_speed")
        values.push_back(p.friction_decay_speed);
      else if (name == "restitution")
        values.push_back(in.restitution);
      else if (name == "mass")
        values.push_back(p.mass);
      else if (name == "centre_height")
        values.push_back(p.centre_of_mass.y);
      else if (name == "incidence")
        values.push_back(in.incidence);
    }
  }
  return columns;
}

EnsembleResults rollout(const EnsemblePlan& plan, const MotionTables& tables, const RolloutOptions& options) {
  EnsembleResults results(plan);
  RunOptions run;
  run.isa = options.isa;
  run.threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  run.lanes = plan.spec().block_lanes;
  std::optional<DeviceLanes> device_lanes;
  if (options.device) {
    device_lanes.emplace(plan, device_tables(plan, tables), *options.device);
    run.device = &*device_lanes;
  }
  std::vector<std::int64_t> all(static_cast<std::size_t>(plan.size()));
  std::iota(all.begin(), all.end(), std::int64_t(0));
  std::int64_t done = 0;
  run_realisations(plan, tables, all, run,
                   [&](const std::vector<std::int64_t>& indices, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < indices.size(); ++k) {
                       results.record(indices[k], outcomes[k], plan.stability_angle());
                     }
                     done += static_cast<std::int64_t>(indices.size());
                     if (options.on_progress) options.on_progress(done);
                   });
  return results;
}

}  // namespace caskdem
