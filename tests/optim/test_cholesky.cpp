#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdint>
#include <vector>
#include <random>

#include "ek/core/sparse_assembler.hpp"
#include "ek/optim/cholesky.hpp"
#include "matrices.hpp"

using namespace ek;

namespace {

using test_matrices::tridiagonal;

}  // namespace

TEST(Cholesky, SolvesPositiveDefiniteSystems) {
  for (CholeskyMode mode : {CholeskyMode::Simplicial, CholeskyMode::Supernodal, CholeskyMode::Block}) {
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

// A failed attempt leaves the last good factor in place: recall() makes it
// current again (same shift, no analysis since), in both modes; a failed
// attempt alone leaves no factor to solve with, and a new pattern forgets it.
TEST(Cholesky, FailedAttemptKeepsTheLastGoodFactor) {
  for (CholeskyMode mode : {CholeskyMode::Simplicial, CholeskyMode::Supernodal, CholeskyMode::Block}) {
    CholeskySolver chol(mode);
    const auto H = tridiagonal(30, 1.0);  // eigenvalues 1 - 2 cos(k π/31): the lowest ≈ -0.99
    ASSERT_TRUE(chol.factorize(H, 1.5, 3));
    EXPECT_FALSE(chol.factorize(H, 0.5, 3));
    EXPECT_THROW(chol.solve(VecX::Ones(30)), std::invalid_argument);
    EXPECT_FALSE(chol.recall(0.5));  // not the good factor's shift
    ASSERT_TRUE(chol.recall(1.5));
    const VecX b = VecX::LinSpaced(30, -1, 2);
    const VecX x = chol.solve(b);
    const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
    EXPECT_LT(((full + 1.5 * Eigen::MatrixXd::Identity(30, 30)) * x - b).norm(), 1e-12 * b.norm());
    EXPECT_EQ(chol.numeric_count(), 2);  // recall factorises nothing
    EXPECT_FALSE(chol.factorize(tridiagonal(30, 0.5), 0.0, 4));  // a new analysis
    EXPECT_FALSE(chol.recall(1.5));
  }
}

TEST(Cholesky, RejectsNonFinite) {
  CholeskySolver chol;
  auto H = tridiagonal(5, 3.0);
  H.valuePtr()[0] = std::nan("");
  EXPECT_THROW(chol.factorize(H, 0.0, 1), std::invalid_argument);
}

namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// Random symmetric sparse matrix (full storage): a banded "rod" part plus
/// `extra` random off-diagonal entries (the "contacts"), values N(0, 1).
Eigen::MatrixXd random_symmetric(int n, int extra, std::mt19937_64& rng) {
  std::normal_distribution<double> N;
  std::uniform_int_distribution<int> U(0, n - 1);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    S(i, i) = N(rng);
    for (int k = 1; k <= 3 && i + k < n; ++k) S(i, i + k) = S(i + k, i) = N(rng);
  }
  for (int k = 0; k < extra; ++k) {
    const int i = U(rng), j = U(rng);
    if (i != j) S(i, j) = S(j, i) = N(rng);
  }
  return S;
}

double smallest_eigenvalue(const Eigen::MatrixXd& S) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
}

/// S + (margin − λ_min(S)) I: symmetric positive definite with λ_min = margin.
Eigen::MatrixXd make_spd(const Eigen::MatrixXd& S, double margin) {
  return S + (margin - smallest_eigenvalue(S)) * Eigen::MatrixXd::Identity(S.rows(), S.cols());
}

/// Upper triangle of a dense symmetric matrix (its non-zeros), compressed.
CholeskySolver::Matrix upper_of(const Eigen::MatrixXd& S) {
  Triplets t;
  for (int j = 0; j < S.cols(); ++j)
    for (int i = 0; i <= j; ++i)
      if (S(i, j) != 0.0) t.emplace_back(i, j, S(i, j));
  CholeskySolver::Matrix U(S.rows(), S.cols());
  U.setFromTriplets(t.begin(), t.end());
  U.makeCompressed();
  return U;
}

/// ||x − x_ref|| / ||x_ref|| with x_ref from a dense LLT of (S + shift I).
double error_against_dense(const CholeskySolver& chol, const Eigen::MatrixXd& S, double shift, const VecX& b) {
  const Eigen::MatrixXd M = S + shift * Eigen::MatrixXd::Identity(S.rows(), S.cols());
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  EXPECT_EQ(llt.info(), Eigen::Success);
  const VecX ref = llt.solve(b);
  return (chol.solve(b) - ref).norm() / ref.norm();
}

const char* name(CholeskyMode m) {
  return m == CholeskyMode::Simplicial ? "simplicial" : m == CholeskyMode::Supernodal ? "supernodal" : "block";
}

}  // namespace

TEST(Cholesky, RandomSparseSpdMatchesDenseLlt) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> N;
  for (CholeskyMode mode : {CholeskyMode::Simplicial, CholeskyMode::Supernodal, CholeskyMode::Block})
    for (int trial = 0; trial < 6; ++trial) {
      const int n = 40 + 37 * trial;
      const Eigen::MatrixXd S = make_spd(random_symmetric(n, 2 * n, rng), 0.5);
      const CholeskySolver::Matrix U = upper_of(S);
      CholeskyOptions o;
      o.mode = mode;
      CholeskySolver chol(o);
      EXPECT_EQ(chol.factor_nonzeros(), 0);
      ASSERT_TRUE(chol.factorize(U, 0.0, 1)) << name(mode) << " n = " << n;
      // L holds at least the (permuted) lower triangle of H
      EXPECT_GE(chol.factor_nonzeros(), U.nonZeros()) << name(mode);
      for (int k = 0; k < 3; ++k) {
        VecX b(n);
        for (int i = 0; i < n; ++i) b(i) = N(rng);
        EXPECT_LT(error_against_dense(chol, S, 0.0, b), 1e-10) << name(mode) << " n = " << n;
      }
      // a shift is applied to the same pattern without a new analysis
      ASSERT_TRUE(chol.factorize(U, 2.5, 1));
      EXPECT_LT(error_against_dense(chol, S, 2.5, VecX::Ones(n)), 1e-10) << name(mode);
      EXPECT_EQ(chol.symbolic_count(), 1);
      EXPECT_EQ(chol.ordering_count(), 1);
      EXPECT_EQ(chol.numeric_count(), 2);
      EXPECT_THROW(chol.solve(VecX::Ones(n + 1)), std::invalid_argument);
    }
}

TEST(Cholesky, ReusedOrderingSolvesChangingPatterns) {
  // A fixed "rod" band plus contact entries that change from one pattern to
  // the next (as the contact set does in a Newton solve); every pattern gets
  // a new version. The kept ordering must give the same solutions as a fresh
  // dense factorisation, and AMD is rerun exactly when the fill of the kept
  // ordering exceeds (1 + reorder_fill_growth) times that of the last AMD.
  for (CholeskyMode mode : {CholeskyMode::Simplicial, CholeskyMode::Supernodal, CholeskyMode::Block})
    for (bool reuse : {true, false}) {
      std::mt19937_64 rng(11);
      CholeskyOptions o;
      o.mode = mode;
      o.reuse_ordering = reuse;
      CholeskySolver chol(o);
      const int n = 150;
      const Eigen::MatrixXd band = random_symmetric(n, 0, rng);
      long long fill_at_ordering = 0;
      std::uint64_t version = 0;
      int reorders_from_growth = 0;
      for (int step = 0; step < 16; ++step) {
        // a few contact entries, or (steps 7 and 12) many: much more fill
        const int extra = step == 7 || step == 12 ? 400 : 6;
        Eigen::MatrixXd S = band + random_symmetric(n, extra, rng);
        S = make_spd(S, 0.3);
        const int orderings_before = chol.ordering_count();
        ASSERT_TRUE(chol.factorize(upper_of(S), 0.0, ++version)) << name(mode) << " step " << step;
        const bool reordered = chol.ordering_count() > orderings_before;
        EXPECT_LE(chol.ordering_count(), orderings_before + 1);
        // with reuse, a new ordering after the first costs a second analysis
        // (the kept ordering was analysed first and found to fill too much)
        if (reordered && step > 0 && reuse) ++reorders_from_growth;
        EXPECT_EQ(chol.symbolic_count(), static_cast<int>(version) + reorders_from_growth) << name(mode);
        if (reordered) {
          fill_at_ordering = chol.factor_nonzeros();
        } else {
          EXPECT_TRUE(reuse);
          EXPECT_LE(static_cast<double>(chol.factor_nonzeros()),
                    (1.0 + o.reorder_fill_growth) * static_cast<double>(fill_at_ordering))
              << name(mode) << " step " << step;
        }
        EXPECT_GT(chol.factor_nonzeros(), 0);
        EXPECT_LE(chol.ordering_count(), chol.symbolic_count());
        VecX b = VecX::LinSpaced(n, -1.0, 2.0);
        EXPECT_LT(error_against_dense(chol, S, 0.0, b), 1e-10) << name(mode) << " step " << step;
        // a second factorisation of the same version reuses everything
        ASSERT_TRUE(chol.factorize(upper_of(S), 0.1, version));
        EXPECT_LT(error_against_dense(chol, S, 0.1, b), 1e-10) << name(mode) << " step " << step;
      }
      if (reuse) {
        EXPECT_LT(chol.ordering_count(), chol.symbolic_count()) << name(mode);
        EXPECT_GE(reorders_from_growth, 1) << name(mode);  // the dense steps needed a new ordering
      } else {
        EXPECT_EQ(chol.ordering_count(), chol.symbolic_count()) << name(mode);
      }
      // a new size always gets a fresh ordering
      const int orderings = chol.ordering_count();
      const Eigen::MatrixXd T = make_spd(random_symmetric(n + 10, 20, rng), 0.3);
      ASSERT_TRUE(chol.factorize(upper_of(T), 0.0, ++version));
      EXPECT_EQ(chol.ordering_count(), orderings + 1);
      EXPECT_LT(error_against_dense(chol, T, 0.0, VecX::Ones(n + 10)), 1e-10) << name(mode);
    }
}

TEST(Cholesky, IndefiniteFailsAndLargeEnoughShiftSucceeds) {
  std::mt19937_64 rng(17);
  for (CholeskyMode mode : {CholeskyMode::Simplicial, CholeskyMode::Supernodal, CholeskyMode::Block}) {
    const int n = 120;
    const Eigen::MatrixXd S = random_symmetric(n, 150, rng);
    const double lmin = smallest_eigenvalue(S);
    ASSERT_LT(lmin, -0.5);
    const CholeskySolver::Matrix U = upper_of(S);
    CholeskyOptions o;
    o.mode = mode;
    CholeskySolver chol(o);
    EXPECT_FALSE(chol.factorize(U, 0.0, 1)) << name(mode);
    EXPECT_THROW(chol.solve(VecX::Ones(n)), std::invalid_argument);
    EXPECT_GT(chol.factor_nonzeros(), 0);  // the symbolic factor exists even when the numeric one failed
    // just below −λ_min: still indefinite; just above: positive definite
    EXPECT_FALSE(chol.factorize(U, -lmin - 0.01, 1)) << name(mode);
    const double shift = -lmin + 0.01;
    ASSERT_TRUE(chol.factorize(U, shift, 1)) << name(mode);
    EXPECT_LT(error_against_dense(chol, S, shift, VecX::LinSpaced(n, 1.0, 3.0)), 1e-10) << name(mode);
    // a failure after a success invalidates the factorisation
    EXPECT_FALSE(chol.factorize(U, 0.0, 1));
    EXPECT_THROW(chol.solve(VecX::Ones(n)), std::invalid_argument);
    ASSERT_TRUE(chol.factorize(U, 1.0 - lmin, 1));
    EXPECT_LT(error_against_dense(chol, S, 1.0 - lmin, VecX::Ones(n)), 1e-10) << name(mode);
    EXPECT_EQ(chol.symbolic_count(), 1);
    EXPECT_EQ(chol.numeric_count(), 5);
  }
}

// The block factorisation on the sizes where its blocks are degenerate: one
// and two dofs (a padded block), a block-diagonal matrix (no edge for AMD),
// and the error for a matrix whose pattern was not analysed.
TEST(Cholesky, BlockFactorisationOfTinyAndBlockDiagonalMatrices) {
  for (int n : {1, 2, 3, 4, 7}) {
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) S(i, i) = 2.0 + i;
    for (int i = 0; i + 1 < n; ++i)
      if (i % 3 != 2) S(i, i + 1) = S(i + 1, i) = 0.5;  // couplings inside blocks only
    CholeskySolver chol(CholeskyMode::Block);
    ASSERT_TRUE(chol.factorize(upper_of(S), 0.25, 1)) << n;
    const VecX b = VecX::LinSpaced(n, 1.0, 2.0);
    EXPECT_LT(error_against_dense(chol, S, 0.25, b), 1e-14) << n;
    EXPECT_FALSE(chol.factorize(upper_of(S), -2.5, 1)) << n;  // S - 2.5 I has a negative eigenvalue
  }
  BlockCholesky block;
  const Eigen::MatrixXd S = Eigen::MatrixXd::Identity(6, 6);
  block.analyse(upper_of(S));
  EXPECT_THROW(block.factorize(upper_of(Eigen::MatrixXd::Ones(6, 6) + S), 0.0), std::invalid_argument);
  EXPECT_THROW(block.solve(VecX::Ones(6)), std::invalid_argument);
}

// A failed block factorisation at shift s proves that H + (s + δ')·I is
// indefinite for every δ' <= δ = shift_deficit(): the Rayleigh quotient of
// x = (−L₁₁⁻ᵀ L_kᵀ v, v) is μ / ‖x‖² = −δ below λ_min(H + s·I). Checked
// against the dense spectrum on random indefinite matrices (δ <= the true
// deficit −λ_min − s, and δ > 0), exact on an uncoupled matrix (its failing
// pivot block is its own eigen-problem), 0 after a success and for CHOLMOD.
TEST(Cholesky, ShiftDeficitIsALowerBoundOnTheMissingShift) {
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 60 + 3 * trial;
    const Eigen::MatrixXd S = random_symmetric(n, 80, rng);
    const double lmin = smallest_eigenvalue(S);
    ASSERT_LT(lmin, -0.1);
    const CholeskySolver::Matrix U = upper_of(S);
    CholeskySolver chol(CholeskyMode::Block);
    for (double s : {0.0, 0.5 * -lmin, 0.99 * -lmin}) {
      ASSERT_FALSE(chol.factorize(U, s, 1)) << trial;
      const double missing = -lmin - s, delta = chol.shift_deficit();
      EXPECT_GT(delta, 0.0) << trial;
      EXPECT_LE(delta, missing * (1.0 + 1e-10) + 1e-14) << trial << " s " << s;
    }
    ASSERT_TRUE(chol.factorize(U, -lmin + 0.01, 1));
    EXPECT_EQ(chol.shift_deficit(), 0.0);
  }
  // uncoupled: the second diagonal block has eigenvalues −1, 2, 3; at s = 0.5
  // the missing shift is exactly 0.5
  Eigen::MatrixXd D = Eigen::MatrixXd::Identity(9, 9);
  D.block<3, 3>(3, 3) << 0.5, 1.5, 0.0, 1.5, 0.5, 0.0, 0.0, 0.0, 3.0;
  CholeskySolver block(CholeskyMode::Block), simplicial(CholeskyMode::Simplicial);
  ASSERT_FALSE(block.factorize(upper_of(D), 0.5, 1));
  EXPECT_NEAR(block.shift_deficit(), 0.5, 1e-12);
  ASSERT_FALSE(simplicial.factorize(upper_of(D), 0.5, 1));
  EXPECT_EQ(simplicial.shift_deficit(), 0.0);
}
