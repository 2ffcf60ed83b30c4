#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "ek/analysis/mds.hpp"

using namespace ek;

namespace {

Eigen::MatrixXd random_points(int N, int dim, std::uint64_t seed, const Eigen::VectorXd& scales) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> G(0.0, 1.0);
  Eigen::MatrixXd X(N, dim);
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < dim; ++k) X(i, k) = scales(k) * G(rng);
  return X;
}

Eigen::MatrixXd distances(const Eigen::MatrixXd& X) {
  const auto N = X.rows();
  Eigen::MatrixXd D(N, N);
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) D(i, j) = (X.row(i) - X.row(j)).norm();
  return D;
}

}  // namespace

TEST(Mds, RecoversPlanarConfigurations) {
  // exactly 2D Euclidean distances are reproduced (dense path N <= 16, Spectra path above)
  for (int N : {3, 10, 16, 17, 60, 200}) {
    const Eigen::MatrixXd X = random_points(N, 2, static_cast<std::uint64_t>(N), Eigen::Vector2d(3.0, 1.0));
    const Eigen::MatrixXd D = distances(X);
    const MdsResult r = classical_mds(D, 2);
    ASSERT_EQ(r.status, MdsStatus::Converged);
    EXPECT_LT((distances(r.coordinates) - D).cwiseAbs().maxCoeff(), 1e-9 * D.maxCoeff()) << N;
    EXPECT_NEAR(r.explained, 1.0, 1e-9);
    EXPECT_GE(r.eigenvalues(0), r.eigenvalues(1));
    // centred output
    EXPECT_LT(r.coordinates.colwise().sum().norm(), 1e-9 * D.maxCoeff() * N);
  }
}

TEST(Mds, TopEigenvaluesMatchDenseSolverIn3D) {
  const int N = 80;
  const Eigen::MatrixXd X = random_points(N, 3, 7, Eigen::Vector3d(4.0, 2.0, 0.5));
  const Eigen::MatrixXd D = distances(X);
  const MdsResult r = classical_mds(D, 2);
  ASSERT_EQ(r.status, MdsStatus::Converged);
  // dense reference on B = -1/2 J D² J
  const Eigen::MatrixXd J = Eigen::MatrixXd::Identity(N, N) - Eigen::MatrixXd::Constant(N, N, 1.0 / N);
  const Eigen::MatrixXd B = -0.5 * J * D.cwiseProduct(D) * J;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(B);
  EXPECT_NEAR(r.eigenvalues(0), es.eigenvalues()(N - 1), 1e-9 * es.eigenvalues()(N - 1));
  EXPECT_NEAR(r.eigenvalues(1), es.eigenvalues()(N - 2), 1e-9 * es.eigenvalues()(N - 1));
  EXPECT_NEAR(r.explained, (es.eigenvalues()(N - 1) + es.eigenvalues()(N - 2)) / B.trace(), 1e-9);
  EXPECT_LT(r.explained, 1.0);
  // the 2D coordinates are the projection onto the top principal plane: Gram matrix = top-2 part of B
  const Eigen::MatrixXd G = r.coordinates * r.coordinates.transpose();
  const Eigen::MatrixXd V = es.eigenvectors().rightCols(2);
  const Eigen::MatrixXd B2 = V * es.eigenvalues().tail(2).asDiagonal() * V.transpose();
  EXPECT_LT((G - B2).cwiseAbs().maxCoeff(), 1e-8 * B.cwiseAbs().maxCoeff());
  // 3 dimensions recover the points exactly
  const MdsResult r3 = classical_mds(D, 3);
  EXPECT_LT((distances(r3.coordinates) - D).cwiseAbs().maxCoeff(), 1e-9 * D.maxCoeff());
}

TEST(Mds, DeterministicSignsAndEdgeCases) {
  const Eigen::MatrixXd D = distances(random_points(30, 2, 3, Eigen::Vector2d(1.0, 1.0)));
  const MdsResult a = classical_mds(D), b = classical_mds(D);
  EXPECT_EQ(a.coordinates, b.coordinates);
  for (int k = 0; k < 2; ++k) {
    Eigen::Index i = 0;
    a.coordinates.col(k).cwiseAbs().maxCoeff(&i);
    EXPECT_GT(a.coordinates(i, k), 0.0);
  }
  const MdsResult one = classical_mds(Eigen::MatrixXd::Zero(1, 1));
  EXPECT_EQ(one.coordinates.rows(), 1);
  EXPECT_EQ(one.coordinates.norm(), 0.0);
  // a similarity matrix: distance 1 - S
  const Eigen::MatrixXd S = Eigen::MatrixXd::Ones(D.rows(), D.cols()) - D / (2 * D.maxCoeff());
  const MdsResult s = classical_mds_from_similarity(S);
  EXPECT_LT((distances(s.coordinates) - (D / (2 * D.maxCoeff()))).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_THROW(classical_mds(D, 0), std::invalid_argument);
  EXPECT_THROW(classical_mds(D, 30), std::invalid_argument);
  EXPECT_THROW(classical_mds(Eigen::MatrixXd::Zero(3, 2)), std::invalid_argument);
}

// Degenerate configurations above the dense limit, as data sets produce them
// (a BB knot's 40 samples all relax to the same multi-covered circle): all
// points at one place give the origin; points on a line (B of rank 1 < d = 2)
// are recovered exactly, the second axis 0.
TEST(Mds, CoincidingAndCollinearPoints) {
  const int N = 40;
  const MdsResult same = classical_mds(Eigen::MatrixXd::Zero(N, N));
  EXPECT_EQ(same.status, MdsStatus::Converged);
  EXPECT_EQ(same.coordinates.norm(), 0.0);
  const MdsResult near_same = classical_mds_from_similarity(Eigen::MatrixXd::Constant(N, N, 1.0 - 1e-17));
  EXPECT_EQ(near_same.status, MdsStatus::Converged);
  EXPECT_LE(near_same.coordinates.norm(), 1e-12);
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(N, 2);
  for (int i = 0; i < N; ++i) X(i, 0) = (i % 3) * 0.25;  // three clusters on a line
  const MdsResult line = classical_mds(distances(X));
  EXPECT_EQ(line.status, MdsStatus::Converged);
  // the second axis is the square root of a round-off eigenvalue (~1e-16): up to ~1e-8
  EXPECT_LT((distances(line.coordinates) - distances(X)).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT(line.coordinates.col(1).norm(), 1e-6);
}
