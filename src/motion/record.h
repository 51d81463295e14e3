#pragma once
// Recorded accelerograms: reading, intensity measures and scaling.
//
// Formats read (../shared/motions has one of each):
//   PEER NGA-West2 .AT2   4 header lines, the 4th "NPTS=  5372, DT=   .0100 SEC", then
//                         accelerations in g, several per line
//   old PEER .AT2         4 header lines, the 4th "4000    0.01000    NPTS, DT" or
//                         "NPTS=  4000, DT= .01000 SEC"; accelerations in g
//   columns               text or CSV with two columns "t, a" (comma, tab, space or
//                         semicolon separated), or one column "a" with a time step given;
//                         "#" comment lines, free-text header lines before the data, a
//                         UTF-8 byte-order mark and CRLF line ends are all accepted; units
//                         g, gal or m/s^2 must be stated (ReadOptions::unit)
// Every problem is an InputError naming the file and the line and what was expected; a sample
// above kLargestGroundAcceleration in magnitude (below) is one.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace caskdem::motion {

// The largest acceleration magnitude of any recorded or synthetic ground motion, or of a
// shaking table, m/s^2 (about 100 g; strong earthquakes and tables stay within a few g). A
// larger value is in another unit or corrupt: every record reader refuses such a sample (in
// SI, after its unit is applied), scaling refuses to make one, and the case file bounds table
// accelerations by it. Keeping records within it keeps every derived quantity finite.
inline constexpr double kLargestGroundAcceleration = 1000.0;
inline constexpr std::string_view kLargestGroundAccelerationText = "1000 m/s^2 (about 100 g)";

// The coarsest sampling and the longest duration of a record or a measured test. Strong-motion
// records are sampled at 0.005-0.02 s and last minutes; a step above 0.1 s cannot resolve
// rocking at a few Hz and is a header in another unit or a corrupt one (`DT= 1000 SEC`), and
// a record of hours is not one earthquake. Readers refuse both, naming the file and line.
inline constexpr double kLargestRecordTimeStep = 0.1;  // s
inline constexpr double kLongestRecord = 1.0e4;        // s

// A uniformly sampled acceleration record in SI: sample k is at t = k * time_step.
struct Record {
  std::string source;             // where it came from (a path, or a description)
  double time_step = 0.0;         // s
  std::vector<double> acceleration;  // m/s^2

  double duration() const {
    return acceleration.empty() ? 0.0 : time_step * static_cast<double>(acceleration.size() - 1);
  }
};

enum class RecordFormat { automatic, peer_nga_west2, peer_old, columns };
enum class AccelerationUnit { g, gal, si };

struct ReadOptions {
  RecordFormat format = RecordFormat::automatic;
  // Required for column files (they do not say their unit); .AT2 files are in g and
  // a unit given here for them must be g.
  std::optional<AccelerationUnit> unit;
  // Required for single-column files; a two-column file's time column gives it.
  std::optional<double> time_step;
};

// Parses "g", "gal", "m/s^2" (also "m/s2", and "Gal", "cm/s^2", "cm/s2" as gal);
// std::nullopt for anything else.
std::optional<AccelerationUnit> parse_acceleration_unit(const std::string& text);
std::optional<RecordFormat> parse_record_format(const std::string& text);  // automatic, peer_nga_west2, peer_old, columns

// Reads a record. A two-column file must be uniformly sampled (within 1e-6 relative of
// its mean step); an irregular one is an error naming the line where the step changes. Its
// first time is taken as t = 0 of the record. A time step given in the options must agree
// with the one the file states (AT2 DT or time column) within 1e-6 relative.
Record read_record(const std::filesystem::path& file, const ReadOptions& options = {});

// Ground velocity and displacement by trapezoidal integration of the acceleration, with
// the baseline correction that removes the linear trend making the final velocity zero
// (v(t) - t v(T) / T), the usual correction for a record that ends at rest; the
// displacement is the trapezoid integral of the corrected velocity (not itself corrected, so
// it may end offset). Used for PGV and for plotting the table's motion, never for the
// cask's sliding (which is computed in the floor's frame).
struct GroundMotion {
  std::vector<double> velocity;      // m/s
  std::vector<double> displacement;  // m
};
GroundMotion integrate_record(const Record& record);

double peak_ground_acceleration(const Record& record);  // max |a|, m/s^2
double peak_ground_velocity(const Record& record);      // max |v| of integrate_record, m/s

// kLargestGroundAcceleration / PGA: the largest factor (in magnitude) scaled accepts for
// this record; infinity for a record of zeros.
double largest_scale_factor(const Record& record);

// Scaling throws std::invalid_argument for a non-finite factor, a negative or non-finite
// target, a record whose PGA (PGV) is zero or so small that the factor to the target is not
// finite, a PGA target above kLargestGroundAcceleration, and any factor larger in magnitude
// than largest_scale_factor (the scaled PGA would pass the bound). A scaled record is
// therefore always finite.
Record scaled(const Record& record, double factor);
Record scaled_to_pga(const Record& record, double target_pga);
Record scaled_to_pgv(const Record& record, double target_pgv);
// Multiplies the time step by time_factor (the similarity law compresses a prototype
// motion's time by 1/sqrt(N) for an N-times smaller model; accelerations are unchanged).
// Throws std::invalid_argument unless time_factor is finite and positive and the scaled
// time step is positive and finite with a finite duration.
Record time_scaled(const Record& record, double time_factor);

}  // namespace caskdem::motion
