#include "ek/mechanics/loads.hpp"

#include <cmath>
#include <stdexcept>

#include "ek/contact/barrier.hpp"
#include "ek/core/errors.hpp"

namespace ek {

namespace {

Vec3 vertex(const VecX& x, int i) { return x.segment<3>(3 * i); }

/// Adds the 6 by 6 Hessian block of a function of (x_i, x_j) through their
/// difference u = x_i − x_j: [K, −K; −K, K].
void add_pair_block(SparseAssembler& A, int i, int j, const Mat3& K) {
  Eigen::Matrix<double, 6, 6> H;
  H << K, -K, -K, K;
  const int idx[6] = {3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2};
  A.add_local(idx, H);
}

/// ∇δ and the Hessian of δ = |x_i − x_j| with respect to x_i: (u, (I − u uᵀ)/δ).
std::pair<Vec3, Mat3> distance_derivatives(const Vec3& xi, const Vec3& xj) {
  const Vec3 d = xi - xj;
  const double delta = d.norm();
  const Vec3 u = d / delta;
  return {u, (Mat3::Identity() - u * u.transpose()) / delta};
}

}  // namespace

// ---- pull ------------------------------------------------------------------

PullLoad::PullLoad(int i, int j, double distance, double stiffness) : i_(i), j_(j), D_(distance), k_(stiffness) {
  require_input(i >= 0 && j >= 0 && i != j, "pull: the two vertices must be distinct vertices of the curve");
  require_input(stiffness > 0.0 && std::isfinite(stiffness), "pull: the stiffness must be positive");
  require_input(std::isfinite(distance), "pull: the distance must be finite");
}

void PullLoad::set_dofs(const VecX& x) {
  require_input(3 * std::max(i_, j_) + 2 < x.size(), "pull: a vertex index is beyond the curve");
  xi_ = vertex(x, i_);
  xj_ = vertex(x, j_);
}

double PullLoad::energy() const { return 0.5 * k_ * std::pow(distance() - D_, 2); }

void PullLoad::add_gradient(Eigen::Ref<VecX> g) const {
  const Vec3 f = k_ * (distance() - D_) * distance_derivatives(xi_, xj_).first;
  g.segment<3>(3 * i_) += f;
  g.segment<3>(3 * j_) -= f;
}

void PullLoad::add_hessian(SparseAssembler& A, HessianKind kind) const {
  const auto [u, P] = distance_derivatives(xi_, xj_);
  const double stretch = distance() - D_;
  // k(∇δ∇δᵀ + (δ − D)∇²δ); the second part is negative when the spring is
  // compressed (δ < D is the pull's normal state: it is then dropped in the projected Hessian)
  Mat3 K = k_ * u * u.transpose();
  if (kind == HessianKind::Exact || stretch > 0.0) K += k_ * stretch * P;
  add_pair_block(A, i_, j_, K);
}

VecX PullLoad::parameter_gradient(int dofs) const {
  VecX d = VecX::Zero(dofs);
  const Vec3 u = distance_derivatives(xi_, xj_).first;
  d.segment<3>(3 * i_) = -k_ * u;
  d.segment<3>(3 * j_) = k_ * u;
  return d;
}

// ---- forces ------------------------------------------------------------------

ForceLoad::ForceLoad(int i, int j, double force) : i_(i), j_(j), F_(force) {
  require_input(i >= 0 && j >= 0 && i != j, "force: the two vertices must be distinct vertices of the curve");
  require_input(std::isfinite(force), "force: the force must be finite");
}

void ForceLoad::set_dofs(const VecX& x) {
  require_input(3 * std::max(i_, j_) + 2 < x.size(), "force: a vertex index is beyond the curve");
  xi_ = vertex(x, i_);
  xj_ = vertex(x, j_);
}

void ForceLoad::add_gradient(Eigen::Ref<VecX> g) const {
  const Vec3 f = -F_ * distance_derivatives(xi_, xj_).first;
  g.segment<3>(3 * i_) += f;
  g.segment<3>(3 * j_) -= f;
}

void ForceLoad::add_hessian(SparseAssembler& A, HessianKind kind) const {
  // −F ∇²δ: negative semidefinite for a pulling force; dropped in the projected Hessian
  const Mat3 K = kind == HessianKind::Exact || F_ < 0.0 ? Mat3(-F_ * distance_derivatives(xi_, xj_).second)
                                                         : Mat3(Mat3::Zero());
  add_pair_block(A, i_, j_, K);
}

VecX ForceLoad::parameter_gradient(int dofs) const {
  VecX d = VecX::Zero(dofs);
  const Vec3 u = distance_derivatives(xi_, xj_).first;
  d.segment<3>(3 * i_) = -u;
  d.segment<3>(3 * j_) = u;
  return d;
}

// ---- plates ------------------------------------------------------------------

PlatesLoad::PlatesLoad(const Vec3& center, const Vec3& normal, double gap, double reach, double stiffness)
    : c_(center), a_(normal.normalized()), g_(gap), reach_(reach), kappa_(stiffness) {
  require_input(normal.norm() > 0.0 && center.allFinite() && normal.allFinite(), "plates: a finite, nonzero normal");
  require_input(gap > 0.0 && std::isfinite(gap), "plates: the gap must be positive");
  require_input(reach > 0.0 && stiffness > 0.0, "plates: the barrier's reach and stiffness must be positive");
}

void PlatesLoad::set_dofs(const VecX& x) {
  const Eigen::Index n = x.size() / 3;
  s_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) s_(i) = a_.dot(x.segment<3>(3 * i) - c_);
}

bool PlatesLoad::inside(double g) const { return s_.size() > 0 && s_.cwiseAbs().maxCoeff() < 0.5 * g; }

double PlatesLoad::energy() const {
  if (!inside(g_)) return INFINITY;
  double e = 0.0;
  for (Eigen::Index i = 0; i < s_.size(); ++i) e += barrier(0.5 * g_ - s_(i), reach_) + barrier(0.5 * g_ + s_(i), reach_);
  return kappa_ * e;
}

void PlatesLoad::add_gradient(Eigen::Ref<VecX> g) const {
  for (Eigen::Index i = 0; i < s_.size(); ++i) {
    const double d = -barrier_first_derivative(0.5 * g_ - s_(i), reach_) +
                     barrier_first_derivative(0.5 * g_ + s_(i), reach_);
    g.segment<3>(3 * i) += kappa_ * d * a_;
  }
}

void PlatesLoad::add_hessian(SparseAssembler& A, HessianKind) const {
  const Mat3 aa = a_ * a_.transpose();
  for (Eigen::Index i = 0; i < s_.size(); ++i) {
    const double h = barrier_second_derivative(0.5 * g_ - s_(i), reach_) +
                     barrier_second_derivative(0.5 * g_ + s_(i), reach_);
    const int idx[3] = {static_cast<int>(3 * i), static_cast<int>(3 * i + 1), static_cast<int>(3 * i + 2)};
    A.add_local(idx, Mat3(kappa_ * h * aa));
  }
}

double PlatesLoad::max_step(const VecX& x, const VecX& dx) const {
  // keep at least a tenth of each vertex's distance to each plate
  double t = 1.0;
  for (Eigen::Index i = 0; i < x.size() / 3; ++i) {
    const double s = a_.dot(x.segment<3>(3 * i) - c_), ds = a_.dot(dx.segment<3>(3 * i));
    if (ds > 0.0) t = std::min(t, 0.9 * (0.5 * g_ - s) / ds);
    if (ds < 0.0) t = std::min(t, 0.9 * (0.5 * g_ + s) / -ds);
  }
  return std::max(t, 0.0);
}

double PlatesLoad::parameter_derivative() const {
  double d = 0.0;
  for (Eigen::Index i = 0; i < s_.size(); ++i)
    d += 0.5 * (barrier_first_derivative(0.5 * g_ - s_(i), reach_) + barrier_first_derivative(0.5 * g_ + s_(i), reach_));
  return kappa_ * d;
}

VecX PlatesLoad::parameter_gradient(int dofs) const {
  VecX d = VecX::Zero(dofs);
  for (Eigen::Index i = 0; i < s_.size(); ++i) {
    const double h = 0.5 * (-barrier_second_derivative(0.5 * g_ - s_(i), reach_) +
                            barrier_second_derivative(0.5 * g_ + s_(i), reach_));
    d.segment<3>(3 * i) = kappa_ * h * a_;
  }
  return d;
}

}  // namespace ek
