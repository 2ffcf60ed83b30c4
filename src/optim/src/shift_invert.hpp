#pragma once
// The operator of the shift-invert Lanczos eigen-solves (Spectra's operator
// interface), shared by eigen_analysis.cpp and saddle.cpp.
#include <Eigen/Dense>

#include "ek/optim/cholesky.hpp"

namespace ek::detail {

/// y = P (H − τI)⁻¹ P x, P = I − Q Qᵀ: `chol` holds the factor of the
/// shifted matrix (whatever its shift), Q has orthonormal columns (none:
/// P = I). Its eigenvalues μ are 1/(λ − τ) for the eigenvalues λ of H on
/// the complement of Q.
class ShiftInvertOp {
 public:
  using Scalar = double;  ///< Spectra's scalar type
  ShiftInvertOp(const CholeskySolver& chol, const Eigen::MatrixXd& Q, Eigen::Index n) : chol_(chol), Q_(Q), n_(n) {}
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  void perform_op(const double* in, double* out) const {
    VecX x = Eigen::Map<const VecX>(in, n_);
    if (Q_.cols() > 0) x -= Q_ * (Q_.transpose() * x);
    VecX y = chol_.solve(x);
    if (Q_.cols() > 0) y -= Q_ * (Q_.transpose() * y);
    Eigen::Map<VecX>(out, n_) = y;
  }

 private:
  const CholeskySolver& chol_;
  const Eigen::MatrixXd& Q_;
  Eigen::Index n_;
};

}  // namespace ek::detail
