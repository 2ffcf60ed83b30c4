#pragma once
// summary.json of exp_hausdorff (docs/results.md, "hausdorff"): the Hausdorff
// distance against the curvature-torsion similarity on 6_1's equilibria
// (paper Fig. 5).
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// A pair of equilibria in different clusters that the Hausdorff distance puts close.
struct HausdorffPair {
  int a = -1, b = -1;                ///< equilibrium indices in hausdorff.h5 (a < b)
  int cluster_a = -1, cluster_b = -1;  ///< cluster ranks at the cut (by energy)
  double hausdorff = 0.0;            ///< [length] after rigid alignment of b onto a
  double similarity_distance = 0.0;  ///< [1] 1 - similarity
  double icp_distance = 0.0;         ///< [length] the alignment's RMS distance
  double energy_a = 0.0, energy_b = 0.0;  ///< [energy]
  std::string curve_a, curve_b;      ///< OBJ paths relative to the folder (b aligned onto a)
};
EK_JSON_FIELDS(HausdorffPair, a, b, cluster_a, cluster_b, hausdorff, similarity_distance, icp_distance, energy_a,
               energy_b, curve_a, curve_b)

struct HausdorffSummary {
  std::string scale;
  std::string knot;                  ///< "6_1"
  double cut = 0.0;                  ///< [1] kClusterCut
  long samples = 0;                  ///< [1] lattice samples relaxed
  long equilibria = 0;               ///< [1] stable equilibria
  int clusters = 0;                  ///< [1] distinct states at the cut
  long pairs = 0;                    ///< [1] equilibrium pairs compared (pairs.csv)
  int same_cluster_pairs = 0;        ///< [1]
  std::optional<double> median_same_cluster_hausdorff;  ///< [length] null: no cluster with two members
  int different_cluster_pairs = 0;   ///< [1] pairs in different clusters at the cut
  int below_median_pairs = 0;        ///< [1] of them, those with a Hausdorff distance below that median (the claim)
  /// [1] pairs in different clusters and farther apart than the cut in similarity
  int distinct_pairs = 0;
  int separated_pairs = 0;           ///< [1] of them, those with a Hausdorff distance below that median
  /// The same over the unique equilibria (ek::HausdorffSeparation): members
  /// of one cluster closer than `identical_hausdorff` are one equilibrium.
  double identical_hausdorff = 0.0;  ///< [length] ek::kIdenticalHausdorff
  int identical_pairs = 0;           ///< [1] same-cluster pairs closer than it
  int unique_equilibria = 0;         ///< [1]
  int unique_same_cluster_pairs = 0; ///< [1]
  std::optional<double> median_unique_same_cluster_hausdorff;  ///< [length] null: no cluster with two of them
  int unique_different_cluster_pairs = 0;  ///< [1]
  int below_unique_median_pairs = 0;       ///< [1] of them, those below that median (the claim, asserted)
  int separated_below_unique_median = 0;   ///< [1] of them, those also farther apart than the cut in similarity
  /// the closest distinct pairs (the stricter definition) in Hausdorff
  /// distance, one per pair of clusters
  std::vector<HausdorffPair> shown;
};
EK_JSON_FIELDS(HausdorffSummary, scale, knot, cut, samples, equilibria, clusters, pairs, same_cluster_pairs,
               median_same_cluster_hausdorff, different_cluster_pairs,
               below_median_pairs, distinct_pairs, separated_pairs, identical_hausdorff, identical_pairs,
               unique_equilibria, unique_same_cluster_pairs, median_unique_same_cluster_hausdorff,
               unique_different_cluster_pairs, below_unique_median_pairs, separated_below_unique_median, shown)

}  // namespace ek::results
