#pragma once
/// \file
/// The segment of a polyline (or of a link's polygons) nearest to a point,
/// found through a bounding-sphere tree over runs of consecutive segments
/// instead of a scan of every segment.
///
/// The answer is exactly the scan's: the smallest
/// point_segment_distance_squared() over all segments, and among segments at
/// that same value the first in scan order (component by component, segment
/// j from vertex j to vertex j + 1). A subtree is skipped only when its
/// sphere proves every segment in it farther than the best found so far, by
/// a margin of 1e-9 relative (far above the rounding of the bound), so the
/// pruning never changes a result. A query costs O(log n) for a point near
/// the curve and O(n) at worst (a point equidistant from everything).
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// One query's answer: the nearest segment and the closest point's parameter.
struct NearestSegmentHit {
  double distance_squared = 0.0;  ///< [length²] point_segment_distance_squared to that segment
  int component = 0;              ///< the polygon of the segment (0 for a single polyline)
  Eigen::Index segment = 0;       ///< segment index within its component: from vertex `segment` to the next
  double t = 0.0;                 ///< [1] parameter of the closest point on the segment, in [0, 1]
};

/// The segments of a polyline or a link, for repeated nearest-segment queries.
class NearestSegment {
 public:
  /// Segments of the polyline P (n by 3, n >= 2): n of them when `closed`
  /// (the last joins vertex n - 1 to vertex 0), n - 1 otherwise.
  explicit NearestSegment(const Points& P, bool closed = true);
  /// Segments of every closed component of `link` (each at least 2 vertices).
  explicit NearestSegment(const Link& link);

  /// The nearest segment to x (the exact scan's answer, see the file comment).
  NearestSegmentHit nearest(const Vec3& x) const;

  /// Number of segments.
  Eigen::Index size() const { return static_cast<Eigen::Index>(a_.size()); }

 private:
  struct Node {
    Vec3 center;                 // sphere holding every endpoint of the node's segments
    double radius;               // [length]
    Eigen::Index begin, end;     // segments [begin, end) in scan order
    int left = -1, right = -1;   // children (leaves: -1)
  };
  void add_polygon(const Points& P, bool closed, int component);
  int build(Eigen::Index begin, Eigen::Index end);
  void search(int node, const Vec3& x, double& best, Eigen::Index& best_index) const;

  std::vector<Vec3> a_, b_;                  // segment k from a_[k] to b_[k]
  std::vector<int> component_;               // component of segment k
  std::vector<Eigen::Index> first_;          // first segment of each component
  std::vector<Node> nodes_;
};

}  // namespace ek
