#include "ek/optim/cholesky.hpp"

#include <cholmod.h>

#include <cmath>
#include <string>
#include <utility>

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"

namespace ek {

struct CholeskySolver::Cholmod {
  cholmod_common c;
  cholmod_factor* L = nullptr;      // the current factor (the last successful factorisation)
  cholmod_factor* spare = nullptr;  // same symbolic analysis; each factorisation is computed here first
  cholmod_dense* X = nullptr;  // solve2 workspaces, reused
  cholmod_dense* Y = nullptr;
  cholmod_dense* E = nullptr;
  Cholmod() {
    cholmod_start(&c);
    c.print = 0;                         // failures are expected (indefinite H) and handled: no stderr noise
    c.error_handler = nullptr;
    c.quick_return_if_not_posdef = 1;    // stop at the first non-positive pivot
    c.final_ll = 1;                      // LL' directly (no LDL' and conversion)
    c.final_asis = 1;
  }
  ~Cholmod() {
    if (L) cholmod_free_factor(&L, &c);
    if (spare) cholmod_free_factor(&spare, &c);
    if (X) cholmod_free_dense(&X, &c);
    if (Y) cholmod_free_dense(&Y, &c);
    if (E) cholmod_free_dense(&E, &c);
    cholmod_finish(&c);
  }
};

namespace {


/// A cholmod_sparse header over compressed column arrays (no copy).
cholmod_sparse view(int n, const int* p, const int* i, const double* x, int stype) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(n);
  A.nzmax = static_cast<size_t>(p[n]);
  A.p = const_cast<int*>(p);
  A.i = const_cast<int*>(i);
  A.nz = nullptr;
  A.x = const_cast<double*>(x);
  A.z = nullptr;
  A.stype = stype;
  A.itype = CHOLMOD_INT;
  A.xtype = x ? CHOLMOD_REAL : CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

}  // namespace

CholeskySolver::CholeskySolver(CholeskyMode mode) : CholeskySolver(CholeskyOptions{mode}) {}

CholeskySolver::CholeskySolver(const CholeskyOptions& options) : options_(options), cm_(std::make_unique<Cholmod>()) {
  require(options.reorder_fill_growth >= 0.0, "CholeskySolver: reorder_fill_growth must be >= 0");
}

CholeskySolver::~CholeskySolver() = default;

long long CholeskySolver::factor_nonzeros() const {
  if (options_.mode == CholeskyMode::Block) return 9 * block_.factor_blocks();
  const cholmod_factor* L = cm_->L;
  if (!L) return 0;
  const int* count = static_cast<const int*>(L->ColCount);
  long long nnz = 0;
  for (size_t j = 0; j < L->n; ++j) nnz += count[j];
  return nnz;
}

void CholeskySolver::order(const Matrix& upper) {
  // AMD with elimination-tree postordering (CHOLMOD's default analysis) on the pattern of H.
  const int n = static_cast<int>(upper.rows());
  cholmod_sparse A = view(n, upper.outerIndexPtr(), upper.innerIndexPtr(), nullptr, 1);
  cholmod_common& c = cm_->c;
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_AMD;
  c.postorder = 1;
  c.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_factor* L = cholmod_analyze(&A, &c);
  require(L != nullptr, "CholeskySolver: CHOLMOD analysis failed (status " + std::to_string(c.status) + ")");
  const int* P = static_cast<const int*>(L->Perm);
  perm_.assign(P, P + n);
  cholmod_free_factor(&L, &c);
  inverse_.resize(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) inverse_[static_cast<size_t>(perm_[static_cast<size_t>(k)])] = k;
  ++ordering_count_;
}

void CholeskySolver::build_permuted_pattern(const Matrix& upper) {
  // Entry (i, j), i <= j, of H goes to (a, b) = (inverse[i], inverse[j]) of B,
  // stored at (min, max) for the upper triangle (simplicial) or (max, min) for
  // the lower one (supernodal: CHOLMOD then factorises it without transposing).
  // Two counting passes (by row, then stably by column) sort every column.
  const int n = static_cast<int>(upper.rows());
  const int nnz = static_cast<int>(upper.nonZeros());
  const bool lower = options_.mode == CholeskyMode::Supernodal;
  const int* p = upper.outerIndexPtr();
  const int* idx = upper.innerIndexPtr();
  std::vector<int> row(static_cast<size_t>(nnz)), col(static_cast<size_t>(nnz));
  for (int j = 0; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k) {
      const int a = inverse_[static_cast<size_t>(idx[k])], b = inverse_[static_cast<size_t>(j)];
      const int lo = std::min(a, b), hi = std::max(a, b);
      row[static_cast<size_t>(k)] = lower ? hi : lo;
      col[static_cast<size_t>(k)] = lower ? lo : hi;
    }
  std::vector<int> count(static_cast<size_t>(n) + 1, 0), by_row(static_cast<size_t>(nnz));
  for (int k = 0; k < nnz; ++k) ++count[static_cast<size_t>(row[static_cast<size_t>(k)]) + 1];
  for (int r = 0; r < n; ++r) count[static_cast<size_t>(r) + 1] += count[static_cast<size_t>(r)];
  for (int k = 0; k < nnz; ++k) by_row[static_cast<size_t>(count[static_cast<size_t>(row[static_cast<size_t>(k)])]++)] = k;
  Bp_.assign(static_cast<size_t>(n) + 1, 0);
  for (int k = 0; k < nnz; ++k) ++Bp_[static_cast<size_t>(col[static_cast<size_t>(k)]) + 1];
  for (int c = 0; c < n; ++c) Bp_[static_cast<size_t>(c) + 1] += Bp_[static_cast<size_t>(c)];
  std::vector<int> next(Bp_.begin(), Bp_.end() - 1);
  Bi_.resize(static_cast<size_t>(nnz));
  Bx_.assign(static_cast<size_t>(nnz), 0.0);
  slot_.resize(static_cast<size_t>(nnz));
  for (int k : by_row) {
    const int dst = next[static_cast<size_t>(col[static_cast<size_t>(k)])]++;
    Bi_[static_cast<size_t>(dst)] = row[static_cast<size_t>(k)];
    slot_[static_cast<size_t>(k)] = dst;
  }
}

void CholeskySolver::analyse(const Matrix& upper) {
  const int n = static_cast<int>(upper.rows());
  const bool fresh = !options_.reuse_ordering || reorder_ || static_cast<int>(perm_.size()) != n;
  if (fresh) order(upper);
  build_permuted_pattern(upper);
  cholmod_common& c = cm_->c;
  if (cm_->L) cholmod_free_factor(&cm_->L, &c);
  if (cm_->spare) cholmod_free_factor(&cm_->spare, &c);
  good_ = false;
  cholmod_sparse B = view(n, Bp_.data(), Bi_.data(), nullptr,
                          options_.mode == CholeskyMode::Supernodal ? -1 : 1);
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_NATURAL;
  c.postorder = 0;
  c.supernodal = options_.mode == CholeskyMode::Supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  cm_->L = cholmod_analyze(&B, &c);
  require(cm_->L != nullptr, "CholeskySolver: CHOLMOD analysis failed (status " + std::to_string(c.status) + ")");
  cm_->spare = cholmod_copy_factor(cm_->L, &c);
  require(cm_->spare != nullptr, "CholeskySolver: CHOLMOD could not copy the symbolic factor (out of memory)");
  ++symbolic_count_;
  const long long fill = factor_nonzeros();
  reorder_ = false;
  if (fresh) {
    ordered_fill_ = fill;
  } else if (static_cast<double>(fill) > (1.0 + options_.reorder_fill_growth) * static_cast<double>(ordered_fill_)) {
    reorder_ = true;  // the kept ordering fills too much for this pattern: order afresh
    analyse(upper);
  }
}

bool CholeskySolver::factorize(const Matrix& upper, double shift, std::uint64_t pattern_version) {
  if (upper.rows() != upper.cols()) require(false, "CholeskySolver::factorize: matrix must be square");
  if (!std::isfinite(shift)) require(false, "CholeskySolver::factorize: shift must be finite");
  if (!upper.isCompressed()) require(false, "CholeskySolver::factorize: matrix must be compressed");
  const double* v = upper.valuePtr();
  const Eigen::Index nnz = upper.nonZeros();
  bool finite = true;
  for (Eigen::Index k = 0; k < nnz; ++k) finite &= std::isfinite(v[k]);
  if (!finite) require(false, "CholeskySolver::factorize: matrix has a non-finite entry");
  ok_ = false;
  const int n = static_cast<int>(upper.rows());
  if (n == 0) return ok_ = true;
  if (options_.mode == CholeskyMode::Block) return factorize_block(upper, shift, pattern_version);
  if (pattern_version != analysed_version_ || upper.rows() != analysed_size_ ||
      static_cast<size_t>(nnz) != slot_.size()) {
    const Stopwatch t0;
    analyse(upper);
    analysed_version_ = pattern_version;
    analysed_size_ = upper.rows();
    symbolic_seconds_ += t0.seconds();
  }
  for (Eigen::Index k = 0; k < nnz; ++k) Bx_[static_cast<size_t>(slot_[static_cast<size_t>(k)])] = v[k];
  cholmod_common& c = cm_->c;
  cholmod_sparse B = view(n, Bp_.data(), Bi_.data(), Bx_.data(), options_.mode == CholeskyMode::Supernodal ? -1 : 1);
  double beta[2] = {shift, 0.0};
  cholmod_factorize_p(&B, beta, nullptr, 0, cm_->spare, &c);
  ++numeric_count_;
  ok_ = c.status == CHOLMOD_OK && cm_->spare->minor == cm_->spare->n;
  if (ok_) {
    std::swap(cm_->L, cm_->spare);  // the failed attempts in between never touch the good factor
    good_ = true;
    good_shift_ = shift;
  }
  return ok_;
}

bool CholeskySolver::factorize_block(const Matrix& upper, double shift, std::uint64_t pattern_version) {
  if (pattern_version != analysed_version_ || upper.rows() != analysed_size_ || upper.rows() != block_.size() ||
      static_cast<size_t>(upper.nonZeros()) != block_.pattern_nonzeros()) {
    const Stopwatch t0;
    const int symbolic = block_.symbolic_count(), orderings = block_.ordering_count();
    block_.analyse(upper, options_.reuse_ordering, options_.reorder_fill_growth);
    symbolic_count_ += block_.symbolic_count() - symbolic;
    ordering_count_ += block_.ordering_count() - orderings;
    good_ = false;
    analysed_version_ = pattern_version;
    analysed_size_ = upper.rows();
    symbolic_seconds_ += t0.seconds();
  }
  ++numeric_count_;
  ok_ = block_.factorize(upper, shift);
  if (ok_) {
    good_ = true;
    good_shift_ = shift;
  }
  return ok_;
}

double CholeskySolver::shift_deficit() const {
  return reports_shift_deficit() && !ok_ ? block_.shift_deficit() : 0.0;
}

bool CholeskySolver::recall(double shift) {
  if (!good_ || shift != good_shift_) return false;
  ok_ = true;
  return true;
}

VecX CholeskySolver::solve(const VecX& b) const {
  require(ok_, "CholeskySolver::solve: no successful factorisation");
  const Eigen::Index n = analysed_size_;
  require(b.size() == n, "CholeskySolver::solve: right-hand side has the wrong size");
  VecX x(n);
  if (n == 0) return x;
  if (options_.mode == CholeskyMode::Block) return block_.solve(b);
  work_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) work_(k) = b(perm_[static_cast<size_t>(k)]);
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(n);
  rhs.ncol = 1;
  rhs.nzmax = static_cast<size_t>(n);
  rhs.d = static_cast<size_t>(n);
  rhs.x = work_.data();
  rhs.z = nullptr;
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  const bool solved = cholmod_solve2(CHOLMOD_A, cm_->L, &rhs, nullptr, &cm_->X, nullptr, &cm_->Y, &cm_->E, &cm_->c);
  require(solved, "CholeskySolver::solve: CHOLMOD solve failed");
  const double* y = static_cast<const double*>(cm_->X->x);
  for (Eigen::Index k = 0; k < n; ++k) x(perm_[static_cast<size_t>(k)]) = y[k];
  return x;
}

}  // namespace ek
