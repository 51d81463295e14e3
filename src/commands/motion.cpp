// caskdem motion FILE: read a record and report its intensity after scaling.

#include <cmath>
#include <iomanip>
#include <iostream>
#include <stdexcept>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "core/text.h"
#include "core/units.h"
#include "motion/record.h"

namespace caskdem::commands {

void add_motion(CLI::App& app) {
  struct Options {
    std::string file, unit, format = "automatic";
    double time_step = 0.0, scale = 0.0, target_pga_gal = 0.0, target_pgv_cm_s = 0.0, similarity = 1.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("motion", "Read an accelerogram and print its PGA, PGV, duration (after scaling)");
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
  cmd->callback([options, time_step, scale, pga, pgv]() {
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
    std::cout << std::setprecision(5);
    std::cout << "record     " << record.source << "\n";
    std::cout << "samples    " << record.acceleration.size() << " at dt = " << record.time_step << " s (duration "
              << record.duration() << " s)\n";
    std::cout << "PGA        " << pga << " m/s^2 = " << units::si_to_gal(pga) << " gal = " << units::si_to_g(pga) << " g\n";
    std::cout << "PGV        " << pgv << " m/s = " << 100.0 * pgv << " cm/s (baseline-corrected)\n";
  });
}

}  // namespace caskdem::commands
