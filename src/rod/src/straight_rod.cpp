#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Spectra/MatOp/SparseSymShiftSolve.h>
#include <Spectra/SymEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/rod/elastic_rod.hpp"

namespace ek {

namespace {

/// Smallest eigenvalue of D Dᵀ, D the (m by m+2) second-difference matrix
/// (rows [1 -2 1]): the pentadiagonal m by m matrix with 6 on the diagonal,
/// -4 on the first and 1 on the second off-diagonals. Positive definite.
double smallest_second_difference_eigenvalue(int m) {
  if (m <= 40) {
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < m; ++i) {
      M(i, i) = 6.0;
      if (i + 1 < m) M(i, i + 1) = M(i + 1, i) = -4.0;
      if (i + 2 < m) M(i, i + 2) = M(i + 2, i) = 1.0;
    }
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly).eigenvalues()(0);
  }
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < m; ++i) {
    trip.emplace_back(i, i, 6.0);
    for (int k = 1; k <= 2; ++k)
      if (i + k < m) {
        const double v = k == 1 ? -4.0 : 1.0;
        trip.emplace_back(i, i + k, v);
        trip.emplace_back(i + k, i, v);
      }
  }
  Eigen::SparseMatrix<double> M(m, m);
  M.setFromTriplets(trip.begin(), trip.end());
  // Shift-invert about 0: the largest eigenvalues of M⁻¹ are the smallest of M.
  Spectra::SparseSymShiftSolve<double> op(M);
  Spectra::SymEigsShiftSolver<Spectra::SparseSymShiftSolve<double>> eigs(op, 1, std::min(m, 20), 0.0);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
  require(eigs.info() == Spectra::CompInfo::Successful,
          "straight_rod_min_eigenvalue: Spectra did not converge for m = " + std::to_string(m));
  return eigs.eigenvalues()(0);
}

}  // namespace

double straight_rod_min_eigenvalue(int n, double edge_length, const RodMaterial& material, TwistModel model) {
  require(n >= 3, "straight_rod_min_eigenvalue: n must be at least 3");
  require(std::isfinite(edge_length) && edge_length > 0.0, "straight_rod_min_eigenvalue: edge length must be positive");
  material.validate();
  const double h = edge_length;
  const double axial = 4.0 * material.stretching_stiffness() / h * std::pow(std::sin(M_PI / (2.0 * (n + 1))), 2);
  const double bending = material.bending_stiffness() / (h * h * h) * smallest_second_difference_eigenvalue(n - 1);
  double lambda = std::min(axial, bending);
  if (model != TwistModel::TwistFree)
    lambda = std::min(lambda, 4.0 * material.twisting_stiffness() / h * std::pow(std::sin(M_PI / (2.0 * n)), 2));
  return lambda;
}

}  // namespace ek
