#pragma once
/// \file
/// Analyses of a knot's stored states (a KnotEntry of a data set) used by the
/// paper experiments: how many distinct states are distinctly 3D (Figs.\ 2, 6,
/// 8), which low-energy states a prefix of the samples finds (adaptive
/// sampling, Section 7.4), knot puzzles (Section 8.3, Fig.\ 14), and the
/// Hausdorff distance against the similarity measure (Section 7.1, Fig.\ 5).
///
/// Distinct states are the clusters of clusters_at_cut(): complete linkage on
/// 1 - similarity cut at a distance, sorted by increasing lowest energy, each
/// represented by its lowest-energy member; `rank` maps an equilibrium (row
/// of KnotEntry::equilibria) to its cluster's position in that order.
#include <cstdint>
#include <set>
#include <vector>

#include "ek/analysis/search.hpp"
#include "ek/analysis/unseen.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"

namespace ek {

/// Clusters whose representative's 3D-ness (attribute "threedim") is at
/// least `planar_threshold`: the distinctly 3D states.
int count_3d_states(const KnotEntry& entry, const std::vector<StateCluster>& clusters, double planar_threshold);

/// Cluster ranks of the stored runs among the first `samples` samples (runs
/// with sample < samples that stored an equilibrium). `rank` as above.
std::set<int> clusters_seen(const KnotEntry& entry, const std::vector<int>& rank, int samples);

/// The entry with its runs in a random order (Fisher-Yates driven by
/// splitmix64 from `state`, which advances) and renumbered 0.., as if the
/// stored samples were exchangeable: replay_adaptive() then sees them in that
/// order. Equilibria, attributes and the clustering are unchanged.
KnotEntry shuffled_runs(const KnotEntry& entry, std::uint64_t& state);

/// Which low-energy states a prefix of the samples finds. Low-energy: a
/// cluster whose lowest energy is at most `energy_factor` times the knot's
/// lowest (clusters.front().energy_min; energies are positive).
struct LowEnergyCoverage {
  /// A low-energy cluster that the prefix did not find.
  struct Missed {
    int rank = -1;    ///< cluster rank of a low-energy cluster not seen
    int samples = 0;  ///< [samples] stored runs whose equilibrium lies in it
  };
  int clusters = 0;             ///< [1] low-energy clusters of the entry
  int found = 0;                ///< [1] of them, those seen in the prefix
  std::vector<Missed> missed;   ///< the others, by rank
  int missed_samples = 0;       ///< [samples] sum of missed[].samples
};
/// `clusters` and `rank` from clusters_at_cut(entry, ...); `seen` from
/// clusters_seen() (of this entry or of a reordering of its runs).
LowEnergyCoverage low_energy_coverage(const KnotEntry& entry, const std::vector<StateCluster>& clusters,
                                      const std::vector<int>& rank, const std::set<int>& seen,
                                      double energy_factor);

/// What a run that stopped after the first `samples` samples would estimate
/// it has not seen (estimate_unseen, ek/analysis/unseen.hpp): the stable
/// equilibria of those runs clustered alone at `cut` (state_counts on the
/// stored similarities), over every state (`all`) and over the states whose
/// lowest energy is at most `energy_factor` times the prefix's lowest
/// (`low_energy`, their samples only, as ledger_unseen).
struct PrefixUnseen {
  ///@{
  /// The estimates over every state (`all`) and over the low-energy states
  /// (`low_energy`).
  UnseenEstimate all, low_energy;
  ///@}
};
/// The estimates of a run stopped after the first `samples` samples (see
/// PrefixUnseen).
PrefixUnseen prefix_unseen(const KnotEntry& entry, int samples, double cut, double energy_factor);

/// A knot puzzle (Section 8.3): two distinct stable states of one knot with
/// the same writhe within a tolerance. The joined wire cannot change its link
/// and the data set's states are twist-free (Lk = Wr), so the puzzle's link
/// is the mean writhe.
struct Puzzle {
  ///@{
  /// Equilibrium indices (cluster representatives, a lower in energy).
  int state_a = -1, state_b = -1;
  ///@}
  ///@{
  /// [1] the writhes of the two states.
  double writhe_a = 0.0, writhe_b = 0.0;
  ///@}
  double link = 0.0;                      ///< [1] (writhe_a + writhe_b) / 2
  double similarity = 0.0;                ///< [1] of the two states
};
/// Every pair of cluster representatives (clusters at `cut`) whose writhes
/// differ by at most `writhe_tolerance` and which are themselves farther
/// apart than the cut (distance 1 - similarity > cut: complete linkage can
/// keep two clusters apart whose lowest-energy members look alike), in order
/// of the clusters' energies.
std::vector<Puzzle> find_puzzles(const KnotEntry& entry, double cut, double writhe_tolerance);

/// Two equilibria of one knot compared by the similarity measure and by
/// geometric distances after rigid alignment (Fig.\ 5).
struct StatePair {
  ///@{
  /// Equilibrium indices, a < b.
  int a = -1, b = -1;
  ///@}
  ///@{
  /// Their cluster ranks at the cut (clusters_at_cut).
  int cluster_a = -1, cluster_b = -1;
  ///@}
  double similarity_distance = 0.0;    ///< [1] 1 - similarity (the entry's stored matrix)
  /// [length] Hausdorff distance d_H(E_a, E_b') between the polygons
  /// (ek::hausdorff_distance, tolerance 1e-6), E_b' = E_b moved onto E_a by
  /// ek::align_curves (the alignment of the cross-topology search)
  double hausdorff = 0.0;
  double icp_distance = 0.0;           ///< [length] the alignment's own RMS distance
  bool same_cluster() const { return cluster_a == cluster_b; }  ///< Whether a and b lie in one cluster at the cut.
};

/// Every pair a < b of the entry's equilibria (m(m-1)/2, in order (0,1),
/// (0,2), ...), aligned in `jobs` threads (the values do not depend on it).
/// Cost: one alignment and one Hausdorff distance per pair (6_1, n = 400:
/// about 40 ms per pair and thread on a 2-core machine shared with other
/// runs, measured 2026-12-01; mostly the alignment).
std::vector<StatePair> pairwise_shape_distances(const KnotEntry& entry, double cut,
                                                const AlignmentOptions& alignment = {}, int jobs = 1);

/// Hausdorff distance [length] below which two equilibria of one cluster
/// are the same equilibrium reached twice (hausdorff_separation). Measured on
/// 6_1's equilibria (40 and 150 samples, one and two coarse levels;
/// docs/reproducing.md): every pair is either below 3e-5 (the round-off of
/// converged positions) or above 0.16.
inline constexpr double kIdenticalHausdorff = 1e-3;

/// How well the Hausdorff distance separates the states. The reference is
/// the median Hausdorff distance of the pairs within one cluster (one
/// state): a pair of different clusters below it cannot be told apart by a
/// Hausdorff cut that keeps the states together (the claim of Fig. 5).
/// Stricter, a pair is separated by the similarity when its equilibria lie
/// in different clusters at the cut and are themselves farther apart than
/// the cut (similarity_distance > cut: complete linkage can put two
/// look-alike members into different clusters).
///
/// Over all pairs, an equilibrium that many samples reach is counted once
/// per pair of them, and its pairs of distance ~0 pull the median down by
/// how often a method lands on it, not by the spread of the state. So the
/// same counts are also taken over the unique equilibria: the members of a
/// cluster closer than `identical` (kIdenticalHausdorff) to each other,
/// joined transitively, are one equilibrium, represented by its smallest
/// index.
struct HausdorffSeparation {
  int same_cluster_pairs = 0;       ///< [1]
  /// [length] median Hausdorff distance of the same-cluster pairs (NaN without any)
  double median_same_cluster_hausdorff = 0.0;
  int different_cluster_pairs = 0;  ///< [1] pairs in different clusters at the cut
  int below_median_pairs = 0;       ///< [1] of them, those with hausdorff < the median
  int distinct_pairs = 0;           ///< [1] pairs separated by the similarity (stricter definition above)
  int separated_pairs = 0;          ///< [1] of them, those with hausdorff < the median
  int identical_pairs = 0;          ///< [1] same-cluster pairs with hausdorff < identical
  int unique_equilibria = 0;        ///< [1] equilibria with the identical ones joined
  int unique_same_cluster_pairs = 0;  ///< [1] same-cluster pairs of unique equilibria
  /// [length] median Hausdorff distance of those pairs (NaN without any: no
  /// cluster with two unique equilibria)
  double median_unique_same_cluster_hausdorff = 0.0;
  int unique_different_cluster_pairs = 0;  ///< [1] pairs of unique equilibria in different clusters
  int below_unique_median_pairs = 0;       ///< [1] of them, those with hausdorff < the unique median
  int separated_below_unique_median = 0;   ///< [1] of them, those also separated by the similarity
};
/// The separation of `pairs` (every pair a < b of pairwise_shape_distances()
/// at `cut`); see HausdorffSeparation. InputError for identical < 0.
HausdorffSeparation hausdorff_separation(const std::vector<StatePair>& pairs, double cut,
                                         double identical = kIdenticalHausdorff);

/// Pairs separated by the similarity (as above) by increasing Hausdorff
/// distance, at most one per pair of clusters, the first `count` (the pairs
/// of Fig.\ 5: close in Hausdorff distance, apart in similarity).
std::vector<StatePair> closest_distinct_pairs(const std::vector<StatePair>& pairs, double cut, int count);

}  // namespace ek
