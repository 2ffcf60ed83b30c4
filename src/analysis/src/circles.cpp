#include "ek/analysis/circles.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

/// Top eigenvector of the symmetric 3x3 matrix.
Vec3 top_eigenvector(const Mat3& M) {
  const Eigen::SelfAdjointEigenSolver<Mat3> es(M);
  return es.eigenvectors().col(2);
}

/// Binormals of the local chord triangles (zero where the chords are parallel).
std::vector<Vec3> local_binormals(const Points& P, int w) {
  const Eigen::Index n = P.rows();
  const double scale = (P.rowwise() - P.colwise().mean()).rowwise().norm().maxCoeff();
  std::vector<Vec3> b(static_cast<size_t>(n), Vec3::Zero());
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 x = P.row(i).transpose();
    const Vec3 u = x - P.row((i - w + n) % n).transpose(), v = P.row((i + w) % n).transpose() - x;
    const Vec3 c = u.cross(v);
    if (c.norm() > 1e-12 * scale * scale) b[static_cast<size_t>(i)] = c.normalized();
  }
  return b;
}

/// Axial k-means of the binormals: a plane orientation per vertex (-1: no vote).
std::vector<int> plane_groups(const std::vector<Vec3>& b, int k) {
  Mat3 S = Mat3::Zero();
  for (const Vec3& v : b) S += v * v.transpose();
  std::vector<Vec3> c = {top_eigenvector(S)};
  while (static_cast<int>(c.size()) < k) {  // farthest binormal from the chosen orientations
    double worst = -1.0;
    Vec3 pick = Vec3::UnitX();
    for (const Vec3& v : b) {
      if (v.squaredNorm() == 0.0) continue;
      double nearest = 0.0;
      for (const Vec3& cj : c) nearest = std::max(nearest, std::fabs(v.dot(cj)));
      if (1.0 - nearest > worst) {
        worst = 1.0 - nearest;
        pick = v;
      }
    }
    c.push_back(pick);
  }
  std::vector<int> group(b.size(), -1);
  for (int it = 0; it < 50; ++it) {
    bool changed = false;
    for (size_t i = 0; i < b.size(); ++i) {
      if (b[i].squaredNorm() == 0.0) continue;
      int best = 0;
      for (int j = 1; j < k; ++j)
        if (std::fabs(b[i].dot(c[static_cast<size_t>(j)])) > std::fabs(b[i].dot(c[static_cast<size_t>(best)]))) best = j;
      changed |= group[i] != best;
      group[i] = best;
    }
    if (!changed && it > 0) break;
    for (int j = 0; j < k; ++j) {
      Mat3 M = Mat3::Zero();
      for (size_t i = 0; i < b.size(); ++i)
        if (group[i] == j) M += b[i] * b[i].transpose();
      if (M.trace() > 0.0) c[static_cast<size_t>(j)] = top_eigenvector(M);
    }
  }
  return group;
}

/// Plane by PCA, then the algebraic (Kåsa) circle in it. `fallback` when fewer than 3 points.
Circle3 fit_circle(const Points& P, const std::vector<int>& group, int j, const Circle3& fallback) {
  std::vector<Eigen::Index> idx;
  for (size_t i = 0; i < group.size(); ++i)
    if (group[i] == j) idx.push_back(static_cast<Eigen::Index>(i));
  if (idx.size() < 3) return fallback;
  Vec3 mean = Vec3::Zero();
  for (Eigen::Index i : idx) mean += P.row(i).transpose();
  mean /= static_cast<double>(idx.size());
  Mat3 C = Mat3::Zero();
  for (Eigen::Index i : idx) C += (P.row(i).transpose() - mean) * (P.row(i).transpose() - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> es(C);
  const Vec3 e1 = es.eigenvectors().col(2), e2 = es.eigenvectors().col(1), normal = es.eigenvectors().col(0);
  Eigen::MatrixXd A(static_cast<Eigen::Index>(idx.size()), 3);
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(idx.size()));
  for (size_t q = 0; q < idx.size(); ++q) {
    const Vec3 d = P.row(idx[q]).transpose() - mean;
    const double u = d.dot(e1), v = d.dot(e2);
    A.row(static_cast<Eigen::Index>(q)) << u, v, 1.0;
    rhs(static_cast<Eigen::Index>(q)) = -(u * u + v * v);
  }
  const Vec3 s = A.colPivHouseholderQr().solve(rhs);  // u² + v² + D u + E v + F = 0
  const double cu = -0.5 * s(0), cv = -0.5 * s(1);
  Circle3 c;
  c.center = mean + cu * e1 + cv * e2;
  c.normal = normal;
  c.radius = std::sqrt(std::max(0.0, cu * cu + cv * cv - s(2)));
  return c;
}

}  // namespace

double Circle3::distance(const Vec3& x) const {
  const Vec3 d = x - center;
  const double h = d.dot(normal);
  const double rho = (d - h * normal).norm();
  return std::hypot(rho - radius, h);
}

void CircleFitOptions::validate() const {
  require(circles >= 1, "CircleFitOptions: circles must be >= 1");
  require(window > 0.0 && window < 0.5, "CircleFitOptions: window must be in (0, 0.5)");
  require(iterations >= 0, "CircleFitOptions: iterations must be >= 0");
}

CircleFit fit_circles(const Points& P, const CircleFitOptions& options) {
  options.validate();
  const int k = options.circles;
  const Eigen::Index n = P.rows();
  require(n >= 4 * k, "fit_circles: at least 4 vertices per circle expected");
  require(P.allFinite(), "fit_circles: non-finite coordinates");
  const int w = std::max(1, static_cast<int>(std::lround(options.window * static_cast<double>(n))));
  std::vector<int> group = plane_groups(local_binormals(P, w), k);
  for (int& g : group) g = std::max(g, 0);  // vertices without a vote start in the first group
  std::vector<Circle3> circles(static_cast<size_t>(k));
  for (int j = 0; j < k; ++j) circles[static_cast<size_t>(j)] = fit_circle(P, group, j, Circle3{});
  for (int it = 0; it < options.iterations; ++it) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vec3 x = P.row(i).transpose();
      int best = 0;
      for (int j = 1; j < k; ++j)
        if (circles[static_cast<size_t>(j)].distance(x) < circles[static_cast<size_t>(best)].distance(x)) best = j;
      changed |= group[static_cast<size_t>(i)] != best;
      group[static_cast<size_t>(i)] = best;
    }
    if (!changed) break;
    for (int j = 0; j < k; ++j) circles[static_cast<size_t>(j)] = fit_circle(P, group, j, circles[static_cast<size_t>(j)]);
  }
  // order by decreasing share
  std::vector<int> count(static_cast<size_t>(k), 0);
  for (int g : group) ++count[static_cast<size_t>(g)];
  std::vector<int> order(static_cast<size_t>(k));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return count[static_cast<size_t>(a)] > count[static_cast<size_t>(b)]; });
  std::vector<int> position(static_cast<size_t>(k));
  for (int q = 0; q < k; ++q) position[static_cast<size_t>(order[static_cast<size_t>(q)])] = q;
  CircleFit fit;
  for (int q = 0; q < k; ++q) {
    fit.circles.push_back(circles[static_cast<size_t>(order[static_cast<size_t>(q)])]);
    fit.share.push_back(static_cast<double>(count[static_cast<size_t>(order[static_cast<size_t>(q)])]) / static_cast<double>(n));
    fit.mean_radius += fit.share.back() * fit.circles.back().radius;
  }
  double sum2 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const int g = position[static_cast<size_t>(group[static_cast<size_t>(i)])];
    fit.assignment.push_back(g);
    const double d = fit.circles[static_cast<size_t>(g)].distance(P.row(i).transpose());
    sum2 += d * d;
    fit.max_distance = std::max(fit.max_distance, d);
  }
  fit.rms_distance = std::sqrt(sum2 / static_cast<double>(n));
  fit.min_plane_angle = k > 1 ? M_PI / 2 : 0.0;
  for (int a = 0; a < k; ++a)
    for (int b = a + 1; b < k; ++b) {
      const double c = std::min(1.0, std::fabs(fit.circles[static_cast<size_t>(a)].normal.dot(fit.circles[static_cast<size_t>(b)].normal)));
      fit.min_plane_angle = std::min(fit.min_plane_angle, std::acos(c));
    }
  return fit;
}

bool meets(const CircleFit& fit, const CircleCriterion& c) {
  if (fit.relative_rms() > c.max_relative_rms || fit.min_plane_angle < c.min_plane_angle) return false;
  for (double s : fit.share)
    if (s < c.min_share) return false;
  return true;
}

}  // namespace ek
