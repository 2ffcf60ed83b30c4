#pragma once
/// \file
/// Conservative continuous collision detection for two moving segments
/// (paper Section 6: "continuous-time collision detection ... to compute
/// admissible, collision-free step sizes"). Additive CCD in the spirit of
/// Li et al. 2021 ("Codimensional Incremental Potential Contact", ACCD), with
/// a certified floor and a second, separating-plane bound.
///
/// Motion: every endpoint moves linearly, p(s) = p + s·dp, s ∈ [0, 1]. Let
/// d(s) be the segment distance and
///   L = max over i ∈ {a0, a1}, j ∈ {b0, b1} of |dp_i − dp_j|,
/// the largest relative speed of a point of one segment with respect to a
/// point of the other (the relative displacement of the points with
/// parameters (u, v) is bilinear in (u, v), so its norm is largest at a
/// corner). Then |d(s') − d(s)| <= L |s' − s| (the closest pair at s' was at
/// most L|s' − s| farther apart at s).
///
/// Algorithm: with the floor δ = separation · min(d(0), distance_cap), start
/// at s = 0 and advance by the longer of two certified steps:
///  - Lipschitz: Δ = (d(s) − δ)/L, since d >= d(s) − L·Δ;
///  - separating plane: with n the unit vector between the closest points at
///    s, every point of A lies at height >= d(s) above every point of B along
///    n (closest points of convex sets); the height n·(p_A − p_B) of points
///    with parameters (u, v) at time s' is multilinear in (u, v, s'), so it
///    stays >= δ on [s, s + Δ] iff it does for the four endpoint pairs at both
///    ends: Δ = min over endpoint pairs (i, j) approaching along n of
///    (n·(a_i − b_j) − δ) / (−n·(da_i − db_j)).
/// The plane step is exact for translations and long for tangential motion
/// (sliding, grazing), where the Lipschitz step alone would crawl. Both steps
/// use, instead of the computed distance d(s), the lower bound
/// min over endpoint pairs of n·(a_i − b_j) (<= d(s) for any unit n, by
/// bilinearity): the distance formulas lose up to ~1e-11 for nearly parallel
/// segments, this bound only the rounding of dot products (n is taken along
/// the closest pair, made orthogonal to the segment(s) whose interior holds a
/// closest point, so it stays accurate for nearly touching segments too). Stop when
/// s reaches t_max (no contact before it: return t_max), when
/// d(s) <= δ + tolerance·(d(0) − δ) (the motion is about to bring the pair to
/// the floor: return s), or after max_iterations (return s). Every returned t
/// is certified: d(s) >= δ > 0 for all s ∈ [0, t] (up to the rounding of the
/// distance evaluations, ~1e-16 relative), so the segments never touch or pass
/// through each other before t.
#include "ek/contact/distance.hpp"

namespace ek {

/// Parameters of edge_edge_ccd().
struct CcdParams {
  double separation = 0.1;    ///< [1] floor δ = separation · min(d(0), distance_cap); in (0, 1)
  double distance_cap = 1e300;  ///< [length] cap on the distance used for the floor (ContactPotential: d̂)
  double tolerance = 0.1;     ///< [1] stop once d(s) <= δ + tolerance·(d(0) − δ); in (0, 1]
  int max_iterations = 1000;  ///< [1] cap on distance evaluations (the result stays certified)
};

/// Outcome of edge_edge_ccd().
struct CcdResult {
  double t = 0.0;           ///< [1] certified step (<= t_max)
  double distance = 0.0;    ///< [length] d(0)
  double floor = 0.0;       ///< [length] δ
  int iterations = 0;       ///< distance evaluations after the first
};

/// Largest certified step t <= t_max for segments [a0, a1], [b0, b1] moving by
/// (da0, da1, db0, db1) times s (see above). t = 0 when the segments touch
/// at s = 0; t_max when the motion cannot bring them to the floor before t_max.
CcdResult edge_edge_ccd(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, const Vec3& da0,
                        const Vec3& da1, const Vec3& db0, const Vec3& db1, double t_max, const CcdParams& params);

}  // namespace ek
