#pragma once
/// Sparse Cholesky factorisation with CHOLMOD (SuiteSparse) through Eigen's
/// CholmodSupport wrapper (RAII for the cholmod_common context).
///
/// The symbolic analysis (fill-reducing ordering, elimination tree) is done
/// once per sparsity pattern and reused while the pattern stays the same
/// (paper Section 6, "Numerical Solver": the pattern of the contact Hessian
/// changes only when the contact set does). The numeric factorisation is of
/// H + shift·I (CHOLMOD's cholmod_factorize_p with beta = shift), always in
/// LL' form so that a matrix that is not positive definite is detected.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <cstdint>

#include "ek/geometry/types.hpp"

namespace ek {

enum class CholeskyMode {
  Simplicial,  ///< simplicial LL' (best for the banded rod Hessians of a few thousand dofs)
  Supernodal,  ///< supernodal LL' (BLAS-3; better for large, dense fill)
};

class CholeskySolver {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  explicit CholeskySolver(CholeskyMode mode = CholeskyMode::Simplicial);

  /// Factorises H + shift·I, where H is given by its upper triangle. The
  /// symbolic analysis is redone only when `pattern_version` differs from the
  /// previous call's (pass SparseAssembler::pattern_version()). Returns false
  /// when the shifted matrix is not positive definite. Throws
  /// std::invalid_argument for non-finite entries or a non-square matrix.
  bool factorize(const Matrix& upper, double shift, std::uint64_t pattern_version);

  /// Solves (H + shift·I) x = b with the last successful factorisation.
  VecX solve(const VecX& b) const;

  /// Statistics.
  int symbolic_count() const { return symbolic_count_; }
  int numeric_count() const { return numeric_count_; }

 private:
  Eigen::CholmodDecomposition<Matrix, Eigen::Upper> chol_;
  std::uint64_t analysed_version_ = ~std::uint64_t(0);
  Eigen::Index analysed_size_ = -1;
  bool ok_ = false;
  int symbolic_count_ = 0;
  int numeric_count_ = 0;
};

}  // namespace ek
