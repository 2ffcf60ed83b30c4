#include "common.hpp"

#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"

namespace ek::python {
namespace {

/// Text from files (knot names, attribute names, messages) may not be UTF-8:
/// such bytes become U+FFFD, as in the command's JSON (print_json).
py::str text(const std::string& s) {
  PyObject* o = PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}

}  // namespace

py::object from_json(const Json& j, const std::string& kind) {
  switch (j.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case Json::value_t::number_float:
      return py::float_(j.get<double>());
    case Json::value_t::string:
      return text(j.get<std::string>());
    case Json::value_t::array: {
      py::list list;
      for (const Json& item : j) list.append(from_json(item, kind));
      return std::move(list);
    }
    case Json::value_t::object:
      return py::cast(result_from_json(j, kind));
    default:
      throw std::logic_error("from_json: unexpected JSON value");
  }
}

Result result_from_json(const Json& j, const std::string& kind) {
  Result r{kind, py::dict()};
  for (const auto& [key, value] : j.items()) r.fields[text(key)] = from_json(value, key);
  return r;
}

namespace {

/// The array of shape (n, 3) as Points, unchecked otherwise.
Points shaped_rows3(const py::handle& array, const std::string& name) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a) throw InputError(name + ": expected an array of shape (n, 3)");
  if (a.ndim() != 2 || a.shape(1) != 3) {
    std::string shape;
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    throw InputError(name + ": expected an array of shape (n, 3), got shape (" + shape + ")");
  }
  return Eigen::Map<const Points>(a.data(), a.shape(0), 3);
}

}  // namespace

Points rows3_arg(const py::handle& array, const std::string& name) {
  Points P = shaped_rows3(array, name);
  require_input(P.allFinite(), name + ": the array has entries that are not finite");
  return P;
}

Points curve_arg(const py::handle& array, const std::string& name) {
  Points P = shaped_rows3(array, name);
  validate_closed_curve(P, name);
  return P;
}

py::array_t<double> to_array(const Points& P) {
  py::array_t<double> a({static_cast<py::ssize_t>(P.rows()), py::ssize_t{3}});
  Eigen::Map<Points>(a.mutable_data(), P.rows(), 3) = P;
  return a;
}

py::array_t<double> to_array(const Eigen::MatrixXd& M) {
  py::array_t<double> a({static_cast<py::ssize_t>(M.rows()), static_cast<py::ssize_t>(M.cols())});
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::Map<RowMajor>(a.mutable_data(), M.rows(), M.cols()) = M;
  return a;
}

Eigen::MatrixXd to_matrix(const py::handle& array, const std::string& name) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a || a.ndim() != 2 || a.shape(0) != a.shape(1) || a.shape(0) < 1)
    throw InputError(name + ": expected a square array of shape (N, N), N >= 1");
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::MatrixXd M = Eigen::Map<const RowMajor>(a.data(), a.shape(0), a.shape(1));
  if (!M.allFinite()) throw InputError(name + ": entries must be finite");
  return M;
}

}  // namespace ek::python
