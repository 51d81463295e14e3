// caskdem calibrate CASE.toml: the free-vibration restitution of the case, and the damping
// ratio that gives a target restitution (the source paper's calibration of h).

#include <iomanip>
#include <iostream>

#include "casefile/case_file.h"
#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "sim/case_run.h"
#include "sim/free_vibration.h"

namespace caskdem::commands {

void add_calibrate(CLI::App& app) {
  struct Options {
    std::string case_file;
    double target = 0.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Free-vibration restitution, and the damping ratio h that reaches a target restitution");
  cmd->add_option("case", options->case_file, "Case file (TOML)")->required();
  cmd->add_option("--target", options->target,
                  "Target restitution (default: [free_vibration] target_restitution of the case)")
      ->check(number_within("a restitution", 0.01, 0.9999));
  cmd->callback([options]() {
    const Case c = load_case(options->case_file);
    require_planar(c, "calibrate");
    const Model model = build_case_model(c);
    const FreeVibrationResult now = free_vibration(model, c.parameters, c.free_vibration);
    std::cout << std::setprecision(5);
    std::cout << "free vibration  released at " << now.initial_tilt << " rad (" << c.free_vibration.initial_tilt_ratio
              << " alpha), damping ratio " << c.parameters.damping_ratio << "\n";
    std::cout << "peaks |omega|   ";
    for (double p : now.peaks) std::cout << p << " ";
    std::cout << "rad/s\n";
    std::cout << "restitution     " << now.restitution << " (mean of " << c.free_vibration.ratios
              << " successive peak ratios)\n";
    const double target = options->target > 0.0 ? options->target : c.free_vibration.target_restitution.value_or(0.0);
    if (target <= 0.0) {
      std::cout << "no target given (--target or [free_vibration] target_restitution): nothing to calibrate\n";
      return;
    }
    const CalibrationResult result = calibrate_damping(c, target);
    std::cout << "target          " << result.target << "\n";
    std::cout << "damping ratio   h = " << std::setprecision(6) << result.damping_ratio << " gives restitution "
              << result.restitution << " (" << result.evaluations << " free-vibration runs)\n";
    std::cout << "reachable       " << result.lowest_restitution << " (h = " << result.largest_damping << ") to "
              << result.highest_restitution << " (h = " << result.smallest_damping << ")\n";
    std::cout << "case file       [damping] ratio = " << result.damping_ratio << "\n";
  });
}

}  // namespace caskdem::commands
