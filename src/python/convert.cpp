#include "python/convert.h"

#include "core/error.h"

namespace caskdem::python {

namespace {

[[noreturn]] void refuse(const std::string& key, const py::handle& value, const std::string& expected) {
  throw py::value_error("key " + key + ": expected " + expected + ", got " +
                        py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                        py::repr(value).cast<std::string>());
}

toml::table table_of(const py::dict& tables, const std::string& prefix);

// One value (bool before int: Python's True is an int).
void put(toml::array& array, const py::handle& value, const std::string& key);

std::string key_of(const std::string& prefix, const py::handle& key) {
  if (!py::isinstance<py::str>(key)) refuse(prefix.empty() ? "(top level)" : prefix, key, "a string key");
  const std::string name = key.cast<std::string>();
  return prefix.empty() ? name : prefix + "." + name;
}

// numpy's scalars pass as the Python kinds they stand for (np.bool_, its integers by __index__,
// its floats by __float__), its arrays as lists; numpy itself is never imported here, so keyword
// tables work in an interpreter without it.
template <class Insert>
void insert_value(const py::handle& value, const std::string& key, Insert&& insert) {
  const std::string type = py::str(py::type::of(value).attr("__name__")).cast<std::string>();
  if (py::isinstance<py::bool_>(value) || type == "bool_") {
    insert(py::bool_(py::reinterpret_borrow<py::object>(value)).cast<bool>());
  } else if (PyIndex_Check(value.ptr()) && !PyFloat_Check(value.ptr())) {
    insert(py::int_(py::reinterpret_borrow<py::object>(value)).cast<std::int64_t>());
  } else if (py::isinstance<py::str>(value)) {
    insert(value.cast<std::string>());
  } else if (py::isinstance<py::dict>(value)) {
    insert(table_of(value.cast<py::dict>(), key));
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) || type == "ndarray") {
    toml::array array;
    std::size_t k = 0;
    for (const py::handle item : py::iter(value)) put(array, item, key + "[" + std::to_string(k++) + "]");
    insert(std::move(array));
  } else if (PyFloat_Check(value.ptr()) || py::hasattr(value, "__float__")) {
    insert(py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
  } else {
    refuse(key, value, "a table (dict), a list, a string, a number or a boolean");
  }
}

void put(toml::array& array, const py::handle& value, const std::string& key) {
  insert_value(value, key, [&](auto&& v) { array.push_back(std::forward<decltype(v)>(v)); });
}

toml::table table_of(const py::dict& tables, const std::string& prefix) {
  toml::table table;
  for (const auto& [key, value] : tables) {
    const std::string path = key_of(prefix, key);
    const std::string name = key.cast<std::string>();
    if (value.is_none()) refuse(path, value, "a value (leave the key out for its default)");
    insert_value(value, path,
                              [&](auto&& v) { table.insert_or_assign(name, std::forward<decltype(v)>(v)); });
  }
  return table;
}

}  // namespace

toml::table toml_document(const py::dict& tables) { return table_of(tables, ""); }

std::vector<double> column(const py::handle& values, const std::string& name) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.ndim() > 1) {
    throw py::value_error("rollout parameter " + name +
                          ": expected a number or a one-dimensional array of numbers, got " +
                          py::repr(values).cast<std::string>().substr(0, 80));
  }
  return std::vector<double>(a.data(), a.data() + a.size());
}

py::array_t<double> array(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::array_t<std::int64_t> array(const std::vector<std::int64_t>& values) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

void register_errors(py::module_& m) {
  (void)m;
  // Bad input is the caller's: ValueError, with the message the command line prints.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace caskdem::python
