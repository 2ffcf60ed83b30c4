#pragma once
// Helpers shared by the rod tests: finite differences of ElasticRod energies
// and gradients, block-wise relative errors, test curves.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <random>

#include "ek/rod/elastic_rod.hpp"
#include "testing.hpp"

namespace ek::rodtest {

/// Central differences of the energy (one term) over the dofs at the rod's
/// current dofs (source frames fixed). Leaves the rod at its dofs.
inline VecX fd_gradient(ElasticRod& rod, EnergyTerm term, double h) {
  const VecX x0 = rod.dofs();
  VecX g = fixtures::fd_gradient(
      [&](const VecX& x) {
        rod.set_dofs(x);
        return rod.energy(term);
      },
      x0, h);
  rod.set_dofs(x0);
  return g;
}

/// Central differences of the analytic gradient: column k is
/// (g(x + h e_k) - g(x - h e_k)) / 2h. Dense, symmetrised.
inline Eigen::MatrixXd fd_hessian(ElasticRod& rod, EnergyTerm term, double h) {
  const VecX x0 = rod.dofs();
  const Eigen::Index N = x0.size();
  Eigen::MatrixXd H(N, N);
  VecX x = x0;
  for (Eigen::Index k = 0; k < N; ++k) {
    x(k) = x0(k) + h;
    rod.set_dofs(x);
    const VecX gp = rod.gradient(term);
    x(k) = x0(k) - h;
    rod.set_dofs(x);
    const VecX gm = rod.gradient(term);
    x(k) = x0(k);
    H.col(k) = (gp - gm) / (2.0 * h);
  }
  rod.set_dofs(x0);
  return 0.5 * (H + H.transpose());
}

/// ||a - b|| / ||b||, or ||a - b|| when b = 0 (then the caller checks an
/// absolute bound).
inline double rel_error(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& b) {
  const double nb = b.norm();
  return nb > 0.0 ? (a - b).norm() / nb : (a - b).norm();
}

/// A smooth random closed curve with moderate turning angles (n vertices).
inline Points smooth_random_curve(int n, std::uint64_t seed, double scale = 1.0) {
  Points P = fixtures::random_fourier_curve(n, 3, seed);
  return scale * P;
}

/// Adds independent Gaussian noise of standard deviation sigma to every coordinate.
inline Points perturbed(const Points& P, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, sigma);
  Points Q = P;
  for (Eigen::Index i = 0; i < Q.size(); ++i) Q.data()[i] += N(rng);
  return Q;
}

}  // namespace ek::rodtest
