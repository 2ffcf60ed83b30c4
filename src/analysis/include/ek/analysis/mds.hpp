#pragma once
/// \file
/// Classical multidimensional scaling (Torgerson 1952; Gower 1966) of a
/// distance matrix, for the 2D scatter plot of Fig.\ 6 (paper Section 7.2).
///
/// Given an N by N distance matrix D, with J = I - 11ᵀ/N the centring matrix,
///   B = -½ J D⁽²⁾ J     (D⁽²⁾ the entrywise squares),
/// and B's largest eigenpairs (λ_1 >= ... >= λ_d, v_k unit), the coordinates
/// are X = [v_1 √λ_1, ..., v_d √λ_d] (N by d; a column whose λ_k <= 0 is 0).
/// When D is Euclidean (D_ij = |p_i - p_j| for points p in R^d) X reproduces
/// the points up to a rigid motion. Each column's sign is fixed so that its
/// entry of largest magnitude is positive (deterministic output).
///
/// The top eigenpairs come from Spectra's Lanczos solver (SymEigsSolver on the
/// dense product) for N > kMdsDenseLimit, from a dense eigensolver below and
/// when Lanczos fails (B of rank below d, as for many identical states).
/// Points that all coincide (B = 0 up to round-off) give the origin.
#include <Eigen/Core>

namespace ek {

/// Matrices up to this size use the dense eigensolver.
inline constexpr int kMdsDenseLimit = 16;

/// Outcome of the eigensolver: Converged, or NotConverged when the dense
/// eigensolver failed.
enum class MdsStatus { Converged, NotConverged };

/// Result of classical_mds().
struct MdsResult {
  Eigen::MatrixXd coordinates;  ///< N by d embedding [distance units]
  Eigen::VectorXd eigenvalues;  ///< the d largest eigenvalues of B, descending [distance²]
  /// [1] Σ_k max(λ_k, 0) / trace(B): the share of the total squared spread
  /// (trace B = Σ_i |p_i - centroid|² for Euclidean D) that the d axes keep.
  double explained = 0.0;
  MdsStatus status = MdsStatus::Converged;  ///< NotConverged when the dense eigensolver failed
};

/// Classical MDS of a symmetric N by N distance matrix (finite, symmetric to
/// 1e-9 relative; zero diagonal expected) into d dimensions (1 <= d < N;
/// N = 1 gives one point at the origin).
MdsResult classical_mds(const Eigen::MatrixXd& distance, int dims = 2);

/// Classical MDS of D = 1 - S for a similarity matrix S (diagonal set to 0).
MdsResult classical_mds_from_similarity(const Eigen::MatrixXd& similarity, int dims = 2);

}  // namespace ek
