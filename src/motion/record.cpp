// Intensity measures and scaling of records.
//
// Integration (integrate_record): trapezoid rule on the uniform grid t_k = k dt,
//   v_0 = 0,  v_k = v_{k-1} + dt (a_{k-1} + a_k) / 2,
// then the baseline correction of record.h, v_k <- v_k - (t_k / T) v_N with T = t_N the
// duration: the same as subtracting the constant acceleration v_N / T, so the corrected
// velocity ends at exactly zero. The displacement is the trapezoid integral of the corrected
// velocity, u_0 = 0; it need not end at zero (a residual offset is kept, not corrected).
// The trapezoid rule integrates the linear correction exactly, so correcting before or after
// integrating gives the same displacement.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/text.h"
#include "motion/record.h"

namespace caskdem::motion {

GroundMotion integrate_record(const Record& record) {
  const std::vector<double>& a = record.acceleration;
  const std::size_t n = a.size();
  GroundMotion ground;
  ground.velocity.assign(n, 0.0);
  ground.displacement.assign(n, 0.0);
  if (n < 2) return ground;  // a single sample has no duration to integrate over

  const double dt = record.time_step;
  std::vector<double>& v = ground.velocity;
  for (std::size_t k = 1; k < n; ++k) v[k] = v[k - 1] + 0.5 * dt * (a[k - 1] + a[k]);
  // t_k / T = k / N exactly, so the last sample becomes v_N - v_N = 0.
  const double final_velocity = v[n - 1];
  const double last = static_cast<double>(n - 1);
  for (std::size_t k = 0; k < n; ++k) v[k] -= (static_cast<double>(k) / last) * final_velocity;

  std::vector<double>& u = ground.displacement;
  for (std::size_t k = 1; k < n; ++k) u[k] = u[k - 1] + 0.5 * dt * (v[k - 1] + v[k]);
  return ground;
}

double peak_ground_acceleration(const Record& record) {
  double peak = 0.0;
  for (const double a : record.acceleration) peak = std::max(peak, std::abs(a));
  return peak;
}

double peak_ground_velocity(const Record& record) {
  double peak = 0.0;
  for (const double v : integrate_record(record).velocity) peak = std::max(peak, std::abs(v));
  return peak;
}

double largest_scale_factor(const Record& record) {
  return kLargestGroundAcceleration / peak_ground_acceleration(record);
}

Record scaled(const Record& record, double factor) {
  if (!std::isfinite(factor)) throw std::invalid_argument("scaled: the factor must be finite");
  const double largest = largest_scale_factor(record);
  if (!(std::abs(factor) <= largest))
    throw std::invalid_argument("a scale factor of " + number_text(factor) + " would take the record's PGA of " +
                                number_text(peak_ground_acceleration(record)) + " m/s^2 above " +
                                std::string(kLargestGroundAccelerationText) +
                                ", more than any ground motion; expected a factor of at most " + number_text(largest) +
                                " in magnitude");
  Record out = record;
  for (double& a : out.acceleration) a *= factor;
  return out;
}

namespace {
// The factor that brings a measure (PGA or PGV) to its target; a zero record, or one so near
// zero that the factor overflows, has no such factor.
double factor_for(double measure, double target, const char* measure_name, const char* unit) {
  if (!std::isfinite(target) || target < 0.0)
    throw std::invalid_argument(std::string("the target ") + measure_name + " must be finite and not negative");
  if (!(measure > 0.0))
    throw std::invalid_argument(std::string("the record's accelerations are all zero, so no scale factor brings its ") +
                                measure_name + " to the target; expected a record with motion");
  const double factor = target / measure;
  if (!std::isfinite(factor))
    throw std::invalid_argument(std::string("the record's ") + measure_name + " of " + number_text(measure) + " " +
                                unit + " is too small for any finite factor to bring it to the target of " +
                                number_text(target) + " " + unit + "; expected a record with motion");
  return factor;
}
}  // namespace

Record scaled_to_pga(const Record& record, double target_pga) {
  if (target_pga > kLargestGroundAcceleration)
    throw std::invalid_argument("the target PGA of " + number_text(target_pga) + " m/s^2 is above " +
                                std::string(kLargestGroundAccelerationText) +
                                ", more than any ground motion; expected a smaller target");
  return scaled(record, factor_for(peak_ground_acceleration(record), target_pga, "PGA", "m/s^2"));
}

Record scaled_to_pgv(const Record& record, double target_pgv) {
  // PGV is linear in the accelerations (integration and baseline correction are linear).
  return scaled(record, factor_for(peak_ground_velocity(record), target_pgv, "PGV", "m/s"));
}

Record time_scaled(const Record& record, double time_factor) {
  if (!std::isfinite(time_factor) || time_factor <= 0.0)
    throw std::invalid_argument("time_scaled: the time factor must be finite and positive");
  Record out = record;
  out.time_step *= time_factor;
  if (!(out.time_step > 0.0 && std::isfinite(out.time_step) && std::isfinite(out.duration())))
    throw std::invalid_argument("a time factor of " + number_text(time_factor) + " on the record's time step of " +
                                number_text(record.time_step) +
                                " s leaves no positive, finite time step and duration; expected a similarity scale "
                                "nearer 1");
  return out;
}

}  // namespace caskdem::motion
