#include "ek/analysis/signature.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"

namespace ek {

namespace {

/// Unit binormals per node; `defined[i]` false where the incident edges are
/// (anti)parallel; err[i] estimates the rounding error of b_i (see the header).
void binormals(const Points& E, const VecX& len, double coord_scale, Points& B, std::vector<char>& defined,
               VecX& err) {
  const auto n = E.rows();
  B.resize(n, 3);
  err.setZero(n);
  defined.assign(static_cast<size_t>(n), 0);
  const double u = 0.5 * std::numeric_limits<double>::epsilon();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index p = (i + n - 1) % n;
    const Vec3 c = E.row(p).transpose().cross(E.row(i).transpose());
    const double cn = c.norm();
    if (cn > kBinormalTolerance * len(p) * len(i)) {
      B.row(i) = (c / cn).transpose();
      defined[static_cast<size_t>(i)] = 1;
      err(i) = 2.0 * u * coord_scale * (len(p) + len(i)) / cn;
    } else {
      B.row(i).setZero();
    }
  }
}

}  // namespace

VecX discrete_curvature(const Points& P) {
  require_closed_polygon(P, "discrete_curvature");
  const auto n = P.rows();
  const VecX len = edge_lengths(P);
  require(len.minCoeff() > 0.0, "discrete_curvature: zero-length edge");
  const VecX phi = turning_angles(P);
  VecX k(n);
  for (Eigen::Index i = 0; i < n; ++i) k(i) = phi(i) / (0.5 * (len((i + n - 1) % n) + len(i)));
  return k;
}

VecX discrete_torsion(const Points& P) {
  require_closed_polygon(P, "discrete_torsion");
  const auto n = P.rows();
  const Points E = edge_vectors(P);
  const VecX len = E.rowwise().norm();
  require(len.minCoeff() > 0.0, "discrete_torsion: zero-length edge");
  Points B;
  std::vector<char> defined;
  VecX err;
  binormals(E, len, P.cwiseAbs().maxCoeff(), B, defined, err);
  VecX tau(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index k = (j + 1) % n;
    if (!defined[static_cast<size_t>(j)] || !defined[static_cast<size_t>(k)]) {
      tau(j) = 0.0;
      continue;
    }
    const Vec3 bj = B.row(j).transpose(), bk = B.row(k).transpose();
    const Vec3 t = E.row(j).transpose() / len(j);
    double s = bj.cross(bk).dot(t);
    if (std::abs(s) <= kCoplanarTolerance + kCoplanarSafety * (err(j) + err(k)))
      s = 0.0;  // also turns -0.0 into +0.0: θ = +π, not -π
    tau(j) = std::atan2(s, bj.dot(bk)) / len(j);
  }
  return tau;
}

CurveSignature curve_signature(const Points& P) {
  CurveSignature s;
  s.curvature = discrete_curvature(P);
  const VecX tau = discrete_torsion(P);
  const auto n = P.rows();
  s.torsion.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) s.torsion(i) = s.curvature(i) * 0.5 * (tau((i + n - 1) % n) + tau(i));
  return s;
}

CurveSignature reversed(const CurveSignature& s) {
  CurveSignature r;
  r.curvature = s.curvature.reverse();
  r.torsion = s.torsion.reverse();
  return r;
}

CurveSignature mirrored(const CurveSignature& s) {
  CurveSignature r;
  r.curvature = s.curvature;
  r.torsion = -s.torsion;
  return r;
}

}  // namespace ek
