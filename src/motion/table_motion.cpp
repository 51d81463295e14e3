// Table motions: sine, pulses, records, still.
//
// Sine. u(t) = A r(t) s(t), s = sin(w t), c = cos(w t), w = 2 pi f, lasting D = cycles / f.
// The envelope rises over the ramp time tau = ramp_cycles / f as
//   r = (1 - cos(p t)) / 2 = sin^2(p t / 2),  p = pi / tau,
//   r' = (p / 2) sin(p t),  r'' = (p^2 / 2) cos(p t),
// holds r = 1, and falls mirror-wise with t replaced by D - t (r' changes sign). Then
//   v = A (r' s + w r c),   a = A (r'' s + 2 w r' c - w^2 r s),
// exactly. r and r' vanish at 0 and D, so the table starts and ends at rest in position and
// velocity. r'' jumps at the ends of the ramps, so a(t) jumps there by A (p^2 / 2) |s| unless
// ramp_cycles is a multiple of 1/2 (then s = 0 there). ramp_cycles = 0: r = 1 throughout,
// u = A sin(w t) from t = 0 (the table starts with velocity A w). Everything is zero for
// t < 0 and t > D.
//
// Pulses, a_p the amplitude, d the duration, w = pi / d (half_sine) or 2 pi / d (one_sine):
//   half_sine    v = (a_p / w) (1 - cos w t),  u = (a_p / w) (t - sin(w t) / w)
//   one_sine     the same formulas with its w
//   rectangular  v = a_p t,  u = a_p t^2 / 2
// for 0 <= t <= d. After the pulse the acceleration is zero and the table moves on at the
// velocity the pulse left, v(d) = 2 a_p / w, 0 and a_p d; the displacement grows linearly.
//
// Record. Linear interpolation between samples for a, v and u (v and u from
// integrate_record); a is zero after the last sample, v and u keep their last values
// (v ends at zero by the baseline correction).

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/text.h"
#include "core/units.h"
#include "motion/response_spectrum.h"
#include "motion/table_motion.h"

namespace caskdem::motion {
namespace {

using std::numbers::pi;

class SineMotion final : public TableMotion {
 public:
  SineMotion(double amplitude, double frequency, double cycles, double ramp_cycles)
      : amplitude_(amplitude),
        frequency_(frequency),
        cycles_(cycles),
        ramp_cycles_(ramp_cycles),
        omega_(units::hz_to_rad_per_s(frequency)),
        duration_(cycles / frequency),
        ramp_(ramp_cycles / frequency) {}

  double acceleration(double t) const override {
    if (!(t >= 0.0 && t <= duration_)) return 0.0;  // also for a NaN t
    const Envelope e = envelope(t);
    const double s = std::sin(omega_ * t);
    const double c = std::cos(omega_ * t);
    return amplitude_ * (e.ddr * s + 2.0 * omega_ * e.dr * c - omega_ * omega_ * e.r * s);
  }
  double velocity(double t) const override {
    if (!(t >= 0.0 && t <= duration_)) return 0.0;  // also for a NaN t
    const Envelope e = envelope(t);
    return amplitude_ * (e.dr * std::sin(omega_ * t) + omega_ * e.r * std::cos(omega_ * t));
  }
  double displacement(double t) const override {
    if (!(t >= 0.0 && t <= duration_)) return 0.0;  // also for a NaN t
    return amplitude_ * envelope(t).r * std::sin(omega_ * t);
  }
  double duration() const override { return duration_; }
  std::string describe() const override {
    return "sine: displacement amplitude " + number_text(units::m_to_cm(amplitude_)) + " cm, " +
           number_text(frequency_) + " Hz, " + number_text(cycles_) + " cycles, ramps of " +
           number_text(ramp_cycles_) + " cycles (hold acceleration amplitude " +
           number_text(std::abs(amplitude_) * omega_ * omega_) + " m/s^2)";
  }

 private:
  struct Envelope {
    double r, dr, ddr;  // r(t), r'(t), r''(t)
  };
  Envelope envelope(double t) const {
    if (ramp_ <= 0.0) return {1.0, 0.0, 0.0};
    const double p = pi / ramp_;
    if (t < ramp_) return {0.5 * (1.0 - std::cos(p * t)), 0.5 * p * std::sin(p * t), 0.5 * p * p * std::cos(p * t)};
    const double s = duration_ - t;  // time left
    if (s < ramp_) return {0.5 * (1.0 - std::cos(p * s)), -0.5 * p * std::sin(p * s), 0.5 * p * p * std::cos(p * s)};
    return {1.0, 0.0, 0.0};
  }

  double amplitude_, frequency_, cycles_, ramp_cycles_;
  double omega_, duration_, ramp_;
};

class PulseMotion final : public TableMotion {
 public:
  PulseMotion(PulseShape shape, double amplitude, double duration)
      : shape_(shape),
        amplitude_(amplitude),
        duration_(duration),
        omega_(shape == PulseShape::half_sine ? pi / duration : 2.0 * pi / duration) {}

  double acceleration(double t) const override {
    if (!(t >= 0.0 && t <= duration_)) return 0.0;  // also for a NaN t
    if (shape_ == PulseShape::rectangular) return amplitude_;
    return amplitude_ * std::sin(omega_ * t);
  }
  double velocity(double t) const override {
    if (!(t >= 0.0)) return 0.0;
    if (t > duration_) return final_velocity();
    if (shape_ == PulseShape::rectangular) return amplitude_ * t;
    return amplitude_ / omega_ * (1.0 - std::cos(omega_ * t));
  }
  double displacement(double t) const override {
    if (!(t >= 0.0)) return 0.0;
    if (t > duration_) return displacement_at_end() + final_velocity() * (t - duration_);
    if (shape_ == PulseShape::rectangular) return 0.5 * amplitude_ * t * t;
    return amplitude_ / omega_ * (t - std::sin(omega_ * t) / omega_);
  }
  double duration() const override { return duration_; }
  std::string describe() const override {
    const char* name = shape_ == PulseShape::half_sine ? "half-sine" : shape_ == PulseShape::one_sine ? "one-sine" : "rectangular";
    return std::string(name) + " pulse: " + number_text(amplitude_) + " m/s^2 (" +
           number_text(units::si_to_g(amplitude_)) + " g) for " + number_text(duration_) + " s";
  }

 private:
  // Closed forms at t = d (sin(w d) = 0 for both sine shapes), so no rounding leaks into
  // the motion after the pulse: a one-sine pulse leaves the table exactly at rest.
  double final_velocity() const {
    switch (shape_) {
      case PulseShape::half_sine: return 2.0 * amplitude_ / omega_;
      case PulseShape::one_sine: return 0.0;
      case PulseShape::rectangular: return amplitude_ * duration_;
    }
    return 0.0;
  }
  double displacement_at_end() const {
    if (shape_ == PulseShape::rectangular) return 0.5 * amplitude_ * duration_ * duration_;
    return amplitude_ * duration_ / omega_;
  }

  PulseShape shape_;
  double amplitude_, duration_, omega_;
};

class RecordMotion final : public TableMotion {
 public:
  explicit RecordMotion(Record record) : record_(std::move(record)), ground_(integrate_record(record_)) {}

  double acceleration(double t) const override {
    if (t > record_.duration()) {
      // Only t = T itself (up to rounding in t / dt) still sees the last sample.
      const Position p = position(t);
      return p.index + 1 == record_.acceleration.size() && p.fraction == 0.0 ? record_.acceleration.back() : 0.0;
    }
    return interpolate(record_.acceleration, t);
  }
  double velocity(double t) const override { return interpolate(ground_.velocity, t); }
  double displacement(double t) const override { return interpolate(ground_.displacement, t); }
  double duration() const override { return record_.duration(); }
  std::string describe() const override {
    return "record " + record_.source + ": " + std::to_string(record_.acceleration.size()) + " samples at " +
           number_text(record_.time_step) + " s (" + number_text(record_.duration()) + " s), PGA " +
           number_text(units::si_to_g(peak_ground_acceleration(record_))) + " g";
  }
  const Record& record() const { return record_; }

 private:
  struct Position {
    std::size_t index;  // sample at or before t
    double fraction;    // of the way to the next sample
  };
  // x = t / dt, snapped to the nearest sample when within rounding of it, so t = n dt
  // (computed as n * dt) reads sample n exactly.
  Position position(double t) const {
    const double x = t / record_.time_step;
    const double nearest = std::round(x);
    const double last = static_cast<double>(record_.acceleration.size() - 1);
    if (std::abs(x - nearest) <= 64.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, nearest))
      return {static_cast<std::size_t>(std::min(nearest, last)), nearest > last ? 1.0 : 0.0};
    if (x >= last) return {static_cast<std::size_t>(last), 1.0};
    const double k = std::floor(x);
    return {static_cast<std::size_t>(k), x - k};
  }
  // Zero before the start, the last value after the end.
  double interpolate(const std::vector<double>& values, double t) const {
    if (!(t >= 0.0)) return 0.0;  // also for a NaN t
    const Position p = position(t);
    if (p.index + 1 >= values.size()) return values.back();
    if (p.fraction == 0.0) return values[p.index];
    return values[p.index] + p.fraction * (values[p.index + 1] - values[p.index]);
  }

  Record record_;
  GroundMotion ground_;
};

class StillMotion final : public TableMotion {
 public:
  double acceleration(double) const override { return 0.0; }
  double velocity(double) const override { return 0.0; }
  double displacement(double) const override { return 0.0; }
  double duration() const override { return 0.0; }
  std::string describe() const override { return "still (no motion)"; }
};

bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

std::optional<PulseShape> parse_pulse_shape(const std::string& text) {
  if (text == "half_sine") return PulseShape::half_sine;
  if (text == "one_sine") return PulseShape::one_sine;
  if (text == "rectangular") return PulseShape::rectangular;
  return std::nullopt;
}

std::unique_ptr<TableMotion> make_sine(double displacement_amplitude, double frequency, double cycles, double ramp_cycles) {
  if (!std::isfinite(displacement_amplitude)) throw std::invalid_argument("make_sine: the amplitude must be finite");
  if (!finite_positive(frequency)) throw std::invalid_argument("make_sine: the frequency must be finite and positive");
  if (!finite_positive(cycles)) throw std::invalid_argument("make_sine: the number of cycles must be finite and positive");
  if (!std::isfinite(ramp_cycles) || ramp_cycles < 0.0 || 2.0 * ramp_cycles > cycles)
    throw std::invalid_argument("make_sine: ramp_cycles must be between 0 and half the number of cycles");
  return std::make_unique<SineMotion>(displacement_amplitude, frequency, cycles, ramp_cycles);
}

std::unique_ptr<TableMotion> make_pulse(PulseShape shape, double acceleration_amplitude, double duration) {
  if (!std::isfinite(acceleration_amplitude)) throw std::invalid_argument("make_pulse: the amplitude must be finite");
  if (!finite_positive(duration)) throw std::invalid_argument("make_pulse: the duration must be finite and positive");
  return std::make_unique<PulseMotion>(shape, acceleration_amplitude, duration);
}

std::unique_ptr<TableMotion> make_record_motion(Record record) {
  if (record.acceleration.empty()) throw std::invalid_argument("make_record_motion: the record has no samples");
  if (!finite_positive(record.time_step))
    throw std::invalid_argument("make_record_motion: the time step must be finite and positive");
  if (!std::all_of(record.acceleration.begin(), record.acceleration.end(), [](double a) { return std::isfinite(a); }))
    throw std::invalid_argument("make_record_motion: the accelerations must be finite");
  return std::make_unique<RecordMotion>(std::move(record));
}

std::unique_ptr<TableMotion> make_still() { return std::make_unique<StillMotion>(); }

void sample_acceleration(const TableMotion& motion, double dt, std::int64_t first_step, int count, double* out) {
  for (int i = 0; i < count; ++i) {
    const std::int64_t n = first_step + i;
    out[i] = motion.acceleration(static_cast<double>(n) * dt);
  }
}

namespace {
// max |f(n dt)| over n = 0 .. ceil(duration / dt), the steps a run of the motion takes.
template <class F>
double sampled_peak(const TableMotion& motion, double dt, F f) {
  if (!finite_positive(dt)) throw std::invalid_argument("peak of a motion: the time step must be finite and positive");
  const auto steps = static_cast<std::int64_t>(std::ceil(motion.duration() / dt));
  double peak = 0.0;
  for (std::int64_t n = 0; n <= steps; ++n) peak = std::max(peak, std::abs(f(static_cast<double>(n) * dt)));
  return peak;
}
}  // namespace

double peak_acceleration(const TableMotion& motion, double dt) {
  if (const auto* r = dynamic_cast<const RecordMotion*>(&motion)) return peak_ground_acceleration(r->record());
  return sampled_peak(motion, dt, [&](double t) { return motion.acceleration(t); });
}

double spectral_acceleration(const TableMotion& motion, double period, double damping_ratio, double dt) {
  if (const auto* r = dynamic_cast<const RecordMotion*>(&motion)) return spectral_acceleration(r->record(), period, damping_ratio);
  // At most kSpectrumSamples samples (32 MB): a long motion at a fine run step is sampled more
  // coarsely, still far finer than any period a spectrum is asked for.
  constexpr std::int64_t kSpectrumSamples = std::int64_t(1) << 22;
  const double step = std::max(dt, motion.duration() / static_cast<double>(kSpectrumSamples - 1));
  Record sampled;
  sampled.source = motion.describe();
  sampled.time_step = step;
  const auto steps = std::min(static_cast<std::int64_t>(std::ceil(motion.duration() / step)), kSpectrumSamples - 1);
  sampled.acceleration.resize(static_cast<std::size_t>(steps + 1));
  sample_acceleration(motion, step, 0, static_cast<int>(steps + 1), sampled.acceleration.data());
  return spectral_acceleration(sampled, period, damping_ratio);
}

double peak_velocity(const TableMotion& motion, double dt) {
  if (const auto* r = dynamic_cast<const RecordMotion*>(&motion)) return peak_ground_velocity(r->record());
  return sampled_peak(motion, dt, [&](double t) { return motion.velocity(t); });
}

}  // namespace caskdem::motion
