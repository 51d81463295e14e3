// Measured tests: a CSV file of one shaking-table run (or field record) into a MeasuredTest.
//
// Format:
//   - A header row naming the columns, then one row per sample. Blank lines and '#' comment
//     lines are skipped anywhere; a UTF-8 byte-order mark and CRLF line ends are accepted.
//   - The separator is ',', ';' or a tab: the one the header row uses most, then the same
//     on every row.
//   - Columns, in any order (names match ignoring case, blanks and surrounding quotes):
//       t (s), table_acc (m/s^2), theta (rad), slide (m)      required
//       theta_dot (rad/s), table_acc_v (m/s^2)                 optional
//     Any other column is ignored (and reported); its fields are not read.
//   - Every row has as many fields as the header. An empty field or "nan" (any case) is a
//     missing value; any other field of a known column must be a finite number.
//   - The time is given on every row and strictly increases.
// What is done with imperfect data, in order (each step reported as one line in `issues`):
//   1. Sampling: steps all within 1e-6 (relative) of the median step are taken as uniform,
//      t = k * median step. Otherwise every channel is resampled onto that grid by linear
//      interpolation; a resampled sample is missing if a sample it is made from is.
//   2. The table channels (table_acc, table_acc_v: the input motion): a constant channel is
//      an error for table_acc (nothing to simulate) and unused for table_acc_v; clipping is
//      reported (the input cannot be masked); gaps up to kLongestBridgedInputGap are bridged
//      (linearly inside, by holding the nearest value at the ends), longer ones are errors.
//   3. The response channels (theta, slide, theta_dot): gaps are masked; a constant channel
//      is masked whole (a dead sensor); samples clipped at the channel's extreme are masked.
// Every error is an InputError "FILE:LINE: what was found; expected what" (LINE left out
// where the problem is the whole file or channel).

#include "diagnosis/measured_test.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>

#include "core/error.h"
#include "core/text.h"
#include "motion/record.h"

namespace caskdem::diagnosis {
namespace {

using std::filesystem::path;

// Fewer rows than this are not a test record (and give no meaningful median step).
constexpr std::size_t kFewestRows = 10;
// Steps within this (relative to the median step) count as uniform sampling, as for records.
constexpr double kStepTolerance = 1e-6;
// A flat run at the channel's extreme this long or longer is a clipped sensor.
constexpr std::size_t kShortestClippedRun = 3;
// A channel whose range is below this times max(1, |value|) is constant.
constexpr double kConstantRange = 1e-12;
// A gap of exactly kLongestBridgedInputGap must not be refused for the rounding in count * dt.
constexpr double kGapRoundoff = 1e-9;

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

// The channels, in the order issues are reported.
enum Channel : std::size_t { kTime, kTable, kVertical, kRotation, kSlide, kAngularVelocity, kChannelCount };

struct ChannelSpec {
  std::string_view name;  // the column name in the file
  std::string_view unit;
  bool required;
  // Larger magnitudes are not a measurement of a cask on a shaking table (a value in other
  // units, or a corrupt field), and would overflow the error measures' squares.
  double largest;
  std::string_view largest_text;  // what `largest` is, for messages
};

constexpr double kInfinity = std::numeric_limits<double>::infinity();

constexpr std::array<ChannelSpec, kChannelCount> kChannels{{
    {"t", "s", true, kInfinity, ""},
    {"table_acc", "m/s^2", true, motion::kLargestGroundAcceleration, motion::kLargestGroundAccelerationText},
    {"table_acc_v", "m/s^2", false, motion::kLargestGroundAcceleration, motion::kLargestGroundAccelerationText},
    {"theta", "rad", true, 2.0 * 3.141592653589793, "2 pi rad (a whole turn)"},
    {"slide", "m", true, 100.0, "100 m"},
    {"theta_dot", "rad/s", false, 1e3, "1000 rad/s"},
}};

// Undeclared SI columns beyond these are reported as likely in other units (a slide in mm, a
// rotation in degrees); they are read as they are.
constexpr double kLargestPlausibleSlide = 1.0;     // m
constexpr double kLargestPlausibleRotation = 1.0;  // rad


using Series = std::vector<double>;  // NaN where a sample is missing
using Mask = std::vector<std::uint8_t>;

// ---- text --------------------------------------------------------------------------------

// Built by appending: "'" + std::string(s) trips a false -Wrestrict in GCC 12.
std::string in_quotes(std::string_view s) {
  std::string out(1, '\'');
  out.append(s).push_back('\'');
  return out;
}

std::string with_unit(double x, Channel channel) {
  return number_text(x) + " " + std::string(kChannels[channel].unit);
}

std::string plural(std::size_t n, std::string_view word) {
  return std::to_string(n) + " " + std::string(word) + (n == 1 ? "" : "s");
}

// Where messages go: errors name the file and line, issues the file name and channel.
class Reporter {
 public:
  Reporter(const path& file, std::vector<std::string>& issues)
      : file_(file), name_(file.filename().string()), issues_(issues) {}

  const path& file() const { return file_; }

  void issue(Channel channel, const std::string& what) { issue(kChannels[channel].name, what); }
  void issue(std::string_view column, const std::string& what) {
    issues_.push_back(name_ + ": " + std::string(column) + ": " + what);
  }

  [[noreturn]] void fail(long line, const std::string& what) const { fail_at(file_, line, what); }
  [[noreturn]] void fail(long line, Channel channel, const std::string& what) const {
    fail_at(file_, line, std::string(kChannels[channel].name) + ": " + what);
  }

 private:
  const path& file_;
  std::string name_;
  std::vector<std::string>& issues_;
};

// ---- lines and fields ---------------------------------------------------------------------

std::vector<std::string> read_lines(const Reporter& report) {
  return read_text_lines(report.file(), "a measured-test CSV file");
}

bool is_skipped(std::string_view line) {
  line = trim(line);
  return line.empty() || line.starts_with('#');
}

// The separator the header uses most (',' when it uses none: a single column).
char choose_separator(std::string_view header) {
  char best = ',';
  std::ptrdiff_t best_count = 0;
  for (const char candidate : {',', ';', '\t'}) {
    const auto count = std::count(header.begin(), header.end(), candidate);
    if (count > best_count) {
      best = candidate;
      best_count = count;
    }
  }
  return best;
}

std::string separator_name(char separator) {
  return separator == '\t' ? "tab" : in_quotes(std::string(1, separator));
}

// Every field between separators, trimmed and unquoted. Trailing empty fields are kept: an
// empty field is a missing value, so "1,2,," has four fields.
std::vector<std::string_view> split_fields(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  std::size_t at = 0;
  while (true) {
    const auto end = line.find(separator, at);
    std::string_view field = trim(line.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (field.size() >= 2 && field.front() == '"' && field.back() == '"') field = trim(field.substr(1, field.size() - 2));
    fields.push_back(field);
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  return fields;
}

// ---- header -------------------------------------------------------------------------------

struct Layout {
  long header_line = 0;
  char separator = ',';
  std::size_t field_count = 0;
  std::array<std::optional<std::size_t>, kChannelCount> column;  // field index of each channel
  std::array<double, kChannelCount> to_si{1.0, 1.0, 1.0, 1.0, 1.0, 1.0};  // the declared unit's SI value
  std::array<bool, kChannelCount> declared{};                            // a unit in the header
};

// A header name and the unit it may declare: "table_acc [g]" or "table_acc (g)".
struct NamedColumn {
  std::string_view name, unit;
};
NamedColumn split_unit(std::string_view field) {
  const auto open = field.find_first_of("[(");
  if (open == std::string_view::npos) return {field, {}};
  const auto close = field.find_first_of("])", open);
  std::string_view name = field.substr(0, open), unit = field.substr(open + 1, close == std::string_view::npos
                                                                                    ? std::string_view::npos
                                                                                    : close - open - 1);
  while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  while (!unit.empty() && unit.back() == ' ') unit.remove_suffix(1);
  return {name, unit};
}

std::optional<Channel> channel_named(std::string_view field) {
  const std::string key = lower_case(split_unit(field).name);
  for (std::size_t c = 0; c < kChannelCount; ++c)
    if (kChannels[c].name == key) return static_cast<Channel>(c);
  return std::nullopt;
}

// The units a channel may be declared in, with their SI values.
struct Unit {
  std::string_view name;
  double si;
};
std::vector<Unit> units_of(Channel channel) {
  constexpr double degree = 3.141592653589793 / 180.0;
  switch (channel) {
    case kTime: return {{"s", 1.0}, {"ms", 1e-3}};
    case kTable:
    case kVertical:
      return {{"m/s^2", 1.0}, {"m/s2", 1.0}, {"g", 9.80665}, {"gal", 0.01}, {"cm/s^2", 0.01}, {"cm/s2", 0.01},
              {"mm/s^2", 1e-3}};
    case kRotation: return {{"rad", 1.0}, {"mrad", 1e-3}, {"deg", degree}};
    case kSlide: return {{"m", 1.0}, {"cm", 0.01}, {"mm", 1e-3}};
    case kAngularVelocity: return {{"rad/s", 1.0}, {"deg/s", degree}};
    case kChannelCount: break;
  }
  return {};
}

std::string expected_columns() {
  return "expected a header row naming the columns t, table_acc, theta and slide (theta_dot and table_acc_v "
         "optional), in any order";
}

Layout parse_header(Reporter& report, long line_number, std::string_view line) {
  Layout layout;
  layout.header_line = line_number;
  layout.separator = choose_separator(line);
  const auto names = split_fields(line, layout.separator);
  layout.field_count = names.size();

  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto channel = channel_named(names[i]);
    if (!channel) continue;  // reported below
    if (layout.column[*channel])
      report.fail(line_number, "the column " + in_quotes(kChannels[*channel].name) + " appears twice (columns " +
                                   std::to_string(*layout.column[*channel] + 1) + " and " + std::to_string(i + 1) +
                                   "); expected each column once");
    layout.column[*channel] = i;
    const std::string_view unit = split_unit(names[i]).unit;
    if (unit.empty()) continue;
    const std::vector<Unit> units = units_of(*channel);
    const auto known = std::find_if(units.begin(), units.end(), [&](const Unit& u) { return u.name == unit; });
    if (known == units.end()) {
      std::string list;
      for (const Unit& u : units) list += (list.empty() ? "" : ", ") + std::string(u.name);
      report.fail(line_number, "the unit " + in_quotes(unit) + " of the column " + in_quotes(kChannels[*channel].name) +
                                   "; expected one of " + list);
    }
    layout.to_si[*channel] = known->si;
    layout.declared[*channel] = true;
  }

  std::vector<std::string_view> missing;
  for (std::size_t c = 0; c < kChannelCount; ++c)
    if (kChannels[c].required && !layout.column[c]) missing.push_back(kChannels[c].name);
  if (!missing.empty()) {
    std::string found, absent;
    for (const auto name : names) found += (found.empty() ? "" : ", ") + in_quotes(name);
    for (const auto name : missing) absent += (absent.empty() ? "" : ", ") + in_quotes(name);
    report.fail(line_number, "missing required column" + std::string(missing.size() == 1 ? " " : "s ") + absent +
                                 "; found the columns " + found + " (separated by " +
                                 separator_name(layout.separator) + "); " + expected_columns());
  }

  // Reported only once the header is known to be usable, so an error comes alone.
  // A near miss of a channel the header lacks is most likely that channel misspelt.
  std::vector<std::string> absent;
  for (std::size_t c = 0; c < kChannelCount; ++c)
    if (!layout.column[c]) absent.emplace_back(kChannels[c].name);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (channel_named(names[i])) continue;
    const auto meant = likely_meant(names[i], absent);
    report.issue(names[i].empty() ? std::string_view("(unnamed column)") : names[i],
                 "unknown column (column " + std::to_string(i + 1) + " of the header, line " +
                     std::to_string(line_number) + "); ignored" +
                     (meant ? "; did you mean " + in_quotes(*meant) + "?" : ""));
  }
  return layout;
}

// ---- rows ---------------------------------------------------------------------------------

// The channels as read: one series per channel present, and each row's line in the file.
struct Columns {
  std::array<Series, kChannelCount> values;
  std::vector<long> line;
};

bool is_missing_text(std::string_view field) { return field.empty() || lower_case(field) == "nan"; }

double parse_value(const Reporter& report, long line_number, Channel channel, std::string_view field, double to_si) {
  if (is_missing_text(field)) return kMissing;
  auto value = parse_double(field);
  if (value) *value *= to_si;
  const std::string found = "found " + in_quotes(field) + " in the column " + in_quotes(kChannels[channel].name);
  // A ';'-separated file from a spreadsheet may use decimal commas: say so.
  const std::string hint = field.find(',') != std::string_view::npos ? " (with a decimal point, not a comma)" : "";
  if (!value)
    report.fail(line_number, found + "; expected a number" + hint + ", or an empty field or nan for a missing value");
  if (!std::isfinite(*value)) report.fail(line_number, found + "; expected a finite number");
  const ChannelSpec& spec = kChannels[channel];
  if (std::abs(*value) > spec.largest)
    report.fail(line_number, found + "; expected at most " + std::string(spec.largest_text) +
                                 " in magnitude (SI, unless the header declares another unit, e.g. '" +
                                 std::string(spec.name) + " [" + std::string(units_of(channel).back().name) + "]')");
  return *value;
}

void check_time(const Reporter& report, const Columns& columns) {
  const Series& t = columns.values[kTime];
  const std::size_t k = t.size() - 1;
  if (std::isnan(t[k]))
    report.fail(columns.line[k], "the time t is missing; expected a time (s) on every row");
  if (k > 0 && !(t[k] > t[k - 1]))
    report.fail(columns.line[k], "t = " + number_text(t[k]) + " s after t = " + number_text(t[k - 1]) + " s (line " +
                                     std::to_string(columns.line[k - 1]) + "); expected strictly increasing times");
}

Columns parse_rows(const Reporter& report, const std::vector<std::string>& lines, const Layout& layout) {
  Columns columns;
  for (std::size_t i = static_cast<std::size_t>(layout.header_line); i < lines.size(); ++i) {
    if (is_skipped(lines[i])) continue;
    const long line_number = static_cast<long>(i + 1);
    const auto fields = split_fields(lines[i], layout.separator);
    if (fields.size() != layout.field_count)
      report.fail(line_number, "found " + plural(fields.size(), "field") + "; expected " +
                                   std::to_string(layout.field_count) + " (one per column of the header, line " +
                                   std::to_string(layout.header_line) + ") separated by " +
                                   separator_name(layout.separator));
    for (std::size_t c = 0; c < kChannelCount; ++c)
      if (layout.column[c])
        columns.values[c].push_back(
            parse_value(report, line_number, static_cast<Channel>(c), fields[*layout.column[c]], layout.to_si[c]));
    columns.line.push_back(line_number);
    check_time(report, columns);
  }
  if (columns.line.size() < kFewestRows)
    report.fail(0, "found " + plural(columns.line.size(), "data row") + "; expected at least " +
                       std::to_string(kFewestRows) + " rows of samples after the header");
  return columns;
}

// ---- uniform sampling ---------------------------------------------------------------------

// The channels on the uniform grid t = k * step, with each sample's line in the file (the
// row at or before it) for messages.
struct Uniform {
  double step = 0.0;
  std::vector<double> time;
  std::array<Series, kChannelCount> values;  // empty for channels not in the file
  std::vector<long> line;
};

double median(std::vector<double> x) {
  const std::size_t middle = x.size() / 2;
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(middle), x.end());
  const double upper = x[middle];
  if (x.size() % 2 == 1) return upper;
  const double lower_middle = *std::max_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(middle));
  return 0.5 * (lower_middle + upper);
}

// Linear interpolation of `values` (at times `from`) at the increasing times `to`, which lie
// within [from.front(), from.back()] up to rounding. A sample that lands on a time of `from`
// is that value; otherwise it is missing when either neighbour is.
struct Bracket {
  std::size_t left;
  double weight;  // of the right neighbour, in [0, 1)
};

std::vector<Bracket> brackets(const std::vector<double>& from, const std::vector<double>& to) {
  // Grid times within this fraction of a step from a sample take that sample alone.
  constexpr double coincident = 1e-9;
  std::vector<Bracket> out;
  out.reserve(to.size());
  std::size_t left = 0;
  for (const double t : to) {
    while (left + 2 < from.size() && from[left + 1] <= t) ++left;
    const double width = from[left + 1] - from[left];
    double weight = std::clamp((t - from[left]) / width, 0.0, 1.0);
    if (weight < coincident) weight = 0.0;
    if (weight > 1.0 - coincident) {
      out.push_back({left + 1, 0.0});
      continue;
    }
    out.push_back({left, weight});
  }
  return out;
}

Series interpolate(const Series& values, const std::vector<Bracket>& at) {
  Series out;
  out.reserve(at.size());
  for (const Bracket& b : at) {
    const double a = values[b.left];
    if (b.weight == 0.0) {
      out.push_back(a);
      continue;
    }
    // a + w (b - a), not (1 - w) a + w b: a flat (clipped) stretch stays exactly flat.
    const double next = values[b.left + 1];
    out.push_back(std::isnan(a) || std::isnan(next) ? kMissing : a + b.weight * (next - a));
  }
  return out;
}

Uniform make_uniform(Reporter& report, const Columns& columns) {
  const Series& t = columns.values[kTime];
  const std::size_t n = t.size();
  std::vector<double> steps(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) steps[k] = t[k + 1] - t[k];
  const double step = median(steps);
  if (!(step >= kSmallestSamplingStep))
    report.fail(0, kTime, "the median sampling step is " + number_text(step) + " s; expected at least " +
                              number_text(kSmallestSamplingStep) + " s (is t in seconds?)");
  if (step > motion::kLargestRecordTimeStep)
    report.fail(0, kTime, "the median sampling step is " + number_text(step) + " s; expected at most " +
                              number_text(motion::kLargestRecordTimeStep) + " s (is t in seconds?)");
  if (t.back() - t.front() > motion::kLongestRecord)
    report.fail(0, kTime, "the test lasts " + number_text(t.back() - t.front()) + " s; expected at most " +
                              number_text(motion::kLongestRecord) + " s");
  // Resampling would invent the table motion across a jump in time: it is a gap in the input.
  const auto longest = std::max_element(steps.begin(), steps.end());
  if (*longest - step > kLongestBridgedInputGap + kGapRoundoff) {
    const auto k = static_cast<std::size_t>(longest - steps.begin());
    report.fail(columns.line[k + 1], "t jumps from " + number_text(t[k]) + " s (line " +
                                                std::to_string(columns.line[k]) + ") to " + number_text(t[k + 1]) +
                                                " s, a gap of " + number_text(*longest - step) +
                                                " s in the table channel; expected gaps of at most " +
                                                number_text(kLongestBridgedInputGap) +
                                                " s (mark missing samples with empty fields or nan, or split the test)");
  }

  Uniform uniform;
  uniform.step = step;
  const auto irregular = std::find_if(steps.begin(), steps.end(), [&](double s) {
    return !(std::abs(s - step) <= kStepTolerance * step);
  });
  if (irregular == steps.end()) {
    // Uniform already: the samples stay as read, at t = k * step.
    for (std::size_t k = 0; k < n; ++k) uniform.time.push_back(static_cast<double>(k) * step);
    uniform.values = columns.values;
    uniform.line = columns.line;
    return uniform;
  }

  std::vector<double> file_time(n);
  for (std::size_t k = 0; k < n; ++k) file_time[k] = t[k] - t[0];
  // The grid stops at the last sample (no extrapolation); the ratio's rounding must not drop
  // a grid time on the last sample, and one a rounding error beyond it takes that sample.
  const auto grid_size = static_cast<std::size_t>(std::floor(file_time.back() / step * (1.0 + 1e-12))) + 1;
  for (std::size_t k = 0; k < grid_size; ++k) uniform.time.push_back(static_cast<double>(k) * step);
  const std::vector<Bracket> at = brackets(file_time, uniform.time);
  for (std::size_t c = 0; c < kChannelCount; ++c)
    if (c != kTime && !columns.values[c].empty()) uniform.values[c] = interpolate(columns.values[c], at);
  for (const Bracket& b : at) uniform.line.push_back(columns.line[b.left]);

  const auto [smallest, largest] = std::minmax_element(steps.begin(), steps.end());
  const auto first = static_cast<std::size_t>(irregular - steps.begin());
  report.issue(kTime, "irregular sampling: steps from " + number_text(*smallest) + " s to " + number_text(*largest) +
                          " s, the first irregular one between lines " + std::to_string(columns.line[first]) + " and " +
                          std::to_string(columns.line[first + 1]) + "; every channel resampled onto t = k * " +
                          number_text(step) + " s (the median step) by linear interpolation");
  return uniform;
}

// ---- channel checks -----------------------------------------------------------------------

struct Run {
  std::size_t first = 0;
  std::size_t count = 0;
  std::size_t end() const { return first + count; }
};

// Runs of consecutive samples for which `is_in` holds.
template <class Predicate>
std::vector<Run> runs_where(const Series& values, Predicate is_in) {
  std::vector<Run> runs;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!is_in(values[k])) continue;
    if (!runs.empty() && runs.back().end() == k)
      ++runs.back().count;
    else
      runs.push_back({k, 1});
  }
  return runs;
}

std::vector<Run> missing_runs(const Series& values) {
  return runs_where(values, [](double v) { return std::isnan(v); });
}

std::size_t total_count(const std::vector<Run>& runs) {
  std::size_t total = 0;
  for (const Run& r : runs) total += r.count;
  return total;
}

struct Range {
  std::size_t count = 0;  // samples present
  double min = 0.0, max = 0.0;
};

Range range_of(const Series& values) {
  Range range;
  for (const double v : values) {
    if (std::isnan(v)) continue;
    range.min = range.count == 0 ? v : std::min(range.min, v);
    range.max = range.count == 0 ? v : std::max(range.max, v);
    ++range.count;
  }
  return range;
}

bool is_constant(const Range& range) {
  const double scale = std::max({1.0, std::abs(range.min), std::abs(range.max)});
  return range.max - range.min < kConstantRange * scale;
}

std::string constant_text(const Range& range, Channel channel) {
  if (range.min == range.max) return "every sample present is " + with_unit(range.min, channel);
  return "every sample present is within " + number_text(range.min) + " to " + with_unit(range.max, channel);
}

// A clipped sensor reads flat at its extreme: the samples equal to the channel's maximum (or
// minimum) in runs of kShortestClippedRun or more. A peak attained once is not clipping.
struct Clipping {
  std::string_view extreme;  // "maximum" or "minimum"
  double level;
  std::vector<Run> runs;
};

std::vector<Clipping> find_clipping(const Series& values, const Range& range) {
  std::vector<Clipping> found;
  for (const auto& [extreme, level] : {std::pair<std::string_view, double>{"maximum", range.max}, {"minimum", range.min}}) {
    auto runs = runs_where(values, [level = level](double v) { return v == level; });
    std::erase_if(runs, [](const Run& r) { return r.count < kShortestClippedRun; });
    if (!runs.empty()) found.push_back({extreme, level, std::move(runs)});
  }
  return found;
}

std::string clipping_text(const Clipping& clip, const Uniform& uniform, Channel channel) {
  return "clipped at its " + std::string(clip.extreme) + ", " + with_unit(clip.level, channel) + ", for " +
         plural(total_count(clip.runs), "sample") + " in " + plural(clip.runs.size(), "run") + " from t = " +
         number_text(uniform.time[clip.runs.front().first]) + " s (line " +
         std::to_string(uniform.line[clip.runs.front().first]) + ")";
}

// ---- table channels (the input) -----------------------------------------------------------

std::string gap_text(const Run& gap, const Uniform& uniform) {
  return plural(gap.count, "missing sample") + " (" + number_text(static_cast<double>(gap.count) * uniform.step) +
         " s) from t = " + number_text(uniform.time[gap.first]) + " s";
}

// Bridges every gap of the input no longer than kLongestBridgedInputGap: linearly between
// its neighbours inside the record, by holding the nearest value at either end. A gap's
// length is its number of missing samples times the step. A longer gap is an error: the
// input motion must be known throughout to simulate the test.
void bridge_input_gaps(Reporter& report, const Uniform& uniform, Channel channel, Series& values) {
  const std::vector<Run> gaps = missing_runs(values);
  const std::size_t n = values.size();
  std::vector<Run> inside;
  for (const Run& gap : gaps) {
    if (static_cast<double>(gap.count) * uniform.step > kLongestBridgedInputGap * (1.0 + kGapRoundoff))
      report.fail(uniform.line[gap.first], channel,
                  gap_text(gap, uniform) + "; expected gaps in the table acceleration (the input motion, which "
                                           "must be known to simulate the test) no longer than " +
                      number_text(kLongestBridgedInputGap) + " s, which are bridged by linear interpolation");
    if (gap.first == 0) {
      const double held = values[gap.end()];
      std::fill_n(values.begin(), gap.count, held);
      report.issue(channel, gap_text(gap, uniform) + " at the start; held at the first value present, " +
                                with_unit(held, channel));
    } else if (gap.end() == n) {
      const double held = values[gap.first - 1];
      std::fill_n(values.begin() + static_cast<std::ptrdiff_t>(gap.first), gap.count, held);
      report.issue(channel, gap_text(gap, uniform) + " to the end; held at the last value present, " +
                                with_unit(held, channel));
    } else {
      const double before = values[gap.first - 1], after = values[gap.end()];
      const double span = static_cast<double>(gap.count + 1);
      for (std::size_t j = 1; j <= gap.count; ++j)
        values[gap.first - 1 + j] = before + (after - before) * (static_cast<double>(j) / span);
      inside.push_back(gap);
    }
  }
  if (inside.empty()) return;
  const auto longest = std::max_element(inside.begin(), inside.end(), [](const Run& a, const Run& b) { return a.count < b.count; });
  report.issue(channel, plural(total_count(inside), "missing sample") + " in " + plural(inside.size(), "gap") +
                            " (the longest " + number_text(static_cast<double>(longest->count) * uniform.step) +
                            " s) bridged by linear interpolation, the first at t = " +
                            number_text(uniform.time[inside.front().first]) + " s (line " +
                            std::to_string(uniform.line[inside.front().first]) + ")");
}

// The table acceleration (horizontal or vertical) ready to drive a simulation; nullopt for
// a vertical channel that cannot be used (which is reported). The horizontal one must be usable.
std::optional<Series> prepare_input(Reporter& report, const Uniform& uniform, Channel channel) {
  Series values = uniform.values[channel];
  const bool optional = channel == kVertical;
  const Range range = range_of(values);
  if (range.count == 0) {
    if (!optional)
      report.fail(0, channel, "no values (every sample is missing); expected the table acceleration (m/s^2)");
    report.issue(channel, "no values (every sample is missing): not used");
    return std::nullopt;
  }
  if (is_constant(range)) {
    if (!optional)
      report.fail(0, channel, constant_text(range, channel) + " (constant: sensor dead?); expected a varying "
                                  "table acceleration (a constant input has nothing to simulate)");
    report.issue(channel, "constant (sensor dead?): not used; " + constant_text(range, channel));
    return std::nullopt;
  }
  for (const Clipping& clip : find_clipping(values, range))
    report.issue(channel, clipping_text(clip, uniform, channel) +
                              "; the input is clipped and cannot be masked: simulations will see the clipped input");
  bridge_input_gaps(report, uniform, channel, values);
  return values;
}

// ---- response channels (compared with simulations) ----------------------------------------

struct Response {
  Series values;  // NaN in gaps; clipped and dead samples keep the value read
  Mask valid;
  bool usable() const { return any_valid(valid); }
};

void mask_runs(Mask& valid, const std::vector<Run>& runs) {
  for (const Run& r : runs)
    std::fill_n(valid.begin() + static_cast<std::ptrdiff_t>(r.first), r.count, std::uint8_t{0});
}

Response prepare_response(Reporter& report, const Uniform& uniform, Channel channel) {
  Response response{uniform.values[channel], Mask(uniform.time.size(), 1)};
  const std::vector<Run> gaps = missing_runs(response.values);
  mask_runs(response.valid, gaps);

  const Range range = range_of(response.values);
  if (range.count == 0) {
    report.issue(channel, "no values (every sample is missing): not used");
    return response;
  }
  if (!gaps.empty())
    report.issue(channel, plural(total_count(gaps), "missing sample") + " in " + plural(gaps.size(), "gap") +
                              ", the first at t = " + number_text(uniform.time[gaps.front().first]) + " s (line " +
                              std::to_string(uniform.line[gaps.front().first]) + "); masked");
  if (is_constant(range)) {
    std::fill(response.valid.begin(), response.valid.end(), std::uint8_t{0});
    report.issue(channel, "constant (sensor dead?): not used; " + constant_text(range, channel));
    return response;
  }
  for (const Clipping& clip : find_clipping(response.values, range)) {
    mask_runs(response.valid, clip.runs);
    report.issue(channel, clipping_text(clip, uniform, channel) + "; masked");
  }
  return response;
}

}  // namespace

MeasuredTest read_measured_test(const std::filesystem::path& csv) {
  MeasuredTest test;
  test.name = csv.stem().string();
  test.file = csv;
  Reporter report(csv, test.issues);

  const std::vector<std::string> lines = read_lines(report);
  const auto header = std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return !is_skipped(l); });
  if (header == lines.end()) report.fail(0, "no header row (the file is empty or only comments); " + expected_columns());
  const Layout layout = parse_header(report, static_cast<long>(header - lines.begin()) + 1, *header);
  const Uniform uniform = make_uniform(report, parse_rows(report, lines, layout));

  test.time_step = uniform.step;
  test.time = uniform.time;

  test.table_acceleration = *prepare_input(report, uniform, kTable);
  if (layout.column[kVertical]) {
    if (auto vertical = prepare_input(report, uniform, kVertical)) {
      test.vertical_table_acceleration = std::move(*vertical);
      test.has_vertical = true;
    }
  }

  Response rotation = prepare_response(report, uniform, kRotation);
  Response slide = prepare_response(report, uniform, kSlide);
  if (!rotation.usable() && !slide.usable())
    report.fail(0, "neither theta nor slide has a usable sample (missing, constant or clipped throughout); expected "
                   "at least one response channel to compare a simulation with");
  // SI assumed where no unit was declared: a value no cask on a table shows in SI but would in
  // another unit is reported with the header that declares it.
  const auto peak = [](const std::vector<double>& values) {
    double p = 0.0;
    for (double v : values)
      if (std::isfinite(v)) p = std::max(p, std::abs(v));
    return p;
  };
  if (!layout.declared[kSlide] && peak(slide.values) > kLargestPlausibleSlide) {
    report.issue(kSlide, "peaks at " + with_unit(peak(slide.values), kSlide) + ", further than a cask slides on a "
                         "shaking table: a column in mm or cm? declare it in the header, e.g. 'slide [mm]'");
  }
  if (!layout.declared[kRotation] && peak(rotation.values) > kLargestPlausibleRotation) {
    report.issue(kRotation, "peaks at " + with_unit(peak(rotation.values), kRotation) + ", beyond a radian: a column in "
                            "degrees? declare it in the header, e.g. 'theta [deg]'");
  }
  test.table_unit_declared = layout.declared[kTable];
  test.rotation = std::move(rotation.values);
  test.rotation_valid = std::move(rotation.valid);
  test.slide = std::move(slide.values);
  test.slide_valid = std::move(slide.valid);
  if (layout.column[kAngularVelocity]) {
    Response angular_velocity = prepare_response(report, uniform, kAngularVelocity);
    if (angular_velocity.usable()) {
      test.angular_velocity = std::move(angular_velocity.values);
      test.angular_velocity_valid = std::move(angular_velocity.valid);
      test.has_angular_velocity = true;
    }
  }
  return test;
}

}  // namespace caskdem::diagnosis
