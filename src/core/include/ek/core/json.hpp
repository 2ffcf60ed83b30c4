#pragma once
/// \file
/// JSON descriptions of results: the objects that `knots COMMAND --json`
/// prints and that the Python module returns as result objects (their keys
/// are the documented contract of docs/cli.md). Each module's json.hpp
/// describes its own results with these types.
#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace ek {

/// A JSON object keeps the insertion order of its keys (stable output).
using Json = nlohmann::ordered_json;

/// A double for JSON: finite values as numbers, NaN and ±inf as null.
Json json_number(double x);

/// An integer matrix as an array of rows (linking numbers, ...).
Json integer_matrix_json(const Eigen::MatrixXi& matrix);

}  // namespace ek
