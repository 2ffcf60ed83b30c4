#include "ek/geometry/link.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "ek/geometry/writhe.hpp"

namespace ek {

double mean_component_length(const Link& link) {
  double total = 0.0;
  for (const Points& P : link) total += curve_length(P);
  return link.empty() ? 0.0 : total / static_cast<double>(link.size());
}

Points all_vertices(const Link& link) {
  Eigen::Index rows = 0;
  for (const Points& P : link) rows += P.rows();
  Points all(rows, 3);
  rows = 0;
  for (const Points& P : link) {
    all.middleRows(rows, P.rows()) = P;
    rows += P.rows();
  }
  return all;
}

double component_distance(const Points& A, const Points& B) {
  double d2 = std::numeric_limits<double>::infinity();
  const Eigen::Index na = A.rows(), nb = B.rows();
  for (Eigen::Index i = 0; i < na; ++i) {
    const Vec3 p0 = A.row(i).transpose(), p1 = A.row((i + 1) % na).transpose();
    for (Eigen::Index j = 0; j < nb; ++j)
      d2 = std::min(d2, segment_segment_distance_squared(p0, p1, B.row(j).transpose(), B.row((j + 1) % nb).transpose()));
  }
  return std::sqrt(d2);
}

double validate_link(const Link& link, const std::string& source) {
  if (link.empty()) throw InputError(source + ": a link needs at least one component");
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (size_t c = 0; c < link.size(); ++c) {
    validate_closed_curve(link[c], link.size() == 1 ? source : source + " (component " + std::to_string(c + 1) + ")");
    lo = lo.cwiseMin(link[c].colwise().minCoeff().transpose());
    hi = hi.cwiseMax(link[c].colwise().maxCoeff().transpose());
  }
  const double tolerance = 1e-9 * (hi - lo).norm();
  double clearance = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < link.size(); ++a)
    for (size_t b = a + 1; b < link.size(); ++b) {
      const double d = component_distance(link[a], link[b]);
      if (d <= tolerance) {
        std::ostringstream msg;
        msg << source << ": components " << a + 1 << " and " << b + 1 << " touch or cross (distance " << d << ")";
        throw InputError(msg.str());
      }
      clearance = std::min(clearance, d);
    }
  return clearance;
}

double linking_number(const Points& A, const Points& B) {
  double sum = 0.0;
  const Eigen::Index na = A.rows(), nb = B.rows();
  for (Eigen::Index i = 0; i < na; ++i) {
    const Vec3 p1 = A.row(i).transpose(), p2 = A.row((i + 1) % na).transpose();
    for (Eigen::Index j = 0; j < nb; ++j)
      sum += segment_pair_writhe(p1, p2, B.row(j).transpose(), B.row((j + 1) % nb).transpose());
  }
  return sum;
}

Eigen::MatrixXd linking_matrix(const Link& link) {
  const auto m = static_cast<Eigen::Index>(link.size());
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(m, m);
  for (Eigen::Index a = 0; a < m; ++a)
    for (Eigen::Index b = a + 1; b < m; ++b)
      L(a, b) = L(b, a) = linking_number(link[static_cast<size_t>(a)], link[static_cast<size_t>(b)]);
  return L;
}

}  // namespace ek
