#pragma once
/// \file
/// Elementary geometry of closed polygons (n by 3 arrays, see types.hpp).
#include <vector>

#include "ek/geometry/types.hpp"

namespace ek {

/// Throws std::invalid_argument naming `who` unless P is a closed polygon
/// of at least 3 vertices with finite coordinates (a caller's misuse, not
/// bad input: input is validated on reading).
void require_closed_polygon(const Points& P, const char* who);

/// Edge vectors e_i = x_{i+1} - x_i (cyclic), n by 3.
Points edge_vectors(const Points& P);

/// Edge lengths |e_i|, length n.
VecX edge_lengths(const Points& P);

/// Total length Σ|e_i|.
double curve_length(const Points& P);

/// Turning angle at each vertex i, the angle in [0, π] between e_{i-1} and e_i
/// (0 for a straight continuation). Computed with atan2(|a×b|, a·b), accurate
/// for small and large angles.
VecX turning_angles(const Points& P);

/// Total curvature Σ_i turning angle_i (paper Section 7.3, "Curvature";
/// Milnor's theorem: > 2π·bridge index for a knot). For a convex planar
/// polygon it is exactly 2π.
double total_curvature(const Points& P);

/// Result of clearance(): the smallest distance between two edges that share
/// no vertex, and which edges realise it.
struct Clearance {
  double distance = 0.0;  ///< [length] min over non-adjacent edge pairs
  int edge_a = -1;        ///< index of the first edge (edge i joins vertex i to i+1)
  int edge_b = -1;        ///< index of the second edge
};

/// Smallest distance between any two edges i, j of the closed polygon whose
/// cyclic index distance is at least `min_index_gap` (default 2: edges sharing
/// a vertex are excluded). O(n log n) typical: segments are swept in x with
/// pruning by the best distance found so far. Needs n >= 4.
Clearance clearance(const Points& P, int min_index_gap = 2);

/// Centroid (mean of the vertices).
Vec3 centroid(const Points& P);

/// The principal axes of the vertices: the unit eigenvectors of their
/// scatter matrix Σ (x_i − c)(x_i − c)ᵀ about the centroid c, as columns in
/// the order of ascending spread (column 0: the axis of least extent, the
/// normal of the best-fitting plane), signs as the eigen-solver gives them.
Mat3 principal_axes(const Points& P);

}  // namespace ek
