#pragma once
/// \file
/// Oriented bounding boxes of point sets, for the 3D-ness attribute (paper
/// Section 7.3).
#include "ek/geometry/types.hpp"

namespace ek {

/// A box center + Σ_k c_k a_k with |c_k| <= extents_k / 2.
struct OrientedBox {
  Vec3 center = Vec3::Zero();  ///< [length]
  Mat3 axes = Mat3::Identity();  ///< orthonormal columns a_0, a_1, a_2 (right-handed)
  Vec3 extents = Vec3::Zero();   ///< [length] edge lengths along the axes, sorted descending
  double volume() const { return extents.prod(); }  ///< [length³] product of the extents
};

/// Box aligned with the principal axes of the points' covariance (PCA box).
OrientedBox pca_bounding_box(const Points& P);

/// Approximately minimal-volume oriented bounding box of the points (n by 3,
/// n >= 1). Every box has an axis u; for a fixed u the optimal box is exact:
/// the extent of P along u times the minimum-area rectangle of P projected on
/// the plane ⊥ u (2D convex hull and rotating calipers: one side of that
/// rectangle lies on a hull edge, Freeman & Shapira 1975). The direction u is
/// optimised globally then locally: V(u) is evaluated at the three PCA axes
/// and 200 Fibonacci directions of the hemisphere; from the 6 best of them
/// that are at least 0.3 rad apart, a Nelder–Mead search in the gnomonic chart
/// around the start (initial simplex 0.1 rad, stopped at a simplex of 1e-7 rad
/// or 300 evaluations) refines u; the smallest box wins. The result's volume
/// never exceeds the PCA box's (the PCA axes are sampled, and the box for a
/// PCA axis is at most the PCA box). Measured on 400-vertex curves: the same
/// aspect ratio to ~1e-8 for rotated copies; ~1000 evaluations. For
/// planar points the box has zero volume (one extent is 0 up to rounding).
///
/// Each evaluation reads only the points on the boundary of P's convex hull
/// (convex_hull_boundary_points(), geometry/convex_hull.hpp): the box of an
/// axis depends on the points only through their extremes, so the result is
/// the same as from every point (tested to the last bit), and an evaluation
/// costs O(h log h) for h boundary points instead of O(n log n).
OrientedBox min_volume_bounding_box(const Points& P);

/// The same, with every evaluation over all of P (no convex-hull filter):
/// the reference that min_volume_bounding_box() must equal, for tests and
/// benchmarks.
OrientedBox min_volume_bounding_box_all_points(const Points& P);

}  // namespace ek
