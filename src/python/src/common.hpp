#pragma once
// Shared pieces of the bindings: the result object (a record whose fields
// are the keys of the CLI's JSON), the JSON -> Python conversion, and the
// numpy <-> Points conversions. Each library module has its own binding file
// (geometry.cpp, knots.cpp, ...), declared here and called by module.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "ek/core/json.hpp"
#include "ek/geometry/types.hpp"

namespace ek::python {

namespace py = pybind11;

/// A result: named fields (Python attributes and items) in a fixed order.
/// Built from a library JSON description, so its fields are the JSON keys
/// of the matching `knots` command; arrays (positions, matrices) are added
/// as numpy fields.
struct Result {
  std::string kind;  ///< shown by repr(), e.g. "relax"
  py::dict fields;
};

/// The JSON value as Python: objects as Result (kind = `kind`), arrays as
/// lists, null as None.
py::object from_json(const Json& j, const std::string& kind = "");
/// A Result of a JSON object.
Result result_from_json(const Json& j, const std::string& kind);

/// A float array of shape (n, 3) (any sequence numpy converts) as Points,
/// checked as a closed curve (validate_closed_curve: at least 4 vertices,
/// finite, no zero-length edge); `name` names the argument in messages.
Points curve_arg(const py::handle& array, const std::string& name);
/// A finite float array of shape (n, 3) as Points, not checked as a curve
/// (vectors such as velocities: equal rows allowed).
Points rows3_arg(const py::handle& array, const std::string& name);
/// Points as a new float64 numpy array of shape (n, 3).
py::array_t<double> to_array(const Points& P);
/// A dense matrix as a new float64 numpy array (rows, cols).
py::array_t<double> to_array(const Eigen::MatrixXd& M);
/// A square float matrix (N, N) from numpy; `name` names the argument.
Eigen::MatrixXd to_matrix(const py::handle& array, const std::string& name);

void bind_core(py::module_& m);
void bind_geometry(py::module_& m);
void bind_knots(py::module_& m);
void bind_embedding(py::module_& m);
void bind_lattice(py::module_& m);
void bind_contact(py::module_& m);
void bind_solver(py::module_& m);
void bind_analysis(py::module_& m);
void bind_mechanics(py::module_& m);
void bind_dataset(py::module_& m);

}  // namespace ek::python
