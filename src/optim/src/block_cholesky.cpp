#include "ek/optim/block_cholesky.hpp"

#include <amd.h>

#include <algorithm>
#include <cmath>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

using Mat3 = Eigen::Matrix3d;
using Vec3d = Eigen::Vector3d;

/// Lower Cholesky factor of the symmetric 3 × 3 matrix d (its lower
/// triangle is read) and that factor's inverse; false at a pivot <= 0.
bool cholesky3(const Mat3& d, Mat3& inverse) {
  const double a00 = d(0, 0);
  if (!(a00 > 0.0)) return false;
  const double l00 = std::sqrt(a00), l10 = d(1, 0) / l00, l20 = d(2, 0) / l00;
  const double a11 = d(1, 1) - l10 * l10;
  if (!(a11 > 0.0)) return false;
  const double l11 = std::sqrt(a11), l21 = (d(2, 1) - l20 * l10) / l11;
  const double a22 = d(2, 2) - l20 * l20 - l21 * l21;
  if (!(a22 > 0.0)) return false;
  const double l22 = std::sqrt(a22);
  const double i00 = 1.0 / l00, i11 = 1.0 / l11, i22 = 1.0 / l22;
  const double i10 = -l10 * i00 * i11, i21 = -l21 * i11 * i22;
  const double i20 = -(l20 * i00 + l21 * i10) * i22;
  inverse << i00, 0.0, 0.0, i10, i11, 0.0, i20, i21, i22;
  return true;
}

}  // namespace

long long BlockCholesky::factor_blocks() const { return static_cast<long long>(col_row_.size()) + nb_; }

// The block graph of H (old block indices, both triangles, no diagonal) in
// CSR form, for AMD; every block pair (i < j) is one edge, and each stored
// value of H remembers its edge (-1 inside a diagonal block). H's upper
// triangle has r <= c, hence block(r) <= block(c): a pair is met only in the
// block column of its larger index.
void BlockCholesky::block_pattern(const Matrix& upper) {
  n_ = static_cast<int>(upper.rows());
  nb_ = (n_ + 2) / 3;
  const int* p = upper.outerIndexPtr();
  const int* r = upper.innerIndexPtr();
  edge_lo_.clear();
  edge_hi_.clear();
  entry_edge_.resize(static_cast<size_t>(upper.nonZeros()));
  mark_.assign(nb_, -1);
  last_edge_.resize(nb_);
  for (int bc = 0; bc < nb_; ++bc)
    for (int c = 3 * bc; c < std::min(3 * bc + 3, n_); ++c)
      for (int q = p[c]; q < p[c + 1]; ++q) {
        const int br = r[q] / 3;
        if (br == bc) {
          entry_edge_[q] = -1;
          continue;
        }
        if (mark_[br] != bc) {
          mark_[br] = bc;
          last_edge_[br] = static_cast<int>(edge_lo_.size());
          edge_lo_.push_back(br);
          edge_hi_.push_back(bc);
        }
        entry_edge_[q] = last_edge_[br];
      }
  adj_ptr_.assign(nb_ + 1, 0);
  for (size_t e = 0; e < edge_lo_.size(); ++e) {
    ++adj_ptr_[edge_lo_[e] + 1];
    ++adj_ptr_[edge_hi_[e] + 1];
  }
  for (int b = 0; b < nb_; ++b) adj_ptr_[b + 1] += adj_ptr_[b];
  adj_.resize(2 * edge_lo_.size());
  std::vector<int>& next = last_edge_;
  std::copy(adj_ptr_.begin(), adj_ptr_.end() - 1, next.begin());
  for (size_t e = 0; e < edge_lo_.size(); ++e) {
    adj_[next[edge_lo_[e]]++] = edge_hi_[e];
    adj_[next[edge_hi_[e]]++] = edge_lo_[e];
  }
}

void BlockCholesky::order() {
  perm_.resize(nb_);
  if (adj_.empty()) {  // a block-diagonal matrix: any order (AMD rejects an empty pattern)
    for (int k = 0; k < nb_; ++k) perm_[k] = k;
  } else {
    double info[AMD_INFO];
    const int status = amd_order(nb_, adj_ptr_.data(), adj_.data(), perm_.data(), nullptr, info);
    require(status == AMD_OK || status == AMD_OK_BUT_JUMBLED, "BlockCholesky: AMD ordering failed");
  }
  inverse_.resize(nb_);
  ++ordering_count_;
  for (int k = 0; k < nb_; ++k) inverse_[perm_[k]] = k;
}

// A = P H Pᵀ by block columns: the diagonal block first, then the rows
// j < k (in no particular order); each edge's block slot.
void BlockCholesky::permuted_pattern() {
  acol_ptr_.assign(nb_ + 1, 0);
  for (size_t e = 0; e < edge_lo_.size(); ++e)
    ++acol_ptr_[std::max(inverse_[edge_lo_[e]], inverse_[edge_hi_[e]]) + 1];
  for (int k = 0; k < nb_; ++k) acol_ptr_[k + 1] += acol_ptr_[k] + 1;  // + the diagonal block
  acol_row_.resize(acol_ptr_[nb_]);
  edge_slot_.resize(edge_lo_.size());
  std::vector<int>& next = last_edge_;
  for (int k = 0; k < nb_; ++k) {
    acol_row_[acol_ptr_[k]] = k;
    next[k] = acol_ptr_[k] + 1;
  }
  for (size_t e = 0; e < edge_lo_.size(); ++e) {
    const int a = inverse_[edge_lo_[e]], b = inverse_[edge_hi_[e]];
    const int slot = next[std::max(a, b)]++;
    acol_row_[slot] = std::min(a, b);
    edge_slot_[e] = slot;
  }
}

// Liu's algorithm with path compression (ancestor links).
void BlockCholesky::elimination_tree() {
  parent_.assign(nb_, -1);
  std::vector<int> ancestor(nb_, -1);
  for (int k = 0; k < nb_; ++k)
    for (int q = acol_ptr_[k] + 1; q < acol_ptr_[k + 1]; ++q)
      for (int i = acol_row_[q]; i != -1 && i < k;) {
        const int next = ancestor[i];
        ancestor[i] = k;
        if (next == -1) parent_[i] = k;
        i = next;
      }
}

// Row k of L holds the nodes on the elimination-tree paths from A's entries
// j < k of column k up to k (the paths stop at nodes already met). They are
// listed children before parents, a topological order as the up-looking
// factorisation needs: each path is appended parent first, a later path
// joins an earlier one below its nodes, and the whole row is reversed (the
// order of CSparse's ereach). Then the column structure, rows increasing,
// and where each L_kj is stored.
void BlockCholesky::row_patterns() {
  mark_.assign(nb_, -1);
  std::vector<int>& count = last_edge_;
  std::fill(count.begin(), count.end(), 0);
  row_ptr_.assign(nb_ + 1, 0);
  row_col_.clear();
  path_.resize(nb_);
  for (int k = 0; k < nb_; ++k) {
    mark_[k] = k;
    const size_t start = row_col_.size();
    for (int q = acol_ptr_[k] + 1; q < acol_ptr_[k + 1]; ++q) {
      int len = 0;  // the path from A's entry up to a marked node
      for (int i = acol_row_[q]; mark_[i] != k; i = parent_[i]) {
        mark_[i] = k;
        path_[len++] = i;
      }
      while (len > 0) {
        const int i = path_[--len];
        row_col_.push_back(i);
        ++count[i];
      }
    }
    std::reverse(row_col_.begin() + static_cast<std::ptrdiff_t>(start), row_col_.end());
    row_ptr_[k + 1] = static_cast<int>(row_col_.size());
  }
  col_ptr_.assign(nb_ + 1, 0);
  for (int j = 0; j < nb_; ++j) col_ptr_[j + 1] = col_ptr_[j] + count[j];
  std::vector<int>& next = count;
  std::copy(col_ptr_.begin(), col_ptr_.end() - 1, next.begin());
  col_row_.resize(row_col_.size());
  row_pos_.resize(row_col_.size());
  for (int k = 0; k < nb_; ++k)
    for (int p = row_ptr_[k]; p < row_ptr_[k + 1]; ++p) {
      const int pos = next[row_col_[p]]++;
      col_row_[pos] = k;
      row_pos_[p] = pos;
    }
}

// Where each stored value of H goes among A's blocks (9 values each,
// column-major): entry (r, c), r <= c, is A(j, k)(a, b) with j, k the
// permuted blocks of r and c, transposed when j > k; inside a diagonal
// block also at its mirror position.
void BlockCholesky::gather_map(const Matrix& upper) {
  const int* p = upper.outerIndexPtr();
  const int* r = upper.innerIndexPtr();
  dst_.resize(static_cast<size_t>(upper.nonZeros()));
  mirror_.assign(static_cast<size_t>(upper.nonZeros()), -1);
  for (int c = 0; c < n_; ++c)
    for (int q = p[c]; q < p[c + 1]; ++q) {
      const int a = r[q] % 3, b = c % 3, edge = entry_edge_[q];
      if (edge < 0) {
        const int e = acol_ptr_[inverse_[c / 3]];
        dst_[q] = 9 * e + a + 3 * b;
        if (a != b) mirror_[q] = 9 * e + b + 3 * a;
        continue;
      }
      const bool transposed = inverse_[r[q] / 3] > inverse_[c / 3];
      dst_[q] = 9 * edge_slot_[edge] + (transposed ? b + 3 * a : a + 3 * b);
    }
}

void BlockCholesky::analyse(const Matrix& upper, bool reuse_ordering, double reorder_fill_growth) {
  require(upper.rows() == upper.cols() && upper.isCompressed(), "BlockCholesky: matrix must be square and compressed");
  const int old_blocks = nb_;
  block_pattern(upper);
  const bool fresh = !reuse_ordering || nb_ != old_blocks || static_cast<int>(perm_.size()) != nb_;
  if (fresh) order();
  symbolic(upper);
  if (!fresh && static_cast<double>(factor_blocks()) > (1.0 + reorder_fill_growth) * static_cast<double>(ordered_fill_)) {
    order();
    symbolic(upper);
    ordered_fill_ = factor_blocks();
    return;
  }
  if (fresh) ordered_fill_ = factor_blocks();
}

void BlockCholesky::symbolic(const Matrix& upper) {
  ++symbolic_count_;
  permuted_pattern();
  elimination_tree();
  row_patterns();
  gather_map(upper);
  a_.assign(9 * acol_row_.size(), 0.0);
  L_.assign(col_row_.size(), Mat3::Zero());
  spare_L_.assign(col_row_.size(), Mat3::Zero());
  Dinv_.assign(nb_, Mat3::Zero());
  spare_Dinv_.assign(nb_, Mat3::Zero());
  work_.assign(nb_, Mat3::Zero());
  good_ = false;
}

bool BlockCholesky::factor_row(int k, std::vector<Mat3>& L, std::vector<Mat3>& Dinv) {
  std::vector<Mat3>& x = work_;
  const int r0 = row_ptr_[k], r1 = row_ptr_[k + 1];
  for (int p = r0; p < r1; ++p) x[row_col_[p]].setZero();
  const int a0 = acol_ptr_[k];
  Mat3 d = Eigen::Map<const Mat3>(&a_[9 * a0]);
  for (int q = a0 + 1; q < acol_ptr_[k + 1]; ++q)  // A_kj = A(j, k)ᵀ
    x[acol_row_[q]] = Eigen::Map<const Mat3>(&a_[9 * q]).transpose();
  for (int p = r0; p < r1; ++p) {
    const int j = row_col_[p], pos = row_pos_[p];
    const Mat3 Lkj = x[j] * Dinv[j].transpose();
    for (int q = col_ptr_[j]; q < pos; ++q)
      x[col_row_[q]].noalias() -= Lkj * L[q].transpose();
    d.noalias() -= Lkj * Lkj.transpose();
    L[pos] = Lkj;
  }
  if (cholesky3(d, Dinv[k])) return true;
  failed_pivot_ = d;
  return false;
}

// The failure's lower bound on the missing shift (file comment): with the
// spare factor's rows 0..k (row k's off-diagonal blocks are complete when
// its pivot block fails), y = L₁₁⁻ᵀ L_kᵀ v by back substitution, and
// |μ| / (1 + ‖y‖²).
double BlockCholesky::deficit_at(int k) const {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(failed_pivot_);
  if (eig.info() != Eigen::Success) return 0.0;
  const double mu = eig.eigenvalues()(0);
  if (!(mu < 0.0)) return 0.0;  // positive definite but for round-off: nothing proven
  const Vec3d v = eig.eigenvectors().col(0);
  std::vector<Vec3d> y(static_cast<size_t>(k), Vec3d::Zero());
  for (int p = row_ptr_[k]; p < row_ptr_[k + 1]; ++p) y[row_col_[p]] = spare_L_[row_pos_[p]].transpose() * v;
  double norm2 = 1.0;
  for (int j = k - 1; j >= 0; --j) {  // L₁₁ᵀ y = r, rows j of L₁₁ᵀ are L's column j
    Vec3d r = y[j];
    for (int q = col_ptr_[j]; q < col_ptr_[j + 1] && col_row_[q] < k; ++q)
      r.noalias() -= spare_L_[q].transpose() * y[col_row_[q]];
    y[j] = spare_Dinv_[j].transpose() * r;
    norm2 += y[j].squaredNorm();
  }
  return std::isfinite(norm2) ? -mu / norm2 : 0.0;
}

bool BlockCholesky::factorize(const Matrix& upper, double shift) {
  require(upper.rows() == n_ && static_cast<size_t>(upper.nonZeros()) == dst_.size(),
          "BlockCholesky::factorize: the matrix does not have the analysed pattern");
  std::fill(a_.begin(), a_.end(), 0.0);
  const double* v = upper.valuePtr();
  for (size_t q = 0; q < dst_.size(); ++q) {
    a_[dst_[q]] += v[q];
    if (mirror_[q] >= 0) a_[mirror_[q]] += v[q];
  }
  for (int b = 0; b < nb_; ++b) {
    double* diag = &a_[9 * acol_ptr_[inverse_[b]]];
    for (int a = 0; a < 3; ++a) diag[4 * a] += 3 * b + a < n_ ? shift : 1.0;  // padding rows: identity
  }
  deficit_ = 0.0;
  for (int k = 0; k < nb_; ++k)
    if (!factor_row(k, spare_L_, spare_Dinv_)) {
      deficit_ = deficit_at(k);
      return false;
    }
  std::swap(L_, spare_L_);
  std::swap(Dinv_, spare_Dinv_);
  good_ = true;
  return true;
}

VecX BlockCholesky::solve(const VecX& b) const {
  require(good_, "BlockCholesky::solve: no successful factorisation");
  require(b.size() == n_, "BlockCholesky::solve: right-hand side has the wrong size");
  std::vector<Vec3d> y(nb_, Vec3d::Zero());
  for (int s = 0; s < n_; ++s) y[inverse_[s / 3]](s % 3) = b(s);
  for (int k = 0; k < nb_; ++k) {  // L z = P b
    Vec3d v = y[k];
    for (int p = row_ptr_[k]; p < row_ptr_[k + 1]; ++p)
      v.noalias() -= L_[row_pos_[p]] * y[row_col_[p]];
    y[k] = Dinv_[k] * v;
  }
  for (int k = nb_ - 1; k >= 0; --k) {  // Lᵀ x = z
    Vec3d v = y[k];
    for (int q = col_ptr_[k]; q < col_ptr_[k + 1]; ++q)
      v.noalias() -= L_[q].transpose() * y[col_row_[q]];
    y[k] = Dinv_[k].transpose() * v;
  }
  VecX x(n_);
  for (int s = 0; s < n_; ++s) x(s) = y[inverse_[s / 3]](s % 3);
  return x;
}

}  // namespace ek
