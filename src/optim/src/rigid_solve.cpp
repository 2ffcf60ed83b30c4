#include "ek/optim/rigid_solve.hpp"

#include <Eigen/SparseLU>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/core/sparse_assembler.hpp"

namespace ek {

struct RigidRegularizedSolver::Lu {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
};

RigidRegularizedSolver::RigidRegularizedSolver(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper,
                                               const Eigen::MatrixXd& rigid)
    : lu_(std::make_unique<Lu>()), Q_(rigid) {
  const Eigen::Index n = upper.rows(), m = rigid.cols();
  require(upper.cols() == n && (m == 0 || rigid.rows() == n), "RigidRegularizedSolver: H is N by N, Q is N by m");
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<size_t>(2 * upper.nonZeros() + 2 * n * m + m));
  for (Eigen::Index j = 0; j < upper.outerSize(); ++j)
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(upper, j); it; ++it) {
      if (it.row() > j) continue;  // the upper triangle only
      t.emplace_back(static_cast<int>(it.row()), static_cast<int>(j), it.value());
      if (it.row() != j) t.emplace_back(static_cast<int>(j), static_cast<int>(it.row()), it.value());
    }
  if (m > 0) {
    kappa_ = upper.diagonal().cwiseAbs().mean();
    for (Eigen::Index k = 0; k < m; ++k) {
      const int border = static_cast<int>(n + k);
      for (Eigen::Index i = 0; i < n; ++i) {
        const double q = rigid(i, k);
        if (q == 0.0) continue;
        t.emplace_back(static_cast<int>(i), border, q);
        t.emplace_back(border, static_cast<int>(i), q);
      }
      t.emplace_back(border, border, -1.0 / kappa_);
    }
  }
  Eigen::SparseMatrix<double> K(n + m, n + m);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  lu_->lu.compute(K);
  ok_ = lu_->lu.info() == Eigen::Success && (m == 0 || kappa_ > 0.0);
}

namespace {

Eigen::SparseMatrix<double, Eigen::ColMajor, int> exact_hessian(Objective& f) {
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);
  return A.matrix();
}

}  // namespace

RigidRegularizedSolver::RigidRegularizedSolver(Objective& f) : RigidRegularizedSolver(exact_hessian(f), f.rigid_modes()) {}

RigidRegularizedSolver::~RigidRegularizedSolver() = default;

VecX RigidRegularizedSolver::solve(const VecX& r) const {
  require(ok_, "RigidRegularizedSolver::solve: the matrix did not factorise");
  const Eigen::Index m = Q_.cols(), n = lu_->lu.rows() - m;
  require(r.size() == n, "RigidRegularizedSolver::solve: the right-hand side has N entries");
  VecX rhs = VecX::Zero(n + m);
  rhs.head(n) = r;
  VecX x = lu_->lu.solve(rhs).head(n);
  if (m > 0) x -= Q_ * (Q_.transpose() * x);
  return x;
}

}  // namespace ek
