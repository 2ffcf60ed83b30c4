#pragma once
/// Analyses of a knot's stored states (a KnotEntry of a data set) used by the
/// paper experiments: how many distinct states are distinctly 3D (Figs. 2, 6,
/// 8), which low-energy states a prefix of the samples finds (adaptive
/// sampling, Section 7.4), and knot puzzles (Section 8.3, Fig. 14).
///
/// Distinct states are the clusters of clusters_at_cut(): complete linkage on
/// 1 - similarity cut at a distance, sorted by increasing lowest energy, each
/// represented by its lowest-energy member; `rank` maps an equilibrium (row
/// of KnotEntry::equilibria) to its cluster's position in that order.
#include <cstdint>
#include <set>
#include <vector>

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

/// A knot puzzle (Section 8.3): two distinct stable states of one knot with
/// the same writhe within a tolerance. The joined wire cannot change its link
/// and the data set's states are twist-free (Lk = Wr), so the puzzle's link
/// is the mean writhe.
struct Puzzle {
  int state_a = -1, state_b = -1;  ///< equilibrium indices (cluster representatives, a lower in energy)
  double writhe_a = 0.0, writhe_b = 0.0;  ///< [1]
  double link = 0.0;                      ///< [1] (writhe_a + writhe_b) / 2
  double similarity = 0.0;                ///< [1] of the two states
};
/// Every pair of cluster representatives (clusters at `cut`) whose writhes
/// differ by at most `writhe_tolerance` and which are themselves farther
/// apart than the cut (distance 1 - similarity > cut: complete linkage can
/// keep two clusters apart whose lowest-energy members look alike), in order
/// of the clusters' energies.
std::vector<Puzzle> find_puzzles(const KnotEntry& entry, double cut, double writhe_tolerance);

}  // namespace ek
