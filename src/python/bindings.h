#pragma once
// The parts of the Python module, one file each: ensembles and their realisations
// (python/ensemble.cpp), rollout (python/rollout.cpp), fragility fits and site risk
// (python/statistics.cpp).

#include <pybind11/pybind11.h>

#include <memory>
#include <mutex>
#include <optional>

#include "ensemble/device_runner.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"

namespace caskdem::python {

namespace py = pybind11;

// An ensemble as Python holds it: the plan (the file's realisations), and what rollout keeps
// between calls: the motions' tables (for the CPU; whole, for a GPU) and the device it opened.
// Calls on one ensemble from several Python threads run one at a time (`busy`, taken with the
// GIL released): they share the plan's calibration, the tables and the device.
struct Ensemble {
  explicit Ensemble(const EnsembleSpec& spec) : plan(spec, InstructionSet::automatic) {}
  EnsemblePlan plan;
  std::unique_ptr<MotionTables> cpu_tables, device_tables;
  std::optional<DeviceKind> device_kind;  // the kind `device` was opened for
  std::unique_ptr<LaneDevice> device;     // null: the CPU
  std::mutex busy;
};

void bind_ensemble(py::module_& m);
void bind_rollout(py::module_& m);
void bind_statistics(py::module_& m);

}  // namespace caskdem::python
