#pragma once
// summary.json of exp_loads (docs/results.md, "loads").
#include <string>

#include "json_fields.hpp"

namespace ek::results {

struct LoadsSummary {
  std::string scale;
  double radius = 0.0;        ///< [length] wire radius r of the data sets' curves
  double plates_to = 0.0;     ///< [r] the plates' final gap, in wire radii
  double pull_stretch = 0.0;  ///< [1] the pull's final distance over the start's diameter
  double reach = 0.0;         ///< [1] similarity that names a released state as the start or the other state
  int pairs = 0;              ///< [1] puzzle pairs loaded (the first rows of transitions/puzzle_barriers.csv)
  int runs = 0;               ///< [1] rows of loads.csv (pair × direction × load)
  int runs_reached = 0;       ///< [1] runs whose control reached its end
  int runs_with_snaps = 0;    ///< [1]
  int snaps = 0;              ///< [1] rows of snaps.csv
  int flips = 0;              ///< [1] runs in which a snap's released state is the pair's other state
  /// [1] path points where a run left its branch without a snap (no energy
  /// released at the same control: PathEvent::BranchJump), over all runs
  int branch_jumps = 0;
  double seconds = 0.0;       ///< [s]
};
EK_JSON_FIELDS(LoadsSummary, scale, radius, plates_to, pull_stretch, reach, pairs, runs, runs_reached, runs_with_snaps,
               snaps, flips, branch_jumps, seconds)

}  // namespace ek::results
