// Event-driven simulation of a rigid block rocking on a shaking table (simulate_rocking), and
// the overturning threshold of a pulse by bisection on it.
//
// Between impacts the block turns about one base corner, pivot side s (+1: theta > 0):
//   theta'' = p^2 [-sin(s alpha - theta) + (a_g / g) cos(s alpha - theta)]
// (Housner 1963; Yim, Chopra & Penzien 1980; caskdem's sign convention, see rocking.h).
// s is held fixed over a segment, so the right side is smooth and the dense output runs on
// through theta = 0, where the impact is then found by root finding. Events:
//   impact    s theta falls to 0            -> theta' = e theta', s = -s (Housner's impact);
//   tip-over  s theta reaches the tip angle -> the run stops;
//   peak      s theta' falls to 0           -> recorded (local maximum of |theta|);
//   uplift    at rest, |a_g| first exceeds g tan alpha -> rocking on s = sgn(a_g), the side
//             a_g drives up (at theta = 0 the bracket above is cos(alpha) (s a_g/g - tan alpha));
//   rest      an impact leaves |theta'| < 1e-8 p; with e < 1 impacts accumulate geometrically
//             (Zeno), so some cut-off is needed; the excursion it drops would reach
//             theta'^2 / (2 p^2 sin alpha) = 5e-17 / sin(alpha) rad.
// Integration: Dormand-Prince 5(4) with its dense output (Boost.Odeint), 1e-12 relative error
// per step (absolute floor 1e-15). Events are looked for at 8 points of the dense output per step
// (steps are capped by max_step) and located with TOMS 748 (Boost.Math) to 1e-13 s.

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "theory/rocking.h"
#include "theory/root_tolerance.h"

namespace caskdem::theory {
namespace {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 2>;  // theta (rad), theta' (rad/s)

// Error per step: relative 1e-12, with an absolute floor far below it so that small excursions
// keep their relative accuracy too (an absolute 1e-12 rad would allow 1e-5 relative error in an
// excursion of 1e-7 rad, which appears as 3e-9 s in its impact time).
constexpr double kRelativeTolerance = 1e-12;
constexpr double kAbsoluteTolerance = 1e-15;  // rad, rad/s
constexpr double kEventTimeWidth = 1e-13;       // s: final bracket of an event time
constexpr int kEventSamplesPerStep = 8;
constexpr double kDefaultMaxStep = 1e-3;        // s
constexpr double kRestRateOverP = 1e-8;         // |theta'| / p after an impact below which the block rests

// theta'' on a fixed pivot side.
class PivotEquation {
 public:
  PivotEquation(const RigidBlock& block, const std::function<double(double)>& table_acceleration, int side)
      : pivot_angle_(side * block.slenderness()),
        p_squared_(block.gravity * block.size() / block.inertia_about_pivot_per_mass),
        gravity_(block.gravity),
        table_acceleration_(&table_acceleration) {}

  void operator()(const State& x, State& dxdt, double t) const {
    const double lever = pivot_angle_ - x[0];
    dxdt[0] = x[1];
    dxdt[1] = p_squared_ * (-std::sin(lever) + (*table_acceleration_)(t) / gravity_ * std::cos(lever));
  }

 private:
  double pivot_angle_;
  double p_squared_;
  double gravity_;
  const std::function<double(double)>* table_acceleration_;
};

double locate(auto f, double a, double b, double f_a, double f_b) {
  return locate_time(f, a, b, f_a, f_b, kEventTimeWidth);
}

class RockingRun {
 public:
  RockingRun(const RigidBlock& block, const std::function<double(double)>& table_acceleration,
             const RockingOptions& options)
      : block_(block),
        table_acceleration_(table_acceleration),
        options_(options),
        alpha_(block.slenderness()),
        p_(block.frequency_parameter()),
        restitution_(options.restitution < 0.0 ? housner_restitution(block) : options.restitution),
        uplift_acceleration_(block.gravity * std::tan(block.slenderness())),
        max_step_(options.max_step > 0.0 ? options.max_step : kDefaultMaxStep) {}

  RockingResponse run() {
    state_ = {options_.initial_rotation, options_.initial_rate};
    side_ = sign(state_[0] != 0.0 ? state_[0] : state_[1]);  // 0: at rest on the base
    note_rotation(state_[0]);
    if (std::abs(state_[0]) >= options_.tip_over_angle) {
      response_.tipped_over = true;
      return response_;
    }
    bool running = true;
    while (running && time_ < options_.duration) running = side_ == 0 ? wait_at_rest() : rock();
    if (!response_.tipped_over) record_samples_until(options_.duration, [this](double) { return state_; });
    return response_;
  }

 private:
  static int sign(double value) { return (value > 0.0) - (value < 0.0); }

  void note_rotation(double theta) {
    response_.max_abs_rotation = std::max(response_.max_abs_rotation, std::abs(theta));
  }

  template <class StateAt>
  void record_samples_until(double t, StateAt state_at) {
    if (options_.output_interval <= 0.0) return;
    for (;;) {
      const double sample_time = static_cast<double>(next_sample_) * options_.output_interval;
      if (sample_time > t || sample_time > options_.duration) return;
      const State x = state_at(sample_time);
      response_.time.push_back(sample_time);
      response_.rotation.push_back(x[0]);
      response_.rate.push_back(x[1]);
      ++next_sample_;
    }
  }

  // At rest on the base: scan a_g at max_step for |a_g| > g tan(alpha), then locate the crossing.
  bool wait_at_rest() {
    const State rest{0.0, 0.0};
    auto at_rest = [&rest](double) { return rest; };
    auto excess = [this](double t) { return std::abs(table_acceleration_(t)) - uplift_acceleration_; };
    double uplift_time = std::numeric_limits<double>::quiet_NaN();
    double a = time_;
    double excess_a = excess(a);
    if (excess_a > 0.0) uplift_time = a;
    while (std::isnan(uplift_time) && a < options_.duration) {
      const double b = std::min(a + max_step_, options_.duration);
      const double excess_b = excess(b);
      if (excess_b > 0.0) uplift_time = locate(excess, a, b, excess_a, excess_b);
      a = b;
      excess_a = excess_b;
    }
    if (std::isnan(uplift_time)) {
      record_samples_until(options_.duration, at_rest);
      time_ = options_.duration;
      return false;
    }
    record_samples_until(uplift_time, at_rest);
    time_ = uplift_time;
    side_ = sign(table_acceleration_(uplift_time));
    state_ = rest;
    response_.uplift_times.push_back(uplift_time);
    return true;
  }

  // A first step well inside the coming excursion, so that the event samples see it.
  double first_step() const {
    if (state_[1] == 0.0) return std::min(max_step_, 1e-3 / p_);
    const double angular_acceleration_bound =
        p_ * p_ * (std::sin(alpha_) + std::abs(table_acceleration_(time_)) / block_.gravity);
    return std::min(max_step_, 0.1 * std::abs(state_[1]) / angular_acceleration_bound);
  }

  enum class SegmentEnd { kNone, kImpact, kTipOver, kNoLift };

  // Integrates on pivot side_ until an impact, a tip-over or the end of the run.
  bool rock() {
    const int side = side_;
    const PivotEquation equation(block_, table_acceleration_, side);
    auto stepper = odeint::make_dense_output(kAbsoluteTolerance, kRelativeTolerance, max_step_,
                                             odeint::runge_kutta_dopri5<State>());
    stepper.initialize(state_, time_, first_step());
    auto state_at = [&stepper](double t) {
      State x;
      stepper.calc_state(t, x);
      return x;
    };
    auto lift = [&](double t) { return side * state_at(t)[0]; };      // s theta
    auto opening = [&](double t) { return side * state_at(t)[1]; };   // s theta'
    const double tip = options_.tip_over_angle;

    double previous_time = time_;
    State previous = state_;
    for (;;) {
      const double step_start = stepper.current_time();
      stepper.do_step(equation);
      const double step_end = std::min(stepper.current_time(), options_.duration);
      for (int sample = 1; sample <= kEventSamplesPerStep; ++sample) {
        const double t = sample == kEventSamplesPerStep
                             ? step_end
                             : step_start + (step_end - step_start) * sample / kEventSamplesPerStep;
        const State x = state_at(t);
        const double lift_a = side * previous[0], lift_b = side * x[0];
        SegmentEnd end = SegmentEnd::kNone;
        double end_time = std::numeric_limits<double>::infinity();

        if (lift_b <= 0.0) {
          end = SegmentEnd::kImpact;
          if (lift_a > 0.0) {
            end_time = locate(lift, previous_time, t, lift_a, lift_b);
          } else {
            // Only at the segment's start (theta = 0): the excursion is shorter than this
            // interval. Halve towards the start until the block is seen lifted.
            end = SegmentEnd::kNoLift;
            end_time = t;
            double inner_end = t, inner_lift = lift_b;
            for (int halving = 1; halving <= 60; ++halving) {
              const double inner = previous_time + (t - previous_time) * std::ldexp(1.0, -halving);
              const double inner_lift_here = lift(inner);
              if (inner_lift_here > 0.0) {
                end = SegmentEnd::kImpact;
                end_time = locate(lift, inner, inner_end, inner_lift_here, inner_lift);
                break;
              }
              inner_end = inner;
              inner_lift = inner_lift_here;
            }
          }
        }
        if (lift_a < tip && lift_b >= tip) {
          const double tip_time =
              locate([&](double s) { return lift(s) - tip; }, previous_time, t, lift_a - tip, lift_b - tip);
          if (tip_time < end_time) {
            end = SegmentEnd::kTipOver;
            end_time = tip_time;
          }
        }
        const double opening_a = side * previous[1], opening_b = side * x[1];
        if (opening_a > 0.0 && opening_b <= 0.0) {
          const double peak_time = locate(opening, previous_time, t, opening_a, opening_b);
          if (peak_time <= end_time) {
            const double peak = std::abs(state_at(peak_time)[0]);
            response_.peak_times.push_back(peak_time);
            response_.peak_rotations.push_back(peak);
            note_rotation(peak);
          }
        }

        if (end != SegmentEnd::kNone) {
          record_samples_until(end_time, state_at);
          return finish_segment(end, end_time, state_at(end_time));
        }
        record_samples_until(t, state_at);
        previous_time = t;
        previous = x;
      }
      if (step_end >= options_.duration) {
        time_ = options_.duration;
        state_ = previous;
        note_rotation(state_[0]);
        return false;
      }
    }
  }

  bool finish_segment(SegmentEnd end, double end_time, const State& x) {
    time_ = end_time;
    switch (end) {
      case SegmentEnd::kTipOver:
        response_.tipped_over = true;
        response_.tip_over_time = end_time;
        note_rotation(options_.tip_over_angle);
        return false;
      case SegmentEnd::kNoLift:  // the block never rose measurably: it stayed on its base
        side_ = 0;
        state_ = {0.0, 0.0};
        return true;
      case SegmentEnd::kImpact: {
        ++response_.impacts;
        response_.impact_times.push_back(end_time);
        response_.impact_rates_before.push_back(std::abs(x[1]));
        const double rate_after = restitution_ * x[1];  // same direction: the block rolls on to the other corner
        if (std::abs(rate_after) < kRestRateOverP * p_) {
          side_ = 0;
          state_ = {0.0, 0.0};
        } else {
          side_ = -side_;
          state_ = {0.0, rate_after};
        }
        return true;
      }
      case SegmentEnd::kNone:
        break;
    }
    return true;
  }

  const RigidBlock& block_;
  const std::function<double(double)>& table_acceleration_;
  const RockingOptions options_;
  const double alpha_;
  const double p_;
  const double restitution_;
  const double uplift_acceleration_;  // g tan(alpha)
  const double max_step_;

  double time_ = 0.0;
  State state_{0.0, 0.0};
  int side_ = 0;
  long next_sample_ = 0;
  RockingResponse response_;
};

}  // namespace

RockingResponse simulate_rocking(const RigidBlock& block, const std::function<double(double)>& table_acceleration,
                                 const RockingOptions& options) {
  return RockingRun(block, table_acceleration, options).run();
}

double overturning_beta_by_simulation(const RigidBlock& block,
                                      const std::function<double(double beta, double t)>& pulse_acceleration,
                                      double duration, double beta_low, double beta_high, double tolerance) {
  auto overturns = [&](double beta) {
    RockingOptions options;
    options.duration = duration;
    const std::function<double(double)> acceleration = [&pulse_acceleration, beta](double t) {
      return pulse_acceleration(beta, t);
    };
    return simulate_rocking(block, acceleration, options).tipped_over;
  };
  if (overturns(beta_low)) return beta_low;
  if (!overturns(beta_high)) throw std::domain_error("overturning_beta_by_simulation: beta_high does not overturn");
  while (beta_high - beta_low > tolerance) {
    const double middle = 0.5 * (beta_low + beta_high);
    (overturns(middle) ? beta_high : beta_low) = middle;
  }
  return beta_high;
}

}  // namespace caskdem::theory
