#pragma once
// Helpers for the contact tests: finite differences of fixed-size kernels,
// random segment pairs by closest-feature case, lattice curves.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <vector>

#include "ek/contact/distance.hpp"
#include "ek/geometry/types.hpp"

namespace ek::contacttest {

using X12 = Eigen::Matrix<double, 12, 1>;

inline std::array<Vec3, 4> split(const X12& x) {
  return {x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), x.segment<3>(9)};
}
inline X12 join(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  X12 x;
  x << a, b, c, d;
  return x;
}

/// Central-difference gradient of f at x with step h.
template <int N>
Eigen::Matrix<double, N, 1> fd_grad(const std::function<double(const Eigen::Matrix<double, N, 1>&)>& f,
                                    const Eigen::Matrix<double, N, 1>& x, double h) {
  Eigen::Matrix<double, N, 1> g;
  for (int i = 0; i < N; ++i) {
    Eigen::Matrix<double, N, 1> p = x, m = x;
    p(i) += h;
    m(i) -= h;
    g(i) = (f(p) - f(m)) / (2 * h);
  }
  return g;
}

/// Central-difference Jacobian of the analytic gradient g at x (the Hessian).
template <int N>
Eigen::Matrix<double, N, N> fd_hess(
    const std::function<Eigen::Matrix<double, N, 1>(const Eigen::Matrix<double, N, 1>&)>& g,
    const Eigen::Matrix<double, N, 1>& x, double h) {
  Eigen::Matrix<double, N, N> H;
  for (int i = 0; i < N; ++i) {
    Eigen::Matrix<double, N, 1> p = x, m = x;
    p(i) += h;
    m(i) -= h;
    H.col(i) = (g(p) - g(m)) / (2 * h);
  }
  return H;
}

/// Smallest relative error ‖a − b‖ / ‖a‖ of an analytic derivative `a`
/// against finite differences over the step sizes (the truncation error falls
/// with h, the rounding error grows, so the best step is what a correct
/// derivative achieves).
template <class F>
double best_relative_error(const F& fd_at_step, const Eigen::MatrixXd& analytic,
                           std::initializer_list<double> steps = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
  double best = 1e300;
  const double scale = std::max(analytic.norm(), 1e-300);
  for (double h : steps) best = std::min(best, (Eigen::MatrixXd(fd_at_step(h)) - analytic).norm() / scale);
  return best;
}

/// Random point in [-1, 1]³.
inline Vec3 rand_vec(std::mt19937_64& rng, double s = 1.0) {
  std::uniform_real_distribution<double> U(-s, s);
  return Vec3(U(rng), U(rng), U(rng));
}

inline Vec3 rand_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> N;
  Vec3 v(N(rng), N(rng), N(rng));
  return v.normalized();
}

/// Some unit vector orthogonal to u.
inline Vec3 orthogonal(const Vec3& u) {
  Vec3 v = std::abs(u.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (v - v.dot(u) * u).normalized();
}

/// A closed self-avoiding random walk on the integer lattice with unit edges
/// (n even): a random walk out and a walk back found by trying the moves
/// that keep the curve simple; returns an empty array if it got stuck.
inline Points lattice_loop(int half, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::array<Eigen::Vector3i, 6> dirs = {Eigen::Vector3i(1, 0, 0),  Eigen::Vector3i(-1, 0, 0),
                                               Eigen::Vector3i(0, 1, 0),  Eigen::Vector3i(0, -1, 0),
                                               Eigen::Vector3i(0, 0, 1),  Eigen::Vector3i(0, 0, -1)};
  // A rectangle-ish closed walk: a self-avoiding walk of `half` steps in a
  // half-space, then returned by a shifted copy: go out along the walk at
  // z-levels 0, come back at z-level 1 in reverse, joined by two vertical
  // edges. Random bends are added by the walk itself.
  std::vector<Eigen::Vector3i> walk = {Eigen::Vector3i(0, 0, 0)};
  std::set<std::array<int, 2>> used = {{0, 0}};
  for (int k = 0; k < half; ++k) {
    std::vector<Eigen::Vector3i> options;
    for (int d = 0; d < 4; ++d) {
      const Eigen::Vector3i q = walk.back() + dirs[static_cast<size_t>(d)];
      if (!used.count({q.x(), q.y()})) options.push_back(q);
    }
    if (options.empty()) return Points();
    const Eigen::Vector3i q = options[std::uniform_int_distribution<size_t>(0, options.size() - 1)(rng)];
    used.insert({q.x(), q.y()});
    walk.push_back(q);
  }
  // out at z = 0, back at z = 1 (same xy path reversed): a closed simple curve
  // whose two halves lie exactly 1 apart, with many lattice contacts.
  const int m = static_cast<int>(walk.size());
  Points P(2 * m, 3);
  for (int i = 0; i < m; ++i) P.row(i) << walk[static_cast<size_t>(i)].x(), walk[static_cast<size_t>(i)].y(), 0;
  for (int i = 0; i < m; ++i)
    P.row(m + i) << walk[static_cast<size_t>(m - 1 - i)].x(), walk[static_cast<size_t>(m - 1 - i)].y(), 1;
  return P;
}

}  // namespace ek::contacttest
