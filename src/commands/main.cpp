// caskdem: does a free-standing cask rock, slide or tip over in an earthquake?
// The command line: one executable, one subcommand per task.

#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "caskdem/build_info.h"
#include "commands/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
  // A file-size limit reached while writing (ulimit -f) is then a failed write, reported with
  // the file and leaving the previous checkpoint, not a signal that kills the run.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"caskdem: rocking, sliding and tip-over of free-standing casks in earthquakes (2D DEM)"};
  app.set_version_flag("--version", std::string(caskdem::build_info::version));
  app.require_subcommand(1);
  caskdem::commands::add_run(app);
  caskdem::commands::add_calibrate(app);
  caskdem::commands::add_sweep(app);
  caskdem::commands::add_motion(app);
  caskdem::commands::add_similarity(app);
  caskdem::commands::add_ensemble(app);
  caskdem::commands::add_plot(app);
  caskdem::commands::add_diagnose(app);
  caskdem::commands::add_evaluate_measured(app);
  caskdem::commands::add_risk(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are CLI11's successes; a command line that does not parse is bad
    // input: one line, as every other input error, and status 2.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "caskdem: error: " << e.what() << " (--help says what each command expects)\n";
    return 2;
  } catch (const caskdem::InputError& e) {
    std::cerr << "caskdem: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "caskdem: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
