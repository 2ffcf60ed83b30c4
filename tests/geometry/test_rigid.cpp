// The best rigid motion (rigid.hpp) on point sets with known answers.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "ek/geometry/rigid.hpp"

using namespace ek;

namespace {

Points cloud() {
  Points P(6, 3);
  P << 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 1, 1, 0.5, -0.7, 0.4, 1.2;
  return P;
}

}  // namespace

// X = R0 Y + t0 exactly: the motion is recovered and the residual is 0.
TEST(Rigid, RecoversAKnownMotion) {
  const Mat3 R0 = Eigen::AngleAxisd(0.83, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  const Vec3 t0(0.3, -1.1, 2.0);
  const Points Y = cloud();
  const Points X = (Y * R0.transpose()).rowwise() + t0.transpose();
  const RigidMotion m = best_rigid_motion(Y, X);
  EXPECT_LT((m.R - R0).norm(), 1e-12);
  EXPECT_LT((m.t - t0).norm(), 1e-12);
  EXPECT_LT((m.apply(Y) - X).norm(), 1e-12);
  EXPECT_LT((align_onto(Y, X) - X).norm(), 1e-12);
  const Points Yc = Y.rowwise() - Y.colwise().mean(), Xc = X.rowwise() - X.colwise().mean();
  EXPECT_NEAR(rigid_residual(Yc.transpose() * Xc, Yc.squaredNorm() + Xc.squaredNorm()), 0.0, 1e-10);
}

// X is Y's mirror image: no rotation matches it; the motion is proper and the
// residual is the one of the best proper motion (Σ|R y + t − x|² computed).
TEST(Rigid, MirrorImageGetsAProperRotationAndItsResidual) {
  const Points Y = cloud();
  Points X = Y;
  X.col(2) = -X.col(2);
  const RigidMotion m = best_rigid_motion(Y, X);
  EXPECT_NEAR(m.R.determinant(), 1.0, 1e-12);
  const double direct = (m.apply(Y) - X).squaredNorm();
  const Points Yc = Y.rowwise() - Y.colwise().mean(), Xc = X.rowwise() - X.colwise().mean();
  EXPECT_NEAR(rigid_residual(Yc.transpose() * Xc, Yc.squaredNorm() + Xc.squaredNorm()), direct, 1e-10);
  EXPECT_GT(direct, 0.1);
  // no other rotation does better (a few perturbations of the optimum)
  for (int k = 0; k < 3; ++k) {
    const Mat3 dR = Eigen::AngleAxisd(0.05, Vec3::Unit(k)).toRotationMatrix();
    RigidMotion other = m;
    other.R = dR * m.R;
    other.t = X.colwise().mean().transpose() - other.R * Y.colwise().mean().transpose();
    EXPECT_GE((other.apply(Y) - X).squaredNorm(), direct);
  }
  EXPECT_THROW(best_rigid_motion(Y, Points(5, 3)), std::invalid_argument);
}
