// caskdem motion FILE: read a record and report its intensity after scaling: PGA, PGV and,
// when asked for, spectral accelerations Sa(T, zeta) and their average over a period range.

#include <cmath>
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

}  // namespace

void add_motion(CLI::App& app) {
  struct Options {
    std::string file, unit, format = "automatic";
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
  cmd->callback([options, time_step, scale, pga, pgv]() {
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
