// Rigid-plastic two-way sliding of a block on a harmonically shaken floor: the exact,
// piecewise closed-form solution (Newmark 1965, Geotechnique 15(2), for the rigid-plastic
// block; Den Hartog 1931, Trans ASME 53, for harmonic excitation with Coulomb friction).
//
// a_g(t) = A sin(w t). In a slip phase with direction s that starts at t0 with u = u0, u' = 0
// (every phase starts at rest relative to the floor, from sticking or at a reversal):
//   u'' = -A sin(w t) - s mu g
//   u'  = (A/w) [cos(w t) - cos(w t0)] - s mu g (t - t0)
//   u   = u0 + (A/w) [(sin(w t) - sin(w t0))/w - cos(w t0) (t - t0)] - s mu g (t - t0)^2 / 2.
// u' is monotone between its critical points, where A sin(w t) = -s mu g (closed form), so the
// end of the phase (s u' back to 0) is bracketed exactly by walking those points and is then
// found with TOMS 748. Within a phase u is monotone (u' keeps the sign s), so max |u| is reached
// at the ends of phases. Sticking ends where |a_g| rises through mu g: w t = asin(mu g / A)
// (a_g = +mu g, slip towards -x) or pi + asin(mu g / A) (a_g = -mu g, slip towards +x).

#include "theory/sliding.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "theory/root_tolerance.h"

namespace caskdem::theory {
namespace {

constexpr double kPhaseEndWidth = 1e-13;  // s: final bracket of the end of a slip phase

struct SlipPhase {
  double start;               // s
  double start_displacement;  // m
  int direction;              // s = sign of u' during the phase
};

// sin(x) - x without cancellation for small x (Taylor series below 0.1: error < 1e-19 x^3).
double sine_minus_argument(double x) {
  if (std::abs(x) >= 0.1) return std::sin(x) - x;
  const double x2 = x * x;
  return -x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0 * (1.0 - x2 / 110.0))));
}

class HarmonicSliding {
 public:
  HarmonicSliding(double friction, double gravity, double amplitude, double circular_frequency)
      : friction_acceleration_(friction * gravity), amplitude_(amplitude), frequency_(circular_frequency) {}

  bool ever_slips() const { return std::abs(amplitude_) > friction_acceleration_; }
  double friction_acceleration() const { return friction_acceleration_; }
  double table_acceleration(double t) const { return amplitude_ * std::sin(frequency_ * t); }

  // The closed forms above, written with the phase's start angle w t0 and advance d = w (t - t0)
  // so that no two large terms cancel: a phase that starts where A barely exceeds mu g moves
  // u by ~ (A - mu g)^2 / (A w^2), far below the separate terms of the plain formula.
  double velocity(const SlipPhase& phase, double t) const {
    const double advance = frequency_ * (t - phase.start);
    const double start_angle = frequency_ * phase.start;
    // cos(w t) - cos(w t0) = -2 sin(w t0 + d/2) sin(d/2)
    return -2.0 * amplitude_ / frequency_ * std::sin(start_angle + 0.5 * advance) * std::sin(0.5 * advance) -
           phase.direction * friction_acceleration_ * (t - phase.start);
  }

  double displacement(const SlipPhase& phase, double t) const {
    const double elapsed = t - phase.start;
    const double advance = frequency_ * elapsed;
    const double start_angle = frequency_ * phase.start;
    const double half_advance_sine = std::sin(0.5 * advance);
    // sin(w t) - sin(w t0) - d cos(w t0) = -2 sin(w t0) sin^2(d/2) + cos(w t0) (sin d - d)
    const double table_part = -2.0 * std::sin(start_angle) * half_advance_sine * half_advance_sine +
                              std::cos(start_angle) * sine_minus_argument(advance);
    return phase.start_displacement + amplitude_ / (frequency_ * frequency_) * table_part -
           0.5 * phase.direction * friction_acceleration_ * elapsed * elapsed;
  }

  // The first slip after sticking from `after`: its start and direction.
  SlipPhase next_slip_start(double after, double displacement) const {
    const double threshold_angle = std::asin(friction_acceleration_ / std::abs(amplitude_));
    const double rising = next_time_at_angle(threshold_angle, after);                 // a_g/A rises through +mu g/|A|
    const double falling = next_time_at_angle(std::numbers::pi + threshold_angle, after);
    const double start = std::min(rising, falling);
    return {start, displacement, table_acceleration(start) > 0.0 ? -1 : +1};  // against a_g
  }

  // End of a slip phase (u' back to 0), or nothing if the phase lasts past `limit`.
  std::optional<double> slip_end(const SlipPhase& phase, double limit) const {
    const int s = phase.direction;
    auto opening = [&](double t) { return s * velocity(phase, t); };
    const double critical_angle = std::asin(-s * friction_acceleration_ / amplitude_);
    double previous = phase.start;
    double previous_opening = 0.0;
    bool opened = false;  // a phase from sticking starts at a minimum of s u' (= 0) at a critical point
    for (;;) {
      if (previous > limit) return std::nullopt;
      const double critical = std::min(next_time_at_angle(critical_angle, previous),
                                       next_time_at_angle(std::numbers::pi - critical_angle, previous));
      const double opening_here = opening(critical);
      if (opening_here <= 0.0 && opened) {
        const double end = locate_time(opening, previous, critical, previous_opening, opening_here, kPhaseEndWidth);
        if (end > limit) return std::nullopt;
        return end;
      }
      opened = opened || opening_here > 0.0;
      previous = critical;
      previous_opening = opening_here;
    }
  }

 private:
  // The first t > after with w t = angle (mod 2 pi).
  double next_time_at_angle(double angle, double after) const {
    const double turn = 2.0 * std::numbers::pi;
    double t = (angle + turn * std::ceil((frequency_ * after - angle) / turn)) / frequency_;
    while (t <= after) t += turn / frequency_;
    return t;
  }

  double friction_acceleration_;  // mu g
  double amplitude_;              // A
  double frequency_;              // w
};

class SlidingRun {
 public:
  SlidingRun(const HarmonicSliding& model, double duration, double output_interval)
      : model_(model), duration_(duration), output_interval_(output_interval) {}

  SlidingResponse run() {
    double t = 0.0;
    double u = 0.0;
    while (model_.ever_slips()) {
      SlipPhase phase = model_.next_slip_start(t, u);
      if (phase.start >= duration_) break;
      record_sticking_until(phase.start, u);
      for (;;) {  // slip phases linked by reversals
        ++response_.slip_phases;
        response_.slip_start_times.push_back(phase.start);
        const std::optional<double> end = model_.slip_end(phase, duration_);
        const double end_time = end.value_or(duration_);
        record_slip_until(phase, end_time);
        t = end_time;
        u = model_.displacement(phase, end_time);
        note_displacement(u);
        if (!end) return finish(u);
        const double table_acceleration = model_.table_acceleration(end_time);
        if (std::abs(table_acceleration) <= model_.friction_acceleration()) break;  // sticks
        phase = {end_time, u, table_acceleration > 0.0 ? -1 : +1};                 // reverses
      }
    }
    record_sticking_until(duration_, u);
    return finish(u);
  }

 private:
  SlidingResponse finish(double final_displacement) {
    response_.final_displacement = final_displacement;
    note_displacement(final_displacement);
    return response_;
  }

  void note_displacement(double u) {
    response_.max_abs_displacement = std::max(response_.max_abs_displacement, std::abs(u));
  }

  template <class Sample>
  void record_until(double t, Sample sample) {
    if (output_interval_ <= 0.0) return;
    for (;;) {
      const double sample_time = static_cast<double>(next_sample_) * output_interval_;
      if (sample_time > t || sample_time > duration_) return;
      const auto [displacement, velocity] = sample(sample_time);
      response_.time.push_back(sample_time);
      response_.displacement.push_back(displacement);
      response_.velocity.push_back(velocity);
      ++next_sample_;
    }
  }

  void record_sticking_until(double t, double u) {
    record_until(t, [u](double) { return std::pair{u, 0.0}; });
  }

  void record_slip_until(const SlipPhase& phase, double t) {
    record_until(t, [&](double s) { return std::pair{model_.displacement(phase, s), model_.velocity(phase, s)}; });
  }

  const HarmonicSliding& model_;
  const double duration_;
  const double output_interval_;
  long next_sample_ = 0;
  SlidingResponse response_;
};

}  // namespace

SlidingResponse sliding_under_harmonic(double friction, double gravity, double amplitude, double circular_frequency,
                                       double duration, double output_interval) {
  const HarmonicSliding model(friction, gravity, amplitude, circular_frequency);
  return SlidingRun(model, duration, output_interval).run();
}

}  // namespace caskdem::theory
