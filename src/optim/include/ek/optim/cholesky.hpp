#pragma once
/// \file
/// Sparse Cholesky factorisation of H + shift·I with CHOLMOD (SuiteSparse),
/// keeping the symbolic analysis between factorisations (paper Section 6,
/// "Numerical Solver": the pattern of the contact Hessian changes only when
/// the contact set does, and only then is the symbolic factorisation redone).
///
/// How CHOLMOD is driven (all through its C API, one cholmod_common per
/// solver, released by the destructor):
///  - Ordering: a fill-reducing permutation P (AMD with elimination-tree
///    postordering, CHOLMOD's cholmod_analyze) is computed for a pattern;
///    the solver then keeps B = P H Pᵀ itself (upper triangle, a gather of
///    H's values through a slot map) and lets CHOLMOD factorise B in its
///    natural order. This is the same factorisation CHOLMOD would compute
///    with P, without the two permuted transposes (allocations) that
///    cholmod_factorize_p makes of an upper-triangular input on every call.
///  - Symbolic analysis (elimination tree, column counts, storage of L) is
///    redone only when `pattern_version` changes. With reuse_ordering the
///    previous P is kept for the new pattern (any P is valid; only the fill
///    differs) and AMD is rerun only when nnz(L) has grown by more than
///    reorder_fill_growth over the nnz(L) right after the last AMD, or the
///    size changed.
///  - Numeric factorisation: simplicial LL' (Simplicial) or supernodal LL'
///    (Supernodal) of B + shift·I (cholmod_factorize_p with beta = shift),
///    stopping at the first non-positive pivot (quick_return_if_not_posdef),
///    so a matrix that is not positive definite is detected at the cost of
///    the columns before the failing pivot. Each factorisation is computed
///    into a second factor object (same symbolic analysis) that replaces the
///    current one only on success: a failed attempt leaves the last good
///    factor in place, and recall() makes it current again.
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <vector>

#include "ek/core/types.hpp"
#include "ek/optim/block_cholesky.hpp"

namespace ek {

/// Which sparse Cholesky factorisation CholeskySolver uses.
enum class CholeskyMode {
  Simplicial,  ///< CHOLMOD's simplicial LL'
  Supernodal,  ///< CHOLMOD's supernodal LL' (BLAS-3; better for large, dense fill)
  /// Our 3 × 3 block factorisation (block_cholesky.hpp): the same LL' of a
  /// block-permuted H, with the symbolic work on the vertex graph.
  Block,
};

/// How CholeskySolver factorises: the method and the reuse of the fill-reducing
/// ordering.
struct CholeskyOptions {
  CholeskyMode mode = CholeskyMode::Block;  ///< the factorisation (Block: 3-5x faster than Simplicial on rod Hessians)
  /// Keep the fill-reducing ordering across pattern changes (see the file comment).
  bool reuse_ordering = true;
  /// [1] rerun AMD when nnz(L) exceeds (1 + this) times nnz(L) of the last AMD ordering.
  double reorder_fill_growth = 0.2;
};

/// Sparse Cholesky factorisation of H + shift·I with the symbolic analysis
/// kept while the pattern is unchanged (see the file's description); the
/// CHOLMOD context is owned (RAII) and released by the destructor.
class CholeskySolver {
 public:
  /// Upper triangle of H, compressed, column-major (SparseAssembler::matrix()).
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// A solver of `mode` with the default ordering options.
  explicit CholeskySolver(CholeskyMode mode = CholeskyMode::Block);
  explicit CholeskySolver(const CholeskyOptions& options);  ///< A solver with these options.
  ~CholeskySolver();                                        ///< Releases the CHOLMOD context and factors.
  /// Not copyable: one solver owns its CHOLMOD context.
  CholeskySolver(const CholeskySolver&) = delete;
  CholeskySolver& operator=(const CholeskySolver&) = delete;  ///< Not copyable.

  /// Factorises H + shift·I, where H is given by its upper triangle (compressed,
  /// column-major, sorted row indices, as SparseAssembler::matrix()). The
  /// symbolic analysis is redone only when `pattern_version` differs from the
  /// previous call's (pass SparseAssembler::pattern_version()) or the size
  /// changed. Returns false when the shifted matrix is not positive definite.
  /// Throws std::invalid_argument for non-finite entries or a non-square matrix.
  bool factorize(const Matrix& upper, double shift, std::uint64_t pattern_version);

  /// Makes the last successful factorisation current again (so that solve()
  /// uses it) when it was of H + shift·I with this shift and no symbolic
  /// analysis happened since; the caller guarantees that H's values are those
  /// it factorised. Returns false, changing nothing, otherwise. Costs no
  /// factorisation: a search over shifts that stepped below a good one and
  /// failed gets the good one back.
  bool recall(double shift);

  /// [same unit as the shift] After a failed factorize() at shift s, the
  /// extra shift δ the failure proves necessary: H + (s + δ')·I is not
  /// positive definite for any δ' <= δ (BlockCholesky::shift_deficit(); 0
  /// for the CHOLMOD modes, which do not report it, and after a success).
  double shift_deficit() const;
  /// Whether a failed factorize() reports shift_deficit() (the Block mode).
  bool reports_shift_deficit() const { return options_.mode == CholeskyMode::Block; }

  /// Solves (H + shift·I) x = b with the current factorisation (the last
  /// factorize() must have succeeded, or recall()).
  VecX solve(const VecX& b) const;

  /// Statistics.
  int symbolic_count() const { return symbolic_count_; }   ///< symbolic analyses
  int ordering_count() const { return ordering_count_; }   ///< AMD orderings (<= symbolic_count)
  int numeric_count() const { return numeric_count_; }     ///< numeric factorisations (failed ones included)
  double symbolic_seconds() const { return symbolic_seconds_; }  ///< [s] time in orderings and symbolic analyses
  long long factor_nonzeros() const;                       ///< nnz(L) of the current symbolic factor (0 if none)

 private:
  struct Cholmod;  // the cholmod_common and factor (keeps cholmod.h out of this header)
  bool factorize_block(const Matrix& upper, double shift, std::uint64_t pattern_version);
  void analyse(const Matrix& upper);
  void order(const Matrix& upper);
  void build_permuted_pattern(const Matrix& upper);

  CholeskyOptions options_;
  std::unique_ptr<Cholmod> cm_;
  BlockCholesky block_;       // CholeskyMode::Block
  std::uint64_t analysed_version_ = ~std::uint64_t(0);
  Eigen::Index analysed_size_ = -1;
  std::vector<int> perm_;     // perm_[new] = old (the fill-reducing P)
  std::vector<int> inverse_;  // inverse_[old] = new
  std::vector<int> Bp_, Bi_;  // pattern of B = P H Pᵀ (upper, or lower for Supernodal)
  std::vector<double> Bx_;
  std::vector<int> slot_;     // slot_[k] = index in Bx_ of H's k-th stored value
  long long ordered_fill_ = 0;  // nnz(L) right after the last AMD ordering
  bool reorder_ = true;
  bool ok_ = false;             // the current factor may be used (the last factorize() or recall() succeeded)
  bool good_ = false;           // the current factor holds a successful factorisation of the current analysis
  double good_shift_ = 0.0;     // its shift
  int symbolic_count_ = 0;
  int ordering_count_ = 0;
  int numeric_count_ = 0;
  double symbolic_seconds_ = 0.0;
  mutable VecX work_;
};

}  // namespace ek
