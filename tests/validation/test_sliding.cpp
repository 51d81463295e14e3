// Validation 6, sliding: a wide block that cannot rock, under a harmonic table
// acceleration, slides as the exact rigid-plastic two-way sliding solution (Newmark 1965;
// piecewise closed form in src/theory/sliding.cpp) within 2 %; and its slide converges as
// the time step falls (a convergence study on the spring-slider itself, whose answer the
// rigid-plastic solution cannot give to better than the springs' compliance).

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/function_motion.h"
#include "support/paper_cases.h"
#include "theory/sliding.h"

namespace caskdem {
namespace {

Case wide_block() {
  Case c = testing::one_third_model();
  // A 2 m wide, 0.4 m high slab: tan(alpha) = 5, it slides long before it could rock.
  c.model.section = polygon_section({{-1.0, 0.0}, {1.0, 0.0}, {1.0, 0.4}, {-1.0, 0.4}}, 1.0, 6000.0, std::nullopt,
                                    std::nullopt, 0.005);
  c.parameters.mass = c.model.section.mass;
  c.parameters.inertia = c.model.section.inertia;
  c.parameters.centre_of_mass = c.model.section.centre_of_mass;
  return c;
}

TEST(Sliding, WideBlockFollowsRigidPlasticTwoWaySliding) {
  for (const testing::Scheme& scheme : testing::kSchemes) {
    Case c = wide_block();
    scheme.apply(c);
    const std::string name = scheme.name();
    c.model.friction_law = FrictionLaw::constant;
    const double mu = 0.2;
    c.parameters.friction_static = c.parameters.friction_kinetic = mu;
    const testing::Prepared p = testing::prepare(c);

    const double g = p.model.gravity;
    for (double amplitude_g : {0.3, 0.6}) {
      const double amplitude = amplitude_g * g;
      const double omega = 2.0 * std::numbers::pi * 2.0;
      const double duration = 4.0;
      testing::FunctionMotion table([=](double t) { return amplitude * std::sin(omega * t); }, duration);
      const RunResult run = simulate(p.model, p.lane, rest_state(p.model, p.lane), {&table, nullptr}, {duration, 1e-3});
      const double exact_interval = 1e-5;
      const theory::SlidingResponse exact =
          theory::sliding_under_harmonic(mu, g, amplitude, omega, duration, exact_interval);

      const double max_error = run.summary.max_abs_slide / exact.max_abs_displacement - 1.0;
      double worst_history = 0.0;
      for (std::size_t i = 0; i < run.history.time.size(); ++i) {
        // The exact solution, linearly interpolated at the DEM's sample time.
        const double t = run.history.time[i];
        const std::size_t j = std::min(static_cast<std::size_t>(t / exact_interval), exact.time.size() - 2);
        const double w = (t - exact.time[j]) / (exact.time[j + 1] - exact.time[j]);
        const double u = (1.0 - w) * exact.displacement[j] + w * exact.displacement[j + 1];
        worst_history = std::max(worst_history, std::abs(run.history.slide[i] - u));
      }
      const double history_error = worst_history / exact.max_abs_displacement;
      RecordProperty(name + " max_slide_error_" + std::to_string(amplitude_g), std::to_string(max_error));
      RecordProperty(name + " history_error_" + std::to_string(amplitude_g), std::to_string(history_error));
      EXPECT_LT(std::abs(max_error), 0.02) << name << ", " << amplitude_g << " g: DEM " << run.summary.max_abs_slide
                                           << " m, exact " << exact.max_abs_displacement << " m";
      EXPECT_LT(history_error, 0.02) << name << ", " << amplitude_g << " g";
      EXPECT_LT(run.summary.max_abs_rotation, 1e-3);  // it slid, it did not rock
    }
  }
}

// The work-energy balance with friction: a block launched at v0 over a still floor (it cannot
// rock) slides until friction has taken its kinetic energy, m v0^2 / 2 = m g integral mu(v) dx,
// so it stops after D = (1/g) integral_0^v0 v / mu(v) dv: v0^2 / (2 mu g) for a constant law, and
// for the exponential law the integral by Simpson's rule on 20,000 intervals (independent of the
// step). The spring-sliders' stretch at the stop (mu m g / K_s, 4e-8 m here) is far below the
// tolerance. Every scheme, with each law.
TEST(Sliding, AFreeSlideStopsWhereFrictionHasTakenItsKineticEnergy) {
  const double launch = 1.0;  // m/s
  for (FrictionLaw law : {FrictionLaw::constant, FrictionLaw::exponential}) {
    for (const testing::Scheme& scheme : testing::kSchemes) {
      Case c = wide_block();
      scheme.apply(c);
      c.model.friction_law = law;
      c.parameters.friction_static = 0.3;
      c.parameters.friction_kinetic = law == FrictionLaw::constant ? 0.3 : 0.2;
      c.parameters.friction_decay_speed = 0.05;
      const testing::Prepared p = testing::prepare(c);
      const double g = p.model.gravity;
      const auto mu = [&](double v) {
        return c.parameters.friction_kinetic +
               (c.parameters.friction_static - c.parameters.friction_kinetic) * std::exp(-v / c.parameters.friction_decay_speed);
      };
      double distance = 0.0;
      if (law == FrictionLaw::constant) {
        distance = launch * launch / (2.0 * c.parameters.friction_static * g);
      } else {
        const int n = 20000;
        const double h = launch / n;
        for (int k = 0; k <= n; ++k) {
          const double v = k * h, weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
          distance += weight * v / mu(v);
        }
        distance *= h / (3.0 * g);
      }
      BodyState<double> launched = rest_state(p.model, p.lane);
      launched.vx = launch;
      testing::FunctionMotion still([](double) { return 0.0; }, 1.0);
      const RunResult run = simulate(p.model, p.lane, launched, {&still, nullptr}, {1.0, 0.0});
      const double error = run.summary.residual_slide / distance - 1.0;
      const std::string name = std::string(law == FrictionLaw::constant ? "constant, " : "exponential, ") + scheme.name();
      RecordProperty(name + " stop_error", std::to_string(error));
      EXPECT_LT(std::abs(error), 1e-3) << name << ": stopped after " << run.summary.residual_slide << " m, the energy balance gives "
                                       << distance << " m";
      EXPECT_LT(run.summary.max_abs_rotation, 1e-3);  // it slid, it did not rock
    }
  }
}

// The max slide under two sines (0.6 g at 2 Hz and 0.18 g at 5.4 Hz, so stick and slip
// alternate irregularly) at f_s = 0.0025 .. 0.04, halving, with the source paper's half-step slider. A convergence
// study: the change from the finest step must shrink at least in proportion to the step (first order or better), down
// to the contact's chatter (3e-6 of the slide), and be small over the whole range. The observed order is recorded: it
// is first (0.85 to 1.1), the dashpots and the friction coefficient being read at the half step (docs/time-step.md,
// "Where the step's bias comes from").
TEST(Sliding, MaxSlideConvergesAsTheStepFalls) {
  for (FrictionLaw law : {FrictionLaw::constant, FrictionLaw::exponential}) {
    const std::vector<double> safety_factors = {0.0025, 0.005, 0.01, 0.02, 0.04};
    std::vector<double> slide;
    for (double safety_factor : safety_factors) {
      Case c = wide_block();
      c.model.safety_factor = safety_factor;
      c.model.friction_law = law;
      c.parameters.friction_static = law == FrictionLaw::constant ? 0.2 : 0.3;
      c.parameters.friction_kinetic = 0.2;
      c.parameters.friction_decay_speed = 0.05;
      const testing::Prepared p = testing::prepare(c);
      const double amplitude = 0.6 * p.model.gravity, omega = 2.0 * std::numbers::pi * 2.0;
      testing::FunctionMotion table(
          [=](double t) { return amplitude * (std::sin(omega * t) + 0.3 * std::sin(2.7 * omega * t)); }, 4.0);
      slide.push_back(simulate(p.model, p.lane, rest_state(p.model, p.lane), {&table, nullptr}, {4.0, 0.0}).summary.max_abs_slide);
    }
    const std::string name = law == FrictionLaw::constant ? "constant" : "exponential";
    const double coarsest_change = std::abs(slide.back() - slide.front());
    const double chatter = 3e-6 * slide.front();
    for (std::size_t k = 1; k + 1 < slide.size(); ++k) {
      const double share = (safety_factors[k] - safety_factors[0]) / (safety_factors.back() - safety_factors[0]);
      EXPECT_LE(std::abs(slide[k] - slide.front()), 1.3 * share * coarsest_change + chatter)
          << name << ": f_s " << safety_factors[k] << ", slides " << slide.front() << " (finest), " << slide[k] << ", "
          << slide.back() << " (coarsest) m";
    }
    for (std::size_t k = 0; k + 2 < slide.size(); ++k) {
      const double ratio = (slide[k + 2] - slide[k + 1]) / (slide[k + 1] - slide[k]);
      if (ratio > 0.0) RecordProperty(name + "_order_" + std::to_string(k), std::to_string(std::log2(ratio)));
    }
    // And the answer is near its limit: the coarsest step is within 2e-4 of the finest.
    EXPECT_LT(std::abs(slide.back() / slide.front() - 1.0), 2e-4) << name;
  }
}

// The whole-step slider (kernels/slider.h) on the same block and table: second order. The slide
// history is sampled at the coarsest step's times, which every finer step meets exactly (each
// step half the next), and the RMS change between successive steps, f_s = 0.0003125 .. 0.04, is
// fitted against the step on log scales: its slope is the observed order. The histories rather
// than the max slide, because what is left at these steps is 1e-10 to 1e-7 m, where one sample's
// max moves with the contact's chatter. The half-step slider, measured the same way, has order
// 1.00 for both laws (the change halves with the step).
//
// A steeply falling law keeps part of a first-order error: the onset of a slide under velocity
// weakening is an instability (the slip speed grows as exp(lambda t), lambda ~ (mu_s - mu_k) g /
// v0 near rest), so the slide's start is set by the small speeds at its onset, which the step
// resolves only to first order; the velocity error is set there and carried through the slide.
// With mu 0.3 -> 0.2 over v0 = 0.05 m/s (lambda ~ 20 /s) the order is 1.4; over v0 = 0.5 m/s
// (lambda ~ 2 /s) it is second. Both are asserted as measured: the steep law at least 1.25, so
// that a return to the half-step's first order fails.
TEST(Sliding, WholeStepSliderIsSecondOrder) {
  struct Law {
    const char* name;
    FrictionLaw law;
    double friction_static, decay_speed, least_order;
  };
  for (const Law& law : {Law{"constant", FrictionLaw::constant, 0.2, 0.05, 1.8},
                         Law{"exponential, v0 0.5 m/s", FrictionLaw::exponential, 0.3, 0.5, 1.8},
                         Law{"exponential, v0 0.05 m/s", FrictionLaw::exponential, 0.3, 0.05, 1.25}}) {
    std::vector<double> safety_factors;
    for (double f = 0.0003125; f <= 0.04 + 1e-12; f *= 2.0) safety_factors.push_back(f);
    std::vector<std::vector<double>> slides;
    double sample_interval = 0.0;
    for (auto f = safety_factors.rbegin(); f != safety_factors.rend(); ++f) {  // coarsest first: it sets the samples
      Case c = wide_block();
      c.model.safety_factor = *f;
      c.model.whole_step_terms = kWholeStepSlider;
      c.model.friction_law = law.law;
      c.parameters.friction_static = law.friction_static;
      c.parameters.friction_kinetic = 0.2;
      c.parameters.friction_decay_speed = law.decay_speed;
      const testing::Prepared p = testing::prepare(c);
      if (sample_interval == 0.0) sample_interval = p.model.time_step;
      const double amplitude = 0.6 * p.model.gravity, omega = 2.0 * std::numbers::pi * 2.0;
      testing::FunctionMotion table(
          [=](double t) { return amplitude * (std::sin(omega * t) + 0.3 * std::sin(2.7 * omega * t)); }, 4.0);
      const RunResult run =
          simulate(p.model, p.lane, rest_state(p.model, p.lane), {&table, nullptr}, {4.0, sample_interval});
      slides.insert(slides.begin(), run.history.slide);
    }
    // Least squares of log2(change) on log2(f_s).
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    const int n = static_cast<int>(slides.size()) - 1;
    for (int k = 0; k < n; ++k) {
      const std::size_t samples = std::min(slides[k].size(), slides[k + 1].size());
      ASSERT_GT(samples, 1000u);
      double sum = 0.0;
      for (std::size_t i = 0; i < samples; ++i)
        sum += (slides[k + 1][i] - slides[k][i]) * (slides[k + 1][i] - slides[k][i]);
      const double x = std::log2(safety_factors[k + 1]), y = std::log2(std::sqrt(sum / samples));
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
    const double order = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    RecordProperty(std::string(law.name) + " order", std::to_string(order));
    EXPECT_GE(order, law.least_order) << law.name;
  }
}

}  // namespace
}  // namespace caskdem
