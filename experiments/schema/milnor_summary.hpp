#pragma once
// summary.json of exp_milnor (docs/results.md, "milnor").
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// A BB knot (bridge index = braid index) at its smallest total curvature.
struct MilnorBBKnot {
  std::string knot;
  double ratio = 0.0;     ///< [1] total curvature / (2π · bridge index)
  double threedim = 0.0;  ///< [1] 3D-ness of that equilibrium
};
EK_JSON_FIELDS(MilnorBBKnot, knot, ratio, threedim)

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
};
EK_JSON_FIELDS(MilnorSummary, scale, knots, equilibria, milnor_violations, bb_knots, bb_max_ratio_deviation,
               bb_max_threedim, planar_threshold, top_decile_size, top_decile_two_bridge_share)

}  // namespace ek::results
