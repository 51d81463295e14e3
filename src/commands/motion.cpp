// caskdem motion FILE: read a record and report its intensity after scaling.

#include <iomanip>
#include <iostream>

#include "commands/commands.h"
#include "core/error.h"
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
  cmd->add_option("--time-step", options->time_step, "Time step of a one-column file, s");
  auto* scale = cmd->add_option("--scale", options->scale, "Multiply the record by this factor");
  auto* pga = cmd->add_option("--target-pga", options->target_pga_gal, "Scale to this PGA, gal")->excludes(scale);
  cmd->add_option("--target-pgv", options->target_pgv_cm_s, "Scale to this PGV, cm/s")->excludes(scale)->excludes(pga);
  cmd->add_option("--similarity", options->similarity, "Compress time by sqrt(N) for a 1/N model")->check(CLI::PositiveNumber);
  cmd->callback([options]() {
    motion::ReadOptions read;
    auto format = motion::parse_record_format(options->format);
    if (!format) throw InputError("--format: expected automatic, peer_nga_west2, peer_old or columns");
    read.format = *format;
    if (!options->unit.empty()) {
      read.unit = motion::parse_acceleration_unit(options->unit);
      if (!read.unit) throw InputError("--unit: expected g, gal or m/s^2, got \"" + options->unit + "\"");
    }
    if (options->time_step > 0.0) read.time_step = options->time_step;
    motion::Record record = motion::read_record(options->file, read);
    if (options->scale != 0.0) record = motion::scaled(record, options->scale);
    if (options->target_pga_gal > 0.0) record = motion::scaled_to_pga(record, units::gal_to_si(options->target_pga_gal));
    if (options->target_pgv_cm_s > 0.0) record = motion::scaled_to_pgv(record, options->target_pgv_cm_s * 0.01);
    if (options->similarity != 1.0) record = motion::time_scaled(record, 1.0 / std::sqrt(options->similarity));
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
