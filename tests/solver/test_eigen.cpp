#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "ek/core/sparse_assembler.hpp"
#include "ek/solver/eigen_analysis.hpp"

using namespace ek;

TEST(EigenAnalysis, SmallestEigenvaluesOfTridiagonal) {
  // tridiag(d, -1) of size n: λ_k = d - 2 cos(k π / (n + 1)), k = 1..n
  const int n = 200;
  const double d = 1.5;  // indefinite: some λ < 0
  SparseAssembler A;
  A.begin(n);
  for (int i = 0; i < n; ++i) {
    A.add(i, i, d);
    if (i + 1 < n) A.add(i, i + 1, -1.0);
  }
  A.end();
  EigenOptions o;
  o.count = 3;
  const EigenResult r = smallest_eigenpairs(A.matrix(), Eigen::MatrixXd(), 1e-3, o);
  ASSERT_TRUE(r.converged);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.values(k), d - 2.0 * std::cos((k + 1) * M_PI / (n + 1)), 1e-9);
  // eigenvector residual
  const Eigen::MatrixXd H = Eigen::MatrixXd(A.matrix()).selfadjointView<Eigen::Upper>();
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((H * r.vectors.col(k) - r.values(k) * r.vectors.col(k)).norm(), 1e-7);
}

TEST(EigenAnalysis, RigidModesAreExcluded) {
  // A ring of springs between consecutive 3D points: zero modes are the
  // translations (the energy Σ |x_{i+1} - x_i|² is also invariant under
  // nothing else); excluding rigid modes removes the zeros.
  const int n = 40;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) P.row(i) << std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0.1 * i;
  SparseAssembler A;
  A.begin(3 * n);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    for (int a = 0; a < 3; ++a) {
      A.add(3 * i + a, 3 * i + a, 1.0);
      A.add(3 * j + a, 3 * j + a, 1.0);
      A.add(3 * i + a, 3 * j + a, -1.0);
    }
  }
  A.end();
  const Eigen::MatrixXd Q = rigid_modes(P, 3 * n);
  EXPECT_EQ(Q.cols(), 6);
  EXPECT_LT((Q.transpose() * Q - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-12);
  EigenOptions o;
  o.count = 1;
  const EigenResult with = smallest_eigenpairs(A.matrix(), Q, 1e-6, o);
  const EigenResult without = smallest_eigenpairs(A.matrix(), Eigen::MatrixXd(), 1e-6, o);
  ASSERT_TRUE(with.converged && without.converged);
  EXPECT_NEAR(without.values(0), 0.0, 1e-8);
  // graph Laplacian of a cycle: second eigenvalue 2 - 2 cos(2π/n), per coordinate
  EXPECT_NEAR(with.values(0), 2.0 - 2.0 * std::cos(2.0 * M_PI / n), 1e-8);
}
