// caskdem sweep CASE.toml: maximum rotation against frequency under sinusoidal table
// motion for several displacement amplitudes, DEM against Housner's rigid-block theory with
// the DEM's own restitution (the source paper's Figs. 4 and 11).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "casefile/case_file.h"
#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "core/text.h"
#include "core/units.h"
#include "io/output_paths.h"
#include "io/run_output.h"
#include "sim/case_run.h"
#include "sim/free_vibration.h"
#include "sim/rigid_equivalent.h"

namespace caskdem::commands {

namespace {

struct SweepPoint {
  double amplitude = 0.0, frequency = 0.0;
  double dem_rotation = 0.0, theory_rotation = 0.0;
  bool dem_tipped = false, theory_tipped = false;
};

// Finite positive numbers separated by commas.
std::vector<double> parse_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::optional<double> value = parse_double(trim(item));
    if (!value || !std::isfinite(*value) || !(*value > 0.0))
      throw InputError(option + ": expected finite numbers above zero separated by commas, got \"" + text + "\"");
    values.push_back(*value);
  }
  if (values.empty()) throw InputError(option + ": expected at least one number");
  return values;
}

// More frequencies than this is a step typed in the wrong unit (a sweep runs each amplitude at each).
constexpr double kMostFrequencies = 10000;
// Longer shaking than this (s) is a count typed in the wrong unit, as for a case file's sine.
constexpr double kLongestShaking = 1e5;

}  // namespace

void add_sweep(CLI::App& app) {
  struct Options {
    std::string case_file, out;
    std::string amplitudes = "0.5,1.0,1.5";
    std::string frequencies = "1,12,0.5";
    double cycles = 10.0, ramp_cycles = 2.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Max rotation vs frequency of sinusoidal table motion: DEM against rigid-block theory (table and PNG)");
  cmd->add_option("case", options->case_file, "Case file (TOML): cask, contact, friction, damping")->required();
  cmd->add_option("--amplitudes", options->amplitudes, "Displacement amplitudes, cm (comma separated)");
  cmd->add_option("--frequencies", options->frequencies, "first,last,step in Hz");
  cmd->add_option("--cycles", options->cycles, "Cycles per test")->check(positive_number());
  cmd->add_option("--ramp-cycles", options->ramp_cycles, "Cycles of ramp up and down")->check(non_negative_number());
  cmd->add_option("--out", options->out, "Output directory (default results/<case>-sweep)");
  cmd->callback([options]() {
    const Case base = load_case(options->case_file);
    require_planar(base, "sweep");
    const std::vector<double> amplitudes = parse_list(options->amplitudes, "--amplitudes");
    const std::vector<double> range = parse_list(options->frequencies, "--frequencies");
    if (range.size() != 3 || !(range[1] >= range[0]) || (range[1] - range[0]) / range[2] > kMostFrequencies) {
      throw InputError("--frequencies: expected first,last,step with 0 < first <= last, step > 0 and at most " +
                       number_text(kMostFrequencies) + " frequencies, got \"" + options->frequencies + "\"");
    }
    if (options->ramp_cycles > 0.5 * options->cycles) {
      throw InputError("--ramp-cycles " + number_text(options->ramp_cycles) + ": expected at most half of --cycles (" +
                       number_text(options->cycles) + "): the ramps up and down must fit in the shaking");
    }
    if (options->cycles / range[0] > kLongestShaking) {
      throw InputError("--cycles " + number_text(options->cycles) + ": expected at most " + number_text(kLongestShaking) +
                       " s of shaking at the lowest frequency (" + number_text(range[0]) + " Hz)");
    }
    const std::filesystem::path directory =
        options->out.empty() ? std::filesystem::path("results") / (base.name + "-sweep") : std::filesystem::path(options->out);
    prepare_output_directory(directory);
    std::vector<double> frequencies;
    for (double f = range[0]; f <= range[1] * (1.0 + 1e-12); f += range[2]) frequencies.push_back(f);
    const Model model = build_case_model(base);
    const FreeVibrationResult fv = free_vibration(model, base.parameters, base.free_vibration);
    const theory::RigidBlock block = rigid_equivalent(model, base.parameters);
    std::cout << "theory          Housner block b = " << block.half_width << " m, h = " << block.centre_height
              << " m, alpha = " << block.slenderness() << " rad, restitution " << fv.restitution
              << " (the DEM's free vibration)\n";

    std::vector<SweepPoint> points;
    std::vector<std::unique_ptr<motion::TableMotion>> motions;  // made here: nothing may throw in the parallel loop
    for (double a : amplitudes) {
      for (double f : frequencies) {
        points.push_back({units::cm_to_m(a), f});
        motions.push_back(motion::make_sine(points.back().amplitude, f, options->cycles, options->ramp_cycles));
      }
    }
    const LaneParameters<double> lane = lane_parameters(model, base.parameters);
#pragma omp parallel for schedule(dynamic)
    for (std::size_t i = 0; i < points.size(); ++i) {
      SweepPoint& p = points[i];
      const motion::TableMotion* motion = motions[i].get();
      const double duration = motion->duration() + base.settle_time;
      const RunResult run = simulate(model, lane, rest_state(model, lane), {motion, nullptr}, {duration, 0.0});
      p.dem_rotation = run.summary.max_abs_rotation;
      p.dem_tipped = run.summary.tipped_over;
      theory::RockingOptions rocking;
      rocking.restitution = fv.restitution;
      rocking.duration = duration;
      rocking.tip_over_angle = model.tip_over_angle;
      const theory::RockingResponse response =
          theory::simulate_rocking(block, [&](double t) { return motion->acceleration(t); }, rocking);
      p.theory_rotation = response.max_abs_rotation;
      p.theory_tipped = response.tipped_over;
    }

    // What the sweep compared beside the table (which pandas and numpy read with their defaults).
    std::ofstream(directory / "sweep.json") << nlohmann::json{{"case_file", base.file.string()},
                                                              {"dem_stability_angle_rad", model.stability_angle},
                                                              {"theory_stability_angle_rad", block.slenderness()},
                                                              {"restitution", fv.restitution}}
                                                   .dump(2)
                                            << "\n";
    std::ofstream csv(directory / "sweep.csv");
    csv << "amplitude_cm,frequency_Hz,dem_max_rotation_rad,dem_rotation_ratio,dem_tipped,theory_max_rotation_rad,"
           "theory_rotation_ratio,theory_tipped\n";
    std::cout << std::setprecision(4) << "amplitude cm  frequency Hz  DEM theta/alpha  theory theta/alpha\n";
    for (const SweepPoint& p : points) {
      csv << units::m_to_cm(p.amplitude) << ',' << p.frequency << ',' << p.dem_rotation << ','
          << p.dem_rotation / model.stability_angle << ',' << int(p.dem_tipped) << ',' << p.theory_rotation << ','
          << p.theory_rotation / block.slenderness() << ',' << int(p.theory_tipped) << '\n';
      std::cout << std::setw(12) << units::m_to_cm(p.amplitude) << std::setw(14) << p.frequency << std::setw(17)
                << p.dem_rotation / model.stability_angle << (p.dem_tipped ? " tipped" : "       ") << std::setw(12)
                << p.theory_rotation / block.slenderness() << (p.theory_tipped ? " tipped" : "") << "\n";
    }
    csv.close();
    run_plot_script("plot_sweep.py", {(directory / "sweep.csv").string(), (directory / "sweep.png").string()});
    std::cout << "wrote           " << directory.string() << "/sweep.csv, sweep.png\n";
  });
}

}  // namespace caskdem::commands
