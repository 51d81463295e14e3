#include "ensemble/plan.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"
#include "kernels/step.h"
#include "motion/response_spectrum.h"
#include "sim/case_run.h"
#include "sim/case_run3d.h"
#include "sim/free_vibration.h"
#include "sim/rigid_equivalent.h"

namespace caskdem {

namespace {

constexpr int kChunk = 2048;
constexpr int kCalibrationPoints = 48;  // damping ratios of the restitution curve

int dimension_index(const std::string& name) {
  const auto& names = uncertain_parameter_names();
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

// Restitution falls with damping, but at the smallest damping ratios the undamped springs'
// energy exchange makes the measured value wander by a few 1e-4 from one ratio to the next.
// Isotonic regression (pool adjacent violators; Barlow et al., "Statistical Inference under
// Order Restrictions", 1972) gives the closest non-increasing curve, moving no point by more
// than that wander; pooled runs become one point (geometric mean of their damping ratios), so
// the curve decreases strictly and its inverse is defined everywhere.
CalibrationCurve monotone(const CalibrationCurve& measured) {
  struct Pool {
    double sum_e, sum_log_h;
    int count;
    double e() const { return sum_e / count; }
  };
  std::vector<Pool> pools;
  for (std::size_t k = 0; k < measured.restitution.size(); ++k) {
    pools.push_back({measured.restitution[k], std::log(measured.damping_ratio[k]), 1});
    while (pools.size() > 1 && pools[pools.size() - 2].e() <= pools.back().e()) {
      const Pool last = pools.back();
      pools.pop_back();
      pools.back().sum_e += last.sum_e;
      pools.back().sum_log_h += last.sum_log_h;
      pools.back().count += last.count;
    }
  }
  CalibrationCurve curve;
  for (const Pool& pool : pools) {
    curve.restitution.push_back(pool.e());
    curve.damping_ratio.push_back(std::exp(pool.sum_log_h / pool.count));
  }
  return curve;
}

}  // namespace

double CalibrationCurve::damping_for(double e) const {
  if (!(e <= highest() && e >= lowest())) {
    throw std::out_of_range("restitution " + number_text(e) + " is outside the calibrated range [" +
                            number_text(lowest()) + ", " + number_text(highest()) + "]");
  }
  // restitution falls with damping: find the interval and interpolate in ln h.
  std::size_t k = 1;
  while (k + 1 < restitution.size() && restitution[k] > e) ++k;
  const double w = (restitution[k - 1] - e) / (restitution[k - 1] - restitution[k]);
  return std::exp((1.0 - w) * std::log(damping_ratio[k - 1]) + w * std::log(damping_ratio[k]));
}

CalibrationCurve compute_calibration_curve(const Model& model, const ModelSpec& spec, const RealisationParameters& nominal,
                                           const FreeVibrationSpec& free_vibration, InstructionSet isa, int points) {
  const double smallest = 2e-3;
  const double largest = std::min(1.0, largest_stable_damping_ratio(model, spec, nominal));
  CalibrationCurve curve;
  LaneBlock block(points, model.corner_count);
  const double tilt = free_vibration.initial_tilt_ratio * model.stability_angle;
  for (int l = 0; l < points; ++l) {
    const double h = smallest * std::pow(largest / smallest, double(l) / double(points - 1));
    curve.damping_ratio.push_back(h);
    RealisationParameters p = nominal;
    p.damping_ratio = h;
    const LaneParameters<double> lane = lane_parameters(model, p);
    const BodyState<double> body = tilted_state(model, lane, tilt);
    const CornerState<double> corners[kMaxCorners] = {};
    block.set_lane(l, lane, body, corners, initial_response(lane, body));
  }
  if (block.lane_count() > points) block.pad_from(0);
  const auto steps = static_cast<std::int64_t>(std::ceil(free_vibration_duration(model, nominal, free_vibration) / model.time_step));
  const std::vector<double> still(kChunk, 0.0);
  for (std::int64_t first = 0; first < steps; first += kChunk) {
    const int count = static_cast<int>(std::min<std::int64_t>(kChunk, steps - first));
    advance_block(isa, model, block, still.data(), still.data(), first, count);
  }
  for (int l = 0; l < points; ++l) {
    Response<double> response;
    block.get_lane(l, nullptr, nullptr, nullptr, &response);
    const std::vector<double> peaks(response.peak, response.peak + std::min<int>(kPeakCount, int(response.impacts)));
    const double e = restitution_from_peaks(peaks, free_vibration.ratios);
    if (!(e > 0.0)) {
      throw std::runtime_error("free vibration at damping ratio " + number_text(curve.damping_ratio[l]) +
                               " rocked too few half-cycles to measure a restitution");
    }
    curve.restitution.push_back(e);
  }
  return monotone(curve);
}

EnsemblePlan::EnsemblePlan(const EnsembleSpec& spec, InstructionSet isa)
    : spec_(spec),
      model_spec_(spec.base.model),
      nominal_(spec.base.parameters),
      sampler_(spec.sampling, spec.seed, spec.outer_count() * static_cast<int>(spec.levels.size()),
               spec.realisations_per_stripe, static_cast<int>(uncertain_parameter_names().size())),
      // A key of its own, so that the outer points' numbers are not the first stripe's.
      outer_sampler_(spec.sampling, spec.seed ^ 0x9e3779b97f4a7c15ull, 1, spec.outer_count(),
                     static_cast<int>(uncertain_parameter_names().size())) {
  auto fail = [&](const std::string& message) { throw InputError(located(spec_.file, 0, message)); };
  // One time step for the whole ensemble (lanes advance in lockstep): the one the lightest
  // realisation needs, so that no realisation's result depends on the block it lands in.
  double lightest = nominal_.mass;
  if (auto it = spec_.uncertain.find("mass"); it != spec_.uncertain.end()) lightest = it->second.lowest();
  lightest_mass_ = lightest;
  try {
    if (three_d()) {
      // The solid cylinder's mass properties, then its step from the lightest realisation.
      const Cylinder& cylinder = spec_.base.cask.cylinder;
      const CaskSpec3D cask = cask_spec3d(cylinder, model_spec_.section.rounding, nominal_.mass);
      nominal_ = nominal_parameters3d(cask, spec_.base.parameters);
      const Model3D provisional = build_model3d(model_spec_, cask, nominal_);
      model_spec_.time_step = model_spec_.safety_factor * 2.0 * std::sqrt(lightest / standing_stiffness(provisional.contacts));
      model3d_ = build_model3d(model_spec_, cask, nominal_);
      model_ = model3d_.model;
      frequency_parameter_ = model_.rocking_frequency;
    } else {
      Model provisional = build_model(model_spec_, nominal_);
      model_spec_.time_step = model_spec_.safety_factor * 2.0 * std::sqrt(lightest / total_standing_normal_stiffness(provisional));
      model_ = build_model(model_spec_, nominal_);
      frequency_parameter_ = rigid_equivalent(model_, nominal_).frequency_parameter();
    }
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }

  for (const MotionSpec& m : spec_.motions) {
    std::optional<motion::PairIntensity> pair;
    double duration = 0.0;
    if (three_d()) {
      CaseMotions3D set = make_motions3d(m, spec_.file);
      pair = set.pair;
      motions_.push_back(std::move(set.h1));
      second_horizontal_.push_back(std::move(set.h2));
      vertical_.push_back(std::move(set.vertical));
      for (int c = 0; c < 3; ++c) {
        if (const motion::TableMotion* component = this->component(motion_count() - 1, c)) {
          duration = std::max(duration, component->duration());
        }
      }
    } else {
      motions_.push_back(make_motion(m));
      duration = motions_.back()->duration();
    }
    // Each realisation is held to the bounds of a case run, before the peaks are sought.
    const std::string& name = spec_.motion_names[intensities_.size()];
    const double run = spec_.base.duration > 0.0 ? spec_.base.duration : duration + spec_.base.settle_time;
    const double steps = run / model_.time_step;
    if (!(run <= kLongestRun) || !(steps <= kMostSteps)) {
      fail("motion " + name + ": a realisation would last " + number_text(run) + " s in " + number_text(steps) +
           " steps of " + number_text(model_.time_step) + " s; expected at most " + number_text(kLongestRun) +
           " s and " + number_text(kMostSteps) + " steps (a duration, mass, density or contact stiffness in the wrong "
           "unit?)");
    }
    MotionIntensity intensity;
    intensity.pga = motion::peak_acceleration(*motions_.back(), model_.time_step);
    intensity.pgv = motion::peak_velocity(*motions_.back(), model_.time_step);
    intensity.duration = duration;
    if (pair) {
      // The pair as one intensity (Boore 2010's RotD or the geometric mean of the two).
      switch (spec_.pair_measure) {
        case MotionSpec::PairMeasure::rotd50: intensity.pga = pair->pga_rotd50, intensity.pgv = pair->pgv_rotd50; break;
        case MotionSpec::PairMeasure::rotd100: intensity.pga = pair->pga_rotd100, intensity.pgv = pair->pgv_rotd100; break;
        case MotionSpec::PairMeasure::geometric_mean:
          intensity.pga = pair->pga_geometric_mean, intensity.pgv = pair->pgv_geometric_mean;
          break;
      }
    }
    if (spec_.measure == IntensityMeasure::sa) {
      intensity.sa = motion::spectral_acceleration(*motions_.back(), spec_.spectral_period, spec_.spectral_damping_ratio,
                                                   model_.time_step);
    }
    if (!(intensity.pga > 0.0) || !(intensity.pgv > 0.0) || (spec_.measure == IntensityMeasure::sa && !(intensity.sa > 0.0))) fail("motion " + spec_.motion_names[intensities_.size()] + " does not move the table");
    intensities_.push_back(intensity);
  }

  if (restitution_uncertain()) {
    try {
      calibrate(isa);
    } catch (const std::exception& e) {
      fail(e.what());
    }
    const Distribution& d = spec_.uncertain.at("restitution");
    if (d.lowest() < calibration_.lowest() || d.highest() > calibration_.highest()) {
      fail("key uncertain.restitution: this cask's free vibration reaches restitutions " +
           number_text(calibration_.lowest()) + " to " + number_text(calibration_.highest()) +
           " (rigid-impact limit to undamped springs); the distribution spans " + number_text(d.lowest()) + " to " +
           number_text(d.highest()));
    }
  }
}

double EnsemblePlan::model_scale() const {
  double scale = spec_.motions.empty() ? 1.0 : spec_.motions.front().similarity_scale;
  for (const MotionSpec& m : spec_.motions) {
    if (m.similarity_scale != scale) return 0.0;
  }
  return scale;
}

const motion::TableMotion* EnsemblePlan::component(int m, int c) const {
  if (c == 0) return motions_[m].get();
  if (!three_d()) return nullptr;
  return c == 1 ? second_horizontal_[m].get() : vertical_[m].get();
}

double EnsemblePlan::run_duration(int m) const {
  return spec_.base.duration > 0.0 ? spec_.base.duration : intensities_[m].duration + spec_.base.settle_time;
}

double EnsemblePlan::intensity_of(int m, double scale) const {
  const double g_tan_alpha = model_.gravity * std::tan(model_.stability_angle);
  switch (spec_.measure) {
    case IntensityMeasure::pga: return scale * intensities_[m].pga;
    case IntensityMeasure::pgv: return scale * intensities_[m].pgv;
    case IntensityMeasure::pga_ratio: return scale * intensities_[m].pga / g_tan_alpha;
    case IntensityMeasure::pgv_ratio: return scale * intensities_[m].pgv * frequency_parameter_ / g_tan_alpha;
    case IntensityMeasure::sa: return scale * intensities_[m].sa;  // Sa is linear in the motion
  }
  return 0.0;
}

void EnsemblePlan::calibrate(InstructionSet isa) {
  if (!calibration_.restitution.empty()) return;
  calibration_ =
      compute_calibration_curve(model_, model_spec_, nominal_, spec_.base.free_vibration, isa, kCalibrationPoints);
}

void EnsemblePlan::set_realisations(std::vector<RealisationInput> inputs) {
  chosen_ = std::make_shared<const std::vector<RealisationInput>>(std::move(inputs));
}

RealisationInput EnsemblePlan::realisation(std::int64_t index) const {
  if (chosen_) return (*chosen_)[index];
  RealisationInput in;
  in.index = index;
  const std::int64_t n = spec_.realisations_per_stripe;
  in.outer = outer_of(index);
  const std::int64_t inner = index % spec_.realisations_per_outer_point();
  in.stripe = static_cast<int>(inner / n);
  const std::int64_t position = inner % n;
  in.motion = motion_of(index);
  in.level = spec_.levels[in.stripe];
  in.scale_factor = in.level / intensity_of(in.motion, 1.0);
  in.parameters = nominal_;
  RealisationParameters& p = in.parameters;
  for (const auto& [name, distribution] : spec_.uncertain) {
    const int dimension = dimension_index(name);
    const int sample_stripe = in.outer * static_cast<int>(spec_.levels.size()) + in.stripe;
    const double u = spec_.epistemic.count(name) ? outer_sampler_.uniform(0, in.outer, dimension)
                                                 : sampler_.uniform(sample_stripe, position, dimension);
    const double value = distribution.quantile(u);
    if (name == "friction_static") {
      p.friction_static = value;
      if (model_.friction_law == FrictionLaw::constant) p.friction_kinetic = value;
    } else if (name == "friction_kinetic") {
      p.friction_kinetic = value;
    } else if (name == "friction_decay_speed") {
      p.friction_decay_speed = value;
    } else if (name == "restitution") {
      in.restitution = value;
      p.damping_ratio = calibration_.damping_for(value);
    } else if (name == "mass") {
      p.inertia = nominal_.inertia * value / nominal_.mass;  // same shape, so inertia scales with mass
      p.axial_inertia = nominal_.axial_inertia * value / nominal_.mass;
      p.mass = value;
    } else if (name == "incidence") {
      in.incidence = value;
    } else if (name == "centre_height") {
      p.centre_of_mass.y = value;
    }
  }
  p.horizontal_scale = in.scale_factor;
  if (three_d()) p.vertical_scale = in.scale_factor;  // the station's components scale together
  return in;
}

}  // namespace caskdem
