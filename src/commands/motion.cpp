// caskdem motion FILE: read a record and report its intensity after scaling: PGA, PGV and,
// when asked for, spectral accelerations Sa(T, zeta) and their average over a period range.
// With --pair (and --vertical) FILE is one component of a station's set: the components on
// one time base, each one's PGA and PGV, and the pair's geometric means, RotD50 and RotD100.

#include <cmath>
#include <filesystem>
#include <optional>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "core/text.h"
#include "core/units.h"
#include "motion/component_set.h"
#include "motion/pair_intensity.h"
#include "motion/record.h"
#include "motion/response_spectrum.h"

namespace caskdem::commands {
namespace {

// Damping is given in percent of critical on the command line, as engineers quote it, and is
// a fraction inside.
double damping_ratio_from_percent(double percent) { return percent / 100.0; }

CLI::Validator spectral_period() {
  return number_within("a period in s", motion::kShortestSpectralPeriod, motion::kLongestSpectralPeriod);
}

// A station's components: each read, put on one time base, scaled alike, then reported.
template <class Options>
void report_component_set(const Options& o, const motion::ReadOptions& read) {
  const std::optional<std::filesystem::path> vertical =
      o.vertical.empty() ? std::nullopt : std::optional<std::filesystem::path>(o.vertical);
  motion::ComponentSet set = motion::read_component_set(o.file, o.pair, vertical, read,
                                                        o.pad ? motion::TailRule::pad : motion::TailRule::trim);
  std::vector<motion::Record*> components = {&set.h1, &set.h2};
  if (set.vertical) components.push_back(&*set.vertical);
  for (motion::Record* c : components) {
    try {
      if (o.scale > 0.0) *c = motion::scaled(*c, o.scale);
      if (o.similarity != 1.0) *c = motion::time_scaled(*c, 1.0 / std::sqrt(o.similarity));
    } catch (const std::invalid_argument& e) {
      throw InputError(c->source + ": " + e.what() + " (asked for by " + (o.scale > 0.0 ? "--scale" : "--similarity") + ")");
    }
  }
  const motion::PairIntensity p = motion::pair_intensity(set.h1, set.h2);
  std::cout << std::setprecision(5);
  std::cout << "samples    " << set.h1.acceleration.size() << " at dt = " << set.h1.time_step << " s (duration "
            << set.h1.duration() << " s)" << (set.time_base.empty() ? "" : "; " + set.time_base) << "\n";
  const char* names[] = {"H1", "H2", "vertical"};
  for (std::size_t k = 0; k < components.size(); ++k) {
    const double a = motion::peak_ground_acceleration(*components[k]);
    const double v = motion::peak_ground_velocity(*components[k]);
    std::cout << std::left << std::setw(11) << names[k] << units::si_to_g(a) << " g, " << 100.0 * v << " cm/s  ("
              << components[k]->source << ")\n";
  }
  const auto g = [](double a) { return units::si_to_g(a); };
  std::cout << "pair PGA   geometric mean " << g(p.pga_geometric_mean) << " g, RotD50 " << g(p.pga_rotd50) << " g, RotD100 "
            << g(p.pga_rotd100) << " g (at " << p.pga_rotd100_angle << " deg from H1 towards H2)\n";
  std::cout << "pair PGV   geometric mean " << 100.0 * p.pgv_geometric_mean << " cm/s, RotD50 " << 100.0 * p.pgv_rotd50
            << " cm/s, RotD100 " << 100.0 * p.pgv_rotd100 << " cm/s\n";
}

}  // namespace

void add_motion(CLI::App& app) {
  struct Options {
    std::string file, unit, format = "automatic", pair, vertical;
    bool pad = false;
    double time_step = 0.0, scale = 0.0, target_pga_gal = 0.0, target_pgv_cm_s = 0.0, similarity = 1.0;
    std::vector<double> periods, avg_sa;
    double damping_percent = 5.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "motion", "Read an accelerogram and print its PGA, PGV, duration and spectral accelerations (after scaling)");
  cmd->add_option("file", options->file, "Record file (.AT2 or two-column text/CSV)")->required();
  cmd->add_option("--unit", options->unit, "Acceleration unit of a column file: g, gal or m/s^2");
  cmd->add_option("--format", options->format, "automatic, peer_nga_west2, peer_old or columns");
  auto* time_step =
      cmd->add_option("--time-step", options->time_step, "Time step of a one-column file, s")->check(positive_number());
  auto* scale = cmd->add_option("--scale", options->scale, "Multiply the record by this factor")->check(positive_number());
  auto* pga = cmd->add_option("--target-pga", options->target_pga_gal, "Scale to this PGA, gal")
                  ->excludes(scale)
                  ->check(positive_number());
  auto* pgv = cmd->add_option("--target-pgv", options->target_pgv_cm_s, "Scale to this PGV, cm/s")
                  ->excludes(scale)
                  ->excludes(pga)
                  ->check(positive_number());
  auto* pair = cmd->add_option("--pair", options->pair, "The second horizontal component of FILE's station (.AT2 or columns)");
  cmd->add_option("--vertical", options->vertical, "The vertical component of FILE's station")->needs(pair);
  cmd->add_flag("--pad", options->pad, "Pad shorter components with zeros (default: trim to the shortest)")->needs(pair);
  cmd->add_option("--similarity", options->similarity, "Compress time by sqrt(N) for a 1/N model")->check(positive_number());
  cmd->add_option("--period", options->periods, "Print Sa at this period, s; repeat or separate with ','")
      ->delimiter(',')
      ->check(spectral_period());
  cmd->add_option("--damping", options->damping_percent, "Damping of the spectra, percent of critical (default 5)")
      ->check(number_check("a damping in percent of critical, from 0 to below 100",
                           [](double x) { return x >= 0.0 && x < 100.0; }, "PERCENT"));
  cmd->add_option("--avg-sa", options->avg_sa,
                  "Print AvgSa, the geometric mean of Sa at " + std::to_string(motion::kAverageSpectralAccelerationPoints) +
                      " log-spaced periods from LOW to HIGH s")
      ->delimiter(',')
      ->expected(2)
      ->type_name("LOW,HIGH")
      ->check(spectral_period());
  cmd->callback([options, time_step, scale, pga, pgv, pair]() {
    if (pair->count() > 0 && (pga->count() > 0 || pgv->count() > 0))
      throw InputError(std::string(pga->count() > 0 ? "--target-pga" : "--target-pgv") +
                       ": a station's components are scaled together; expected --scale with --pair");
    if (options->avg_sa.size() == 2 && options->avg_sa[0] > options->avg_sa[1])
      throw InputError("--avg-sa: expected LOW,HIGH with LOW at most HIGH, got " + number_text(options->avg_sa[0]) +
                       "," + number_text(options->avg_sa[1]));
    motion::ReadOptions read;
    auto format = motion::parse_record_format(options->format);
    if (!format) throw InputError("--format: expected automatic, peer_nga_west2, peer_old or columns");
    read.format = *format;
    if (!options->unit.empty()) {
      read.unit = motion::parse_acceleration_unit(options->unit);
      if (!read.unit) throw InputError("--unit: expected g, gal or m/s^2, got \"" + options->unit + "\"");
    }
    if (time_step->count() > 0) read.time_step = options->time_step;
    if (pair->count() > 0) {
      report_component_set(*options, read);
      return;
    }
    motion::Record record = motion::read_record(options->file, read);
    // A scaling refuses what no ground motion can be (a record without motion has no factor to
    // a target; no factor may take the PGA past the bound, nor the time step out of range).
    const auto scale_by = [&](const char* option, auto&& apply) {
      try {
        record = apply();
      } catch (const std::invalid_argument& e) {
        throw InputError(options->file + ": " + e.what() + " (asked for by " + option + ")");
      }
    };
    if (scale->count() > 0) scale_by("--scale", [&] { return motion::scaled(record, options->scale); });
    if (pga->count() > 0)
      scale_by("--target-pga", [&] { return motion::scaled_to_pga(record, units::gal_to_si(options->target_pga_gal)); });
    if (pgv->count() > 0)
      scale_by("--target-pgv", [&] { return motion::scaled_to_pgv(record, options->target_pgv_cm_s * units::kine); });
    if (options->similarity != 1.0)
      scale_by("--similarity", [&] { return motion::time_scaled(record, 1.0 / std::sqrt(options->similarity)); });
    const double pga = motion::peak_ground_acceleration(record);
    const double pgv = motion::peak_ground_velocity(record);
    // Spectra before the first line is printed, so that a refusal is the only line. The
    // options' checks bound every argument; a refusal would still name its option.
    const double zeta = damping_ratio_from_percent(options->damping_percent);
    const auto spectrum = [&](const char* option, auto&& compute) {
      try {
        return compute();
      } catch (const std::invalid_argument& e) {
        throw InputError(std::string(option) + ": " + e.what());
      }
    };
    const std::string damping = number_text(options->damping_percent) + " %";
    std::vector<std::pair<std::string, double>> spectral;
    for (const double period : options->periods)
      spectral.emplace_back("Sa(" + number_text(period) + " s, " + damping + ")",
                            spectrum("--period", [&] { return motion::spectral_acceleration(record, period, zeta); }));
    if (options->avg_sa.size() == 2) {
      const double low = options->avg_sa[0], high = options->avg_sa[1];
      spectral.emplace_back(
          "AvgSa(" + number_text(low) + "-" + number_text(high) + " s, " + damping + ")",
          spectrum("--avg-sa", [&] { return motion::average_spectral_acceleration(record, low, high, zeta); }));
    }
    std::cout << std::setprecision(5);
    std::cout << "record     " << record.source << "\n";
    std::cout << "samples    " << record.acceleration.size() << " at dt = " << record.time_step << " s (duration "
              << record.duration() << " s)\n";
    std::cout << "PGA        " << pga << " m/s^2 = " << units::si_to_gal(pga) << " gal = " << units::si_to_g(pga) << " g\n";
    std::cout << "PGV        " << pgv << " m/s = " << 100.0 * pgv << " cm/s (baseline-corrected)\n";
    for (const auto& [label, sa] : spectral)
      std::cout << label << "  " << sa << " m/s^2 = " << units::si_to_g(sa) << " g\n";
  });
}

}  // namespace caskdem::commands
