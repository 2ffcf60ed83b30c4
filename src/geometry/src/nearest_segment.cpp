#include "ek/geometry/nearest_segment.hpp"

#include <cmath>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/geometry/segment_distance.hpp"

namespace ek {

namespace {
constexpr Eigen::Index kLeafSegments = 4;
/// relative margin of the pruning test, far above the rounding of |x - c| - r
constexpr double kPruneMargin = 1e-9;
}  // namespace

NearestSegment::NearestSegment(const Points& P, bool closed) {
  add_polygon(P, closed, 0);
  build(0, size());
}

NearestSegment::NearestSegment(const Link& link) {
  require(!link.empty(), "NearestSegment: a link needs a component");
  for (size_t c = 0; c < link.size(); ++c) add_polygon(link[c], true, static_cast<int>(c));
  build(0, size());
}

void NearestSegment::add_polygon(const Points& P, bool closed, int component) {
  require(P.rows() >= 2, "NearestSegment: a polyline needs at least 2 vertices");
  const Eigen::Index n = P.rows(), segments = closed ? n : n - 1;
  first_.push_back(size());
  for (Eigen::Index j = 0; j < segments; ++j) {
    a_.push_back(P.row(j).transpose());
    b_.push_back(P.row((j + 1) % n).transpose());
    component_.push_back(component);
  }
}

int NearestSegment::build(Eigen::Index begin, Eigen::Index end) {
  Vec3 lo = a_[static_cast<size_t>(begin)], hi = lo;
  for (Eigen::Index k = begin; k < end; ++k) {
    for (const Vec3& p : {a_[static_cast<size_t>(k)], b_[static_cast<size_t>(k)]}) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  Node node{0.5 * (lo + hi), 0.0, begin, end};
  for (Eigen::Index k = begin; k < end; ++k)
    node.radius = std::max({node.radius, (a_[static_cast<size_t>(k)] - node.center).norm(),
                            (b_[static_cast<size_t>(k)] - node.center).norm()});
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (end - begin > kLeafSegments) {
    const Eigen::Index mid = begin + (end - begin) / 2;
    const int left = build(begin, mid), right = build(mid, end);
    nodes_[static_cast<size_t>(index)].left = left;
    nodes_[static_cast<size_t>(index)].right = right;
  }
  return index;
}

void NearestSegment::search(int index, const Vec3& x, double& best, Eigen::Index& best_index) const {
  const Node& node = nodes_[static_cast<size_t>(index)];
  const double d = (x - node.center).norm();
  // every point of the sphere is at least d - r from x: skip when that is
  // clearly more than the best distance (never on a tie)
  if (d - node.radius > std::sqrt(best) + kPruneMargin * (d + node.radius)) return;
  if (node.left < 0) {
    for (Eigen::Index k = node.begin; k < node.end; ++k) {
      const double d2 = point_segment_distance_squared(x, a_[static_cast<size_t>(k)], b_[static_cast<size_t>(k)]);
      if (d2 < best || (d2 == best && k < best_index)) {
        best = d2;
        best_index = k;
      }
    }
    return;
  }
  const Node &l = nodes_[static_cast<size_t>(node.left)], &r = nodes_[static_cast<size_t>(node.right)];
  const bool left_first = (x - l.center).norm() - l.radius <= (x - r.center).norm() - r.radius;
  search(left_first ? node.left : node.right, x, best, best_index);
  search(left_first ? node.right : node.left, x, best, best_index);
}

NearestSegmentHit NearestSegment::nearest(const Vec3& x) const {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Index k = -1;
  search(0, x, best, k);
  NearestSegmentHit hit;
  if (k < 0) {  // x not finite: no segment is nearer than infinity
    hit.distance_squared = std::numeric_limits<double>::infinity();
    return hit;
  }
  hit.distance_squared = point_segment_distance_squared(x, a_[static_cast<size_t>(k)], b_[static_cast<size_t>(k)], &hit.t);
  hit.component = component_[static_cast<size_t>(k)];
  hit.segment = k - first_[static_cast<size_t>(hit.component)];
  return hit;
}

}  // namespace ek
