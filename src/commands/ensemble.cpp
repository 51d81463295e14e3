// caskdem ensemble FILE: Monte Carlo realisations in SIMD lanes, stripe probabilities and
// fragility curves, written to HDF5 (resumable) with a PNG.

#include <omp.h>

#include <filesystem>
#include <iomanip>
#include <iostream>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "core/units.h"
#include "ensemble/device_runner.h"
#include "ensemble/execute.h"
#include "ensemble/report_text.h"
#include "ensemble/results.h"
#ifdef CASKDEM_WITH_MPI
#include "ensemble/distributed.h"
#else
namespace caskdem {
class MpiSession;  // ensembles run in one process without MPI
}
#endif
#include "io/hdf5_file.h"
#include "io/output_paths.h"
#include "io/run_output.h"
#include "model/build.h"

namespace caskdem::commands {

namespace {

struct EnsembleOptions {
  std::string file, out, isa = "automatic", device;  // device empty: the ensemble file's [run] device
  int threads = 0;
  bool resume = false, no_plot = false, quiet = false;
};
// One process, or one rank of an MPI job (mpi not null): only rank 0 reports and plots.
void run_ensemble_command(const EnsembleOptions& options, [[maybe_unused]] const MpiSession* mpi) {
  const EnsembleSpec spec = load_ensemble(options.file);
  InstructionSet isa;
  try {
    isa = parse_instruction_set(options.isa);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--isa: ") + e.what());
  }
  if (!instruction_set_available(isa)) {
    throw InputError("--isa: " + instruction_set_name(isa) + " is not available on this machine; expected automatic (" +
                     instruction_set_name(best_instruction_set()) + " here) or an instruction set it has");
  }
  const std::filesystem::path out =
      options.out.empty() ? std::filesystem::path("results") / (spec.name + ".h5") : std::filesystem::path(options.out);
  bool root = true;
#ifdef CASKDEM_WITH_MPI
  if (mpi) root = mpi->rank() == 0;
#endif
  if (root) prepare_output_file(out);
  if (options.resume && !std::filesystem::exists(out)) {
    throw InputError(out.string() + ": no such file to resume (run without --resume first)");
  }
  if (options.resume) check_result_file_seal(out);  // a damaged file refused before the plan's work
  // Where the realisations run: --device, else the file's [run] device, else auto.
  const std::string device_text = options.device.empty() ? spec.device : options.device;
  const std::string device_source =
      options.device.empty()
          ? (spec.device_line > 0 ? located(spec.file, spec.device_line, "[run] device") : "--device auto")
          : "--device " + options.device;
  int preferred_device = 0;
#ifdef CASKDEM_WITH_MPI
  if (mpi) preferred_device = mpi->local_rank();
#endif
  const std::unique_ptr<LaneDevice> device =
      open_device(parse_device_kind(device_text), preferred_device, device_source);
  const EnsemblePlan plan(spec, isa);
  if (root) {
    std::cout << "ensemble        " << spec.title << "\n";
    std::cout << "realisations    " << plan.size() << " ("
              << (spec.outer_count() > 1 ? std::to_string(spec.outer_count()) + " epistemic outer points x " : "")
              << spec.levels.size() << " stripes x " << spec.realisations_per_stripe << ", " << plan.motion_count()
              << " motions)\n";
    std::cout << "time step       " << plan.model().time_step << " s (" << slider_name_of(plan.model().whole_step_terms)
              << " slider), alpha " << plan.stability_angle() << " rad\n";
    std::cout << "contact         " << contact_law_text(plan.model(), plan.spec().base.parameters.impact_damping,
                                                          plan.model().normal_law == NormalLaw::hunt_crossley
                                                              ? " + each realisation's damping ratio's share"
                                                              : "") << "\n";
    if (const std::string restitution = restitution_text(plan); !restitution.empty()) {
      std::cout << "restitution     " << restitution << "\n";
    }
    if (device) {
      const std::int64_t lanes =
          std::min<std::int64_t>(plan.size(), device->lane_capacity(plan.three_d() ? 3 : 2, plan.model().friction_law));
      std::cout << "device          GPU " << device->name() << ", " << lanes << " lanes (one realisation per thread)\n";
    } else {
      std::cout << "device          CPU, "
                << instruction_set_name(isa == InstructionSet::automatic ? best_instruction_set() : isa) << ", "
                << (options.threads > 0 ? options.threads : omp_get_max_threads()) << " threads\n";
    }
#ifdef CASKDEM_WITH_MPI
    if (mpi) std::cout << "MPI             " << mpi->size() << " ranks\n";
#endif
    std::cout.flush();
  }
  ExecuteOptions execute;
  execute.isa = isa;
  execute.threads = options.threads;
  execute.resume = options.resume;
  execute.progress = !options.quiet;
  execute.output = out;
  execute.device = device.get();
#ifdef CASKDEM_WITH_MPI
  const ExecuteReport report = mpi ? execute_ensemble_distributed(plan, execute, *mpi) : execute_ensemble(plan, execute);
#else
  const ExecuteReport report = execute_ensemble(plan, execute);
#endif
  if (!root) return;
  std::cout << std::setprecision(4) << "wall time       " << report.wall_seconds << " s (" << report.realisations_run
            << " realisations in this run)\n";
  for (const LimitStateSummary& s : report.limit_states) {
    for (const std::string& line : limit_state_lines(plan, s)) std::cout << line << "\n";
    if (spec.outer_count() > 1) {
      const fragility::NestedFit& n = s.nested;
      std::cout << std::left << std::setw(20) << "  family";
      if (n.fitted) {
        std::cout << "A_m " << intensity_text(spec.measure, n.median) << " [" << intensity_text(spec.measure, n.median_low)
                  << ", " << intensity_text(spec.measure, n.median_high) << "], beta_R " << n.beta_r << " ["
                  << n.beta_r_low << ", " << n.beta_r_high << "], beta_U " << n.beta_u << " [" << n.beta_u_low << ", "
                  << n.beta_u_high << "] (" << 100.0 * n.confidence << " %, " << n.outer_points << " outer points)\n";
      } else {
        std::cout << "no family: " << n.reason << "\n";
      }
    }
  }
  std::cout << "wrote           " << out.string() << "\n";
  for (const std::filesystem::path& table : report.tables) std::cout << "wrote           " << table.string() << "\n";
  if (!options.no_plot) {
    std::filesystem::path png = out;
    png.replace_extension(".png");
    run_plot_script("plot_fragility.py", {out.string(), png.string()});
    std::cout << "wrote           " << png.string() << "\n";
  }
}

}  // namespace

void add_ensemble(CLI::App& app) {
  auto options = std::make_shared<EnsembleOptions>();
  CLI::App* cmd = app.add_subcommand("ensemble", "Run an ensemble: realisations, stripe probabilities, fragility curves");
  cmd->add_option("file", options->file, "Ensemble file (TOML)")->required();
  cmd->add_option("--out", options->out, "Result file (HDF5; default results/<name>.h5)");
  cmd->add_flag("--resume", options->resume, "Continue an interrupted run from its result file");
  cmd->add_option("--threads", options->threads, "OpenMP threads (default: all cores)")->check(thread_count());
  cmd->add_option("--isa", options->isa, "Instruction set of the CPU engine: automatic, avx512f, avx2, sse2 or scalar");
  cmd->add_option("--device", options->device,
                  "Where the realisations run: auto (a GPU when one is present), cpu or cuda (default: the "
                  "ensemble file's [run] device, else auto)")
      ->check(CLI::IsMember({"auto", "cpu", "cuda"}));
  cmd->add_flag("--no-plot", options->no_plot, "Do not make the PNG");
  cmd->add_flag("--quiet", options->quiet, "No progress output");
  cmd->callback([options]() {
#ifdef CASKDEM_WITH_MPI
    if (launched_by_mpi()) {
      const MpiSession mpi(nullptr, nullptr);
      try {
        run_ensemble_command(*options, &mpi);
      } catch (const InputError&) {
        // Every rank reads the same files and fails alike: one message, from rank 0.
        if (mpi.rank() == 0) throw;
      }
      return;
    }
#endif
    run_ensemble_command(*options, nullptr);
  });
}

void add_plot(CLI::App& app) {
  struct Options {
    std::string file, out;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("plot", "Plot the fragility curves of an ensemble result file");
  cmd->add_option("file", options->file, "Ensemble result file (HDF5)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", options->out, "PNG file (default: beside the result file)");
  cmd->callback([options]() {
    // What the plotting script reads, checked here: one message instead of a Python traceback.
    try {
      verify_ensemble_file(options->file);
      const hdf5::Group root = hdf5::open_file(options->file);
      if (!root.has("limit_states"))
        throw InputError(located(options->file, 0, "has no limit_states group; expected a result file of caskdem "
                                                    "ensemble whose run completed"));
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const InputError*>(&e)) throw;
      throw InputError(located(options->file, 0, std::string(e.what()) + "; expected a result file of caskdem ensemble"));
    }
    std::filesystem::path png = options->out;
    if (png.empty()) png = std::filesystem::path(options->file).replace_extension(".png");
    prepare_output_file(png);
    run_plot_script("plot_fragility.py", {options->file, png.string()});
    std::cout << "wrote " << png.string() << "\n";
  });
}

}  // namespace caskdem::commands
