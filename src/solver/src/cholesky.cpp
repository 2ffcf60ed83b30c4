#include "ek/solver/cholesky.hpp"

#include <cmath>

#include "ek/core/errors.hpp"

namespace ek {

CholeskySolver::CholeskySolver(CholeskyMode mode) {
  chol_.setMode(mode == CholeskyMode::Simplicial ? Eigen::CholmodSimplicialLLt : Eigen::CholmodSupernodalLLt);
  chol_.cholmod().print = 0;            // failures are expected (indefinite H) and handled: no stderr noise
  chol_.cholmod().error_handler = nullptr;
  chol_.cholmod().quick_return_if_not_posdef = 1;  // stop at the first non-positive pivot
}

bool CholeskySolver::factorize(const Matrix& upper, double shift, std::uint64_t pattern_version) {
  require(upper.rows() == upper.cols(), "CholeskySolver::factorize: matrix must be square");
  require(std::isfinite(shift), "CholeskySolver::factorize: shift must be finite");
  const double* v = upper.valuePtr();
  for (Eigen::Index k = 0; k < upper.nonZeros(); ++k)
    require(std::isfinite(v[k]), "CholeskySolver::factorize: matrix has a non-finite entry");
  if (pattern_version != analysed_version_ || upper.rows() != analysed_size_) {
    chol_.analyzePattern(upper);
    analysed_version_ = pattern_version;
    analysed_size_ = upper.rows();
    ++symbolic_count_;
  }
  chol_.setShift(shift);
  chol_.factorize(upper);
  ++numeric_count_;
  ok_ = (chol_.info() == Eigen::Success);
  return ok_;
}

VecX CholeskySolver::solve(const VecX& b) const {
  require(ok_, "CholeskySolver::solve: no successful factorisation");
  return chol_.solve(b);
}

}  // namespace ek
