#pragma once
// summary.json of exp_periodic_links (docs/results.md, "periodic_links"): the
// periodic braids' coils at prescribed links, the jumping-knot pipeline of
// paper Section 8.3 applied to Fig. 16's braids.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

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

/// One member of the periodic braids' families and its link scan.
struct PeriodicLinksMember {
  std::string family;               ///< "s1s2i" or "s1s2is3"
  int p = 0;                        ///< [1] periods
  std::optional<std::string> knot;  ///< the tabulated knot type, null when not tabulated
  double expected_rotation_deg = 0.0;  ///< [deg] 180/p for (σ1σ2⁻¹)^p, 0 for (σ1σ2⁻¹σ3)^p
  PeriodicLinkScan link_scan;
  std::string tabulated() const { return knot.value_or(""); }
};
EK_JSON_FIELDS(PeriodicLinksMember, family, p, knot, expected_rotation_deg, link_scan)

struct PeriodicLinksSummary {
  std::string scale;
  double crossing_gap = 0.0;        ///< [length] kCrossingGap
  double radius = 0.0;              ///< [length] wire radius
  double threedim_threshold = 0.0;  ///< [1] kPlanarThreedim
  std::vector<PeriodicLinksMember> members;
};
EK_JSON_FIELDS(PeriodicLinksSummary, scale, crossing_gap, radius, threedim_threshold, members)

}  // namespace ek::results
