#include "ek/core/json.hpp"

#include <cmath>

namespace ek {

Json json_number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json integer_matrix_json(const Eigen::MatrixXi& matrix) {
  Json rows = Json::array();
  for (Eigen::Index a = 0; a < matrix.rows(); ++a) {
    Json row = Json::array();
    for (Eigen::Index b = 0; b < matrix.cols(); ++b) row.push_back(matrix(a, b));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace ek
