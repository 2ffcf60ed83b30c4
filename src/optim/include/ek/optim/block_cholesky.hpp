#pragma once
/// \file
/// Sparse Cholesky factorisation H + s·I = L Lᵀ in 3 × 3 blocks, for the
/// Hessians of discrete rods: the three coordinates of a vertex form one
/// block, so the symbolic work runs on the graph of the n vertices (not of
/// the 3n dofs) and the numeric work is done on dense 3 × 3 blocks. Written
/// for this project beside CHOLMOD (cholesky.hpp), which the solver keeps as
/// an option: on the rod Hessians (n ≈ 400, 1,200 dofs, a pattern that
/// changes with the contact set almost every Newton iteration) CHOLMOD's
/// symbolic analysis and its scalar simplicial factorisation dominate the run
/// time, and no Debian package offers a block factorisation of this size.
///
/// Any symmetric matrix can be factorised: dofs are grouped by consecutive
/// triples (3i, 3i+1, 3i+2) into blocks (the last block padded with identity
/// rows when the size is not a multiple of 3), which is an exact Cholesky
/// factorisation of a symmetric permutation of H; only its efficiency depends
/// on the grouping.
///
/// Method:
///  - Ordering: AMD (SuiteSparse's AMD library) on the block graph; kept
///    across pattern changes until the factor's block count has grown by
///    more than `reorder_fill_growth` over the count right after the last
///    AMD ordering (as for the CHOLMOD path).
///  - Symbolic: elimination tree (Liu) and the row patterns of L (the
///    elimination-tree reach of each row) on the permuted block graph; the
///    column structure of L and a gather map from H's stored values to the
///    permuted blocks.
///  - Numeric: up-looking (row by row) block Cholesky, L_kj = (A_kj −
///    Σ_{m<j} L_km L_jmᵀ) L_jj⁻ᵀ, L_kk = chol(A_kk + s·I − Σ_j L_kj L_kjᵀ),
///    the 3 × 3 diagonal factors by scalar Cholesky; a pivot <= 0 stops the
///    factorisation: H + s·I is not positive definite. Each factorisation is
///    computed into a spare set of values that replaces the current factor
///    only on success, so a failed attempt keeps the last good factor.
///  - What a failure proves: when the pivot block of row k,
///    S = A_kk + s·I − Σ_j L_kj L_kjᵀ, has a smallest eigenvalue μ <= 0 with
///    unit eigenvector v, the vector x = (−L₁₁⁻ᵀ L_kᵀ v, v) over the first
///    k + 1 blocks has xᵀ (H + s·I) x = μ, so λ_min(H + s·I) <= μ / ‖x‖²
///    (Rayleigh quotient and interlacing), and H + s'·I can be positive
///    definite only for s' > s + |μ| / ‖x‖² (shift_deficit()). Costs one
///    3 × 3 eigen-problem and a triangular solve over the first k blocks,
///    only after a failure.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "ek/core/types.hpp"

namespace ek {

/// Sparse Cholesky factorisation of H + s·I in 3 × 3 blocks with symbolic
/// reuse (see the file's description): analyse() once per pattern,
/// factorize() per shift, solve() with the last good factor.
class BlockCholesky {
 public:
  /// Upper triangle of H, compressed, column-major (SparseAssembler::matrix()).
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Symbolic analysis of the pattern of H (upper triangle, compressed,
  /// sorted, as SparseAssembler::matrix()). With `reuse_ordering` the last
  /// ordering is kept for a matrix of the same size unless the fill has grown
  /// by more than `reorder_fill_growth` (see the file comment); the kept
  /// ordering is analysed first, so a reordering costs a second analysis.
  void analyse(const Matrix& upper, bool reuse_ordering = true, double reorder_fill_growth = 0.2);
  /// Numeric factorisation of H + shift·I with the values of `upper` (the
  /// pattern of the last analyse()). False when it is not positive
  /// definite; then the last good factor stays current.
  bool factorize(const Matrix& upper, double shift);
  /// Solves (H + s·I) x = b with the last good factor (b: the matrix's size).
  VecX solve(const VecX& b) const;
  /// [same unit as the shift] After factorize() failed at shift s: the
  /// least δ >= 0 that the failure proves necessary, H + (s + δ')·I not
  /// positive definite for every δ' <= δ (see the file comment; 0 when the
  /// failing pivot block was positive definite, a failure by round-off).
  /// 0 after a success.
  double shift_deficit() const { return deficit_; }

  int size() const { return n_; }                 ///< [dofs]
  int blocks() const { return nb_; }              ///< 3 × 3 block rows
  long long factor_blocks() const;                ///< blocks of L (diagonal included)
  bool has_factor() const { return good_; }       ///< Whether a factorisation has succeeded (solve() may be called).
  size_t pattern_nonzeros() const { return dst_.size(); }  ///< stored values of the analysed H
  int symbolic_count() const { return symbolic_count_; }  ///< symbolic analyses so far
  int ordering_count() const { return ordering_count_; }  ///< AMD orderings so far

 private:
  void order();
  void symbolic(const Matrix& upper);
  void block_pattern(const Matrix& upper);
  void permuted_pattern();
  void elimination_tree();
  void row_patterns();
  void gather_map(const Matrix& upper);
  bool factor_row(int k, std::vector<Eigen::Matrix3d>& L, std::vector<Eigen::Matrix3d>& Dinv);
  double deficit_at(int k) const;  // from failed_pivot_, row k of the spare factor

  int n_ = 0, nb_ = 0;
  std::vector<int> edge_lo_, edge_hi_;  // block pairs (old indices, lo < hi) of H's pattern
  std::vector<int> entry_edge_;          // each stored value's pair (-1: a diagonal block)
  std::vector<int> edge_slot_;           // each pair's block in A's storage
  std::vector<int> adj_ptr_, adj_;       // block graph of H (old indices, both triangles, CSR)
  std::vector<int> mark_, last_edge_, path_;  // scratch
  std::vector<int> perm_, inverse_;  // perm_[new block] = old block
  long long ordered_fill_ = 0;
  // block pattern of A = P H Pᵀ, upper part, by column k: the diagonal
  // block first, then the rows j < k
  std::vector<int> acol_ptr_, acol_row_;
  std::vector<int> parent_;                 // elimination tree
  // L's strictly lower blocks: by row (row_ptr_, row_col_, row_pos_: where L_kj
  // is stored) and by column (col_ptr_, col_row_), rows increasing
  std::vector<int> row_ptr_, row_col_, row_pos_, col_ptr_, col_row_;
  // gather: H's k-th stored value goes to value index dst_[k] (and mirror_[k] >= 0
  // for the transposed position inside a diagonal block)
  std::vector<int> dst_, mirror_;
  std::vector<double> a_;                   // blocks of A, 9 values each, column-major, by acol order
  std::vector<Eigen::Matrix3d> L_, spare_L_;       // strictly lower blocks of L
  std::vector<Eigen::Matrix3d> Dinv_, spare_Dinv_; // inverses of the diagonal factors L_kk (lower)
  std::vector<Eigen::Matrix3d> work_;
  Eigen::Matrix3d failed_pivot_;  // S of the row where the last factorize() failed
  double deficit_ = 0.0;
  bool good_ = false;
  int symbolic_count_ = 0, ordering_count_ = 0;
};

}  // namespace ek
