#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "ek/core/sparse_assembler.hpp"
#include "ek/optim/eigen_analysis.hpp"
#include "matrices.hpp"

using namespace ek;

TEST(EigenAnalysis, SmallestEigenvaluesOfTridiagonal) {
  // tridiag(d, -1) of size n: λ_k = d - 2 cos(k π / (n + 1)), k = 1..n
  const int n = 200;
  const double d = 1.5;  // indefinite: some λ < 0
  const auto upper = test_matrices::tridiagonal(n, d);
  EigenOptions o;
  o.count = 3;
  const EigenResult r = smallest_eigenpairs(upper, Eigen::MatrixXd(), 1e-3, o);
  ASSERT_TRUE(r.converged);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.values(k), d - 2.0 * std::cos((k + 1) * M_PI / (n + 1)), 1e-9);
  // eigenvector residual
  const Eigen::MatrixXd H = Eigen::MatrixXd(upper).selfadjointView<Eigen::Upper>();
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

namespace {

/// ‖(I − Q Qᵀ) v‖ / ‖v‖: how far v is from the span of the orthonormal Q.
double outside_span(const Eigen::MatrixXd& Q, const VecX& v) { return (v - Q * (Q.transpose() * v)).norm() / v.norm(); }

/// The rigid motions of the points (translations e_a, rotations e_a × (p − c)).
std::vector<VecX> rigid_motions(const Points& P, int dofs) {
  const int n = static_cast<int>(P.rows());
  const Vec3 c = P.colwise().mean().transpose();
  std::vector<VecX> out;
  for (int a = 0; a < 3; ++a) {
    VecX t = VecX::Zero(dofs), r = VecX::Zero(dofs);
    for (int i = 0; i < n; ++i) {
      t(3 * i + a) = 1.0;
      r.segment<3>(3 * i) = Vec3::Unit(a).cross(Vec3(P.row(i).transpose()) - c);
    }
    out.push_back(t);
    out.push_back(r);
  }
  return out;
}

}  // namespace

TEST(EigenAnalysis, PlanarSlabKeepsOnlyTheMotionsTheSlabAllows) {
  // Under the slab |z| < h only x/y translations and the rotation about z
  // leave the energy invariant: 3 orthonormal modes, with no z motion of the
  // centroid-free kind (a z translation is outside their span).
  std::mt19937_64 rng(4);
  std::normal_distribution<double> N;
  Points P(30, 3);
  for (Eigen::Index i = 0; i < P.size(); ++i) P.data()[i] = 2.0 + N(rng);
  const Eigen::MatrixXd Q = rigid_modes(P, 90, -1, true);
  ASSERT_EQ(Q.cols(), 3);
  EXPECT_LT((Q.transpose() * Q - Eigen::MatrixXd::Identity(3, 3)).norm(), 1e-12);
  VecX tz = VecX::Zero(90), tx = VecX::Zero(90), rz = VecX::Zero(90);
  const Vec3 c = P.colwise().mean().transpose();
  for (int i = 0; i < 30; ++i) {
    tz(3 * i + 2) = 1.0;
    tx(3 * i) = 1.0;
    const Vec3 w = Vec3::UnitZ().cross(P.row(i).transpose() - c);
    rz.segment<3>(3 * i) = w;
  }
  VecX ty = VecX::Zero(90);
  for (int i = 0; i < 30; ++i) ty(3 * i + 1) = 1.0;
  EXPECT_LT(outside_span(Q, tx), 1e-12);
  EXPECT_LT(outside_span(Q, ty), 1e-12);
  EXPECT_LT(outside_span(Q, rz), 1e-12);
  EXPECT_NEAR(outside_span(Q, tz), 1.0, 1e-12);  // z translation is orthogonal to every kept mode
  // no kept mode moves any vertex along z (a tilt about x or y would)
  for (int i = 0; i < 30; ++i) EXPECT_EQ(Q.row(3 * i + 2).norm(), 0.0) << "vertex " << i;
  // with material angles: the uniform θ shift is kept as well (4 modes)
  const Eigen::MatrixXd Qt = rigid_modes(P, 90 + 30, 90, true);
  ASSERT_EQ(Qt.cols(), 4);
  EXPECT_LT((Qt.transpose() * Qt - Eigen::MatrixXd::Identity(4, 4)).norm(), 1e-12);
  VecX shift = VecX::Zero(120);
  shift.tail(30).setOnes();
  EXPECT_LT(outside_span(Qt, shift), 1e-12);
  for (int i = 0; i < 30; ++i) EXPECT_EQ(Qt.row(3 * i + 2).norm(), 0.0) << "vertex " << i;
}

TEST(EigenAnalysis, RigidModesAreOrthonormalAndDropDegenerateRotations) {
  // A generic cloud: 6 orthonormal modes spanning every rigid motion; the
  // θ dofs (beyond 3n) are untouched without theta_begin.
  std::mt19937_64 rng(9);
  std::normal_distribution<double> N;
  Points P(30, 3);
  for (Eigen::Index i = 0; i < P.size(); ++i) P.data()[i] = 5.0 + N(rng);  // off the origin
  const Eigen::MatrixXd Q = rigid_modes(P, 100);
  ASSERT_EQ(Q.cols(), 6);
  EXPECT_LT((Q.transpose() * Q - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-12);
  EXPECT_EQ(Q.bottomRows(10).norm(), 0.0);
  for (const VecX& v : rigid_motions(P, 100)) EXPECT_LT(outside_span(Q, v), 1e-12);
  // Collinear points along a skew direction: the rotation about the line
  // moves nothing, so only 5 modes remain, still orthonormal and spanning.
  const Vec3 u = Vec3(1.0, 2.0, -0.5).normalized();
  Points L(25, 3);
  for (int i = 0; i < 25; ++i) L.row(i) = (Vec3(0.3, -1.0, 2.0) + 0.7 * i * u).transpose();
  const Eigen::MatrixXd QL = rigid_modes(L, 75);
  ASSERT_EQ(QL.cols(), 5);
  EXPECT_LT((QL.transpose() * QL - Eigen::MatrixXd::Identity(5, 5)).norm(), 1e-12);
  for (const VecX& v : rigid_motions(L, 75)) {
    ASSERT_GT(v.norm(), 1e-3);
    EXPECT_LT(outside_span(QL, v), 1e-10);
  }
}
