#pragma once
// Output helpers shared by the commands.
#include <string>

#include <Eigen/Core>

#include "ek/core/json.hpp"

namespace ek::cli {

/// JSON objects keep the insertion order of their keys (stable output).
using ek::Json;

/// Prints one JSON object on one line to stdout; bytes of strings that are
/// not UTF-8 print as U+FFFD.
void print_json(const Json& j);

/// A double for JSON: finite values as numbers, others as null.
inline Json number(double x) { return json_number(x); }

/// "%.10g" formatting for human-readable output.
std::string fmt(double x, int digits = 10);

/// An integer matrix for human-readable output: each row's entries separated
/// by one space, the rows after the first on new lines that start with
/// `indent` (no newline at the end).
std::string matrix_rows(const Eigen::MatrixXi& matrix, const std::string& indent);

/// InputError "output <path> exists (use --overwrite to replace it)" when
/// the output file exists and `overwrite` is false.
void refuse_existing_output(const std::string& path, bool overwrite);

}  // namespace ek::cli
