#include "output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "ek/core/errors.hpp"

namespace ek::cli {

void print_json(const Json& j) {
  // text from files (knot names, attribute names, messages) may not be UTF-8:
  // such bytes print as U+FFFD instead of failing the command
  std::cout << j.dump(-1, ' ', false, Json::error_handler_t::replace) << std::endl;
}

std::string matrix_rows(const Eigen::MatrixXi& matrix, const std::string& indent) {
  std::string s;
  for (Eigen::Index a = 0; a < matrix.rows(); ++a) {
    if (a > 0) s += "\n" + indent;
    for (Eigen::Index b = 0; b < matrix.cols(); ++b) s += (b ? " " : "") + std::to_string(matrix(a, b));
  }
  return s;
}

std::string fmt(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

void refuse_existing_output(const std::string& path, bool overwrite) {
  if (!overwrite && std::filesystem::exists(path))
    throw InputError("output " + path + " exists (use --overwrite to replace it)");
}

}  // namespace ek::cli
