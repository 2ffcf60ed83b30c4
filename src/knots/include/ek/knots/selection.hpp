#pragma once
/// \file
/// Choosing knots of the table for a run smaller than the whole table: a
/// deterministic stratified sample, so that a run on a small machine speaks
/// for every kind of knot of the crossing numbers it samples.
#include <vector>

#include "ek/knots/table.hpp"

namespace ek {

/// Which knots stratified_sample() takes.
struct StratifiedSampleOptions {
  int min_crossings = 11;  ///< [1] smallest crossing number sampled
  int max_crossings = 12;  ///< [1] largest crossing number sampled
  /// [1] share of each stratum taken, in (0, 1]: ⌈fraction · size⌉ knots of
  /// every stratum, so at least this share of every crossing number
  double fraction = 0.1;
  /// Also take every BB knot (bridge index = braid index, paper Fig.\ 9) of
  /// the sampled crossing numbers.
  bool all_bb_knots = true;
  void validate() const;  ///< InputError for impossible values
};

/// The table's knots with min_crossings ≤ c ≤ max_crossings grouped into
/// strata by (crossing number, alternating, bridge index) (unknown values
/// form strata of their own); from a stratum of size s, k = ⌈fraction · s⌉
/// knots evenly spread in table order (the j-th of k, j = 0..k−1, at index
/// ⌊(j + 1/2)·s/k⌋); with all_bb_knots, every BB knot besides. In table
/// order, each knot once. The same table gives the same sample.
std::vector<const KnotRecord*> stratified_sample(const KnotTable& table, const StratifiedSampleOptions& options);

/// Whether a knot is a BB knot: its bridge index equals its braid index
/// (both known).
bool is_bb_knot(const KnotRecord& knot);

}  // namespace ek
