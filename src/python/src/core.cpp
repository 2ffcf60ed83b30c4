// core: the result type, the errors, the version and the knot table's path.
#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"

namespace ek::python {
namespace {

py::object field(const Result& r, const std::string& key) {
  if (!r.fields.contains(key)) return py::object();
  return r.fields[py::str(key)];
}

py::object deep_dict(const py::handle& value) {
  if (py::isinstance<Result>(value)) {
    py::dict d;
    for (const auto& [k, v] : value.cast<const Result&>().fields) d[k] = deep_dict(v);
    return std::move(d);
  }
  if (py::isinstance<py::list>(value)) {
    py::list l;
    for (const auto& v : value) l.append(deep_dict(v));
    return std::move(l);
  }
  return py::reinterpret_borrow<py::object>(value);
}

std::string short_repr(const py::handle& value) {
  if (py::isinstance<py::array>(value)) {
    const auto a = value.cast<py::array>();
    std::string shape;
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    return "<array (" + shape + (a.ndim() == 1 ? ",)>" : ")>");
  }
  if (py::isinstance<py::list>(value) && py::len(value) > 6) return "[... " + std::to_string(py::len(value)) + " items]";
  return py::repr(value).cast<std::string>();
}

std::string result_repr(const Result& r) {
  std::string s = (r.kind.empty() ? std::string("Result") : r.kind) + "(";
  bool first = true;
  for (const auto& [k, v] : r.fields) {
    s += (first ? "" : ", ") + k.cast<std::string>() + "=" + short_repr(v);
    first = false;
  }
  return s + ")";
}

void bind_result(py::module_& m) {
  py::class_<Result>(m, "Result", R"doc(
A result: named fields in a fixed order, read as attributes (r.energy) or
items (r["energy"]). The fields are the JSON keys of the matching `knots`
command (docs/cli.md), with null as None; curves and matrices are numpy
arrays. Nested objects (a relaxation's report) are Results too.)doc")
      .def("__getattr__",
           [](const Result& r, const std::string& key) {
             py::object v = field(r, key);
             if (!v) throw py::attribute_error("result has no field '" + key + "'");
             return v;
           })
      .def("__getitem__",
           [](const Result& r, const std::string& key) {
             py::object v = field(r, key);
             if (!v) throw py::key_error(key);
             return v;
           })
      .def("__contains__", [](const Result& r, const std::string& key) { return r.fields.contains(key); })
      .def("__dir__", [](const Result& r) { return py::list(r.fields.attr("keys")()); })
      .def("keys", [](const Result& r) { return py::list(r.fields.attr("keys")()); }, "The field names, in order.")
      .def("items", [](const Result& r) { return py::list(r.fields.attr("items")()); },
           "(name, value) pairs, in order.")
      .def("to_dict", [](const Result& r) { return deep_dict(py::cast(r)); },
           "The fields as a dict; nested results as dicts (equal to the command's JSON for the JSON keys).")
      .def("__repr__", &result_repr);
}

}  // namespace

void bind_core(py::module_& m) {
  bind_result(m);
  static py::exception<TopologyError> topology(m, "TopologyError", PyExc_RuntimeError);
  topology.doc() = "A computed curve changed its knot type (the Alexander polynomial differs): never a silent result.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const TopologyError& e) {
      PyErr_SetString(topology.ptr(), e.what());
    }
  });
  m.attr("__version__") = project_version();
  m.def("knot_table_path", &knot_table_path,
        "Path of the KnotInfo table read: $KNOT_TABLE if set, otherwise the path built in.");
}

}  // namespace ek::python
