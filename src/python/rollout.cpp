// caskdem.rollout: a caller's realisations on the ensemble engine (ensemble/rollout.h), the GIL
// released while they run. Between finished realisations the engine comes back here: on
// Python's main thread a pending Ctrl-C (a KeyboardInterrupt) stops the run, and the progress
// callback is called at most ten times a second.

#include "ensemble/rollout.h"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <thread>

#include "core/error.h"
#include "ensemble/execute.h"
#include "python/bindings.h"
#include "python/convert.h"

namespace caskdem::python {

namespace {

using Clock = std::chrono::steady_clock;

// The device of `kind` for this ensemble, opened once and kept (null: the CPU engine).
LaneDevice* device_for(Ensemble& e, DeviceKind kind) {
  if (!e.device_kind || *e.device_kind != kind) {
    e.device = open_device(kind, 0, "rollout's device=\"" + device_kind_name(kind) + "\"");
    e.device_kind = kind;
  }
  return e.device.get();
}

const MotionTables& tables_for(Ensemble& e, bool device) {
  std::unique_ptr<MotionTables>& tables = device ? e.device_tables : e.cpu_tables;
  if (!tables) {
    tables = std::make_unique<MotionTables>(
        e.plan, device ? MotionTables::kDeviceBudgetBytes : MotionTables::kDefaultBudgetBytes);
  }
  return *tables;
}

py::list rollout_columns(Ensemble& e, const py::dict& parameters, const std::string& device_name, int threads,
                         const std::string& isa_name, const std::function<void(std::int64_t, std::int64_t)>& progress) {
  RolloutOptions options;
  try {
    options.isa = parse_instruction_set(isa_name);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("isa: ") + error.what());
  }
  if (!instruction_set_available(options.isa)) {
    throw py::value_error("isa: this machine does not run " + isa_name + "; expected automatic or one of its own (" +
                          instruction_set_name(best_instruction_set()) + " and narrower)");
  }
  if (threads < 0) throw py::value_error("threads: expected 0 (OpenMP's default) or a positive number");
  options.threads = threads;
  DeviceKind kind;
  try {
    kind = parse_device_kind(device_name);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("device: ") + error.what());
  }

  ParameterColumns columns;
  std::int64_t count = 1;
  bool sized = false;
  for (const auto& [key, values] : parameters) {
    if (!py::isinstance<py::str>(key)) throw py::value_error("rollout parameters: expected names (strings) as keys");
    const std::string name = key.cast<std::string>();
    std::vector<double> column_values = column(values, name);
    if (column_values.size() != 1 || py::array::ensure(values).ndim() == 1) {
      if (sized && static_cast<std::int64_t>(column_values.size()) != count) {
        throw py::value_error("rollout parameter " + name + ": " + std::to_string(column_values.size()) +
                              " values, but an earlier column has " + std::to_string(count) +
                              "; expected one per realisation, or a single number for all");
      }
      count = static_cast<std::int64_t>(column_values.size());
      sized = true;
    }
    columns[name] = std::move(column_values);
  }
  const std::thread::id main_thread = std::this_thread::get_id();
  Clock::time_point last_signal_check = Clock::now(), last_progress = Clock::now();
  options.on_progress = [&](std::int64_t done) {
    const Clock::time_point now = Clock::now();
    const bool check_signals =
        std::this_thread::get_id() == main_thread && now - last_signal_check > std::chrono::milliseconds(50);
    const bool report = progress && (now - last_progress > std::chrono::milliseconds(100) || done == count);
    if (!check_signals && !report) return;
    py::gil_scoped_acquire gil;
    if (check_signals) {
      last_signal_check = now;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C: the engine stops, then raises
    }
    if (report) {
      last_progress = now;
      progress(done, count);
    }
  };
  EnsembleResults results;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(e.busy);
    // Checked against the ensemble's own plan, which keeps a calibration it computes for later
    // calls; the copy that runs them shares its motions.
    std::vector<RealisationInput> inputs = realisations_from_columns(e.plan, columns, count, options.isa);
    EnsemblePlan chosen = e.plan;
    chosen.set_realisations(std::move(inputs));
    options.device = device_for(e, kind);
    results = rollout(chosen, tables_for(e, options.device != nullptr), options);
  }
  py::list out;
  for (const EnsembleResults::Column& c : results.columns()) {
    if (c.name == "stripe") continue;  // a caller's realisations have no stripes
    out.append(py::make_tuple(c.name, c.unit, c.real ? py::object(array(*c.real)) : py::object(array(*c.integer))));
  }
  return out;
}

}  // namespace

void bind_rollout(py::module_& m) {
  m.def("rollout", &rollout_columns, py::arg("ensemble"), py::arg("parameters"), py::arg("device") = "auto",
        py::arg("threads") = 0, py::arg("isa") = "automatic", py::arg("progress") = nullptr);
}

}  // namespace caskdem::python
