#pragma once
// One measured test (a shaking-table run or a field record) as users bring it: a CSV file
// with a header row,
//   t (s), table_acc (m/s^2), theta (rad), slide (m)            required
//   theta_dot (rad/s), table_acc_v (m/s^2)                     optional
// in any column order, in SI units unless the header declares another after a name, in brackets
// or parentheses: "table_acc [g]", "slide (mm)", "theta [deg]" (docs/measured-data.md lists
// them). A column in SI that looks like another unit (a slide of metres no table holds, a
// rotation beyond a radian, a table too weak for the rocking it caused) is reported. Real data are imperfect, and each imperfection is reported, not
// crashed on: irregular sampling is resampled onto a uniform grid; gaps (NaN or empty
// fields) in a response channel are masked, and short gaps in the table channel (the input)
// are bridged by linear interpolation; samples of a clipped channel (flat at its extreme)
// are masked; a constant channel (a dead sensor) is masked whole. What cannot be used (no
// table channel, time not increasing, a long gap in the input) is an InputError naming the
// file, the line or channel, and what was expected.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace caskdem::diagnosis {

struct MeasuredTest {
  std::string name;             // file stem
  std::filesystem::path file;
  double time_step = 0.0;       // s, uniform after resampling (the median step of the file)
  std::vector<double> time;     // 0, dt, 2 dt, ... (the file's first time is t = 0)
  std::vector<double> table_acceleration;           // m/s^2, gaps bridged
  std::vector<double> rotation;                     // rad (theta)
  std::vector<double> slide;                        // m
  std::vector<double> angular_velocity;             // rad/s, when has_angular_velocity
  std::vector<double> vertical_table_acceleration;  // m/s^2, when has_vertical, gaps bridged
  bool has_angular_velocity = false;
  bool has_vertical = false;
  bool table_unit_declared = false;  // the header named table_acc's unit (else SI was assumed)
  // 1 where the sample may be compared with a simulation; 0 in gaps, clipped or dead channels.
  // Where the mask is 0 the value is NaN in a gap and the value read when clipped or dead.
  // angular_velocity(_valid) and vertical_table_acceleration are empty unless has_angular_velocity
  // / has_vertical: an optional column with no usable sample (missing, constant) is not used.
  std::vector<std::uint8_t> rotation_valid, slide_valid, angular_velocity_valid;
  // One line per imperfection found, each naming the file, the channel, what and where
  // (e.g. "test3.csv: slide: clipped at 0.0500 m for 12 samples from t = 4.210 s; masked").
  std::vector<std::string> issues;

  double duration() const { return time.empty() ? 0.0 : time.back(); }
};

// Whether a channel has a sample that may be compared (a 1 in its mask).
inline bool any_valid(const std::vector<std::uint8_t>& valid) {
  return std::find(valid.begin(), valid.end(), std::uint8_t{1}) != valid.end();
}

// Longest gap (s) in the table acceleration that is bridged by interpolation.
inline constexpr double kLongestBridgedInputGap = 0.05;

// A smaller sampling step is not a shaking-table record (t in other units, or a corrupt column);
// a table drive's step is held to it too.
inline constexpr double kSmallestSamplingStep = 1e-6;  // s

MeasuredTest read_measured_test(const std::filesystem::path& csv);

}  // namespace caskdem::diagnosis
