#pragma once
/// \file
/// Attributes of an equilibrium curve for filtering and sorting (paper
/// Section 7.3, Fig.\ 7).
///
/// Geometric attributes (functions of the centerline alone; all invariant
/// under rigid motions and cyclic re-indexing):
///  - total_curvature  Σ_i φ_i, the turning angles [rad] (ek::total_curvature);
///                     2π for a convex planar polygon, > 2π·bridge index for a knot (Milnor).
///  - threedim         3D-ness: shortest over longest edge of the oriented
///                     bounding box [1], in [0, 1]; the box is the
///                     (approximately) minimal-volume box, min_volume_bounding_box().
///                     0 for planar curves, 1 for a curve whose box is a cube.
///  - sphericity       std_i(d_i) / mean_i(d_i) with d_i = |x_i - c|, c the
///                     centroid (mean of the vertices) and std the population
///                     standard deviation (divide by n) [1]. Dividing by the mean
///                     distance makes it scale-free. 0 when all vertices lie on a
///                     sphere about the centroid (circle, regular polygon);
///                     small = close to a sphere.
///  - diameter         max_{i<j} |x_i - x_j| [length]: the largest distance
///                     between two points of the polygon is attained at vertices
///                     (the distance is convex along each edge), so the exact
///                     vertex maximum is the curve's diameter.
///  - writhe           Wr [1] (ek::writhe, exact Gauss double sum; Appendix C).
///
/// Physical attributes need a material (wire radius r, Young's modulus E):
///  - max_stress       σ_max = r E max_i |(κb)_i| [stress], the paper's formula,
///                     with the discrete curvature binormal of discrete elastic
///                     rods (Bergou et al. 2008)
///                         (κb)_i = 2 e_{i-1} × e_i / (|e_{i-1}||e_i| + e_{i-1}·e_i),
///                     |(κb)_i| = 2 tan(φ_i/2). (κb)_i is an integrated
///                     (dimensionless) curvature: the pointwise curvature is
///                     (κb)_i / ℓ_i with ℓ_i the Voronoi length. The formula
///                     therefore equals the surface bending stress r E κ when
///                     ℓ_i = 1, the data set's edge length (n = 400, length 400);
///                     for other edge lengths σ scales as 1/ℓ (not applied here,
///                     to keep the paper's definition). Pure geometry, so
///                     computed here; infinite for a fold-back (φ_i = π).
///  - energy, energy_stretch, energy_bend, energy_twist: E_rod and its parts at
///                     the equilibrium (paper Section 6) — need the rod module.
///  - stiffness        smallest positive eigenvalue of the full Hessian H
///                     (rigid-motion zero modes excluded) — needs the solver
///                     module (sparse shift-invert eigensolver on the CHOLMOD factor).
/// The rod-dependent ones are std::optional and unset here; the module that
/// has the rod and solver fills them (e.g. a later
/// `physical_attributes(const Rod&, ...)`), without changing this struct's
/// existing fields or the names below.
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"

namespace ek {

/// Material for the stress attribute; defaults as in the paper's data set (RodMaterial's defaults).
struct AttributeOptions {
  double radius = 0.2;              ///< [length] wire radius r (length/diameter = 1000 at n = 400, unit edges)
  double young_modulus = 2000.0;    ///< [stress] Young's modulus E

  /// Throws InputError unless radius > 0 and young_modulus > 0 (both finite),
  /// naming the option of `knots attributes` (--radius, --young).
  void validate() const;
};

/// The centerline-only attributes.
struct GeometricAttributes {
  double total_curvature = 0.0;  ///< [rad] Σ turning angles
  double threedim = 0.0;         ///< [1] shortest / longest edge of the oriented bounding box
  double sphericity = 0.0;       ///< [1] std / mean of the vertex distances to the centroid
  double diameter = 0.0;         ///< [length] largest distance between two points of the curve
  double writhe = 0.0;           ///< [1] writhe Wr
};

/// Attributes needing a material or the rod/solver modules; unset when not computed.
struct PhysicalAttributes {
  std::optional<double> max_stress;      ///< [stress] r E max_i |(κb)_i|
  std::optional<double> energy;          ///< [energy] E_rod = stretch + bend + twist (rod module)
  std::optional<double> energy_stretch;  ///< [energy] stretching part (rod module)
  std::optional<double> energy_bend;     ///< [energy] bending part (rod module)
  std::optional<double> energy_twist;    ///< [energy] twisting part (rod module)
  std::optional<double> stiffness;       ///< [energy/length²] smallest positive Hessian eigenvalue (solver module)
};

/// All attributes of one curve.
struct Attributes {
  GeometricAttributes geometric;  ///< functions of the centerline alone
  PhysicalAttributes physical;    ///< stress, energies and stiffness of the wire
};

/// Geometric attributes of the closed polygon P (n by 3, n >= 3, finite, no zero-length edge).
GeometricAttributes geometric_attributes(const Points& P);

/// Geometric attributes and the max stress (the rod-dependent fields stay unset).
Attributes compute_attributes(const Points& P, const AttributeOptions& options = {});

/// Attribute names (stable snake_case keys, also the JSON keys of `knots
/// attributes`), in this order: total_curvature, threedim, sphericity,
/// diameter, writhe, max_stress, energy, energy_stretch, energy_bend,
/// energy_twist, stiffness.
const std::vector<std::string>& attribute_names();

/// Value of an attribute by name (unset optional: not computed). Unknown
/// names throw InputError listing the valid ones (names come from users).
std::optional<double> attribute_value(const Attributes& attributes, const std::string& name);

// ---- the individual attributes ----

/// (κb)_i, n by 3: the discrete curvature binormal at every node (formula above), [1].
Points curvature_binormals(const Points& P);

/// r E max_i |(κb)_i| (formula and units above).
double max_bending_stress(const Points& P, double radius, double young_modulus);

/// Shortest over longest edge of min_volume_bounding_box(P); 0 when all points coincide.
double threedim(const Points& P);

/// Population standard deviation of |x_i - centroid| divided by its mean (0 when the mean is 0).
double sphericity(const Points& P);

/// Largest vertex-to-vertex distance and the vertex pair (i < j) realising it.
struct Diameter {
  double distance = 0.0;  ///< [length]
  ///@{
  /// The vertex pair realising the diameter, i < j.
  int i = 0, j = 0;
  ///@}
};
/// Exact O(n²) maximum over vertex pairs (n = 400: ~80k distances, tens of µs).
Diameter diameter(const Points& P);

}  // namespace ek
