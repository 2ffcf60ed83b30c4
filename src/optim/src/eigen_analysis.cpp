#include "ek/optim/eigen_analysis.hpp"

#include <Spectra/SymEigsSolver.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/optim/cholesky.hpp"
#include "shift_invert.hpp"

namespace ek {

using detail::ShiftInvertOp;

namespace {

// Without material angles the six modes have closed forms: the translations
// (one coordinate of every vertex, 1/√n) are orthonormal, the rotations
// e_a × p_i about the centroid are orthogonal to them (Σ p_i = 0), and the
// rotations' Gram matrix is the inertia tensor J = Σ (|p|² I − p pᵀ), so
// R V Λ^{-1/2} (J = V Λ Vᵀ) is an orthonormal basis of their span: O(n)
// instead of Gram-Schmidt on dofs-long columns. Rotations with Λ at round-off
// level (below 1e-12 of the largest: about the axis of a straight line) are
// dropped.
Eigen::MatrixXd rigid_modes_positions(const Points& positions, int dofs, bool planar_slab) {
  const int n = static_cast<int>(positions.rows());
  const Vec3 c = positions.colwise().mean().transpose();
  Mat3 J = Mat3::Zero();
  for (int i = 0; i < n; ++i) {
    const Vec3 p = positions.row(i).transpose() - c;
    J += p.squaredNorm() * Mat3::Identity() - p * p.transpose();
  }
  Mat3 W = Mat3::Zero();  // rotation a -> its combination of e_b × p
  int rotations = 0;
  if (planar_slab) {
    if (J(2, 2) > 1e-12 * J.trace()) W(2, rotations++) = 1.0 / std::sqrt(J(2, 2));
  } else {
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(J);
    const double largest = eig.eigenvalues().maxCoeff();
    for (int k = 0; k < 3; ++k)
      if (eig.eigenvalues()(k) > 1e-12 * largest) W.col(rotations++) = eig.eigenvectors().col(k) / std::sqrt(eig.eigenvalues()(k));
  }
  const int translations = planar_slab ? 2 : 3;
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(dofs, translations + rotations);
  const double t = 1.0 / std::sqrt(static_cast<double>(n));
  for (int i = 0; i < n; ++i) {
    const Vec3 p = positions.row(i).transpose() - c;
    for (int a = 0; a < translations; ++a) Q(3 * i + a, a) = t;
    for (int k = 0; k < rotations; ++k) Q.block<3, 1>(3 * i, translations + k) = W.col(k).cross(p);
  }
  return Q;
}

}  // namespace

Eigen::MatrixXd rigid_modes(const Points& positions, int dofs, int theta_begin, bool planar_slab) {
  const int n = static_cast<int>(positions.rows());
  require(dofs >= 3 * n, "rigid_modes: fewer dofs than positions");
  if (theta_begin < 0) return rigid_modes_positions(positions, dofs, planar_slab);
  const int k = 6 + (theta_begin >= 0 ? 1 : 0);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(dofs, k);
  const Vec3 c = positions.colwise().mean().transpose();
  for (int i = 0; i < n; ++i) {
    const Vec3 p = positions.row(i).transpose() - c;
    for (int a = 0; a < 3; ++a) {
      M(3 * i + a, a) = 1.0;
      const Vec3 w = Vec3::Unit(a).cross(p);
      M.block<3, 1>(3 * i, 3 + a) = w;
    }
  }
  if (theta_begin >= 0) {
    // A rigid rotation ω also turns the reference frames about the edge
    // tangents by ω·t_j relative to parallel transport; the material angles
    // compensate (θ̇_j = ω·t_j) for the mode to be an exact zero mode.
    for (int j = 0; j < n; ++j) {
      const Vec3 t = (positions.row((j + 1) % n) - positions.row(j)).transpose().normalized();
      for (int a = 0; a < 3; ++a) M(theta_begin + j, 3 + a) = t(a);
    }
  }
  if (theta_begin >= 0) {
    require(theta_begin + n <= dofs, "rigid_modes: theta range out of bounds");
    for (int j = 0; j < n; ++j) M(theta_begin + j, 6) = 1.0;
  }
  // Orthonormalise by modified Gram-Schmidt, twice (O(dofs·k²); cheap enough
  // to run every Newton iteration). A degenerate rotation, e.g. about the
  // axis of a straight line, gives a (numerically) zero column: dropped.
  const double scale = M.colwise().norm().maxCoeff();
  Eigen::MatrixXd out(dofs, k);
  int kept = 0;
  for (int j = 0; j < k; ++j) {
    // with the slab: no translation along z (column 2), no rotation about x or y (3, 4)
    if (planar_slab && (j == 2 || j == 3 || j == 4)) continue;
    VecX v = M.col(j);
    const double norm0 = v.norm();
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i < kept; ++i) v -= out.col(i).dot(v) * out.col(i);
    const double norm = v.norm();
    if (norm <= 1e-10 * scale || norm <= 1e-8 * norm0) continue;
    out.col(kept++) = v / norm;
  }
  return out.leftCols(kept);
}

EigenResult smallest_eigenpairs(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper,
                                const Eigen::MatrixXd& excluded, double base_shift, const EigenOptions& o) {
  const Eigen::Index n = upper.rows();
  require(base_shift > 0.0, "smallest_eigenpairs: base_shift must be positive");
  require(o.count >= 1 && o.count < n, "smallest_eigenpairs: count must be in [1, n)");
  require(excluded.cols() == 0 || excluded.rows() == n, "smallest_eigenpairs: excluded modes have the wrong size");
  EigenResult result;
  CholeskySolver chol(CholeskyMode::Block);
  double s = base_shift;
  bool ok = false;
  for (int attempt = 0; attempt < 60 && !ok; ++attempt) {
    ok = chol.factorize(upper, s, 0);
    if (!ok) s *= 10.0;
  }
  if (!ok) return result;
  result.shift = s;
  ShiftInvertOp op(chol, excluded, n);
  const int nev = o.count;
  const int ncv = static_cast<int>(std::min<Eigen::Index>(n - excluded.cols(), std::max(o.subspace, 2 * nev + 1)));
  if (ncv <= nev) return result;
  Spectra::SymEigsSolver<ShiftInvertOp> solver(op, nev, ncv);
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, o.max_iterations, o.tolerance, Spectra::SortRule::LargestAlge);
  if (solver.info() != Spectra::CompInfo::Successful) return result;
  const VecX mu = solver.eigenvalues();  // descending μ -> ascending λ
  result.values.resize(nev);
  result.vectors = solver.eigenvectors();
  for (int k = 0; k < nev; ++k) result.values(k) = 1.0 / mu(k) - s;
  result.converged = true;
  return result;
}

}  // namespace ek
