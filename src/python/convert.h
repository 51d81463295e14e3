#pragma once
// What crosses between Python and the library: keyword arguments into the TOML document the
// file readers take (so that a table built in Python meets the files' names, units and checks),
// numpy arrays into columns and back, and the library's errors into Python's.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <toml++/toml.h>

#include <string>
#include <vector>

namespace caskdem::python {

namespace py = pybind11;

// A dict of tables (dicts), arrays of tables (lists of dicts), strings, numbers and booleans,
// as a TOML document. Anything else is a ValueError naming its key ("cask.mass").
toml::table toml_document(const py::dict& tables);

// A float64 column of one value or one per realisation; a ValueError naming `name` otherwise.
std::vector<double> column(const py::handle& values, const std::string& name);

py::array_t<double> array(const std::vector<double>& values);
py::array_t<std::int64_t> array(const std::vector<std::int64_t>& values);

// The library's InputError becomes ValueError; registered once by the module.
void register_errors(py::module_& m);

}  // namespace caskdem::python
