#include "ek/geometry/resample.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"

namespace ek {

Points resample_arclength(const Points& P, int m) {
  require(m >= 3, "resample_arclength: need m >= 3 points");
  const auto n = P.rows();
  require(n >= 2, "resample_arclength: need at least 2 input vertices");
  const VecX len = edge_lengths(P);
  const double L = len.sum();
  require(L > 0.0, "resample_arclength: curve has zero length");
  Points Q(m, 3);
  Eigen::Index e = 0;
  double start = 0.0;  // arc length at the start of edge e
  for (int k = 0; k < m; ++k) {
    const double target = L * k / m;
    while (e < n - 1 && start + len(e) < target) {
      start += len(e);
      ++e;
    }
    const double u = len(e) > 0.0 ? std::clamp((target - start) / len(e), 0.0, 1.0) : 0.0;
    Q.row(k) = (1.0 - u) * P.row(e) + u * P.row((e + 1) % n);
  }
  return Q;
}

namespace {

/// Walks m chords of length h along P from vertex 0; returns the unwrapped arc
/// position of the m-th point minus the total length (0 when it closes).
struct Walker {
  const Points& P;
  VecX len;
  VecX cum;  // arc length at the start of each edge
  double L;
  explicit Walker(const Points& p) : P(p), len(edge_lengths(p)), cum(len.size() + 1) {
    cum(0) = 0.0;
    for (Eigen::Index i = 0; i < len.size(); ++i) cum(i + 1) = cum(i) + len(i);
    L = cum(len.size());
  }

  Vec3 point(Eigen::Index edge, double u) const {
    const auto n = P.rows();
    const auto i = edge % n;
    return ((1.0 - u) * P.row(i) + u * P.row((i + 1) % n)).transpose();
  }

  /// From (edge, u) find the first later point at distance h from q; edge
  /// indices are unwrapped (may exceed n - 1). Returns false if none within
  /// two turns.
  bool step(const Vec3& q, double h, Eigen::Index& edge, double& u) const {
    const auto n = P.rows();
    for (Eigen::Index e = edge; e < edge + 2 * n; ++e) {
      const Vec3 a = point(e, 0.0), b = point(e, 1.0);
      const double u0 = (e == edge) ? u : 0.0;
      // |a + s (b - a) - q|² = h², s in [u0, 1]: smallest root where the
      // distance reaches h from below.
      const Vec3 d = b - a, w = a - q;
      const double A = d.squaredNorm(), B = 2.0 * d.dot(w), C = w.squaredNorm() - h * h;
      if (A <= 0.0) continue;
      const double disc = B * B - 4.0 * A * C;
      if (disc < 0.0) continue;
      const double sq = std::sqrt(disc);
      const double r2 = (-B + sq) / (2.0 * A);  // the larger root: leaving the ball
      if (r2 >= u0 && r2 <= 1.0) {
        edge = e;
        u = r2;
        return true;
      }
    }
    return false;
  }

  /// Signed closure error for chord length h, and the points if wanted.
  double closure(double h, int m, Points* out) const {
    Eigen::Index edge = 0;
    double u = 0.0;
    Vec3 q = point(0, 0.0);
    if (out) out->row(0) = q.transpose();
    for (int k = 1; k <= m; ++k) {
      if (!step(q, h, edge, u)) return std::numeric_limits<double>::infinity();
      q = point(edge, u);
      if (out && k < m) out->row(k) = q.transpose();
    }
    const auto n = P.rows();
    const double wraps = static_cast<double>(edge / n);
    return wraps * L + cum(edge % n) + u * len(edge % n) - L;
  }
};

}  // namespace

EquilateralResult resample_equilateral(const Points& P, int m) {
  require(m >= 4, "resample_equilateral: need m >= 4 points");
  Walker walker(P);
  require(walker.L > 0.0, "resample_equilateral: curve has zero length");
  // Chords are no longer than arcs, so h = L/m reaches the start or beyond;
  // a small h stops short. Bisect on the closure error.
  double hi = walker.L / m;
  double lo = 0.0;
  const double f_hi = walker.closure(hi, m, nullptr);
  require(std::isfinite(f_hi) && f_hi >= -1e-12 * walker.L,
          "resample_equilateral: cannot walk the curve with chord L/m");
  for (int it = 0; it < 200 && hi - lo > 1e-15 * walker.L; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double f = walker.closure(mid, m, nullptr);
    if (std::isfinite(f) && f >= 0.0)
      hi = mid;
    else
      lo = mid;
  }
  EquilateralResult result;
  result.points.resize(m, 3);
  walker.closure(hi, m, &result.points);
  result.edge_length = hi;
  const VecX len = edge_lengths(result.points);
  result.max_deviation = (len.array() - hi).abs().maxCoeff();
  return result;
}

Points refine(const Points& P, double max_edge) {
  require(max_edge > 0.0, "refine: max_edge must be positive");
  const auto n = P.rows();
  std::vector<Vec3> out;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 a = P.row(i).transpose(), b = P.row((i + 1) % n).transpose();
    const int k = std::max(1, static_cast<int>(std::ceil((b - a).norm() / max_edge)));
    for (int s = 0; s < k; ++s) out.push_back(a + (b - a) * (static_cast<double>(s) / k));
  }
  Points Q(static_cast<Eigen::Index>(out.size()), 3);
  for (size_t i = 0; i < out.size(); ++i) Q.row(static_cast<Eigen::Index>(i)) = out[i].transpose();
  return Q;
}

}  // namespace ek
