// caskdem run CASE.toml: one deterministic analysis, its summary, time histories and plot.

#include <filesystem>
#include <iostream>

#include "casefile/case_file.h"
#include "commands/commands.h"
#include "core/error.h"
#include "io/output_paths.h"
#include "io/run_output.h"
#include "io/run_output3d.h"
#include "sim/case_run.h"
#include "sim/case_run3d.h"

namespace caskdem::commands {

void add_run(CLI::App& app) {
  struct Options {
    std::string case_file;
    std::string out;
    std::string motion_file;
    bool no_plot = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* run = app.add_subcommand("run", "Run one case: summary, time histories (CSV, HDF5) and a plot");
  run->add_option("case", options->case_file, "Case file (TOML)")->required();
  run->add_option("--out", options->out, "Output directory (default: the case's [output] directory)");
  run->add_option("--motion", options->motion_file,
                  "Record file to use instead of [motion] file (for records that cannot be shipped, e.g. Hachinohe)");
  run->add_flag("--no-plot", options->no_plot, "Do not make the PNG");
  run->callback([options]() {
    Case c = load_case(options->case_file);
    if (!options->motion_file.empty()) {
      if (c.horizontal.kind != MotionSpec::Kind::record) {
        throw InputError(located(c.file, 0, "--motion replaces a record's file, but [motion] kind is not \"record\""));
      }
      if (!c.horizontal.pair.empty()) {
        throw InputError(located(c.file, 0, "--motion replaces one record, and this case's motion is a station's set "
                                            "(pair = ...): give the set's files in the case"));
      }
      c.horizontal.file = options->motion_file;
    }
    const std::filesystem::path directory =
        options->out.empty() ? c.output.directory : std::filesystem::path(options->out);
    prepare_output_directory(directory);
    if (c.cask.dimensions == 3) {
      const RunReport3D report = run_case3d(c, c.output.interval);
      print_summary3d(std::cout, report);
      write_summary_json3d(directory / "summary.json", report);
      if (c.output.csv) write_history_csv3d(directory / "history.csv", report);
      if (c.output.hdf5 || (c.output.plot && !options->no_plot)) write_run_hdf5_3d(directory / "run.h5", report);
      if (c.output.plot && !options->no_plot) {
        run_plot_script("plot_run3d.py", {(directory / "run.h5").string(), (directory / "history.png").string()});
      }
      std::cout << "wrote           " << directory.string() << "/\n";
      return;
    }
    const RunReport report = run_case(c, c.output.interval);
    print_summary(std::cout, report);
    write_summary_json(directory / "summary.json", report);
    if (c.output.csv) write_history_csv(directory / "history.csv", report);
    if (c.output.hdf5 || (c.output.plot && !options->no_plot)) write_run_hdf5(directory / "run.h5", report);
    if (c.output.plot && !options->no_plot) {
      run_plot_script("plot_run.py", {(directory / "run.h5").string(), (directory / "history.png").string()});
    }
    std::cout << "wrote           " << directory.string() << "/\n";
  });
}

}  // namespace caskdem::commands
