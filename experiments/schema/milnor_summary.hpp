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
  /// [samples] the sampling's full budget per knot (fixed samples, or the
  /// adaptive maximum): a knot sampled less has an upper bound of its ratio
  long budget = 0;
  /// [1] knots read from the full-budget ledgers (full_budget/) in place of the scale's own entries
  long full_budget_knots = 0;
  /// full-budget knots whose ratio came out above their adaptive run's (by
  /// more than 1e-9 relative): not expected, since their first samples are
  /// the adaptive run's (a relaxation that no longer reproduces)
  std::vector<std::string> full_budget_raised;
  /// far_end_certificate (ek/analysis/far_end.hpp): the far_end_size knots
  /// of largest ratio at the full budget are all 2-bridge
  bool far_end_certified = false;
  double far_end_other_max_ratio = 0;      ///< [1] M, the largest ratio of a knot that is not 2-bridge
  std::string far_end_other_max_knot;      ///< the knot that sets M
  long far_end_certified_two_bridge = 0;   ///< [1] 2-bridge knots at the full budget with ratio above M
  /// the knots to sample at the full budget to decide it (scripts/ledger_far_end.sh); empty once decided
  std::vector<std::string> far_end_to_sample;
};
EK_JSON_FIELDS(MilnorSummary, scale, knots, equilibria, milnor_violations, bb_knots, bb_max_ratio_deviation,
               bb_max_threedim, planar_threshold, top_decile_size, top_decile_two_bridge_share, far_end_size,
               far_end_two_bridge_share, budget, full_budget_knots, full_budget_raised, far_end_certified,
               far_end_other_max_ratio, far_end_other_max_knot, far_end_certified_two_bridge, far_end_to_sample)

}  // namespace ek::results
