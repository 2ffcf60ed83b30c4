#include <gtest/gtest.h>

#include <random>

#include "ek/optim/rigid_solve.hpp"

using namespace ek;

namespace {

using Upper = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// A banded symmetric matrix (bandwidth 3, diagonal `diagonal` + noise),
/// then made to have Q's columns as null directions: H = P A P, P = I − Q Qᵀ.
/// Returns H's upper triangle (P A P is dense wherever Q is: fine at N = 40).
Eigen::MatrixXd with_null_directions(const Eigen::MatrixXd& Q, double diagonal, std::mt19937& rng) {
  const int n = static_cast<int>(Q.rows());
  std::normal_distribution<double> z(0.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < std::min(n, i + 4); ++j) A(i, j) = A(j, i) = (i == j ? diagonal : 0.0) + 0.3 * z(rng);
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(n, n) - Q * Q.transpose();
  return P * A * P;
}

Upper bordered_test_upper(const Eigen::MatrixXd& H) { return H.triangularView<Eigen::Upper>().toDenseMatrix().sparseView(); }

Eigen::MatrixXd random_orthonormal(int n, int m, std::mt19937& rng) {
  std::normal_distribution<double> z(0.0, 1.0);
  Eigen::MatrixXd R(n, m);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < m; ++k) R(i, k) = z(rng);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(R);
  return qr.householderQ() * Eigen::MatrixXd::Identity(n, m);
}

}  // namespace

// The bordered solve equals the dense solve of H + κ Q Qᵀ (κ the mean
// |H_ii|) with the Q part removed, for positive definite and indefinite H on
// the complement of Q; without rigid modes it is H x = r.
TEST(RigidRegularizedSolver, EqualsTheDenseRegularizedSolve) {
  std::mt19937 rng(7);
  const int n = 40;
  for (int m : {0, 3, 6}) {
    for (double diagonal : {4.0, 0.2}) {  // positive definite on the complement; indefinite
      SCOPED_TRACE("m = " + std::to_string(m) + ", diagonal " + std::to_string(diagonal));
      const Eigen::MatrixXd Q = m > 0 ? random_orthonormal(n, m, rng) : Eigen::MatrixXd(n, 0);
      const Eigen::MatrixXd H = with_null_directions(Q, diagonal, rng);
      const RigidRegularizedSolver solver(bordered_test_upper(H), Q);
      ASSERT_TRUE(solver.ok());
      VecX r(n);
      std::normal_distribution<double> z(0.0, 1.0);
      for (int i = 0; i < n; ++i) r(i) = z(rng);
      const VecX x = solver.solve(r);
      const double kappa = H.diagonal().cwiseAbs().mean();
      EXPECT_EQ(solver.kappa(), m > 0 ? kappa : 0.0);
      const Eigen::MatrixXd M = H + kappa * Q * Q.transpose();
      VecX expected = M.fullPivLu().solve(r);
      if (m > 0) expected -= Q * (Q.transpose() * expected);
      EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
      if (m > 0) {
        EXPECT_LT((Q.transpose() * x).norm(), 1e-12 * x.norm());
        const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(n, n) - Q * Q.transpose();
        EXPECT_LT((H * x - P * r).norm(), 1e-10 * r.norm());  // H x = P r: the step on the complement
      }
    }
  }
}

// A Hessian singular beyond its rigid modes does not factorise.
TEST(RigidRegularizedSolver, ASingularMatrixIsReported) {
  Upper H(4, 4);
  H.insert(0, 0) = 1.0;
  H.insert(1, 1) = 2.0;
  H.insert(2, 2) = 3.0;  // row and column 3 empty: singular
  const RigidRegularizedSolver solver(H, Eigen::MatrixXd(4, 0));
  EXPECT_FALSE(solver.ok());
  EXPECT_THROW(solver.solve(VecX::Ones(4)), std::logic_error);
}
