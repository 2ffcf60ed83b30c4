#pragma once
/// \file
/// Topology-safe rounding of a closed polygon onto the cubic lattice Z³
/// (paper Section 5: "we scale the polygonal curve so that ... rounding
/// [cannot] alter the knot topology").
///
/// Construction (scale s, rotation R, input polygon P with m edges E_i):
///  1. Q = s·R·P. The walk starts at the midpoint S of the longest edge.
///  2. Cell walk: every point x of Q is sent to its nearest lattice site
///     round(x) = floor(x + 1/2) (per coordinate). Following Q from S around
///     to S, the site changes exactly when one coordinate of x crosses a
///     half-integer, and then by a unit step in that coordinate: a closed walk
///     w_0 .. w_N = w_0 of unit steps ("rounding + unit-step joining"). Along
///     one edge every coordinate of the walk is monotone (weakly, in the
///     direction of the edge).
///  3. Loop erasure (chronological, from w_0): when the walk returns to a site
///     still on the path, the loop in between is cut out (this includes
///     immediate back-tracks u, v, u). The result L is a closed self-avoiding
///     lattice polygon, every step of which is a step of the walk.
/// The correspondence φ: Q → L sends x to the site of its cell, and a cut-out
/// arc to the site at which its loop closed (L's steps are traversed on short
/// intervals at the crossing points). Its displacement δ = max |φ(x) − x| is measured exactly
/// (distance to a fixed point is convex along a segment, so the maximum over
/// an arc is attained at its crossing points and polygon vertices). Without
/// cuts δ <= √3/2 (each coordinate within 1/2); cuts add the size of the cut
/// arcs.
///
/// Theorem (certificate checked by round_to_lattice; see rounding.cpp for the
/// proof). Let W >= 2 be such that every W consecutive edges of R·P have a
/// common coordinate k in which all of them are strictly monotone with the
/// same sign, and c_W the smallest distance between two edges of P whose
/// cyclic index distance is >= W (for W = 2: the usual clearance, edges that
/// share no vertex). If
///        s · c_W > 2 δ,
/// then L has the knot type of P.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/lattice/lattice_polygon.hpp"

namespace ek {

/// Options of round_to_lattice().
struct RoundingOptions {
  /// The scale is (1 + margin) times the smallest scale the certificate allows.
  double margin = 0.05;  ///< [1]
  /// Largest window W of consecutive edges used by the monotone-chain
  /// argument (larger windows allow smaller scales on finely sampled curves).
  int max_window = 64;  ///< [edges]
  /// An edge counts as strictly monotone in coordinate k when its unit
  /// direction has |d_k| >= this.
  double min_direction_cosine = 1e-6;  ///< [1]
  /// Scale increases (by at least 1.25x) when the measured displacement
  /// violates the certificate.
  int max_attempts = 12;  ///< [1]
  /// Pseudo-random rotations tried when some corner of P has no common
  /// monotone coordinate (a turn of more than ~33.6° can cause that).
  int rotation_attempts = 32;       ///< [1]
  std::uint64_t rotation_seed = 1;  ///< seed of the rotation sequence
  /// Compute the Alexander polynomial of the result and compare (always
  /// recommended; a mismatch throws TopologyError).
  bool verify = true;
};

/// Result of round_to_lattice().
struct RoundingResult {
  LatticePoints points;              ///< L, n by 3 integer sites (a self-avoiding lattice polygon)
  double scale = 0.0;                ///< [lattice units / input length] s
  Mat3 rotation = Mat3::Identity();  ///< R, applied to the input before scaling
  int window = 0;                    ///< [edges] W
  double window_clearance = 0.0;     ///< [input length] c_W
  double max_turning_angle = 0.0;    ///< [rad] of the input polygon
  double walk_displacement = 0.0;    ///< [lattice units] δ₀ of the cell walk before loop erasure (<= √3/2)
  double displacement = 0.0;         ///< [lattice units] δ of the final correspondence φ
  int walk_length = 0;               ///< [steps] N, before loop erasure
  int loops_erased = 0;              ///< [1] loops cut out
  int attempts = 0;                  ///< [1] scales tried
  /// Empty, or why loop erasure did not leave a self-avoiding polygon (a
  /// scale far too small for the curve: a cut loop swallowed most of it, so
  /// `points` may have fewer than 4 sites). Never set on a certified result:
  /// the certificate's proof rules it out, and round_to_lattice treats it as
  /// a failed certificate and enlarges the scale.
  std::string defect;
  /// The certificate's margin s·c_W / (2δ) (> 1).
  double certificate_ratio = 0.0;  ///< [1]
};

/// Rounds a link's components onto Z³ at one scale s and one rotation R:
/// each component's cell walk as above (lattice_walk_of), certified by the
/// theorem above for each component (s·c_W > 2δ_k), and with the
/// components' δ-tubes disjoint: s·d > 2δ (d the smallest distance between
/// two components, δ the largest displacement), so every lattice component
/// lies within δ of its own scaled component and at least s·d − 2δ > 0 from
/// every other. The link type is then checked, not only argued: one result per
/// component (`scale`, `rotation` shared). The caller checks the invariants
/// (the lattice module's link sampling compares the components' Alexander
/// polynomials, the linking numbers and the Conway polynomial). Throws
/// InputError as round_to_lattice() does, and for touching components.
std::vector<RoundingResult> round_link_to_lattice(const Link& link, const RoundingOptions& options = {});

/// Rounds the closed simple polygon P (m by 3, m >= 4) onto Z³ as described
/// above, with the smallest certified scale (up to `margin`). The result's
/// Alexander polynomial is compared with `expected` (or with P's own when
/// none is given) and a mismatch throws TopologyError. Throws InputError for
/// an invalid curve (validate_closed_curve), a self-intersecting one
/// (clearance below 1e-9 times the bounding-box diagonal), one whose lattice
/// polygon would exceed 10⁷ edges, or one with a corner that no rotation makes
/// monotone.
RoundingResult round_to_lattice(const Points& P, const RoundingOptions& options = {},
                                const std::optional<AlexanderPolynomial>& expected = std::nullopt);

/// The cell walk and loop erasure of steps 1-3 at a given scale and rotation,
/// without the certificate or the Alexander check (for tests and
/// experiments). Fills every field of the result except window,
/// window_clearance and certificate_ratio; a scale too small for the curve
/// can leave a `defect` (then δ is still measured, and large).
RoundingResult lattice_walk_of(const Points& P, double scale, const Mat3& rotation = Mat3::Identity());

/// Largest W (<= max_window, <= m/2) such that every W consecutive edges of P
/// share a coordinate in which they are all strictly monotone with the same
/// sign (|d_k| >= min_direction_cosine); 1 if some corner has none, 0 for a
/// degenerate edge.
int monotone_window(const Points& P, int max_window, double min_direction_cosine);

}  // namespace ek
