#include "ek/geometry/rigid.hpp"

#include <Eigen/SVD>

#include "ek/core/errors.hpp"

namespace ek {

Points RigidMotion::apply(const Points& Y) const { return (Y * R.transpose()).rowwise() + t.transpose(); }

namespace {

/// R of the file comment for centred point sets.
Mat3 best_rotation(const Points& Yc, const Points& Xc) {
  const Mat3 H = Yc.transpose() * Xc;
  const Eigen::JacobiSVD<Mat3> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixV() * D * svd.matrixU().transpose();
}

void check_shapes(const Points& Y, const Points& X) {
  require(Y.rows() == X.rows() && Y.rows() > 0 && Y.cols() == 3 && X.cols() == 3,
          "best_rigid_motion: two m by 3 point sets with m > 0 expected");
}

}  // namespace

RigidMotion best_rigid_motion(const Points& Y, const Points& X) {
  check_shapes(Y, X);
  const Eigen::RowVector3d cy = Y.colwise().mean(), cx = X.colwise().mean();
  RigidMotion m;
  m.R = best_rotation(Y.rowwise() - cy, X.rowwise() - cx);
  m.t = cx.transpose() - m.R * cy.transpose();
  return m;
}

Points align_onto(const Points& Y, const Points& X) {
  check_shapes(Y, X);
  const Eigen::RowVector3d cy = Y.colwise().mean(), cx = X.colwise().mean();
  const Points Yc = Y.rowwise() - cy;
  return (Yc * best_rotation(Yc, X.rowwise() - cx).transpose()).rowwise() + cx;
}

double rigid_residual(const Mat3& H, double centred_norms) {
  const Eigen::JacobiSVD<Mat3> svd(H);
  Vec3 sigma = svd.singularValues();
  if (H.determinant() < 0.0) sigma(2) = -sigma(2);
  return centred_norms - 2.0 * sigma.sum();
}

}  // namespace ek
