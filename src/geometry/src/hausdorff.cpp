#include "ek/geometry/hausdorff.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/geometry/nearest_segment.hpp"
#include "ek/geometry/segment_distance.hpp"

namespace ek {
namespace {

/// Distance from x to the polyline P and the segment realising it.
struct Nearest {
  double distance;
  Eigen::Index segment;
};

Nearest nearest_segment(const Vec3& x, const NearestSegment& B) {
  const NearestSegmentHit hit = B.nearest(x);
  return {std::sqrt(hit.distance_squared), hit.segment};
}

/// One piece [s0, s1] of segment `segment` of A: the distances f0, f1 to B at
/// its ends, the segments of B nearest to them, and an upper bound of f on it.
struct Piece {
  double bound;
  int segment;
  double s0, s1;
  Nearest n0, n1;
  bool operator<(const Piece& o) const { return bound < o.bound; }
};

struct Directed {
  double value = 0.0;
  Vec3 witness = Vec3::Zero();
  int evaluations = 0;
};

/// Upper bound of f = dist(·, B) on the piece from x0 to x1: the Lipschitz
/// bound (f0 + f1 + |x1 - x0|)/2, and for every segment of B near the ends
/// (nearest to either end and their neighbours) the larger of the two end
/// distances to it: the distance to one segment is convex along the piece
/// and bounds f from above. The second bound is 0 where the piece lies on B.
double piece_bound(const Vec3& x0, const Vec3& x1, const Nearest& n0, const Nearest& n1, const Points& B, bool closed) {
  const Eigen::Index m = B.rows(), segments = closed ? m : m - 1;
  double bound = 0.5 * (n0.distance + n1.distance + (x1 - x0).norm());
  for (const Eigen::Index base : {n0.segment, n1.segment})
    for (Eigen::Index d = -1; d <= 1; ++d) {
      Eigen::Index j = base + d;
      if (closed) j = (j + segments) % segments;
      else if (j < 0 || j >= segments) continue;
      const Vec3 a = B.row(j).transpose(), b = B.row((j + 1) % m).transpose();
      bound = std::min(bound, std::sqrt(std::max(point_segment_distance_squared(x0, a, b),
                                                 point_segment_distance_squared(x1, a, b))));
    }
  return bound;
}

Directed directed_hausdorff(const Points& A, const Points& B, bool closed, double tolerance) {
  const Eigen::Index n = A.rows();
  const Eigen::Index segments = closed ? n : n - 1;
  Directed d;
  const NearestSegment tree(B, closed);
  auto f = [&](const Vec3& x) {
    ++d.evaluations;
    return nearest_segment(x, tree);
  };
  std::vector<Nearest> at_vertex;
  d.value = -1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    at_vertex.push_back(f(A.row(i).transpose()));
    if (at_vertex.back().distance > d.value) {
      d.value = at_vertex.back().distance;
      d.witness = A.row(i).transpose();
    }
  }
  std::priority_queue<Piece> queue;
  auto push = [&](int segment, double s0, double s1, const Nearest& n0, const Nearest& n1) {
    const Vec3 a = A.row(segment).transpose(), b = A.row((segment + 1) % n).transpose();
    const double bound = piece_bound(a + s0 * (b - a), a + s1 * (b - a), n0, n1, B, closed);
    if (bound > d.value + tolerance) queue.push({bound, segment, s0, s1, n0, n1});
  };
  for (Eigen::Index i = 0; i < segments; ++i)
    push(static_cast<int>(i), 0.0, 1.0, at_vertex[static_cast<size_t>(i)], at_vertex[static_cast<size_t>((i + 1) % n)]);
  while (!queue.empty() && queue.top().bound > d.value + tolerance) {
    const Piece p = queue.top();
    queue.pop();
    const Vec3 a = A.row(p.segment).transpose(), b = A.row((p.segment + 1) % n).transpose();
    const double sm = 0.5 * (p.s0 + p.s1);
    const Vec3 x = a + sm * (b - a);
    const Nearest fm = f(x);
    if (fm.distance > d.value) {
      d.value = fm.distance;
      d.witness = x;
    }
    push(p.segment, p.s0, sm, p.n0, fm);
    push(p.segment, sm, p.s1, fm, p.n1);
  }
  return d;
}

}  // namespace

void HausdorffOptions::validate() const {
  require(tolerance > 0.0 && std::isfinite(tolerance), "HausdorffOptions: tolerance must be finite and > 0");
}

double point_polyline_distance(const Vec3& x, const Points& P, bool closed) {
  require(P.rows() >= 2, "point_polyline_distance: at least 2 vertices expected");
  // one query: a scan of the segments (a tree pays off over many queries)
  const Eigen::Index n = P.rows(), segments = closed ? n : n - 1;
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < segments; ++j)
    best = std::min(best, point_segment_distance_squared(x, P.row(j).transpose(), P.row((j + 1) % n).transpose()));
  return std::sqrt(best);
}

HausdorffDistance hausdorff_distance(const Points& A, const Points& B, const HausdorffOptions& options) {
  options.validate();
  const Eigen::Index min_rows = options.closed ? 3 : 2;
  require(A.rows() >= min_rows && B.rows() >= min_rows,
          "hausdorff_distance: polylines need at least " + std::to_string(min_rows) + " vertices");
  require(A.allFinite() && B.allFinite(), "hausdorff_distance: non-finite coordinates");
  const Directed ab = directed_hausdorff(A, B, options.closed, options.tolerance);
  const Directed ba = directed_hausdorff(B, A, options.closed, options.tolerance);
  HausdorffDistance h;
  h.forward = ab.value;
  h.backward = ba.value;
  h.distance = std::max(ab.value, ba.value);
  h.witness = ab.value >= ba.value ? ab.witness : ba.witness;
  h.evaluations = ab.evaluations + ba.evaluations;
  return h;
}

}  // namespace ek
