#pragma once
// Table motions: the prescribed horizontal (or vertical) acceleration of the floor as a
// function of time, from a sinusoid, a pulse or a record.
//
//   sine     displacement u(t) = A r(t) sin(2 pi f t), A the displacement amplitude (the
//            source paper's tests used 0.5, 1.0 and 1.5 cm), r(t) a smooth envelope that
//            rises as sin^2 over ramp_cycles cycles, holds, and falls the same way over the
//            last ramp_cycles cycles; a(t) = u''(t) exactly (envelope derivatives included),
//            so the table starts and ends at rest
//   pulse    half_sine    a = a_p sin(w t) for 0 <= t <= pi/w, w = pi / duration
//            one_sine     a = a_p sin(w t) for 0 <= t <= 2 pi/w, w = 2 pi / duration
//            rectangular  a = a_p for 0 <= t <= duration
//            afterwards a = 0 and the table keeps the velocity the pulse left (2 a_p / w,
//            0, a_p duration), its displacement growing linearly
//   record   linear interpolation between samples; zero after the last sample (velocity
//            and displacement keep their last values)
//
// Positive acceleration is along +x (+y for a vertical motion).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "motion/record.h"

namespace caskdem::motion {

class TableMotion {
 public:
  virtual ~TableMotion() = default;
  virtual double acceleration(double time) const = 0;  // m/s^2
  virtual double velocity(double time) const = 0;      // m/s (for output and PGV)
  virtual double displacement(double time) const = 0;  // m (for output)
  virtual double duration() const = 0;                 // s; zero acceleration afterwards
  virtual std::string describe() const = 0;
};

enum class PulseShape { half_sine, one_sine, rectangular };
std::optional<PulseShape> parse_pulse_shape(const std::string& text);

// The make_ functions throw std::invalid_argument for parameters out of range (non-finite,
// frequency/cycles/duration/time step not positive, 2 ramp_cycles > cycles, empty record).
std::unique_ptr<TableMotion> make_sine(double displacement_amplitude, double frequency, double cycles, double ramp_cycles);
std::unique_ptr<TableMotion> make_pulse(PulseShape shape, double acceleration_amplitude, double duration);
// Velocity and displacement come from integrate_record (baseline-corrected), interpolated.
std::unique_ptr<TableMotion> make_record_motion(Record record);
// A motion that is zero everywhere (no vertical excitation).
std::unique_ptr<TableMotion> make_still();

// Table acceleration at steps first_step .. first_step + count - 1 of a run with time step dt,
// at t = n * dt (n counted from 0, never accumulated). The scalar and ensemble paths both
// sample motions through this function, so they see the same numbers.
void sample_acceleration(const TableMotion& motion, double dt, std::int64_t first_step, int count, double* out);

// Peak |a| and peak |v| of a motion, sampled at t = n dt, n = 0 .. ceil(duration / dt)
// (records: their own samples, and PGV from integrate_record).
double peak_acceleration(const TableMotion& motion, double dt);
double peak_velocity(const TableMotion& motion, double dt);
// Sa(T, zeta) of the motion (motion/response_spectrum.h): a record's own samples, any other
// motion sampled at t = n dt as above (linear between samples, as the runs see it), or more
// coarsely where that would take over 2^22 samples.
double spectral_acceleration(const TableMotion& motion, double period, double damping_ratio, double dt);

}  // namespace caskdem::motion
