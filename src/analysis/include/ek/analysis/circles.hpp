#pragma once
/// \file
/// A closed curve as a union of k circles in space (paper Section 8.4, Fig.\ 15:
/// 9_35's 3D state "is composed of three intertwined circles", and the
/// knots retrieved near it "are all composed of three circular parts that are
/// linked through a variable number of crossings at their touching regions").
///
/// fit_circles(P, k):
///  1. local planes: at every vertex i the binormal of the chord triangle
///     b_i = (x_i - x_{i-w}) × (x_{i+w} - x_i), normalised (w vertices each
///     way; vertices where the chords are parallel get no vote);
///  2. the binormals are clustered into k plane orientations by axial k-means
///     (b and -b are the same plane): the first orientation is the dominant
///     one (top eigenvector of Σ b bᵀ), each further start the binormal
///     farthest from those chosen, then alternating assignment to the
///     orientation with the largest |b · c| and re-estimation of c as the top
///     eigenvector of its Σ b bᵀ;
///  3. each group of vertices gets a circle: its plane through the group's
///     centroid with normal the smallest-variance axis (PCA), and in that
///     plane the algebraic least-squares circle (Kåsa 1976:
///     min Σ (u² + v² + D u + E v + F)², linear);
///  4. every vertex is reassigned to the nearest circle and the circles are
///     refitted, until no vertex changes circle (or `iterations`).
/// The distance of x to the circle (c, n, r) is
///     d = sqrt((ρ - r)² + h²),  h = (x - c)·n,  ρ = |x - c - h n|   [length].
/// Invariant under rigid motions and cyclic re-indexing (up to rounding).
/// Cost O(k n) per iteration.
#include <vector>

#include "ek/geometry/types.hpp"

namespace ek {

/// A circle in space.
struct Circle3 {
  Vec3 center = Vec3::Zero();  ///< [length]
  Vec3 normal = Vec3::UnitZ(); ///< unit normal of its plane
  double radius = 0.0;         ///< [length]
  /// [length] distance of x to the circle (formula above).
  double distance(const Vec3& x) const;
};

/// Options of fit_circles().
struct CircleFitOptions {
  int circles = 3;         ///< [1] k >= 1
  double window = 0.025;   ///< [1] w = max(1, round(window · n)) vertices each way for the local planes, in (0, 0.5)
  int iterations = 50;     ///< [1] reassignment rounds (step 4), >= 0

  /// Throws std::invalid_argument for values outside the ranges above.
  void validate() const;
};

/// Result of fit_circles().
struct CircleFit {
  std::vector<Circle3> circles;  ///< k circles, by decreasing share
  std::vector<double> share;     ///< [1] fraction of the vertices assigned to each circle
  std::vector<int> assignment;   ///< n: circle of each vertex
  double rms_distance = 0.0;     ///< [length] RMS distance of the vertices to their circles
  double max_distance = 0.0;     ///< [length] largest distance of a vertex to its circle
  double mean_radius = 0.0;      ///< [length] share-weighted mean radius
  double min_plane_angle = 0.0;  ///< [rad] smallest angle between two circles' planes, in [0, π/2]
  /// [1] rms_distance / mean_radius (0 when the mean radius is 0)
  double relative_rms() const { return mean_radius > 0.0 ? rms_distance / mean_radius : 0.0; }
};

/// Fits k circles to the closed curve P (n by 3, n >= 4k, finite).
CircleFit fit_circles(const Points& P, const CircleFitOptions& options = {});

/// When a fit counts as "composed of k intertwined circles": the vertices
/// lie near their circles, every circle carries a good part of the curve,
/// and no two circles are nearly coplanar (a multi-covered flat circle is not
/// k intertwined circles). The RMS bound was set between measured values
/// (three circles, n = 400): 9_35's relaxed PD drawing 0.037 and the relaxed
/// pretzel knots P(3,3,5), P(3,5,5), P(5,5,5), P(3,3,7) 0.050-0.058 (their
/// longer twisted contact regions leave the circles) lie below it; the
/// torus trefoil T(2,3) of the tests 0.068 and the non-coplanar equilibria
/// of the ci data set (3-7 crossings, 0.093 and more) above it.
struct CircleCriterion {
  double max_relative_rms = 0.065;  ///< [1] rms_distance / mean_radius at most this
  double min_share = 0.15;          ///< [1] every circle holds at least this fraction of the vertices
  double min_plane_angle = 0.5;     ///< [rad] planes at least this far apart (~29°)
};

/// Whether the fit meets the criterion.
bool meets(const CircleFit& fit, const CircleCriterion& criterion = {});

}  // namespace ek
