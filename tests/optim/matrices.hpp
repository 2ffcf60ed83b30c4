#pragma once
// Matrices with known spectra for the tests of the numerics.
#include <Eigen/Sparse>

#include "ek/core/sparse_assembler.hpp"

namespace ek::test_matrices {

/// The upper triangle of the n × n tridiagonal matrix tridiag(−1, d, −1):
/// eigenvalues d − 2 cos(k π / (n + 1)), k = 1..n.
inline Eigen::SparseMatrix<double, Eigen::ColMajor, int> tridiagonal(int n, double d) {
  SparseAssembler A;
  A.begin(n);
  for (int i = 0; i < n; ++i) {
    A.add(i, i, d);
    if (i + 1 < n) A.add(i, i + 1, -1.0);
  }
  A.end();
  return A.matrix();
}

}  // namespace ek::test_matrices
