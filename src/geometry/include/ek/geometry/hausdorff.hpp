#pragma once
/// \file
/// Hausdorff distance between two polylines (as point sets, not their
/// vertices), the "direct measure of geometric similarity" the paper compares
/// its curvature-torsion similarity with (Section 7.1, Fig.\ 5).
///
/// ~~~{.unparsed}
///   h(A → B) = sup_{a ∈ A} dist(a, B),   d_H(A, B) = max(h(A → B), h(B → A))   [length]
/// ~~~
///
/// where A and B are the unions of their segments. The supremum need not lie
/// at a vertex of A (the distance to B along a segment of A is a minimum of
/// convex functions), so a vertex-only maximum can underestimate it by up to
/// half an edge. Here each directed distance is computed by branch and bound
/// over the segments of A. On a piece of a segment from x0 to x1, with
/// f(x) = dist(x, B) known at its ends, f is bounded from above by
///   (f(x0) + f(x1) + |x1 - x0|) / 2          (f is 1-Lipschitz along A), and by
///   max(dist(x0, S), dist(x1, S))            for any segment S of B
/// (the distance to one segment is convex along the piece); the segments
/// nearest to either end and their neighbours are tried, so a piece lying on
/// B gets the bound 0. Pieces are bisected, largest bound first, until no
/// bound exceeds the largest value found by more than `tolerance`. The
/// result x satisfies
///   h - tolerance <= x <= h   (x is attained: a point of A at distance x from B).
/// Cost: O(m_B) per evaluation of f (brute force over B's segments); n_A
/// evaluations at the vertices plus a few per bisected piece.
#include "ek/geometry/types.hpp"

namespace ek {

/// Options of hausdorff_distance().
struct HausdorffOptions {
  bool closed = true;        ///< both polylines are closed (edge n-1 joins the last vertex to the first)
  double tolerance = 1e-6;   ///< [length] absolute accuracy of each directed distance (> 0)

  /// Throws std::invalid_argument unless tolerance > 0 and finite.
  void validate() const;
};

/// Result of hausdorff_distance().
struct HausdorffDistance {
  double distance = 0.0;  ///< [length] d_H(A, B) = max(forward, backward)
  double forward = 0.0;   ///< [length] h(A → B)
  double backward = 0.0;  ///< [length] h(B → A)
  Vec3 witness = Vec3::Zero();  ///< a point of A (forward >= backward) or of B where the maximum is attained
  int evaluations = 0;    ///< [1] point-to-polyline distances evaluated (both directions)
};

/// d_H of two polylines (n by 3 each, >= 2 vertices; >= 3 when closed; finite).
/// Throws std::invalid_argument otherwise.
HausdorffDistance hausdorff_distance(const Points& A, const Points& B, const HausdorffOptions& options = {});

/// Distance from point x to the polyline P (closed or open).
double point_polyline_distance(const Vec3& x, const Points& P, bool closed = true);

}  // namespace ek
