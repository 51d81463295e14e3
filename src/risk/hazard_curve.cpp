#include "risk/hazard_curve.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/quantity.h"
#include "core/text.h"
#include "core/units.h"

namespace caskdem::risk {

namespace {

constexpr double kSiteTolerance = 1e-4;  // degrees: coordinates as printed with 4-5 decimals

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  const char delimiter = line.find(',') != std::string_view::npos   ? ','
                         : line.find(';') != std::string_view::npos ? ';'
                         : line.find('\t') != std::string_view::npos ? '\t'
                                                                     : ' ';
  if (delimiter == ' ') {
    std::istringstream words{std::string(line)};
    for (std::string w; words >> w;) fields.push_back(w);
    return fields;
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(delimiter, start);
    fields.emplace_back(trim(line.substr(start, end == std::string_view::npos ? end : end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return fields;
}

bool blank_or_comment(std::string_view line) {
  const std::string_view t = trim(line);
  return t.empty() || t.front() == '#';
}

// One point of a curve as the file gives it, with where it came from for a message.
struct FilePoint {
  double intensity = 0.0;  // SI
  double value = 0.0;      // annual frequency, or probability in `years`
  long line = 0;
  std::string column;      // "" for a table, the column's header for a CSV row
};

std::string where(const FilePoint& p) { return p.column.empty() ? "" : "column " + p.column + ": "; }

// The checks and the Poisson conversion every form shares. years = 0: values are annual
// frequencies; otherwise probabilities of exceedance within `years`.
// Intensities are printed in the file's unit (`unit`, `unit_to_si` of it in SI).
HazardCurve build_curve(const std::filesystem::path& file, std::string source, const IntensityMeasure& measure,
                        const std::vector<FilePoint>& points, double years, const std::string& unit, double unit_to_si) {
  const auto intensity_text = [&](double a) { return number_text(a / unit_to_si) + " " + unit; };
  HazardCurve curve;
  curve.source = std::move(source);
  curve.measure = measure;
  double previous_intensity = 0.0, previous_frequency = INFINITY;
  for (const FilePoint& p : points) {
    if (!std::isfinite(p.intensity) || p.intensity <= 0.0)
      fail_at(file, p.line, where(p) + "intensity " + intensity_text(p.intensity) + "; expected a finite value above 0");
    if (p.intensity <= previous_intensity)
      fail_at(file, p.line, where(p) + "intensity " + intensity_text(p.intensity) + " after " +
                                intensity_text(previous_intensity) + "; expected intensities increasing");
    previous_intensity = p.intensity;
    double frequency = p.value;
    if (!std::isfinite(p.value) || p.value < 0.0)
      fail_at(file, p.line, where(p) + "hazard " + number_text(p.value) + "; expected a finite value of at least 0");
    if (years > 0.0) {
      if (p.value >= 1.0)
        fail_at(file, p.line, where(p) + "probability of exceedance " + number_text(p.value) + " in " +
                                  number_text(years) + " years" +
                                  (p.value == 1.0 ? " is an infinite annual frequency" : "") +
                                  "; expected a probability below 1");
      frequency = annual_frequency_from_probability(p.value, years);
    }
    if (frequency > previous_frequency * (1.0 + 1e-9))
      fail_at(file, p.line, where(p) + "the hazard rises from " + number_text(previous_frequency) + " to " +
                                number_text(frequency) + " per year; expected a curve that never rises with intensity");
    // A rise within rounding (1e-9) is taken as flat, so the stored curve never rises.
    frequency = std::min(frequency, previous_frequency);
    previous_frequency = frequency;
    if (frequency == 0.0) {
      curve.cut_at_zero = true;
      continue;  // a later positive value was refused above as a rise
    }
    curve.intensity.push_back(p.intensity);
    curve.annual_frequency.push_back(frequency);
  }
  if (curve.intensity.size() < 2)
    fail_at(file, points.empty() ? 0 : points.front().line,
            "has " + std::to_string(curve.intensity.size()) +
                " point(s) with a non-zero hazard; expected a hazard curve of at least two");
  return curve;
}

// The data row of the site asked for (or the only one), among rows of "lon,lat,..." values.
struct SiteRow {
  std::vector<std::string> fields;
  long line = 0;
};

SiteRow choose_site(const std::filesystem::path& file, const std::vector<SiteRow>& rows, std::size_t lon_column,
                    const HazardReadOptions& options) {
  if (rows.empty()) fail_at(file, 0, "has no site rows; expected one row of hazard values per site");
  auto coordinates = [&](const SiteRow& row) {
    const auto lon = parse_double(row.fields[lon_column]), lat = parse_double(row.fields[lon_column + 1]);
    if (!lon || !lat) fail_at(file, row.line, "expected the site's longitude and latitude as numbers");
    return std::pair{*lon, *lat};
  };
  if (!options.site) {
    if (rows.size() == 1) return rows.front();
    const auto [lon, lat] = coordinates(rows.front());
    fail_at(file, 0, "holds " + std::to_string(rows.size()) + " sites; expected the one to use given as --site LON,LAT "
                         "(the first is " + number_text(lon) + "," + number_text(lat) + ")");
  }
  for (const SiteRow& row : rows) {
    const auto [lon, lat] = coordinates(row);
    if (std::abs(lon - options.site->first) <= kSiteTolerance && std::abs(lat - options.site->second) <= kSiteTolerance)
      return row;
  }
  fail_at(file, 0, "has no site at " + number_text(options.site->first) + "," + number_text(options.site->second) +
                       " (within 1e-4 degrees); expected one of its " + std::to_string(rows.size()) + " sites");
}

IntensityMeasure agreed_measure(const std::filesystem::path& file, long line, std::optional<IntensityMeasure> in_file,
                                const HazardReadOptions& options, const std::string& how) {
  if (in_file && options.measure && !(*in_file == *options.measure))
    fail_at(file, line, "is a curve of " + intensity_measure_name(*in_file) + " but " +
                            intensity_measure_name(*options.measure) + " was asked for");
  if (in_file) return *in_file;
  if (options.measure) return *options.measure;
  fail_at(file, line, "does not say its intensity measure; expected " + how);
}

// Rows after the header: the data lines of a CSV, each split, with their line numbers.
std::vector<SiteRow> data_rows(const std::vector<std::string>& lines, std::size_t header, std::size_t columns,
                               const std::filesystem::path& file) {
  std::vector<SiteRow> rows;
  for (std::size_t i = header + 1; i < lines.size(); ++i) {
    if (blank_or_comment(lines[i])) continue;
    SiteRow row{split_fields(lines[i]), static_cast<long>(i + 1)};
    if (row.fields.size() != columns)
      fail_at(file, row.line, "has " + std::to_string(row.fields.size()) + " values; expected " +
                                  std::to_string(columns) + " as the header names");
    rows.push_back(std::move(row));
  }
  return rows;
}

double number_at(const std::filesystem::path& file, long line, const std::string& column, const std::string& token) {
  const auto x = parse_double(token);
  if (!x) fail_at(file, line, "column " + column + ": \"" + token + "\"; expected a number");
  return *x;
}

HazardCurve read_openquake(const std::filesystem::path& file, const std::vector<std::string>& lines,
                           const HazardReadOptions& options) {
  std::size_t comment = 0;
  while (comment < lines.size() && trim(lines[comment]).empty()) ++comment;
  static const std::regex imt_pattern(R"(imt\s*=\s*['"]([^'"]+)['"])");
  static const std::regex time_pattern(R"(investigation_time\s*=\s*([0-9.eE+-]+))");
  std::smatch m;
  std::optional<IntensityMeasure> measure;
  if (comment < lines.size() && std::regex_search(lines[comment], m, imt_pattern)) {
    measure = parse_intensity_measure(m[1].str());
    if (!measure) fail_at(file, comment + 1, "imt '" + m[1].str() + "'; expected PGA, PGV or SA(T)");
  }
  if (comment >= lines.size() || !std::regex_search(lines[comment], m, time_pattern))
    fail_at(file, comment + 1, "expected the OpenQuake header comment with investigation_time=...");
  const auto years = parse_double(m[1].str());
  if (!years || !std::isfinite(*years) || *years <= 0.0)
    fail_at(file, comment + 1, "investigation_time=" + m[1].str() + "; expected a number of years above 0");
  const IntensityMeasure im =
      agreed_measure(file, comment + 1, measure, options, "imt='PGA' (or PGV, SA(T)) in the header comment");

  const std::size_t header = comment + 1;
  if (header >= lines.size()) fail_at(file, header, "ends after its comment; expected lon,lat,depth,poe-... columns");
  const std::vector<std::string> names = split_fields(lines[header]);
  if (names.size() < 5 || lower_case(names[0]) != "lon" || lower_case(names[1]) != "lat" || lower_case(names[2]) != "depth")
    fail_at(file, header + 1, "expected the header lon,lat,depth,poe-<intensity>,... of an OpenQuake hazard curve");
  std::vector<double> levels;
  for (std::size_t c = 3; c < names.size(); ++c) {
    const std::string_view name = names[c];
    if (name.substr(0, 4) != "poe-") fail_at(file, header + 1, "column \"" + names[c] + "\"; expected poe-<intensity>");
    levels.push_back(number_at(file, header + 1, names[c], std::string(name.substr(4))) * display_unit_to_si(im));
  }
  const SiteRow row = choose_site(file, data_rows(lines, header, names.size(), file), 0, options);
  std::vector<FilePoint> points;
  for (std::size_t c = 3; c < names.size(); ++c)
    points.push_back({levels[c - 3], number_at(file, row.line, names[c], row.fields[c]), row.line, names[c]});
  return build_curve(file, file.string() + " (site " + row.fields[0] + "," + row.fields[1] + ")", im, points, *years,
                     display_unit(im), display_unit_to_si(im));
}

HazardCurve read_nshmp(const std::filesystem::path& file, const std::vector<std::string>& lines,
                       const HazardReadOptions& options) {
  std::size_t header = 0;
  while (header < lines.size() && blank_or_comment(lines[header])) ++header;
  if (header >= lines.size()) fail_at(file, 0, "is empty; expected the header lon,lat,<intensity>,... of nshmp-haz");
  const std::vector<std::string> names = split_fields(lines[header]);
  const std::size_t lon = lower_case(names[0]) == "name" ? 1 : 0;
  if (names.size() < lon + 4 || lower_case(names[lon]) != "lon" || lower_case(names[lon + 1]) != "lat")
    fail_at(file, header + 1, "expected the header lon,lat,<intensity>,... of an nshmp-haz curves file");
  const std::string folder = std::filesystem::absolute(file).parent_path().filename().string();
  const IntensityMeasure im = agreed_measure(file, header + 1, parse_intensity_measure(folder), options,
                                             "the folder name (PGA, PGV, SA1P0) or --imt");
  std::vector<double> levels;
  for (std::size_t c = lon + 2; c < names.size(); ++c)
    levels.push_back(number_at(file, header + 1, names[c], names[c]) * display_unit_to_si(im));
  const SiteRow row = choose_site(file, data_rows(lines, header, names.size(), file), lon, options);
  std::vector<FilePoint> points;
  for (std::size_t c = lon + 2; c < names.size(); ++c)
    points.push_back({levels[c - lon - 2], number_at(file, row.line, names[c], row.fields[c]), row.line, names[c]});
  return build_curve(file, file.string() + " (site " + row.fields[lon] + "," + row.fields[lon + 1] + ")", im, points, 0.0,
                     display_unit(im), display_unit_to_si(im));
}

HazardCurve read_table(const std::filesystem::path& file, const std::vector<std::string>& lines,
                       const HazardReadOptions& options) {
  std::size_t header = 0;
  while (header < lines.size() && blank_or_comment(lines[header])) ++header;
  const long header_line = static_cast<long>(header + 1);
  const char* expected_header = "expected a header such as \"PGA [g], annual frequency\" or \"SA(1.0) [g], poe in 50 years\"";
  if (header >= lines.size()) fail_at(file, 0, "is empty; " + std::string(expected_header));
  const std::vector<std::string> names = split_fields(lines[header]);
  if (names.size() != 2) fail_at(file, header_line, std::string(expected_header));

  // The first column: the measure, then its unit in [] or ().
  const std::string& first = names[0];
  const std::size_t open = first.find_last_of("[(");
  const std::size_t close = first.find_last_of("])");
  std::optional<IntensityMeasure> measure;
  std::string unit;
  if (open != std::string::npos && close == first.size() - 1 && close > open) {
    measure = parse_intensity_measure(trim(std::string_view(first).substr(0, open)));
    unit = std::string(trim(std::string_view(first).substr(open + 1, close - open - 1)));
  }
  if (!measure)
    fail_at(file, header_line, "first column \"" + first + "\"; expected the intensity measure and its unit, as PGA [g], "
                                   "PGV [cm/s] or SA(1.0) [g]");
  const IntensityMeasure im = agreed_measure(file, header_line, measure, options, "");
  std::string error;
  const auto factor =
      parse_quantity("1 " + unit, im.is_acceleration() ? Dimension::acceleration : Dimension::velocity, error);
  if (!factor) fail_at(file, header_line, "unit \"" + unit + "\" of " + intensity_measure_name(im) + ": " + error);

  // The second column: annual frequencies, or probabilities in a stated number of years.
  const std::string second = lower_case(names[1]);
  double years = 0.0;
  static const std::regex years_pattern(R"(([0-9]+(\.[0-9]+)?)\s*_?\s*(y|yr|yrs|year|years)\b)");
  std::smatch m;
  const bool probability = second.find("poe") != std::string::npos || second.find("probab") != std::string::npos;
  const bool annual = second.find("annual") != std::string::npos;
  if (probability && annual && !std::regex_search(second, m, years_pattern)) {
    years = 1.0;  // "annual probability of exceedance"
  } else if (probability) {
    if (!std::regex_search(second, m, years_pattern))
      fail_at(file, header_line, "second column \"" + names[1] + "\" holds probabilities; expected the years they are in, "
                                     "as \"poe in 50 years\"");
    years = parse_double(m[1].str()).value_or(0.0);
    if (!(years > 0.0) || !std::isfinite(years))
      fail_at(file, header_line, "second column: expected a number of years above 0");
  } else if (!annual && second.find("frequency") == std::string::npos && second.find("rate") == std::string::npos) {
    fail_at(file, header_line, "second column \"" + names[1] + "\"; expected \"annual frequency\" or \"poe in N years\"");
  }
  std::vector<FilePoint> points;
  for (std::size_t i = header + 1; i < lines.size(); ++i) {
    if (blank_or_comment(lines[i])) continue;
    const std::vector<std::string> fields = split_fields(lines[i]);
    const long line = static_cast<long>(i + 1);
    if (fields.size() != 2) fail_at(file, line, "has " + std::to_string(fields.size()) + " values; expected two");
    const auto a = parse_double(fields[0]), h = parse_double(fields[1]);
    if (!a || !h) fail_at(file, line, "expected two numbers, the intensity and the hazard");
    points.push_back({*a * *factor, *h, line, ""});
  }
  return build_curve(file, file.string(), im, points, years, unit, *factor);
}

HazardFormat detect(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    if (trim(line).empty()) continue;
    // OpenQuake's comment names its investigation time and measure; its header has a depth.
    if (line.find("investigation_time") != std::string::npos || line.find("imt=") != std::string::npos)
      return HazardFormat::openquake;
    if (blank_or_comment(line)) continue;
    const std::vector<std::string> fields = split_fields(line);
    const std::string first = lower_case(fields.front());
    if (first == "lon" && fields.size() > 2 && lower_case(fields[2]) == "depth") return HazardFormat::openquake;
    return first == "lon" || first == "name" ? HazardFormat::nshmp : HazardFormat::table;
  }
  return HazardFormat::table;
}

}  // namespace

bool IntensityMeasure::operator==(const IntensityMeasure& other) const {
  if (kind != other.kind) return false;
  return kind != Kind::sa || std::abs(period - other.period) <= 1e-9 * std::max(period, other.period);
}

std::optional<IntensityMeasure> parse_intensity_measure(std::string_view text) {
  const std::string t = lower_case(trim(text));
  if (t == "pga") return IntensityMeasure{IntensityMeasure::Kind::pga, 0.0};
  if (t == "pgv") return IntensityMeasure{IntensityMeasure::Kind::pgv, 0.0};
  static const std::regex sa(R"(sa\s*\(\s*([0-9]*\.?[0-9]+)\s*(s)?\s*\))");
  static const std::regex folder(R"(sa([0-9]+)p([0-9]+))");
  std::smatch m;
  double period = 0.0;
  if (std::regex_match(t, m, sa)) {
    period = parse_double(m[1].str()).value_or(0.0);
  } else if (std::regex_match(t, m, folder)) {
    period = parse_double(m[1].str() + "." + m[2].str()).value_or(0.0);
  } else {
    return std::nullopt;
  }
  if (!(period > 0.0) || !std::isfinite(period)) return std::nullopt;
  return IntensityMeasure{IntensityMeasure::Kind::sa, period};
}

std::string intensity_measure_name(const IntensityMeasure& measure) {
  switch (measure.kind) {
    case IntensityMeasure::Kind::pga: return "PGA";
    case IntensityMeasure::Kind::pgv: return "PGV";
    case IntensityMeasure::Kind::sa: return "SA(" + number_text(measure.period) + ")";
  }
  return "PGA";
}

std::string display_unit(const IntensityMeasure& measure) { return measure.is_acceleration() ? "g" : "cm/s"; }
double display_unit_to_si(const IntensityMeasure& measure) {
  return measure.is_acceleration() ? units::standard_gravity : units::kine;
}

double annual_frequency_from_probability(double probability, double years) {
  if (!(years > 0.0) || !(probability >= 0.0) || !(probability < 1.0))
    throw std::invalid_argument("a probability in [0, 1) within years > 0 is expected");
  return -std::log1p(-probability) / years;
}

double probability_in_years(double annual_frequency, double years) {
  if (!(years > 0.0) || !(annual_frequency >= 0.0))
    throw std::invalid_argument("an annual frequency >= 0 and years > 0 are expected");
  return -std::expm1(-annual_frequency * years);
}

std::optional<HazardFormat> parse_hazard_format(std::string_view text) {
  const std::string t = lower_case(trim(text));
  if (t == "automatic") return HazardFormat::automatic;
  if (t == "openquake") return HazardFormat::openquake;
  if (t == "nshmp" || t == "nshmp-haz") return HazardFormat::nshmp;
  if (t == "table") return HazardFormat::table;
  return std::nullopt;
}

HazardCurve read_hazard_curve(const std::filesystem::path& file, const HazardReadOptions& options) {
  const std::vector<std::string> lines = read_text_lines(file, "a hazard curve (OpenQuake or nshmp-haz CSV, or a table)");
  const HazardFormat format = options.format == HazardFormat::automatic ? detect(lines) : options.format;
  switch (format) {
    case HazardFormat::openquake: return read_openquake(file, lines, options);
    case HazardFormat::nshmp: return read_nshmp(file, lines, options);
    default: return read_table(file, lines, options);
  }
}

void check_hazard_curve(const HazardCurve& curve) {
  const std::size_t n = curve.intensity.size();
  if (n < 2 || curve.annual_frequency.size() != n)
    throw std::invalid_argument("a hazard curve needs at least two points, each with an intensity and a frequency");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(curve.intensity[i]) || curve.intensity[i] <= 0.0 ||
        (i > 0 && curve.intensity[i] <= curve.intensity[i - 1]))
      throw std::invalid_argument("hazard curve intensities must be finite, above 0 and increasing");
    if (!std::isfinite(curve.annual_frequency[i]) || curve.annual_frequency[i] <= 0.0 ||
        (i > 0 && curve.annual_frequency[i] > curve.annual_frequency[i - 1]))
      throw std::invalid_argument("hazard curve frequencies must be finite, above 0 and never rising");
  }
}

}  // namespace caskdem::risk
