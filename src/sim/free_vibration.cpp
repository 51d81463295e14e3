#include "sim/free_vibration.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <boost/math/tools/roots.hpp>

#include "core/error.h"
#include "core/text.h"
#include "sim/simulate.h"

namespace caskdem {

namespace {

// A table at rest.
class Still final : public motion::TableMotion {
 public:
  double acceleration(double) const override { return 0.0; }
  double velocity(double) const override { return 0.0; }
  double displacement(double) const override { return 0.0; }
  double duration() const override { return 0.0; }
  std::string describe() const override { return "still"; }
};

constexpr double kSmallestDamping = 2e-3;  // below it the undamped springs' energy exchange makes e erratic

}  // namespace

double restitution_from_peaks(const std::vector<double>& peaks, int ratios) {
  if (static_cast<int>(peaks.size()) < ratios + 1) return 0.0;
  double sum = 0.0;
  for (int k = 1; k <= ratios; ++k) sum += peaks[k] / peaks[k - 1];
  return sum / ratios;
}

double free_vibration_duration(const Model& model, const RealisationParameters& p, const FreeVibrationSpec& spec) {
  if (spec.duration > 0.0) return spec.duration;
  // Housner: a half-cycle from amplitude theta lasts (2/p) acosh(1 / (1 - theta/alpha)); the
  // amplitudes only fall, so the first half-cycle bounds the others.
  const double b = std::abs(p.centre_of_mass.x - model.corner_x[0]);
  const double h = p.centre_of_mass.y;
  const double size = std::hypot(b, h);
  const double inertia_about_pivot = p.inertia + p.mass * size * size;
  const double frequency_parameter = std::sqrt(p.mass * model.gravity * size / inertia_about_pivot);
  const double half_cycle = 2.0 / frequency_parameter * std::acosh(1.0 / (1.0 - spec.initial_tilt_ratio));
  return (spec.ratios + 2) * half_cycle * 1.5;
}

FreeVibrationResult free_vibration(const Model& model, const RealisationParameters& parameters,
                                   const FreeVibrationSpec& spec) {
  const LaneParameters<double> lane = lane_parameters(model, parameters);
  FreeVibrationResult result;
  result.initial_tilt = spec.initial_tilt_ratio * model.stability_angle;
  result.duration = free_vibration_duration(model, parameters, spec);
  const Still still;
  const RunResult run = simulate(model, lane, tilted_state(model, lane, result.initial_tilt), {&still, nullptr},
                                 {result.duration, 0.0});
  result.peaks = run.summary.half_cycle_peaks;
  result.restitution = restitution_from_peaks(result.peaks, spec.ratios);
  result.enough_impacts = result.restitution > 0.0;
  return result;
}

double largest_stable_damping_ratio(const Model& model, const ModelSpec& spec, const RealisationParameters& parameters) {
  // Stability with stiffness-proportional damping: dt <= (2/w)(sqrt(1 + z^2) - z) at the highest
  // frequency w, z = beta w / 2, i.e. z <= (1 - q^2) / (2 q) with q = w dt / 2.
  RealisationParameters undamped = parameters;
  undamped.damping_ratio = 0.0;
  const ModelFacts facts = model_facts(model, spec, undamped);
  const double q = facts.highest_frequency * model.time_step / 2.0;
  const double largest_z = (1.0 - q * q) / (2.0 * q);
  const double largest_beta = 2.0 * largest_z / facts.highest_frequency;
  const double omega = parameters.damping_frequency > 0.0 ? parameters.damping_frequency : facts.natural_frequency;
  return 0.9 * largest_beta * omega / 2.0;  // 10 % margin below the limit
}

CalibrationResult calibrate_damping(const Case& c, double target) {
  Model model;
  try {
    model = build_model(c.model, c.parameters);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(c.file, 0, e.what()));
  }
  CalibrationResult result;
  result.target = target;
  result.smallest_damping = kSmallestDamping;
  result.largest_damping = std::min(1.0, largest_stable_damping_ratio(model, c.model, c.parameters));

  auto restitution_at = [&](double damping_ratio) {
    RealisationParameters p = c.parameters;
    p.damping_ratio = damping_ratio;
    ++result.evaluations;
    const FreeVibrationResult fv = free_vibration(model, p, c.free_vibration);
    if (!fv.enough_impacts) {
      throw InputError(located(c.file, 0, "free vibration at damping ratio " + number_text(damping_ratio) +
                                              " rocked fewer than " + std::to_string(c.free_vibration.ratios + 1) +
                                              " half-cycles; raise [free_vibration] duration"));
    }
    return fv.restitution;
  };
  result.highest_restitution = restitution_at(result.smallest_damping);
  result.lowest_restitution = restitution_at(result.largest_damping);
  if (!(target <= result.highest_restitution && target >= result.lowest_restitution)) {
    throw InputError(located(c.file, 0,
                             "target restitution " + number_text(target) + " is out of reach of this model: damping ratios " +
                                 number_text(result.smallest_damping) + " to " + number_text(result.largest_damping) +
                                 " give " + number_text(result.lowest_restitution) + " to " +
                                 number_text(result.highest_restitution) +
                                 " (the rigid-impact limit below, the undamped springs above)"));
  }
  // e(h) falls monotonically; solve e(exp(x)) = target for x = log h.
  auto residual = [&](double log_h) { return restitution_at(std::exp(log_h)) - target; };
  boost::uintmax_t iterations = 60;
  const auto tolerance = [](double a, double b) { return std::abs(b - a) < 1e-4; };  // in log h: 0.01 % in h
  const auto [low, high] = boost::math::tools::toms748_solve(residual, std::log(result.smallest_damping),
                                                            std::log(result.largest_damping),
                                                            result.highest_restitution - target,
                                                            result.lowest_restitution - target, tolerance, iterations);
  result.damping_ratio = std::exp(0.5 * (low + high));
  result.restitution = restitution_at(result.damping_ratio);
  return result;
}

}  // namespace caskdem
