#pragma once
/// \file
/// What two data sets of the same knots, computed by two relaxation methods
/// from the same lattice samples, say alike (`make compare-methods`,
/// docs/reproducing.md). The method decides which local minimum a start
/// reaches, so the frequencies of the states may differ; what a user learns
/// must not:
///  - every state (cluster at the cut) that holds at least `min_share` of a
///    knot's stored equilibria in one data set has a counterpart in the
///    other: an equilibrium of the same knot with similarity >= `counterpart`
///    (with orientation reversal, and the mirror image for amphicheiral
///    knots, as the data-set pipeline compares);
///  - the lowest energy per knot agrees within `energy_tolerance`
///    (relative);
///  - the share of approximately planar equilibria (3D-ness below
///    `planar_threshold`) agrees within `planar_tolerance`.
#include <string>
#include <vector>

#include "ek/dataset/dataset_file.hpp"

namespace ek {

/// The cut and the tolerances of compare_datasets() (see the file's description).
struct CompareOptions {
  double cut = 0.05;               ///< [1] clustering cut on 1 - similarity
  double min_share = 0.03;         ///< [1] clusters below this share of a knot's equilibria need no counterpart
  double counterpart = 0.95;       ///< [1] similarity of a counterpart
  double energy_tolerance = 1e-4;  ///< [1] relative difference of the lowest energies
  double planar_threshold = 0.1;   ///< [1] 3D-ness below which an equilibrium is approximately planar
  double planar_tolerance = 0.05;  ///< [1] difference of the planar shares
  void validate() const;  ///< InputError unless cut ∈ (0, 1), min_share ∈ [0, 1], counterpart ∈ (0, 1], tolerances >= 0
};

/// One cluster of one data set and its best counterpart in the other.
struct ClusterCounterpart {
  int cluster = -1;          ///< rank of the cluster (by energy) in its data set
  int size = 0;              ///< [equilibria]
  double share = 0.0;        ///< [1] size over the knot's equilibria
  double energy = 0.0;       ///< [energy] its representative's (lowest) energy
  double similarity = 0.0;   ///< [1] best similarity of its representative to an equilibrium of the other data set
  bool needs_counterpart = false;  ///< share >= min_share
  bool found = false;              ///< similarity >= counterpart
};

/// The comparison of one knot that both data sets hold.
struct KnotComparison {
  std::string knot;                                ///< the knot's name
  ///@{
  /// [1] stored equilibria of the knot in data set a and in b.
  int equilibria_a = 0, equilibria_b = 0;
  ///@}
  ///@{
  /// [1] clusters of a and of b at the cut.
  int clusters_a = 0, clusters_b = 0;
  ///@}
  ///@{
  /// Every cluster of one data set (a, resp.\ b) with its counterpart in the other.
  std::vector<ClusterCounterpart> a_in_b, b_in_a;
  ///@}
  ///@{
  /// [energy] the lowest energy of the knot's equilibria in a and in b.
  double lowest_a = 0.0, lowest_b = 0.0;
  ///@}
  double energy_difference = 0.0;                  ///< [1] |lowest_a - lowest_b| / min(lowest_a, lowest_b)
  bool counterparts_ok = false;   ///< every cluster that needs one has a counterpart, both ways
  bool energy_ok = false;         ///< energy_difference <= energy_tolerance
};

/// What compare_datasets() returns: every common knot's comparison, the knots
/// of one data set only, and the planar shares.
struct DatasetComparison {
  std::vector<KnotComparison> knots;   ///< the knots both data sets hold, in table order
  ///@{
  /// The knots held by data set a only, and by b only.
  std::vector<std::string> only_a, only_b;
  ///@}
  ///@{
  /// [1] the share of approximately planar equilibria in a and in b, over all
  /// equilibria of the common knots.
  double planar_share_a = 0.0, planar_share_b = 0.0;
  ///@}
  /// both data sets have equilibria and their planar shares differ by <= planar_tolerance
  bool planar_ok = false;
  /// Every knot's counterparts and energy, the planar shares, and no knot in one data set only.
  bool ok() const;
};

/// Compares two data sets knot by knot (the knots of both files).
DatasetComparison compare_datasets(const DatasetReader& a, const DatasetReader& b, const CompareOptions& options = {});

}  // namespace ek
