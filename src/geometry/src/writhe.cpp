#include "ek/geometry/writhe.hpp"

#include <algorithm>
#include <cmath>

namespace ek {
namespace {

/// asin(a·b) for unit vectors a, b, computed as atan2(a·b, |a×b|): accurate
/// also where a·b is close to ±1 (asin loses half the digits there).
inline double asin_dot(const Vec3& a, const Vec3& b) { return std::atan2(a.dot(b), a.cross(b).norm()); }

}  // namespace

double segment_pair_writhe(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
  Vec3 n1 = r13.cross(r14), n2 = r14.cross(r24), n3 = r24.cross(r23), n4 = r23.cross(r13);
  const double l1 = n1.norm(), l2 = n2.norm(), l3 = n3.norm(), l4 = n4.norm();
  // A vanishing normal means the four points are coplanar (or a segment
  // degenerates): the solid angle is zero.
  const double scale = std::max({r13.squaredNorm(), r14.squaredNorm(), r23.squaredNorm(), r24.squaredNorm()});
  const double eps = 1e-15 * scale;
  if (l1 <= eps || l2 <= eps || l3 <= eps || l4 <= eps) return 0.0;
  n1 /= l1;
  n2 /= l2;
  n3 /= l3;
  n4 /= l4;
  const double omega_star = asin_dot(n1, n2) + asin_dot(n2, n3) + asin_dot(n3, n4) + asin_dot(n4, n1);
  const double orient = (p4 - p3).cross(p2 - p1).dot(r13);
  if (orient == 0.0) return 0.0;
  return (orient > 0.0 ? omega_star : -omega_star) / (4.0 * M_PI);
}

double writhe(const Points& P) {
  const auto n = P.rows();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 p1 = P.row(i).transpose(), p2 = P.row((i + 1) % n).transpose();
    for (Eigen::Index j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      sum += segment_pair_writhe(p1, p2, P.row(j).transpose(), P.row((j + 1) % n).transpose());
    }
  }
  return 2.0 * sum;
}

}  // namespace ek
