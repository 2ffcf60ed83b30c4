#include "ek/geometry/writhe.hpp"

#include <cmath>

namespace ek {
namespace {

/// Half the signed solid angle of the triangle (a, b, c) seen from the
/// origin (Van Oosterom & Strackee 1983): atan2 of the triple product `vol`
/// = a·(b×c) over |a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|, with the
/// lengths la, lb, lc given.
inline double half_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, double la, double lb, double lc,
                               double vol) {
  return std::atan2(vol, la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
}

}  // namespace

double segment_pair_writhe(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
  // The parallelogram r13, r14, r24, r23 is cut into two triangles; both have
  // the triple product r13·(r34×r23) (r14 = r13 + r34, r24 = r23 + r34).
  const double vol = r13.dot((p4 - p3).cross(r23));
  if (vol == 0.0) return 0.0;  // coplanar segments (including segments that share a vertex)
  const double l13 = r13.norm(), l14 = r14.norm(), l23 = r23.norm(), l24 = r24.norm();
  const double half = half_solid_angle(r13, r14, r24, l13, l14, l24, vol) +
                      half_solid_angle(r13, r24, r23, l13, l24, l23, vol);
  return -half / (2.0 * M_PI);  // Ω/(4π) with Ω = 2·half, oriented as Klenin & Langowski's
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
