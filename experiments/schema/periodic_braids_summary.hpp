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

  /// The tabulated knot's name, or "" (also for files with "" for none).
  std::string tabulated() const { return knot.value_or(""); }
};
EK_JSON_FIELDS(PeriodicMember, family, p, knot, status, energy, alexander_preserved, alexander_matches_table, threedim,
               symmetry_error, control_error, axis, center, crossings, projection_crossings, polygon_split,
               polygon_error_deg, relative_rotation_deg, expected_rotation_deg, curve, symmetric_curve, symmetric,
               tall_start)

struct PeriodicBraidsSummary {
  std::string scale;
  std::optional<double> crossing_gap;  ///< [length] kCrossingGap (absent before)
  std::optional<double> radius;        ///< [length] wire radius r of the curves (absent before)
  std::vector<PeriodicMember> members;
};
EK_JSON_FIELDS(PeriodicBraidsSummary, scale, crossing_gap, radius, members)

}  // namespace ek::results
