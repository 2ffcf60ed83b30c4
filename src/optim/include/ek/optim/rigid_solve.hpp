#pragma once
/// \file
/// Linear solves with a Hessian whose rigid motions are null directions: the
/// Newton–Raphson steps of symmetric critical points (symmetric.hpp) and the
/// predictor and corrector of path following under load
/// (ek/mechanics/continuation.hpp).
///
/// With Q (N by m, orthonormal columns: Objective::rigid_modes()) the matrix
///   H + κ Q Qᵀ,  κ = the mean |H_ii|,
/// is regular when H is regular on the complement of Q. It is never formed
/// (Q Qᵀ is dense): the solve uses the sparse bordered system
///   [ H   Q      ] [x]   [r]
///   [ Qᵀ  −I/κ   ] [y] = [0],
/// whose second row gives y = κ Qᵀ x and whose first row is then
/// (H + κ Q Qᵀ) x = r, factorised by a sparse LU (H may be indefinite).
/// solve() returns x with its Q part removed. Without rigid modes it is H x = r.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>

#include "ek/core/types.hpp"
#include "ek/optim/objective.hpp"

namespace ek {

/// Factorises H + κ Q Qᵀ (see the file comment) once; solves many right-hand sides.
class RigidRegularizedSolver {
 public:
  /// `upper`: H's upper triangle (N by N, as SparseAssembler::matrix() gives
  /// it); `rigid`: Q (N by m, m >= 0, orthonormal columns). ok() tells
  /// whether the factorisation succeeded (false for a singular matrix).
  RigidRegularizedSolver(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper, const Eigen::MatrixXd& rigid);
  /// The same for f's exact Hessian and rigid modes at its current dofs.
  explicit RigidRegularizedSolver(Objective& f);
  ~RigidRegularizedSolver();                                                  ///< Releases the factorisation.
  RigidRegularizedSolver(const RigidRegularizedSolver&) = delete;             ///< Not copyable.
  RigidRegularizedSolver& operator=(const RigidRegularizedSolver&) = delete;  ///< Not copyable.

  bool ok() const { return ok_; }  ///< The matrix factorised.
  /// x of (H + κ Q Qᵀ) x = r (N), then x − Q Qᵀ x (not finite when the
  /// matrix is nearly singular: callers check). Requires ok().
  VecX solve(const VecX& r) const;
  double kappa() const { return kappa_; }  ///< κ, the mean |H_ii| (0 without rigid modes)

 private:
  struct Lu;
  std::unique_ptr<Lu> lu_;
  Eigen::MatrixXd Q_;
  double kappa_ = 0.0;
  bool ok_ = false;
};

}  // namespace ek
