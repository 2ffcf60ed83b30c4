#pragma once
/// \file
/// Rotational symmetry of closed curves and the crossing polygons of periodic
/// braids (paper Section 8.4, Fig.\ 16: "the observed topological pattern also
/// manifests itself in geometric symmetry"; "the crossing patterns form two
/// regular p-gons, one at the top and one at the bottom of each embedding.
/// For odd p these align, while for even p they are rotated relative to each
/// other by π/p").
///
/// Curves are n by 3 arrays of vertices, edge i joining vertex i to i + 1
/// (cyclic). Angles about an axis a are measured in the plane orthogonal to
/// a, from u = a.unitOrthogonal() towards v = a × u.
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// p-fold rotational symmetry error of P about the line through `center`
/// along the unit vector `axis`:
///
/// ~~~{.unparsed}
///   error = (1/n) Σ_i dist(c + R(2π/p)(x_i - c), P) / r_g,
///   r_g   = sqrt((1/n) Σ_i |x_i - c|²)   (radius of gyration about c),
/// ~~~
///
/// where dist(·, P) is the distance to the polygon (its edges). 0 for a curve
/// that the rotation maps onto itself; scale-free. O(n²). p >= 2, n >= 3.
double rotational_symmetry_error(const Points& P, const Vec3& center, const Vec3& axis, int p);

/// The same for a link (link.hpp): every vertex of every component rotated,
/// its distance taken to the nearest edge of any component (the rotation may
/// map a component onto another), r_g over all vertices. O(N²).
double rotational_symmetry_error(const Link& link, const Vec3& center, const Vec3& axis, int p);

/// The grid searched by find_symmetry_axis().
struct SymmetryAxisOptions {
  double max_tilt = 0.1;  ///< [rad] largest tilt from a principal axis, per tilt direction
  double step = 0.01;     ///< [rad] grid step of the tilt (max_tilt/step steps each way)
};

/// A symmetry axis found by find_symmetry_axis().
struct SymmetryAxis {
  Vec3 center = Vec3::Zero();    ///< [length] centroid of the vertices
  Vec3 axis = Vec3::UnitZ();     ///< unit direction
  double error = 0.0;            ///< [1] rotational_symmetry_error() about it
};

/// The axis of best p-fold symmetry through the centroid c: each of the three
/// principal axes e0 of the vertices' covariance, tilted to
/// normalize(e0 + s·e1 + t·e2) for s, t on the grid {-max_tilt, ..., max_tilt}
/// with the given step ((e0, e1, e2) orthonormal), the direction of smallest
/// rotational_symmetry_error(). The tilt makes the search robust where the
/// principal axes are ill-conditioned (a nearly axisymmetric inertia).
/// Cost: 3 (2k+1)² error evaluations, k = round(max_tilt/step), over one
/// segment tree of P; the untilted axes are tried first, and an axis's error
/// stops as soon as its partial sum exceeds the best so far (the answer is
/// the plain scan's of the grid in its order, the first of equal errors, to
/// the last bit), so most evaluations read a few vertices only.
/// Throws std::invalid_argument for p < 2, n < 3 or a step <= 0.
SymmetryAxis find_symmetry_axis(const Points& P, int p, const SymmetryAxisOptions& options = {});

/// The p-fold average of P about `axis` through `center`, for the closure of
/// a braid on `strands` strands with p periods and n divisible by p: moving
/// k·n/p vertices along the curve (k periods of the word) turns by
/// 2π·k·strands/p about the axis, so vertex i + k·n/p is rotated back by that
/// angle (k = 0..p-1) and the p copies are averaged, in whichever sense of
/// rotation moves P less. The result maps onto itself under the p-fold
/// rotation (error 0 up to rounding). Throws std::invalid_argument when
/// n is not divisible by p.
Points symmetrize(const Points& P, const Vec3& center, const Vec3& axis, int p, int strands);

/// A regular p-gon fitted to angles: phase = arg(Σ_j exp(i p θ_j)) / p (the
/// circular mean of p·θ), and the largest deviation of an angle from the
/// nearest vertex phase + 2πk/p.
struct RegularPolygonFit {
  int count = 0;            ///< [1] angles fitted
  double phase = 0.0;       ///< [rad] in (-π/p, π/p]
  double max_error = 0.0;   ///< [deg] largest deviation from the nearest vertex
};
/// The regular p-gon (p >= 1) fitted to `angles` [rad] (see RegularPolygonFit).
RegularPolygonFit fit_regular_polygon(const std::vector<double>& angles, int p);

/// The two p-gons of a braid closure's crossings seen along `axis`.
struct CrossingPolygons {
  int projected = 0;   ///< [1] crossings of the projection along the axis
  int crossings = 0;   ///< [1] of them, those whose strands pass within max_gap along the axis
  bool by_radius = false;  ///< split at the median distance from the axis (else at the median height)
  ///@{
  /// The two halves (outer and inner ring when by_radius).
  RegularPolygonFit top, bottom;
  ///@}
  double rotation = 0.0;  ///< [deg] between the two p-gons' phases, in [0, 180/p]
  /// [deg] the larger of the two halves' max_error
  double error() const { return top.max_error > bottom.max_error ? top.max_error : bottom.max_error; }
};

/// The braid's crossings of P seen along `axis` (through `center`): the
/// crossings of a generic projection along (a direction within 1e-4 rad of)
/// the axis whose two strands pass within `max_gap` [length] of each other
/// along the axis (where a braid's strands cross they touch; a 3D state's
/// projection also shows strands passing far apart), split into two halves at
/// the median height along the axis (a 3D state: one p-gon at each end) or,
/// when that fits worse, at the median distance from the axis (a flat coil:
/// inner and outer ring); each half's angles (of the midpoints of the two
/// strand points) fitted with fit_regular_polygon().
CrossingPolygons crossing_polygons(const Points& P, const Vec3& center, const Vec3& axis, int p, double max_gap);

}  // namespace ek
