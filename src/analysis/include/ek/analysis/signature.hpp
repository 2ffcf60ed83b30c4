#pragma once
/// \file
/// Curvature and curvature-weighted torsion signatures of a closed polygon
/// (paper Section 7.1).
///
/// For a closed polygon x_0 .. x_{n-1} (n by 3, edge j = x_{j+1} - x_j, cyclic):
///
/// ~~~{.unparsed}
///   curvature   κ_i = φ_i / ℓ_i,   φ_i = turning angle at node i (angle in
///               [0, π] between e_{i-1} and e_i), ℓ_i = (|e_{i-1}| + |e_i|)/2
///               the node's Voronoi length;                     [1/length]
///   binormal    b_i = e_{i-1} × e_i / |e_{i-1} × e_i|  (Carroll et al. 2014);
///   torsion     τ^j = θ_j / |e_j|, θ_j the signed angle from b_j to b_{j+1}
///               about the edge direction t_j = e_j/|e_j|:
///               θ_j = atan2((b_j × b_{j+1})·t_j, b_j·b_{j+1}) ∈ (-π, π];
///               positive for a right-handed helix;           [1/length]
///   signature   K_i = κ_i,  T_i = κ_i (τ^{i-1} + τ^i)/2.   [1/length, 1/length²]
/// ~~~
///
/// Degenerate cases (no NaN is ever produced):
///  - a node whose incident edges are (anti)parallel, |e_{i-1} × e_i| <=
///    kBinormalTolerance·|e_{i-1}||e_i|, has no binormal; the torsion of both
///    edges at that node is set to 0. At the node itself κ_i·(...) vanishes
///    anyway for a straight node (the curvature factor kills the term, which is
///    why the paper weights torsion by curvature); its neighbours lose the
///    undefined half of their average.
///  - when the sine |(b_j × b_{j+1})·t_j| is at most its rounding-error bound,
///    kCoplanarTolerance + kCoplanarSafety·(ε_j + ε_{j+1}) with
///    ε_i = 2u·X·(|e_{i-1}| + |e_i|)/|e_{i-1} × e_i| (u the unit roundoff, X the
///    largest coordinate magnitude of the curve: the error of b_i caused by
///    rounding the coordinates), it is taken as exactly 0, so that θ_j is
///    exactly 0 (parallel binormals) or exactly +π (antiparallel: a planar
///    inflection) whatever the curve's position and orientation in space. Consequently a planar convex curve has T = 0 exactly, and a planar
///    curve with inflections has T ≠ 0 at the nodes beside each inflection edge
///    (θ = π there, as the paper's definition gives), equal for all rigid
///    copies.
///
/// The sign at θ = ±π (a binormal that flips within one edge: an inflection
/// of a planar or nearly planar curve) is decided by the curve's out-of-plane
/// geometry; only exactly planar curves (to rounding) get the fixed +π. This is
/// inherent to the paper's definition (the curvature factor keeps these values
/// bounded, it does not remove them).
///
/// Orientation reversal (vertex order i -> n-1-i) reverses K and T as
/// sequences (torsion does not depend on the orientation); mirroring keeps K
/// and negates T.
#include "ek/geometry/types.hpp"

namespace ek {

/// Binormal undefined when |e_{i-1} × e_i| <= this · |e_{i-1}||e_i| (the sine of the turning angle).
inline constexpr double kBinormalTolerance = 1e-12;
/// Absolute part of the bound below which the sine of a binormal rotation angle is taken as 0 (see above).
inline constexpr double kCoplanarTolerance = 1e-12;
/// Safety factor on the rounding-error estimate in that bound.
inline constexpr double kCoplanarSafety = 16.0;

/// The two signature profiles of one curve, each of length n (one per node).
struct CurveSignature {
  VecX curvature;  ///< K_i = κ_i [1/length]
  VecX torsion;    ///< T_i = κ_i (τ^{i-1} + τ^i)/2 [1/length²]
  int size() const { return static_cast<int>(curvature.size()); }  ///< n, the number of nodes
};

/// Discrete curvature κ_i (length n) of the closed polygon P (n by 3, n >= 3).
VecX discrete_curvature(const Points& P);

/// Discrete torsion τ^j of every edge j (length n; edge j joins node j to j+1).
VecX discrete_torsion(const Points& P);

/// The signature (K, T) of the closed polygon P (n >= 3, no zero-length edge).
CurveSignature curve_signature(const Points& P);

/// Signature of the curve with reversed orientation, Q_i = P_{n-1-i}:
/// K'_i = K_{n-1-i}, T'_i = T_{n-1-i}.
CurveSignature reversed(const CurveSignature& s);

/// Signature of the mirror image: K unchanged, T negated.
CurveSignature mirrored(const CurveSignature& s);

}  // namespace ek
