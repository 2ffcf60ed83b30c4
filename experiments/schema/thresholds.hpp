#pragma once
// The thresholds of the paper experiments, in one place: the experiments
// apply them and write them into their summary.json (docs/results.md), the
// paper checks assert with them, and the figure scripts read them from the
// summaries. Changing one changes what every experiment, check and figure
// means by it.

namespace ek::results {

/// [1] The cut (distance 1 - similarity) at which equilibria count as the
/// same state: for every knot (clusters, distinct equilibria) and as the
/// novelty distance δ of adaptive sampling.
inline constexpr double kClusterCut = 0.05;

/// [1] An equilibrium is approximately planar when its 3D-ness (shortest over
/// longest edge of the oriented bounding box) is below this (paper Section
/// 8.2 "approximately planar"; the value is ours); a state at or above it is
/// distinctly 3D.
inline constexpr double kPlanarThreedim = 0.1;

/// [1] 3D-ness at or above which a jumping knot's released state counts as 3D.
inline constexpr double kJumpThreedim = 0.3;

/// [1] Two states form a puzzle when their writhes differ by at most this.
inline constexpr double kWritheTolerance = 0.1;

/// [1] A state is low-energy when its lowest energy is at most this factor
/// times the knot's lowest (adaptive sampling's coverage).
inline constexpr double kLowEnergyFactor = 1.2;

/// [length] A braid's crossings seen along its axis: strands at most this far
/// apart along the axis where their projections cross (2 d̂ of the data set's
/// wire, d̂ = 0.4; where the strands of a braid cross they touch).
inline constexpr double kCrossingGap = 0.8;

}  // namespace ek::results
