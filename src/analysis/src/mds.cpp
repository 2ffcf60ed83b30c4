#include "ek/analysis/mds.hpp"

#include <Spectra/MatOp/DenseSymMatProd.h>
#include <Spectra/SymEigsSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "ek/core/errors.hpp"

namespace ek {

namespace {

/// The dims largest eigenpairs of the symmetric B by Spectra's Lanczos
/// solver; false when it does not converge or breaks down.
bool top_eigenpairs_lanczos(const Eigen::MatrixXd& B, int dims, Eigen::VectorXd& values, Eigen::MatrixXd& vectors) {
  try {
    Spectra::DenseSymMatProd<double> op(B);
    const Eigen::Index ncv = std::min<Eigen::Index>(B.rows(), std::max<Eigen::Index>(2 * dims + 1, 20));
    Spectra::SymEigsSolver<Spectra::DenseSymMatProd<double>> solver(op, dims, ncv);
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12, Spectra::SortRule::LargestAlge);
    if (solver.info() != Spectra::CompInfo::Successful) return false;
    values = solver.eigenvalues();
    vectors = solver.eigenvectors();
    return true;
  } catch (const std::exception&) {  // Spectra throws when its tridiagonal eigensolver fails
    return false;
  }
}

}  // namespace

MdsResult classical_mds(const Eigen::MatrixXd& D, int dims) {
  const auto N = D.rows();
  require(N >= 1 && D.cols() == N, "classical_mds: a square distance matrix expected");
  require(D.allFinite(), "classical_mds: non-finite distances");
  const double scale = D.cwiseAbs().maxCoeff();
  require((D - D.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale, "classical_mds: the distance matrix is not symmetric");
  require(dims >= 1 && (N == 1 || dims < N), "classical_mds: need 1 <= dims < N");
  MdsResult out;
  out.coordinates = Eigen::MatrixXd::Zero(N, dims);
  out.eigenvalues = Eigen::VectorXd::Zero(dims);
  if (N == 1) {
    out.explained = 1.0;
    return out;
  }

  // B = -1/2 J D² J (double centring), symmetrised.
  Eigen::MatrixXd B = D.cwiseProduct(D);
  B = 0.5 * (B + B.transpose()).eval();
  const Eigen::VectorXd row_mean = B.rowwise().mean();
  const double all_mean = row_mean.mean();
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) B(i, j) = -0.5 * (B(i, j) - row_mean(i) - row_mean(j) + all_mean);

  // Every point at the same place (B = 0 up to round-off): the origin.
  if (B.cwiseAbs().maxCoeff() <= 1e-14 * scale * scale) {
    out.explained = 1.0;
    return out;
  }
  Eigen::VectorXd values(dims);
  Eigen::MatrixXd vectors(N, dims);
  if (N <= kMdsDenseLimit || !top_eigenpairs_lanczos(B, dims, values, vectors)) {
    // dense: small matrices, and the fallback when Lanczos fails (e.g. B of
    // rank below dims, whose Krylov space breaks down)
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(B);
    if (es.info() != Eigen::Success) out.status = MdsStatus::NotConverged;
    for (int k = 0; k < dims; ++k) {  // ascending order: take from the end
      values(k) = es.eigenvalues()(N - 1 - k);
      vectors.col(k) = es.eigenvectors().col(N - 1 - k);
    }
  }
  for (int k = 0; k < dims; ++k) {
    Eigen::Index imax = 0;
    vectors.col(k).cwiseAbs().maxCoeff(&imax);
    const double sign = vectors(imax, k) < 0.0 ? -1.0 : 1.0;
    out.coordinates.col(k) = sign * std::sqrt(std::max(values(k), 0.0)) * vectors.col(k);
  }
  out.eigenvalues = values;
  const double trace = B.trace();
  out.explained = trace > 0.0 ? values.cwiseMax(0.0).sum() / trace : 1.0;
  return out;
}

MdsResult classical_mds_from_similarity(const Eigen::MatrixXd& similarity, int dims) {
  require(similarity.rows() == similarity.cols(), "classical_mds_from_similarity: a square matrix expected");
  Eigen::MatrixXd D = Eigen::MatrixXd::Ones(similarity.rows(), similarity.cols()) - similarity;
  D.diagonal().setZero();
  return classical_mds(D, dims);
}

}  // namespace ek
