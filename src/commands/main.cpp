// caskdem: does a free-standing cask rock, slide or tip over in an earthquake?
// The command line: one executable, one subcommand per task.

#include <algorithm>
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "caskdem/build_info.h"
#include "commands/commands.h"
#include "core/error.h"

namespace {

// Edits (insertions, deletions, substitutions) between two words (Levenshtein).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "did you mean 'ensemble'?" for a first word that is no command but close to one.
std::string suggestion(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string word = argv[1];
  std::string best, all;
  std::size_t best_distance = 3;  // at most two edits away
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->get_name() == word) return "";
    all += (all.empty() ? "" : ", ") + command->get_name();
    const std::size_t d = edit_distance(word, command->get_name());
    if (d < best_distance) best_distance = d, best = command->get_name();
  }
  if (!best.empty()) return "'" + word + "' is not a command; did you mean '" + best + "'?";
  return "'" + word + "' is not a command; expected one of " + all;
}

}  // namespace

int main(int argc, char** argv) {
  // A file-size limit reached while writing (ulimit -f) is then a failed write, reported with
  // the file and leaving the previous checkpoint, not a signal that kills the run.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"caskdem: rocking, sliding and tip-over of free-standing casks in earthquakes: a Distinct Element "
               "Method in 2D (a section) and 3D (a cylinder), ensembles on SIMD lanes or a GPU, fragility and site risk"};
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
  caskdem::commands::add_plan_test(app);
  caskdem::commands::add_risk(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are CLI11's successes; a command line that does not parse is bad
    // input: one line, as every other input error, and status 2.
    if (e.get_exit_code() == 0) return app.exit(e);
    const std::string hint = suggestion(app, argc, argv);
    std::cerr << "caskdem: error: " << (hint.empty() ? std::string(e.what()) : hint)
              << " (--help says what each command expects)\n";
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
