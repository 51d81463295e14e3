// The Python module's native part (_caskdem), imported by the caskdem package
// (src/python/caskdem/__init__.py, which documents the public functions). Everything here calls
// the library the command line calls; nothing of the model is written twice.
//
// Cases and ensembles come from their files or from keyword arguments made into the same TOML
// document (python/convert.h), so that both meet the same readers and checks.

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <toml++/toml.h>

#include <sstream>

#include "casefile/case_file.h"
#include "caskdem/build_info.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/limit_state_file.h"
#include "ensemble/rollout.h"
#include "io/run_output.h"
#include "io/run_output3d.h"
#include "python/bindings.h"
#include "python/convert.h"
#include "sim/case_run.h"
#include "sim/case_run3d.h"

namespace caskdem::python {

namespace {

std::string toml_text(const toml::table& document) {
  std::ostringstream text;
  text << toml::toml_formatter(document);
  return text.str();
}

py::list history(const std::vector<HistoryColumn>& columns) {
  py::list out;
  for (const HistoryColumn& c : columns) out.append(py::make_tuple(c.name, c.unit, array(c.values)));
  return out;
}

// One run of a case: (summary.json's text, [(column, unit, samples)]).
py::tuple run_case_columns(const Case& source, std::optional<double> output_interval) {
  const double interval = output_interval.value_or(source.output.interval);
  if (!(interval >= 0.0) || !std::isfinite(interval)) {
    throw py::value_error("output_interval: expected a non-negative number of seconds (0: no histories)");
  }
  if (source.cask.dimensions == 3) {
    RunReport3D report;
    {
      py::gil_scoped_release release;
      report = run_case3d(source, interval);
    }
    return py::make_tuple(summary_json_text3d(report), history(history_columns3d(report)));
  }
  RunReport report;
  {
    py::gil_scoped_release release;
    report = run_case(source, interval);
  }
  return py::make_tuple(summary_json_text(report), history(history_columns(report)));
}

}  // namespace

}  // namespace caskdem::python

PYBIND11_MODULE(_caskdem, m) {
  using namespace caskdem;
  using namespace caskdem::python;
  m.doc() = "caskdem's native part; use the caskdem package.";
  m.attr("__version__") = build_info::version;
  register_errors(m);

  py::class_<Case>(m, "Case")
      .def_property_readonly("title", [](const Case& c) { return c.title; })
      .def_property_readonly("name", [](const Case& c) { return c.name; })
      .def_property_readonly("file", [](const Case& c) { return c.file.string(); })
      .def_property_readonly("dimensions", [](const Case& c) { return c.cask.dimensions; })
      .def("__repr__", [](const Case& c) {
        return "<caskdem.Case '" + c.title + "' (" + std::to_string(c.cask.dimensions) + "D) from " + c.file.string() +
               ">";
      });

  m.def(
      "load_case", [](const std::filesystem::path& file) { return load_case(file); }, py::arg("file"));
  // `source` names the tables in messages as a file's name would ("keyword arguments"), and its
  // folder is where relative paths start (the working directory for a bare name).
  m.def(
      "case_from_tables",
      [](const py::dict& tables, const std::string& source) { return read_case(toml_document(tables), source); },
      py::arg("tables"), py::arg("source"));
  m.def("run", &run_case_columns, py::arg("case"), py::arg("output_interval") = py::none());

  bind_ensemble(m);
  m.def(
      "ensemble_from_tables",
      [](const py::dict& tables, const std::string& source) {
        const toml::table document = toml_document(tables);
        return std::make_shared<Ensemble>(read_ensemble(document, source, toml_text(document)));
      },
      py::arg("tables"), py::arg("source"));
  bind_rollout(m);
  bind_statistics(m);
}
