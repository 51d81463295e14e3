#pragma once
// Seismic hazard curves: the annual frequency with which a ground-motion intensity is
// exceeded at a site, read from the files hazard analysts hand over.
//
// Forms read (docs/risk.md has an example of each; risk/ in the examples folder ships them):
//   OpenQuake   the engine's hazard-curve CSV export: a comment line ending in
//               "..., investigation_time=50.0, imt='PGA'", then "lon,lat,depth,poe-0.005,..."
//               and one row per site of probabilities of exceedance within the investigation
//               time; intensities in g (PGA, SA) or cm/s (PGV)
//   nshmp-haz   the USGS code's curves CSV: "lon,lat,0.005,..." (or "name,lon,lat,...") and
//               one row per site of annual rates of exceedance; the intensity measure is the
//               name of the folder the file is in (PGA, PGV, SA1P0) or is given
//   table       two columns under a header naming the intensity measure with its unit and
//               what the second column holds: "PGA [g], annual frequency" or
//               "SA(1.0) [g], poe in 50 years"
//
// A probability p of exceedance in T years is the Poisson annual frequency -ln(1 - p) / T.
// A curve must have intensities increasing and > 0 and a hazard that never rises; a
// probability of 1 (an infinite frequency) or outside [0, 1] is refused. Zeros at the top
// (an engine's underflow) end the curve there. Every refusal is an InputError naming the file
// and the line (and column) and what was expected.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace caskdem::risk {

// The intensity measure of a hazard curve or a fragility: PGA, PGV or the 5 %-damped
// pseudo-spectral acceleration SA(T).
struct IntensityMeasure {
  enum class Kind { pga, pgv, sa };
  Kind kind = Kind::pga;
  double period = 0.0;  // s, for SA

  bool is_acceleration() const { return kind != Kind::pgv; }
  bool operator==(const IntensityMeasure& other) const;
};

// "PGA", "PGV", "SA(1.0)", "SA(0.2 s)" and nshmp-haz's folder names "SA1P0", "SA0P2", without
// case; nullopt for anything else.
std::optional<IntensityMeasure> parse_intensity_measure(std::string_view text);
std::string intensity_measure_name(const IntensityMeasure& measure);  // "PGA", "SA(1)"
// The unit users read the measure in: g for accelerations, cm/s for PGV (and its SI factor).
std::string display_unit(const IntensityMeasure& measure);
double display_unit_to_si(const IntensityMeasure& measure);

// Poisson conversions between a probability of exceedance in `years` and an annual frequency.
double annual_frequency_from_probability(double probability, double years);
double probability_in_years(double annual_frequency, double years);

struct HazardCurve {
  std::string source;                    // the file, and the site when it holds several
  IntensityMeasure measure;
  std::vector<double> intensity;         // SI (m/s^2 or m/s), increasing, > 0
  std::vector<double> annual_frequency;  // 1/year, > 0, never increasing
  bool cut_at_zero = false;              // the file's curve went to 0 after the last point
};

enum class HazardFormat { automatic, openquake, nshmp, table };
std::optional<HazardFormat> parse_hazard_format(std::string_view text);  // automatic, openquake, nshmp, table

struct HazardReadOptions {
  HazardFormat format = HazardFormat::automatic;
  // The measure when the file does not say it (nshmp-haz outside its folder); when the file
  // says it too, the two must agree.
  std::optional<IntensityMeasure> measure;
  // The site of a file with several (lon, lat, matched within 1e-4 degrees); a file with one
  // site needs none.
  std::optional<std::pair<double, double>> site;
};

HazardCurve read_hazard_curve(const std::filesystem::path& file, const HazardReadOptions& options = {});

// The checks every reader applies, for a curve built in code: throws std::invalid_argument
// saying what is wrong.
void check_hazard_curve(const HazardCurve& curve);

}  // namespace caskdem::risk
