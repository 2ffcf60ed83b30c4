#pragma once
/// \file
/// Deploying a flat multi-covered coil at a prescribed link: the jumping-knot
/// pipeline of paper Section 8.3 (Figs.\ 12, 13), used for the periodic braids
/// of Section 8.4 (Fig.\ 16: "initialized ... from multi-covered circle
/// embeddings obtained from the generalized braid word representations, as
/// illustrated in Figure 13").
///
/// At a link Lk [turns] the coil (n by 3, in the plane z = 0, every vertex
/// inside the slab) is relaxed with the full model and Θ fixed so that
/// Tw + Wr = Lk (RelaxOptions::link), first under the planarity slab
/// |z| < h (RelaxOptions::slab: the flat coil with that link), then with the
/// slab released from the flat state (a second solve, as in
/// exp_jumping_knots). Newton's method leaves the flat state only when it is
/// not a stable equilibrium without the slab (the saddle escape of
/// newton.hpp), so the released state is the flat coil below the link at
/// which the flat coil loses stability and another state above it. A coil
/// that leaves trades twist for writhe (Călugăreanu–White–Fuller: Lk is
/// fixed), so it counts as buckled when its writhe changes by at least
/// `buckling_writhe` (Michell's instability: a single ring of bending
/// stiffness B and twisting stiffness C buckles at Lk > √3·B/C), or when it
/// ends 3D (a state with the flat coil's writhe, e.g. 4_1's, whose 3D state
/// has Wr = 0 by its symmetry). The state it buckles into need not be 3D: a
/// ring folds into a nearly flat figure eight.
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// The model and the thresholds of deploy_at_link() and scan_links().
struct DeployOptions {
  /// Material, rest lengths, tolerances, ... of every solve; its link, slab
  /// and release_slab are set per run (the full model with Θ fixed).
  RelaxOptions relax;
  /// [length] half-thickness h of the slab |z| < h; unset: 2 d̂ (the
  /// jumping-knot experiment's slab).
  std::optional<double> slab_half_thickness;
  /// [1] a released state with 3D-ness (ek::threedim) at least this counts
  /// as 3D (the planarity threshold of Section 8.2).
  double threedim_threshold = 0.1;
  /// [turns] a released state whose writhe differs from the flat state's by
  /// at least this has left the flat coil (buckled).
  double buckling_writhe = 0.1;
  void validate() const;  ///< throws InputError for a negative threshold
};

/// One coil relaxed at one prescribed link, under the slab and released.
struct DeployRun {
  double link = 0.0;          ///< [turns] prescribed Lk
  RelaxStatus flat_status = RelaxStatus::Stalled;  ///< at the end of the slab phase
  double flat_energy = 0.0;   ///< [energy] at the end of the slab phase (slab barrier included)
  double flat_writhe = 0.0;   ///< [turns] of the flat state
  RelaxStatus status = RelaxStatus::Stalled;       ///< RelaxResult::status() after the release
  double energy = 0.0;        ///< [energy] after the release
  double threedim = 0.0;      ///< [1] after the release
  double writhe = 0.0;        ///< [turns] after the release
  double link_error = 0.0;    ///< [turns] |Lk_result - Lk|
  bool stable = false;        ///< converged-stable with the Alexander polynomial kept
  bool buckled = false;       ///< stable and (|writhe - flat_writhe| >= buckling_writhe or three_d)
  bool three_d = false;       ///< stable and 3D-ness >= threshold
  Points positions;           ///< n by 3, the released state
  VecX theta;                 ///< n material angles of the released state
};

/// The coil relaxed at `link` [turns] under the slab, then released.
/// Throws InputError when the coil does not lie strictly inside the slab.
DeployRun deploy_at_link(const Points& coil, double link, const DeployOptions& options = {});

/// The links scan_links() relaxes the coil at, and the bisection of the onsets.
struct LinkScanOptions {
  /// [turns] links of the coarse scan, ascending, at least one.
  std::vector<double> grid;
  /// [turns] a link inside the coil's stable interval, e.g.\ its twist-free
  /// link (the flat coil's writhe): the interval is the run of consecutive
  /// grid links at which the coil stays flat and stable that contains the
  /// grid link nearest to it.
  double center = 0.0;
  /// [1] bisection steps at each end of the stable interval, between its
  /// last link and the next grid link, at which the coil buckles (0: the grid
  /// only). Each step halves the bracket of that onset.
  int refinements = 0;
  void validate() const;  ///< throws InputError for an empty or unsorted grid or negative refinements
};

/// The links at which the flat coil stays stable and where it stops.
struct LinkScan {
  std::vector<DeployRun> runs;  ///< every run, by ascending link
  ///@{
  /// [turns] the ends of the stable interval: the smallest and largest
  /// scanned links of the run of consecutive flat and stable links around
  /// the centre (null when the coil is not flat and stable there).
  std::optional<double> flat_low, flat_high;
  ///@}
  ///@{
  /// [turns] the next scanned links outside it at which the coil buckles
  /// (null: the neighbour did not buckle, or the interval reaches the
  /// grid's end): the flat coil loses stability in (buckled_below, flat_low)
  /// and in (flat_high, buckled_above).
  std::optional<double> buckled_below, buckled_above;
  ///@}
  ///@{
  /// [turns] the scanned links nearest to the stable interval, below and
  /// above it, whose released states are stable and 3D (null: none).
  std::optional<double> three_d_below, three_d_above;
  ///@}
};

/// Runs deploy_at_link() at every grid link, then bisects each bracket
/// (buckled_below, flat_low) and (flat_high, buckled_above) `refinements`
/// times (a midpoint that buckles moves the bracket's outer end, one that
/// stays flat and stable its inner end; any other outcome stops that side's
/// refinement). The grid's runs show whether the coil is flat and stable
/// throughout the interval; the bisection assumes a single onset per bracket.
LinkScan scan_links(const Points& coil, const LinkScanOptions& scan, const DeployOptions& options = {});

}  // namespace ek
