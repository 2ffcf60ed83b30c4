#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "ek/core/sparse_assembler.hpp"
#include "ek/solver/cholesky.hpp"

using namespace ek;

namespace {

/// 1D Laplacian-like tridiagonal matrix (upper triangle) with diagonal d.
CholeskySolver::Matrix tridiagonal(int n, double d) {
  SparseAssembler A;
  A.begin(n);
  for (int i = 0; i < n; ++i) {
    A.add(i, i, d);
    if (i + 1 < n) A.add(i, i + 1, -1.0);
  }
  A.end();
  return A.matrix();
}

}  // namespace

TEST(Cholesky, SolvesPositiveDefiniteSystems) {
  for (CholeskyMode mode : {CholeskyMode::Simplicial, CholeskyMode::Supernodal}) {
    CholeskySolver chol(mode);
    const auto H = tridiagonal(50, 2.5);
    ASSERT_TRUE(chol.factorize(H, 0.0, 1));
    VecX b = VecX::LinSpaced(50, -1, 1);
    const VecX x = chol.solve(b);
    const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
    EXPECT_LT((full * x - b).norm(), 1e-12 * b.norm());
  }
}

TEST(Cholesky, DetectsIndefiniteAndAppliesShift) {
  CholeskySolver chol;
  // eigenvalues of tridiag(d, -1) are d - 2 cos(k π/(n+1)): d = 1 gives negative ones
  const auto H = tridiagonal(30, 1.0);
  EXPECT_FALSE(chol.factorize(H, 0.0, 7));
  EXPECT_TRUE(chol.factorize(H, 1.01, 7));  // shifted: d + s > 2
  const VecX b = VecX::Ones(30);
  const VecX x = chol.solve(b);
  const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
  EXPECT_LT(((full + 1.01 * Eigen::MatrixXd::Identity(30, 30)) * x - b).norm(), 1e-12 * b.norm());
  // the same pattern version: one symbolic analysis for both factorisations
  EXPECT_EQ(chol.symbolic_count(), 1);
  EXPECT_EQ(chol.numeric_count(), 2);
  EXPECT_TRUE(chol.factorize(tridiagonal(30, 3.0), 0.0, 8));
  EXPECT_EQ(chol.symbolic_count(), 2);
}

TEST(Cholesky, RejectsNonFinite) {
  CholeskySolver chol;
  auto H = tridiagonal(5, 3.0);
  H.valuePtr()[0] = std::nan("");
  EXPECT_THROW(chol.factorize(H, 0.0, 1), std::invalid_argument);
}
