#include "ek/geometry/segment_distance.hpp"

#include <algorithm>
#include <limits>

namespace ek {

double point_segment_distance_squared(const Vec3& x, const Vec3& a, const Vec3& b, double* t) {
  const Vec3 e = b - a;
  const double ee = e.squaredNorm();
  double u = ee > 0.0 ? std::clamp((x - a).dot(e) / ee, 0.0, 1.0) : 0.0;
  if (t) *t = u;
  return (a + u * e - x).squaredNorm();
}

double segment_segment_distance_squared(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                                        double* s_out, double* t_out) {
  // Minimise |d1 s - d2 t + r|² over the unit square. The interior critical
  // point is used when the segments are far from parallel; otherwise, and
  // whenever it falls outside the square, the minimum lies on an edge of the
  // square, i.e. is a point-segment distance from one of the four endpoints.
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm();
  const double b = d1.dot(d2), c = d1.dot(r), f = d2.dot(r);
  const double denom = a * e - b * b;  // = |d1 × d2|² >= 0
  if (a > 0.0 && e > 0.0 && denom > 1e-14 * a * e) {
    const double s = (b * f - c * e) / denom;
    const double t = (a * f - b * c) / denom;
    if (s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0) {
      if (s_out) *s_out = s;
      if (t_out) *t_out = t;
      return (r + s * d1 - t * d2).squaredNorm();
    }
  }
  double best = std::numeric_limits<double>::infinity();
  double bs = 0.0, bt = 0.0, u = 0.0;
  // The parameter u is read after the distance that writes it (separate
  // statements: the order in which a call's arguments are evaluated is unspecified).
  auto consider = [&](double d, bool on_p, double fixed) {
    if (d < best) {
      best = d;
      bs = on_p ? u : fixed;
      bt = on_p ? fixed : u;
    }
  };
  double d = point_segment_distance_squared(p0, q0, q1, &u);
  consider(d, false, 0.0);
  d = point_segment_distance_squared(p1, q0, q1, &u);
  consider(d, false, 1.0);
  d = point_segment_distance_squared(q0, p0, p1, &u);
  consider(d, true, 0.0);
  d = point_segment_distance_squared(q1, p0, p1, &u);
  consider(d, true, 1.0);
  if (s_out) *s_out = bs;
  if (t_out) *t_out = bt;
  return best;
}

}  // namespace ek
