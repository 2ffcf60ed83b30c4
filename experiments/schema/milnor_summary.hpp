#pragma once
// summary.json of exp_milnor (docs/results.md, "milnor").
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// A BB knot (bridge index = braid index): its smallest total curvature,
/// and its smallest among its multi-covered circles (3D-ness below
/// kPlanarThreedim, Fig. 9's "flat" states).
struct MilnorBBKnot {
  std::string knot;
  double ratio = 0.0;     ///< [1] smallest total curvature / (2π · bridge index)
  double threedim = 0.0;  ///< [1] 3D-ness of that equilibrium
  /// [1] the smallest ratio of its equilibria with 3D-ness < kPlanarThreedim;
  /// null when it has none
  std::optional<double> planar_ratio;
  int planar_equilibria = 0;  ///< [1] its equilibria with 3D-ness < kPlanarThreedim
  int equilibria = 0;         ///< [1] its equilibria
};
EK_JSON_FIELDS(MilnorBBKnot, knot, ratio, threedim, planar_ratio, planar_equilibria, equilibria)

struct MilnorSummary {
  std::string scale;
  long knots = 0;                          ///< [1] knot types with equilibria
  long equilibria = 0;                     ///< [1]
  long milnor_violations = 0;              ///< [1] equilibria with total curvature <= 2π · bridge index
  std::vector<MilnorBBKnot> bb_knots;      ///< every BB knot of the data set
  double bb_max_ratio_deviation = 0.0;     ///< [1] max |ratio - 1| over bb_knots
  double bb_max_threedim = 0.0;            ///< [1] max 3D-ness over bb_knots
  double planar_threshold = 0.0;           ///< [1] kPlanarThreedim
  long top_decile_size = 0;                ///< [1] knots in the top decile by ratio (at least 1)
  double top_decile_two_bridge_share = 0;  ///< [1] share of 2-bridge knots in it
  long far_end_size = 0;                   ///< [1] min(top_decile_size, 2-bridge knots that are not BB), at least 1
  double far_end_two_bridge_share = 0;     ///< [1] share of 2-bridge knots among the far_end_size knots of largest ratio
};
EK_JSON_FIELDS(MilnorSummary, scale, knots, equilibria, milnor_violations, bb_knots, bb_max_ratio_deviation,
               bb_max_threedim, planar_threshold, top_decile_size, top_decile_two_bridge_share, far_end_size,
               far_end_two_bridge_share)

}  // namespace ek::results
