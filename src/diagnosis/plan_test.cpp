#include "diagnosis/plan_test.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <numbers>
#include <sstream>

#include <Eigen/Dense>

#include "core/units.h"
#include "diagnosis/test_simulation.h"
#include "ensemble/sampling.h"
#include "motion/record.h"
#include "motion/table_motion.h"

namespace caskdem::diagnosis {

namespace {

// As the diagnosis judges a test (diagnose.cpp): simulations of the test's predictability, and
// draws of a fit's parameters whose spread widens its prediction's tolerances.
constexpr int kPredictabilityRealisations = 8;
constexpr int kFitSpreadDraws = 16;

// The sines tried: frequencies evenly spaced on a log scale over the table's range, at these
// fractions of the largest amplitude the table can reach there; each holds for kHoldSeconds
// between one-cycle ramps, then the table rests for kFreeSeconds (the rocking decays).
constexpr int kFrequencies = 8;
constexpr double kAmplitudeFractions[] = {0.3, 0.5, 0.7, 0.85, 1.0};
constexpr double kHoldSeconds = 5.0, kFreeSeconds = 3.0;
// The measured records, scaled by these where the table can reach it.
constexpr double kRecordScales[] = {0.5, 0.75, 1.25, 1.5, 2.0};
// Where specimen.toml states no limits: this frequency range, and the largest peak the tests reached.
constexpr double kDefaultMinFrequency = 0.5, kDefaultMaxFrequency = 10.0;
// The noise streams of the plan (Philox counter's last word).
constexpr std::uint32_t kTableNoiseStream = 0x91a7, kSensorNoiseStream = 0x5e45;

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct SetNoise {
  double table = 0.0, rotation = 0.0, slide = 0.0;  // the channels' noise levels, medians over the tests
  double time_step = 0.0;                           // s
};

SetNoise noise_of(const MeasuredSet& set) {
  std::vector<double> table, rotation, slide, step;
  for (const MeasuredTest& t : set.tests) {
    table.push_back(noise_level(t.table_acceleration));
    rotation.push_back(noise_level(t.rotation, &t.rotation_valid));
    slide.push_back(noise_level(t.slide, &t.slide_valid));
    step.push_back(t.time_step);
  }
  return {median(table), median(rotation), median(slide), median(step)};
}

// A displacement integrated twice from a noisy channel drifts; the table's own is its
// departure from the least-squares quadratic through it (the usual baseline correction of a
// record's displacement; Boore 2001).
std::vector<double> detrended(const std::vector<double>& d, double dt) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < d.size(); ++k) {
    const Eigen::Vector3d basis(1.0, double(k) * dt, double(k) * dt * double(k) * dt);
    normal += basis * basis.transpose();
    right += basis * d[k];
  }
  const Eigen::Vector3d c = normal.ldlt().solve(right);
  std::vector<double> out(d.size());
  for (std::size_t k = 0; k < d.size(); ++k) {
    const double t = double(k) * dt;
    out[k] = d[k] - (c[0] + c[1] * t + c[2] * t * t);
  }
  return out;
}

TableLimits limits_of(const MeasuredSet& set, std::string& source) {
  if (set.settings.table) {
    source = "specimen.toml [table]";
    return *set.settings.table;
  }
  // What the table demonstrably did: the largest acceleration, velocity and displacement of
  // the tests' table records (velocity and displacement integrated, motion/record.h).
  TableLimits limits;
  for (const MeasuredTest& t : set.tests) {
    motion::Record record;
    record.time_step = t.time_step;
    for (double a : t.table_acceleration) record.acceleration.push_back(std::isfinite(a) ? a : 0.0);
    if (record.acceleration.size() < 2) continue;
    const motion::GroundMotion ground = motion::integrate_record(record);
    for (double a : record.acceleration) limits.peak_acceleration = std::max(limits.peak_acceleration, std::abs(a));
    for (double v : ground.velocity) limits.peak_velocity = std::max(limits.peak_velocity, std::abs(v));
    for (double d : detrended(ground.displacement, t.time_step)) limits.stroke = std::max(limits.stroke, std::abs(d));
  }
  limits.min_frequency = kDefaultMinFrequency;
  limits.max_frequency = kDefaultMaxFrequency;
  std::ostringstream s;
  s.precision(3);
  s << "not stated (no [table] in specimen.toml): the largest the tests' table records reached, peak acceleration "
    << limits.peak_acceleration << " m/s^2, velocity " << limits.peak_velocity << " m/s, displacement "
    << 1e3 * limits.stroke << " mm; frequencies " << kDefaultMinFrequency << " to " << kDefaultMaxFrequency
    << " Hz. State the table's own limits in a [table] table of specimen.toml";
  source = s.str();
  return limits;
}

// A test's input: `acceleration` sampled at the set's step, plus fresh noise at the set's table
// channel level (the table reproduces a command only to its noise); the response channels
// empty until a candidate fills them.
MeasuredTest input_of(const std::string& name, const std::vector<double>& acceleration, const SetNoise& noise,
                      bool vertical, std::uint64_t seed, std::uint32_t index) {
  MeasuredTest t;
  t.name = name;
  t.time_step = noise.time_step;
  for (std::size_t k = 0; k < acceleration.size(); ++k) {
    t.time.push_back(double(k) * noise.time_step);
    t.table_acceleration.push_back(acceleration[k] + noise.table * philox_normal(seed, {static_cast<std::uint32_t>(k),
                                                                                        index, 0, kTableNoiseStream}));
  }
  if (vertical) {  // the table does not move vertically in a planned test: the channel reads zero
    t.has_vertical = true;
    t.vertical_table_acceleration.assign(acceleration.size(), 0.0);
  }
  t.rotation.assign(acceleration.size(), 0.0);
  t.slide.assign(acceleration.size(), 0.0);
  t.rotation_valid.assign(acceleration.size(), 1);
  t.slide_valid.assign(acceleration.size(), 1);
  return t;
}

// The feasible tests (kind, description, input), without predictions.
std::vector<ProposedTest> feasible_tests(const MeasuredSet& set, const TableLimits& limits, const SetNoise& noise) {
  std::vector<ProposedTest> tests;
  const double dt = noise.time_step;
  std::uint32_t index = 0;
  for (int i = 0; i < kFrequencies; ++i) {
    const double f = limits.min_frequency *
                     std::pow(limits.max_frequency / limits.min_frequency, double(i) / double(kFrequencies - 1));
    const double omega = 2.0 * std::numbers::pi * f;
    // The largest amplitude the table reaches at f: acceleration, velocity or stroke limits it.
    const double largest =
        std::min({limits.peak_acceleration, limits.peak_velocity * omega, limits.stroke * omega * omega});
    const double cycles = std::max(3.0, std::round(f * kHoldSeconds)) + 2.0;
    for (double fraction : kAmplitudeFractions) {
      const double target = fraction * largest;
      auto motion = motion::make_sine(target / (omega * omega), f, cycles, 1.0);
      // The envelope's derivatives add a little to the peak: scaled back within the limits.
      double displacement = 0.0;
      for (double time = 0.0; time <= motion->duration(); time += dt) {
        displacement = std::max(displacement, std::abs(motion->displacement(time)));
      }
      const double over =
          std::max({motion::peak_acceleration(*motion, dt) / limits.peak_acceleration,
                    motion::peak_velocity(*motion, dt) / limits.peak_velocity, displacement / limits.stroke, 1.0});
      motion = motion::make_sine(target / (omega * omega) / over, f, cycles, 1.0);
      const int steps = static_cast<int>(std::ceil((motion->duration() + kFreeSeconds) / dt)) + 1;
      std::vector<double> a(steps);
      motion::sample_acceleration(*motion, dt, 0, steps, a.data());
      ProposedTest p;
      p.kind = "sine";
      p.frequency = f;
      p.drive = a;
      p.peak_acceleration = motion::peak_acceleration(*motion, dt);
      p.peak_velocity = motion::peak_velocity(*motion, dt);
      for (int k = 0; k < steps; ++k) {
        p.peak_displacement = std::max(p.peak_displacement, std::abs(motion->displacement(k * dt)));
      }
      std::ostringstream d;
      d.precision(3);
      d << "sine " << f << " Hz, peak " << p.peak_acceleration << " m/s^2 ("
        << p.peak_acceleration / units::standard_gravity << " g), " << p.peak_velocity << " m/s, "
        << 1e3 * p.peak_displacement << " mm; " << cycles << " cycles with one-cycle ramps";
      p.description = d.str();
      p.input =
          input_of("plan-sine-" + std::to_string(index), a, noise, set.vertical_measured, set.settings.seed, index);
      ++index;
      tests.push_back(std::move(p));
    }
  }
  for (const MeasuredTest& t : set.tests) {
    double peak = 0.0;
    for (double a : t.table_acceleration) peak = std::max(peak, std::isfinite(a) ? std::abs(a) : 0.0);
    if (!(peak > 0.0)) continue;
    for (double scale : kRecordScales) {
      if (scale * peak > limits.peak_acceleration) continue;
      std::vector<double> a;
      // The measured record, resampled to the plan's step by its nearest sample, then a rest.
      const double length = t.duration();
      for (double time = 0.0; time <= length + kFreeSeconds; time += dt) {
        const std::size_t k =
            std::min(t.table_acceleration.size() - 1, static_cast<std::size_t>(std::lround(time / t.time_step)));
        const double value = time <= length && std::isfinite(t.table_acceleration[k]) ? t.table_acceleration[k] : 0.0;
        a.push_back(scale * value);
      }
      ProposedTest p;
      p.kind = "record";
      p.scale = scale;
      p.drive = a;
      p.peak_acceleration = scale * peak;
      std::ostringstream d;
      d.precision(3);
      d << t.name << "'s table record scaled by " << scale << ", peak " << p.peak_acceleration << " m/s^2 ("
        << p.peak_acceleration / units::standard_gravity << " g)";
      p.description = d.str();
      p.input =
          input_of("plan-record-" + std::to_string(index), a, noise, set.vertical_measured, set.settings.seed, index);
      ++index;
      tests.push_back(std::move(p));
    }
  }
  return tests;
}

}  // namespace

std::vector<PlanCandidate> leading_candidates(const Diagnosis& d, int count) {
  std::vector<PlanCandidate> out;
  out.push_back({"baseline", {}, d.baseline.fit.best, d.baseline.heldout_standard_error});
  const auto add = [&](const CandidateScore& c) {
    for (const PlanCandidate& p : out) {
      if (p.name == mechanism_name(c.mechanism)) return;
    }
    out.push_back({mechanism_name(c.mechanism), c.model.mechanisms, c.model.fit.best, c.model.heldout_standard_error});
  };
  for (const CandidateScore& c : d.ranking) {
    if (mechanism_name(c.mechanism) == d.cause) add(c);
  }
  std::vector<const CandidateScore*> supported;
  for (const CandidateScore& c : d.ranking) {
    if (!c.at_off_value && c.profile && c.profile->likelihood_ratio >= kProfileBound) supported.push_back(&c);
  }
  std::stable_sort(supported.begin(), supported.end(), [](const CandidateScore* a, const CandidateScore* b) {
    return a->profile->likelihood_ratio > b->profile->likelihood_ratio;
  });
  for (const CandidateScore* c : supported) {
    if (static_cast<int>(out.size()) >= count) break;
    add(*c);
  }
  return out;
}

TestPlan plan_tests(const MeasuredSet& set, const Case& specimen, const std::vector<PlanCandidate>& candidates,
                    const DiagnosisOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  TestPlan plan;
  plan.candidates = candidates;
  for (const PlanCandidate& c : candidates) {
    plan.parameters.push_back(ModelVariant(specimen, c.mechanisms, set.vertical_measured).parameters());
  }
  plan.limits = limits_of(set, plan.limits_source);
  const SetNoise noise = noise_of(set);
  plan.tests = feasible_tests(set, plan.limits, noise);
  if (candidates.size() < 2) {  // nothing to tell apart
    plan.tests.clear();
    plan.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return plan;
  }
  const std::size_t n = candidates.size(), tests = plan.tests.size();
  std::vector<MeasuredTest> inputs;
  for (const ProposedTest& p : plan.tests) inputs.push_back(p.input);
  std::vector<int> all(tests);
  for (std::size_t t = 0; t < tests; ++t) all[t] = static_cast<int>(t);

  // Each candidate's prediction of every test, and the tolerances a measurement of it would have.
  std::vector<std::vector<SimulatedHistory>> predicted(n);  // [candidate][test]
  std::vector<std::vector<MeasuredTest>> measured(n);       // its response as a measurement, with sensor noise
  std::vector<std::vector<TestReference>> references(n);
  for (std::size_t c = 0; c < n; ++c) {
    if (options.log) options.log("predicting " + std::to_string(tests) + " feasible tests with " + candidates[c].name);
    const ModelVariant variant(specimen, candidates[c].mechanisms, set.vertical_measured);
    predicted[c].resize(tests);
    measured[c].resize(tests);
    references[c].resize(tests);
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::size_t t = 0; t < tests; ++t) {
      try {
        SimulatedHistory h = simulate_test(variant, inputs[t], {candidates[c].point}, options.isa)[0];
        h = delayed(h, inputs[t].time, variant.sensor_delay(candidates[c].point));
        // The tolerances a measurement of a's response would have (its channels carrying the
        // set's sensor noise); the differences those of the predictions themselves, noise-free,
        // so that identical predictions cost nothing.
        MeasuredTest m = inputs[t];
        m.rotation = h.rotation;
        m.slide = h.slide;
        MeasuredTest noisy = m;
        for (std::size_t k = 0; k < m.time.size(); ++k) {
          const auto words = [&](std::uint32_t channel) {
            return std::array<std::uint32_t, 4>{static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(t),
                                                static_cast<std::uint32_t>(c) * 2 + channel, kSensorNoiseStream};
          };
          noisy.rotation[k] += noise.rotation * philox_normal(set.settings.seed, words(0));
          noisy.slide[k] += noise.slide * philox_normal(set.settings.seed, words(1));
        }
        TestReference r = reference_of(noisy, variant.model().stability_angle);
        r.measured = features_of(m.time, m.rotation, m.slide, nullptr, nullptr, r.rocking_threshold);
        references[c][t] = r;
        measured[c][t] = std::move(m);
        predicted[c][t] = std::move(h);
      } catch (...) {
#pragma omp critical
        failure = std::current_exception();
      }
    }
    if (failure) std::rethrow_exception(failure);
    add_predictability(references[c], measured[c], variant, candidates[c].point, kPredictabilityRealisations,
                       set.settings.seed, options.threads);
    add_fit_spread(references[c], measured[c], all, variant, candidates[c].point, candidates[c].standard_error,
                   kFitSpreadDraws, set.settings.seed, options.threads);
  }
  for (std::size_t t = 0; t < tests; ++t) {
    ProposedTest& p = plan.tests[t];
    p.pair_loss.assign(n, std::vector<double>(n, 0.0));
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b) {
        if (a != b) p.pair_loss[a][b] = robust_loss(residuals(measured[a][t], references[a][t], predicted[b][t]));
      }
    }
    p.separation = n > 1 ? std::numeric_limits<double>::infinity() : 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = a + 1; b < n; ++b) {
        const double s = std::min(p.pair_loss[a][b], p.pair_loss[b][a]);
        if (s < p.separation) {
          p.separation = s;
          p.closest_pair = candidates[a].name + " / " + candidates[b].name;
        }
      }
    }
    for (std::size_t c = 0; c < n; ++c) p.predicted.push_back(predicted[c][t]);
  }
  std::stable_sort(plan.tests.begin(), plan.tests.end(),
                   [](const ProposedTest& a, const ProposedTest& b) { return a.separation > b.separation; });
  plan.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace caskdem::diagnosis
