#pragma once
// summary.json of exp_periodic_braids (docs/results.md, "periodic_braids").
// Fields marked "absent before" are std::optional: files written before them
// still read (alexander_matches_table was the string "1", "0" or "-" there).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// The measures of the p-fold symmetric equilibrium next to a member.
struct PeriodicSymmetric {
  std::string status;                  ///< solver status
  double energy = 0.0;                 ///< [energy]
  double energy_above = 0.0;           ///< [energy] minus the member's relaxed energy
  double threedim = 0.0;               ///< [1]
  double symmetry_error = 0.0;         ///< [1] p-fold, about the member's axis
  int crossings = 0;                   ///< [1] braid crossings along the axis
  std::string polygon_split;           ///< "height" or "radius"
  double polygon_error_deg = 0.0;      ///< [deg]
  double relative_rotation_deg = 0.0;  ///< [deg]
};
EK_JSON_FIELDS(PeriodicSymmetric, status, energy, energy_above, threedim, symmetry_error, crossings, polygon_split,
               polygon_error_deg, relative_rotation_deg)

/// The member relaxed from its tall start (strands stacked along the axis).
struct PeriodicTallStart {
  double start_threedim = 0.0;  ///< [1]
  std::string status;
  double energy = 0.0;          ///< [energy]
  double energy_above = 0.0;    ///< [energy] minus the coil's relaxed energy
  double threedim = 0.0;        ///< [1]
};
EK_JSON_FIELDS(PeriodicTallStart, start_threedim, status, energy, energy_above, threedim)

/// One prescribed link of a member's link scan: its coil relaxed with the full
/// model (Θ fixed, Lk = Tw + Wr) under the slab, then released
/// (ek::deploy_at_link).
struct PeriodicLinkRun {
  double link = 0.0;              ///< [turns] prescribed Lk
  std::string flat_status;        ///< solver status under the slab
  double flat_energy = 0.0;       ///< [energy] under the slab (barrier included)
  double flat_writhe = 0.0;       ///< [turns] of the flat state
  std::string status;             ///< after the release (RelaxResult::status())
  double energy = 0.0;            ///< [energy] after the release
  double threedim = 0.0;          ///< [1] after the release
  double writhe = 0.0;            ///< [turns] after the release
  double link_error = 0.0;        ///< [turns] |Tw + Wr - link| after the release
  /// converged-stable, knot type kept, and writhe changed from the flat
  /// state's by at least `buckling_writhe` or 3D: the coil has left its flat state
  bool buckled = false;
  bool three_d = false;           ///< converged-stable, knot type kept, 3D-ness >= kPlanarThreedim
  double symmetry_error = 0.0;    ///< [1] p-fold, about ek::find_symmetry_axis() of the released state
  std::optional<std::string> curve;  ///< OBJ of a 3D released state, relative to the folder (null when flat)
};
EK_JSON_FIELDS(PeriodicLinkRun, link, flat_status, flat_energy, flat_writhe, status, energy, threedim, writhe,
               link_error, buckled, three_d, symmetry_error, curve)

/// The p-fold symmetric 3D state of a member at a prescribed link: the most
/// p-fold symmetric 3D state of the scan, averaged over its p periods
/// (ek::symmetrize()) and relaxed again at the same link.
struct PeriodicLinkedSymmetric {
  double link = 0.0;                   ///< [turns]
  double from_symmetry_error = 0.0;    ///< [1] of the scan's state it was averaged from
  std::string status;
  double energy = 0.0;                 ///< [energy]
  double energy_above = 0.0;           ///< [energy] minus the scan's state's energy
  double threedim = 0.0;               ///< [1]
  double writhe = 0.0;                 ///< [turns]
  double symmetry_error = 0.0;         ///< [1] p-fold about `axis` through the centroid
  std::array<double, 3> axis{0.0, 0.0, 1.0};  ///< unit
  std::array<double, 3> center{0.0, 0.0, 0.0};
  int crossings = 0;                   ///< [1] braid crossings along the axis
  std::string polygon_split;           ///< "height" or "radius"
  double polygon_error_deg = 0.0;      ///< [deg]
  double relative_rotation_deg = 0.0;  ///< [deg]
  std::string curve;                   ///< OBJ, relative to the folder
};
EK_JSON_FIELDS(PeriodicLinkedSymmetric, link, from_symmetry_error, status, energy, energy_above, threedim, writhe,
               symmetry_error, axis, center, crossings, polygon_split, polygon_error_deg, relative_rotation_deg, curve)

/// A member's coil at prescribed links (paper Section 8.3's pipeline).
struct PeriodicLinkScan {
  double center = 0.0;                 ///< [turns] the grid's centre: the flat coil's writhe, rounded
  std::vector<double> grid;            ///< [turns] the coarse links
  int refinements = 0;                 ///< [1] bisection steps at each onset
  double slab_half_thickness = 0.0;    ///< [length] h of |z| < h
  double buckling_writhe = 0.0;        ///< [turns] writhe change that counts as buckled
  std::vector<PeriodicLinkRun> runs;   ///< by ascending link
  /// [turns] the ends of the stable interval around `center` (the scanned
  /// links at which the coil stays flat and stable; null when it is not
  /// stable at the centre) and the next scanned links outside it at which
  /// it buckles (null when none): the flat coil loses stability in
  /// (buckled_below, flat_low) and (flat_high, buckled_above).
  std::optional<double> flat_low, flat_high, buckled_below, buckled_above;
  /// [turns] the scanned links nearest to the stable interval, below and
  /// above it, at which the coil deploys to a stable 3D state (null: none);
  /// both null when the centre itself is 3D (4_1, 9_40: then the run at the
  /// centre is the deployed one).
  std::optional<double> three_d_below, three_d_above;
  std::optional<PeriodicLinkedSymmetric> symmetric;  ///< null when no 3D state
  /// Whether the coil deploys to a stable 3D state at some scanned link.
  bool deploys() const {
    for (const auto& r : runs)
      if (r.three_d) return true;
    return false;
  }
};
EK_JSON_FIELDS(PeriodicLinkScan, center, grid, refinements, slab_half_thickness, buckling_writhe, runs, flat_low,
               flat_high, buckled_below, buckled_above, three_d_below, three_d_above, symmetric)

struct PeriodicMember {
  std::string family;              ///< "s1s2i" (σ1σ2⁻¹)^p or "s1s2is3" (σ1σ2⁻¹σ3)^p
  int p = 0;                       ///< [1] periods
  /// The tabulated knot type, null when not tabulated (files written before
  /// typed results hold "" there: see tabulated()).
  std::optional<std::string> knot;
  std::string status;              ///< solver status of the relaxation from the coil
  double energy = 0.0;             ///< [energy]
  bool alexander_preserved = false;
  std::optional<bool> alexander_matches_table;  ///< null when not tabulated
  double threedim = 0.0;           ///< [1]
  double symmetry_error = 0.0;     ///< [1] p-fold about `axis` (ek::rotational_symmetry_error)
  double control_error = 0.0;      ///< [1] (p+1)-fold about the same axis
  /// The symmetry axis (unit) and its centre (the centroid) of the relaxed
  /// state, from ek::find_symmetry_axis (absent before).
  std::optional<std::array<double, 3>> axis, center;
  int crossings = 0;               ///< [1] braid crossings along the axis (within kCrossingGap)
  int projection_crossings = 0;    ///< [1] every crossing of the projection along the axis
  std::string polygon_split;       ///< "height" or "radius"
  double polygon_error_deg = 0.0;  ///< [deg]
  double relative_rotation_deg = 0.0;   ///< [deg]
  double expected_rotation_deg = 0.0;   ///< [deg] 0 for odd p, 180/p for even p
  std::optional<std::string> curve;            ///< OBJ of the relaxed state, relative to the folder (absent before)
  std::optional<std::string> symmetric_curve;  ///< OBJ of the symmetric equilibrium (absent before)
  PeriodicSymmetric symmetric;
  PeriodicTallStart tall_start;
  /// The coil at prescribed links, under the slab and released (absent before).
  std::optional<PeriodicLinkScan> link_scan;

  /// The tabulated knot's name, or "" (also for files with "" for none).
  std::string tabulated() const { return knot.value_or(""); }
};
EK_JSON_FIELDS(PeriodicMember, family, p, knot, status, energy, alexander_preserved, alexander_matches_table, threedim,
               symmetry_error, control_error, axis, center, crossings, projection_crossings, polygon_split,
               polygon_error_deg, relative_rotation_deg, expected_rotation_deg, curve, symmetric_curve, symmetric,
               tall_start, link_scan)

struct PeriodicBraidsSummary {
  std::string scale;
  std::optional<double> crossing_gap;  ///< [length] kCrossingGap (absent before)
  std::optional<double> radius;        ///< [length] wire radius r of the curves (absent before)
  std::optional<double> threedim_threshold;  ///< [1] kPlanarThreedim: a state at least this 3D counts as 3D (absent before)
  std::vector<PeriodicMember> members;
  /// Braids of the families whose closure is not a knot (skipped), e.g.
  /// "s1s2i p=3: 3 components" (absent before).
  std::optional<std::vector<std::string>> skipped;
};
EK_JSON_FIELDS(PeriodicBraidsSummary, scale, crossing_gap, radius, threedim_threshold, members, skipped)

}  // namespace ek::results
