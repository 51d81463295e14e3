// Record readers: text files of accelerations into a Record in SI.
//
// Formats (detected from the content, not the extension, unless ReadOptions::format says):
//   PEER .AT2   free-text header lines, then a line giving the number of points and the step,
//               either "NPTS=  5372, DT=   .0100 SEC" (NGA-West2, also old files) or
//               "4000    0.01000    NPTS, DT" (older files); it is the 4th line in PEER files
//               and is looked for among the first header_search_lines lines. Then exactly
//               NPTS accelerations in g, several per line, separated by blanks (or commas).
//               The two PEER formats differ only in that line; both forms are accepted for
//               either, so peer_nga_west2 and peer_old read the same way.
//   columns     one value "a" or two "t a" per line, separated by commas, semicolons, tabs
//               or spaces. Blank lines and "#" comment lines are skipped anywhere; lines
//               before the first all-numeric line are a free-text header. After the data has
//               started, a non-numeric line or one with another number of values is an error.
//               The unit must be given (the file does not say it). A time column must be
//               uniformly sampled; its first time is taken as t = 0 of the record.
// Every error is an InputError "FILE:LINE: what was found; expected what". Every sample goes
// through one check (sample_in_si): finite, and at most kLargestGroundAcceleration in SI.

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>
#include <sstream>
#include <string_view>
#include <system_error>

#include "core/error.h"
#include "core/text.h"
#include "core/units.h"
#include "motion/record.h"

namespace caskdem::motion {
namespace {

using std::filesystem::path;

// PEER files have the NPTS line 4th; a few more lines allow a longer free-text header.
constexpr std::size_t header_search_lines = 8;
// Sampling uniformity demanded of a time column (relative to the step), as record.h states.
constexpr double step_tolerance = 1e-6;

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A line quoted in a message: trimmed and cut short so the message stays one line.
std::string quote_line(std::string_view s) {
  s = trim(s);
  constexpr std::size_t longest = 60;
  if (s.size() > longest) return "'" + std::string(s.substr(0, longest)) + "...'";
  return "'" + std::string(s) + "'";
}

std::string number_text(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

// The whole token as a double: a leading "+" and Fortran "D" exponents (old records) are
// accepted. "nan"/"inf" parse (the caller rejects them as not finite); so does a value
// beyond the range of a double, as infinity.
std::optional<double> parse_number(std::string_view token) {
  token = trim(token);
  if (token.size() > 64) return std::nullopt;
  std::array<char, 64> buffer{};
  std::transform(token.begin(), token.end(), buffer.begin(), [](char c) { return c == 'd' || c == 'D' ? 'e' : c; });
  return parse_double(std::string_view(buffer.data(), token.size()));
}

// The file's lines (core/text.h); a file with none but blank lines is an error here.
std::vector<std::string> read_lines(const path& file) {
  const std::vector<std::string> lines = read_text_lines(file, "an acceleration record file");
  const bool blank = std::all_of(lines.begin(), lines.end(), [](const std::string& l) { return trim(l).empty(); });
  if (blank) fail_at(file, 0, "the file is empty; expected an acceleration record (PEER .AT2 or columns of numbers)");
  return lines;
}

bool is_comment(std::string_view line) { return trim(line).starts_with('#'); }

// Index of the AT2 "NPTS ... DT" line among the first lines (comments aside), if any.
std::optional<std::size_t> find_npts_line(const std::vector<std::string>& lines) {
  const std::size_t n = std::min(lines.size(), header_search_lines);
  for (std::size_t i = 0; i < n; ++i) {
    if (is_comment(lines[i])) continue;
    const std::string u = upper(lines[i]);
    if (u.find("NPTS") != std::string::npos && u.find("DT") != std::string::npos) return i;
  }
  return std::nullopt;
}

double to_si(double value, AccelerationUnit unit) {
  switch (unit) {
    case AccelerationUnit::g: return units::g_to_si(value);
    case AccelerationUnit::gal: return units::gal_to_si(value);
    case AccelerationUnit::si: return value;
  }
  return value;
}

std::string unit_name(AccelerationUnit unit) {
  switch (unit) {
    case AccelerationUnit::g: return "g";
    case AccelerationUnit::gal: return "gal";
    case AccelerationUnit::si: return "m/s^2";
  }
  return "?";
}

// A sample as written (token) in the file's unit, into SI; the one check of every reader: a
// value that is not finite, or that no ground motion can have, is an error naming the line.
double sample_in_si(const path& file, long line, std::string_view token, double value, AccelerationUnit unit) {
  const std::string found = "found '" + std::string(trim(token)) + "'";
  if (!std::isfinite(value)) fail_at(file, line, found + "; expected finite accelerations");
  const double si = to_si(value, unit);
  if (!(std::abs(si) <= kLargestGroundAcceleration))
    fail_at(file, line,
            found + " " + unit_name(unit) + "; expected accelerations of at most " +
                std::string(kLargestGroundAccelerationText) +
                " in magnitude, as no recorded or synthetic ground motion is larger (is the unit right?)");
  return si;
}

// A time step given in the options must agree with the one the file states.
void check_given_step(const path& file, long line, double file_step, const ReadOptions& options) {
  if (!options.time_step) return;
  const double given = *options.time_step;
  if (!(std::abs(given - file_step) <= step_tolerance * file_step))
    fail_at(file, line,
            "the file's time step is " + number_text(file_step) + " s but " + number_text(given) +
                " s was given; expected them to agree (or no time step to be given)");
}

// A record's sampling and length within kLargestRecordTimeStep and kLongestRecord; `line` is
// where the step comes from (the NPTS line, or the first data line).
void check_step_and_duration(const path& file, long line, const Record& record) {
  if (record.time_step > kLargestRecordTimeStep)
    fail_at(file, line, "the time step is " + number_text(record.time_step) + " s; expected at most " +
                            number_text(kLargestRecordTimeStep) + " s (a time step or time column in another unit?)");
  if (record.duration() > kLongestRecord)
    fail_at(file, line, "the record lasts " + number_text(record.duration()) + " s; expected at most " +
                            number_text(kLongestRecord) + " s");
}

// ---- PEER .AT2 --------------------------------------------------------------------------

struct At2Header {
  long long npts = 0;
  double dt = 0.0;
};

At2Header parse_npts_line(const path& file, long line_number, const std::string& line) {
  // "NPTS= 5372, DT= .0100 SEC" or "4000 0.01000 NPTS, DT"; the values are taken as any
  // token so that a bad one is reported as found rather than as an unmatched line.
  static const std::regex keyed(R"(NPTS\s*=\s*([^\s,]+)\s*,?\s*DT\s*=\s*([^\s,]+))", std::regex::icase);
  static const std::regex positional(R"(^\s*([^\s,]+)\s*,?\s*([^\s,]+)\s*,?\s*NPTS\s*,?\s*DT)", std::regex::icase);
  std::smatch m;
  if (!std::regex_search(line, m, keyed) && !std::regex_search(line, m, positional))
    fail_at(file, line_number,
            "found " + quote_line(line) + "; expected the PEER line 'NPTS= n, DT= dt SEC' or 'n dt NPTS, DT'");
  const std::string npts_text = m[1].str();
  const std::string dt_text = m[2].str();

  At2Header header;
  const auto [end, error] = std::from_chars(npts_text.data(), npts_text.data() + npts_text.size(), header.npts);
  if (error != std::errc() || end != npts_text.data() + npts_text.size() || header.npts <= 0)
    fail_at(file, line_number, "NPTS = '" + npts_text + "'; expected a positive whole number of points");
  const auto dt = parse_number(dt_text);
  if (!dt || !std::isfinite(*dt) || *dt <= 0.0)
    fail_at(file, line_number, "DT = '" + dt_text + "'; expected a positive time step in seconds");
  header.dt = *dt;
  return header;
}

// A header saying "UNITS OF CM/S" is a velocity (.VT2) or displacement (.DT2) file.
void check_at2_units(const path& file, const std::vector<std::string>& lines, std::size_t npts_index) {
  for (std::size_t i = 0; i < npts_index; ++i) {
    const std::string u = upper(lines[i]);
    const auto at = u.find("UNITS OF");
    if (at == std::string::npos) continue;
    std::string_view rest = trim(std::string_view(u).substr(at + 8));
    const auto word_end = rest.find_first_of(" \t,.;");
    const std::string_view unit = rest.substr(0, word_end);
    if (unit != "G")
      fail_at(file, static_cast<long>(i + 1),
              "the header says units of " + std::string(unit) + "; expected an acceleration record in units of G");
  }
}

Record read_at2(const path& file, const std::vector<std::string>& lines, std::size_t npts_index,
                const ReadOptions& options) {
  if (options.unit && *options.unit != AccelerationUnit::g)
    fail_at(file, 0, "a PEER .AT2 record is in g but unit " + unit_name(*options.unit) +
                         " was given; expected unit g or none");
  check_at2_units(file, lines, npts_index);
  const long npts_line = static_cast<long>(npts_index + 1);
  const At2Header header = parse_npts_line(file, npts_line, lines[npts_index]);
  check_given_step(file, npts_line, header.dt, options);

  Record record;
  record.source = file.string();
  record.time_step = header.dt;
  // Reserve no more than the file could hold: NPTS may be wrong.
  record.acceleration.reserve(static_cast<std::size_t>(std::min<long long>(header.npts, 16 * static_cast<long long>(lines.size()))));
  const std::string expected_count = "expected exactly NPTS = " + std::to_string(header.npts) + " values";
  for (std::size_t i = npts_index + 1; i < lines.size(); ++i) {
    const long line_number = static_cast<long>(i + 1);
    std::string_view rest = lines[i];
    while (true) {
      const auto begin = rest.find_first_not_of(" \t,");
      if (begin == std::string_view::npos) break;
      rest.remove_prefix(begin);
      const auto end = std::min(rest.find_first_of(" \t,"), rest.size());
      const std::string_view token = rest.substr(0, end);
      rest.remove_prefix(end);
      const auto value = parse_number(token);
      if (!value)
        fail_at(file, line_number, "found '" + std::string(token) + "'; expected numbers (accelerations in g)");
      const double a = sample_in_si(file, line_number, token, *value, AccelerationUnit::g);
      if (static_cast<long long>(record.acceleration.size()) == header.npts)
        fail_at(file, line_number, "more values than NPTS (line " + std::to_string(npts_line) + "); " + expected_count);
      record.acceleration.push_back(a);
    }
  }
  if (static_cast<long long>(record.acceleration.size()) != header.npts)
    fail_at(file, npts_line,
            "found " + std::to_string(record.acceleration.size()) + " values after this line; " + expected_count +
                " (is the file cut short?)");
  check_step_and_duration(file, npts_line, record);
  return record;
}

// ---- columns ----------------------------------------------------------------------------

// The fields of a line: split at ";" if there is one, else at ",", else at blanks. A
// trailing separator (as spreadsheets write) leaves no field.
std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  const char separator = line.find(';') != std::string_view::npos ? ';' : line.find(',') != std::string_view::npos ? ',' : ' ';
  if (separator == ' ') {
    std::size_t at = 0;
    while ((at = line.find_first_not_of(" \t", at)) != std::string_view::npos) {
      const auto end = std::min(line.find_first_of(" \t", at), line.size());
      fields.push_back(line.substr(at, end - at));
      at = end;
    }
    return fields;
  }
  std::size_t at = 0;
  while (true) {
    const auto end = line.find(separator, at);
    fields.push_back(trim(line.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at)));
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  while (!fields.empty() && fields.back().empty()) fields.pop_back();
  return fields;
}

struct Sample {
  long line;
  double t;  // only with two columns
  double a;  // m/s^2
};

// The acceleration unit a column header states in brackets after the column's name
// (`Accel[g]`, `Acceleration (g's)`, `acc (cm/s^2)`): the last bracketed word of the line, unless
// it is the time column's; nullopt when it states none.
std::optional<AccelerationUnit> stated_unit(const path& file, long line_number, const std::string& header) {
  static const std::regex bracketed(R"([\(\[]\s*([^\)\]]*?)\s*[\)\]])");
  std::optional<std::string> last;
  for (auto it = std::sregex_iterator(header.begin(), header.end(), bracketed); it != std::sregex_iterator(); ++it) {
    last = (*it)[1].str();
  }
  if (!last) return std::nullopt;
  const std::string word = lower_case(*last);
  if (word == "s" || word == "sec" || word == "seconds") return std::nullopt;
  if (word == "g" || word == "g's" || word == "gs") return AccelerationUnit::g;
  if (word == "gal" || word == "cm/s^2" || word == "cm/s2" || word == "cm/sec^2" || word == "cm/s/s")
    return AccelerationUnit::gal;
  if (word == "m/s^2" || word == "m/s2" || word == "m/sec^2" || word == "m/s/s") return AccelerationUnit::si;
  fail_at(file, line_number,
          "the header states the unit '" + *last + "'; expected an acceleration unit: g, gal (cm/s^2) or m/s^2");
}

// The unit of a column file: the one its header states, else the one given; both, they agree.
AccelerationUnit column_unit(const path& file, long header_line, const std::string& header, const ReadOptions& options) {
  const std::optional<AccelerationUnit> stated =
      header_line > 0 ? stated_unit(file, header_line, header) : std::nullopt;
  if (stated && options.unit && *stated != *options.unit) {
    fail_at(file, header_line,
            "the header states unit " + unit_name(*stated) + " but " + unit_name(*options.unit) +
                " was given; expected them to agree (or no unit to be given)");
  }
  if (stated) return *stated;
  if (options.unit) return *options.unit;
  fail_at(file, header_line,
          "the column file does not state its unit (a header such as 't, acc [g]'); expected the unit to be given "
          "with the record (g, gal or m/s^2)");
}

Record read_columns(const path& file, const std::vector<std::string>& lines, const ReadOptions& options) {
  std::vector<Sample> samples;
  std::size_t columns = 0;  // set by the first data line
  long first_data_line = 0;
  long header_line = 0;  // the last line of text before it: the column names
  bool header_begins_with_number = false;
  std::string header_bad;  // its first field that is not a number
  std::size_t header_fields = 0;
  AccelerationUnit unit = AccelerationUnit::si;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const long line_number = static_cast<long>(i + 1);
    const std::string_view line = trim(lines[i]);
    if (line.empty() || line.starts_with('#')) continue;
    const auto fields = split_fields(line);
    std::vector<double> values;
    std::string_view bad;
    for (const auto field : fields) {
      const auto value = parse_number(field);
      if (!value) {
        bad = field;
        break;
      }
      values.push_back(*value);
    }
    const bool numeric = !fields.empty() && values.size() == fields.size();
    if (columns == 0) {
      if (!numeric) {
        header_line = line_number;
        header_begins_with_number = !values.empty();
        header_bad = std::string(bad);
        header_fields = fields.size();
        continue;
      }
      // A line just above the data that begins with a number and has as many fields as the
      // data is their malformed first row ("0.00, 0.1x"), not a header to drop.
      if (header_begins_with_number && header_fields == fields.size()) {
        fail_at(file, header_line,
                "found '" + header_bad + "' in " + quote_line(lines[static_cast<std::size_t>(header_line - 1)]) +
                    "; expected numbers as on line " + std::to_string(line_number) +
                    " (a malformed first data row), or a header line of column names");
      }
      unit = column_unit(file, header_line, header_line > 0 ? lines[static_cast<std::size_t>(header_line - 1)] : "",
                         options);
      if (values.size() > 2)
        fail_at(file, line_number,
                "found " + std::to_string(values.size()) +
                    " values on the first data line; expected 2 columns (t, a) or 1 column (a)");
      columns = values.size();
      first_data_line = line_number;
    }
    const std::string layout = columns == 2 ? "2 numbers (t, a)" : "1 number (a)";
    if (!numeric)
      fail_at(file, line_number,
              "found '" + std::string(bad) + "' in " + quote_line(line) + "; expected " + layout +
                  " as from line " + std::to_string(first_data_line) + " on");
    if (values.size() != columns)
      fail_at(file, line_number,
              "found " + std::to_string(values.size()) + " values; expected " + layout + " as on line " +
                  std::to_string(first_data_line));
    if (!std::isfinite(values.front()))
      fail_at(file, line_number, "found " + quote_line(line) + "; expected finite numbers");
    samples.push_back({line_number, values.front(), sample_in_si(file, line_number, fields.back(), values.back(), unit)});
  }
  if (samples.empty()) {
    (void)column_unit(file, header_line, header_line > 0 ? lines[static_cast<std::size_t>(header_line - 1)] : "", options);
    fail_at(file, 0, "no data lines; expected lines of numbers 't, a' or 'a' after any header");
  }

  Record record;
  record.source = file.string();
  if (columns == 1) {
    if (!options.time_step || !std::isfinite(*options.time_step) || *options.time_step <= 0.0)
      fail_at(file, first_data_line,
              "a single-column file does not give its time step; expected a positive time step to be given "
              "with the record");
    record.time_step = *options.time_step;
  } else {
    const std::size_t n = samples.size();
    if (n < 2) {
      if (!options.time_step || !(*options.time_step > 0.0))
        fail_at(file, samples[0].line, "only one sample; expected at least two to give the time step");
      record.time_step = *options.time_step;
    } else {
      // Locate a change of step against the first step (a missing sample shows where it is),
      // then hold every step to the mean, the record's time step.
      const double first = samples[1].t - samples[0].t;
      const auto step_error = [&](std::size_t k, double reference, const std::string& what) {
        fail_at(file, samples[k].line,
                "the time step changes to " + number_text(samples[k].t - samples[k - 1].t) + " s (t = " +
                    number_text(samples[k - 1].t) + " to " + number_text(samples[k].t) + ") from " + what + " " +
                    number_text(reference) + " s; expected uniform sampling (steps within 1e-6 relative)");
      };
      if (!(first > 0.0))
        fail_at(file, samples[1].line,
                "time " + number_text(samples[1].t) + " does not follow " + number_text(samples[0].t) +
                    "; expected increasing, uniformly spaced times");
      for (std::size_t k = 2; k < n; ++k)
        if (!(std::abs(samples[k].t - samples[k - 1].t - first) <= step_tolerance * first))
          step_error(k, first, "the first step");
      const double mean = (samples[n - 1].t - samples[0].t) / static_cast<double>(n - 1);
      for (std::size_t k = 1; k < n; ++k)
        if (!(std::abs(samples[k].t - samples[k - 1].t - mean) <= step_tolerance * mean))
          step_error(k, mean, "the mean step");
      record.time_step = mean;
      check_given_step(file, first_data_line, mean, options);
    }
  }
  record.acceleration.reserve(samples.size());
  for (const Sample& s : samples) record.acceleration.push_back(s.a);
  check_step_and_duration(file, first_data_line, record);
  return record;
}

}  // namespace

std::optional<AccelerationUnit> parse_acceleration_unit(const std::string& text) {
  const std::string_view t = trim(text);
  if (t == "g") return AccelerationUnit::g;
  if (t == "gal" || t == "Gal" || t == "cm/s^2" || t == "cm/s2") return AccelerationUnit::gal;
  if (t == "m/s^2" || t == "m/s2") return AccelerationUnit::si;
  return std::nullopt;
}

std::optional<RecordFormat> parse_record_format(const std::string& text) {
  const std::string_view t = trim(text);
  if (t == "automatic") return RecordFormat::automatic;
  if (t == "peer_nga_west2") return RecordFormat::peer_nga_west2;
  if (t == "peer_old") return RecordFormat::peer_old;
  if (t == "columns") return RecordFormat::columns;
  return std::nullopt;
}

Record read_record(const std::filesystem::path& file, const ReadOptions& options) {
  if (options.time_step && !(std::isfinite(*options.time_step) && *options.time_step > 0.0))
    fail_at(file, 0, "time step " + number_text(*options.time_step) + " s given; expected a positive time step");
  const std::vector<std::string> lines = read_lines(file);
  const auto npts_line = find_npts_line(lines);
  switch (options.format) {
    case RecordFormat::automatic:
      if (npts_line) return read_at2(file, lines, *npts_line, options);
      return read_columns(file, lines, options);
    case RecordFormat::peer_nga_west2:
    case RecordFormat::peer_old:
      if (!npts_line) {
        const long line = lines.size() >= 4 ? 4 : static_cast<long>(lines.size());
        fail_at(file, line,
                "found " + quote_line(lines[static_cast<std::size_t>(line - 1)]) +
                    "; expected the PEER header line 'NPTS= n, DT= dt SEC' (or 'n dt NPTS, DT') as the 4th line");
      }
      return read_at2(file, lines, *npts_line, options);
    case RecordFormat::columns:
      return read_columns(file, lines, options);
  }
  fail_at(file, 0, "unknown record format; expected automatic, peer_nga_west2, peer_old or columns");
}

}  // namespace caskdem::motion
