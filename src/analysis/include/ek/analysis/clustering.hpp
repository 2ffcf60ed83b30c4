#pragma once
/// \file
/// Agglomerative hierarchical clustering with complete linkage (paper
/// Section 7.2, Fig.\ 6) on a distance matrix, usually D = 1 - S for a
/// similarity matrix S (similarity.hpp).
///
/// Complete linkage: the distance between clusters A and B is
/// max_{a∈A, b∈B} D(a, b); the two closest clusters are merged until one
/// remains. Computed by the nearest-neighbour-chain algorithm (O(N²) time,
/// O(N²) memory; Murtagh 1983, as in SciPy), with the Lance–Williams update
/// d(k, i∪j) = max(d(k, i), d(k, j)); complete linkage is reducible, so the
/// merges sorted by height form the same dendrogram as the naive algorithm
/// and the heights are monotone (non-decreasing).
///
/// The dendrogram uses SciPy's linkage convention (scipy.cluster.hierarchy):
/// leaves are 0 .. N-1; merge k (0-based, in order of non-decreasing height)
/// creates cluster N + k from clusters a and b (a < b), at distance `height`,
/// containing `size` leaves. linkage_matrix() gives the (N-1) by 4 array
/// [a, b, height, size] that scipy.cluster.hierarchy.dendrogram() draws.
#include <vector>

#include <Eigen/Core>

namespace ek {

/// One merge of the dendrogram.
struct Merge {
  int a = 0;            ///< first cluster id (< b); ids < N are leaves, N + k is merge k
  int b = 0;            ///< second cluster id
  double height = 0.0;  ///< [distance] complete-linkage distance between a and b
  int size = 0;         ///< [1] leaves in the merged cluster
};

/// Result of complete_linkage().
struct Dendrogram {
  int leaves = 0;             ///< N
  std::vector<Merge> merges;  ///< N - 1 merges, heights non-decreasing

  /// (N-1) by 4 array [a, b, height, size] (SciPy linkage format).
  Eigen::MatrixXd linkage_matrix() const;
  /// The dendrogram of a stored (N-1) by 4 linkage matrix (N = rows + 1).
  /// Throws std::invalid_argument for a malformed matrix.
  static Dendrogram from_linkage(const Eigen::MatrixXd& linkage);
  /// Leaves in the left-to-right order of the drawn dendrogram (a before b at
  /// every merge), e.g.\ to reorder a similarity matrix for display.
  std::vector<int> leaf_order() const;
};

/// Complete-linkage clustering of the N by N distance matrix D (symmetric,
/// finite; only the strict upper triangle is read; symmetry is checked to
/// 1e-9 · max|D|). Ties are broken towards lower indices, so the result is
/// deterministic. N >= 1.
Dendrogram complete_linkage(const Eigen::MatrixXd& distance);

/// Complete linkage on D = 1 - S for a similarity matrix S.
Dendrogram complete_linkage_from_similarity(const Eigen::MatrixXd& similarity);

/// Flat clusters at a cut: two leaves share a cluster when they are joined by
/// a merge of height <= threshold (SciPy fcluster, criterion "distance").
/// Labels are 0 .. k-1, numbered in order of each cluster's smallest leaf.
std::vector<int> cut_dendrogram(const Dendrogram& dendrogram, double threshold);

/// Number of clusters at a cut (1 + the largest label of cut_dendrogram).
int cluster_count(const Dendrogram& dendrogram, double threshold);

/// Cophenetic distance matrix: entry (i, j) is the height of the merge that
/// first joins leaves i and j (0 on the diagonal).
Eigen::MatrixXd cophenetic_distances(const Dendrogram& dendrogram);

}  // namespace ek
