#pragma once
/// \file
/// The points on the boundary of a 3D point set's convex hull, from Qhull
/// (Barber, Dobkin & Huhdanpaa 1996, "The Quickhull algorithm for convex
/// hulls"; the Debian package libqhull-dev, its reentrant library).
///
/// Why: a quantity that depends on the points only through their extremes
/// in some directions (the extent along an axis, the convex hull of a
/// projection, the minimal bounding box) is the same when it is computed from
/// the hull's boundary points alone: 30–60% of a relaxed knot's vertices,
/// a tenth of a random walk's, most of a coil's. Those boundary points are the hull's vertices and every point
/// within Qhull's rounding tolerance of a facet (its option Qc). A point left
/// out lies inside the hull by more than that tolerance, and, since an
/// orthogonal projection maps a ball inside the hull to a disc inside the
/// projected hull, its projection on any plane or line lies inside the
/// projection of the hull by at least as much: far beyond the rounding of a
/// dot or cross product, so the computation meets the same extremes.
#include <vector>

#include "ek/geometry/types.hpp"

namespace ek {

/// Indices (increasing) of the points of P (n by 3) on the boundary of their
/// convex hull: its vertices and the points within Qhull's tolerance of a
/// facet. Every index 0..n−1 when the hull has no volume or Qhull cannot
/// build it (fewer than 5 points, all points on a plane or a line, or a
/// non-finite coordinate): then nothing is left out.
std::vector<Eigen::Index> convex_hull_boundary_points(const Points& P);

}  // namespace ek
