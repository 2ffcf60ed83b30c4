#include "ek/knots/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ek/core/errors.hpp"
#include "modular.hpp"

namespace ek {

std::int64_t AlexanderPolynomial::determinant() const {
  int128 v = 0, sign = 1;
  for (auto c : coefficients) {
    v += sign * c;
    sign = -sign;
  }
  if (v < 0) v = -v;
  if (v > INT64_MAX) throw std::overflow_error("knot determinant does not fit in 64 bits");
  return static_cast<std::int64_t>(v);
}

bool AlexanderPolynomial::palindromic() const {
  return std::equal(coefficients.begin(), coefficients.end(), coefficients.rbegin());
}

std::string AlexanderPolynomial::to_string() const { return coefficients_string(coefficients); }

void strip_zeros(std::vector<std::int64_t>& c) {
  while (!c.empty() && c.back() == 0) c.pop_back();
  c.erase(c.begin(), std::find_if(c.begin(), c.end(), [](std::int64_t x) { return x != 0; }));
}

std::string coefficients_string(const std::vector<std::int64_t>& coefficients) {
  std::string s = "[";
  for (size_t i = 0; i < coefficients.size(); ++i) s += (i ? ", " : "") + std::to_string(coefficients[i]);
  return s + "]";
}

AlexanderPolynomial normalize_alexander(std::vector<std::int64_t> c) {
  strip_zeros(c);
  require(!c.empty(), "normalize_alexander: the polynomial is zero (not a knot)");
  int128 at_one = 0;
  for (auto x : c) at_one += x;
  if (at_one < 0)
    for (auto& x : c) x = -x;
  AlexanderPolynomial p;
  p.coefficients = std::move(c);
  return p;
}

std::vector<std::int64_t> exact_divide(const std::vector<std::int64_t>& num, const std::vector<std::int64_t>& den) {
  std::vector<int128> r(num.begin(), num.end());
  int dn = static_cast<int>(den.size()) - 1;
  while (dn >= 0 && den[static_cast<size_t>(dn)] == 0) --dn;
  require(dn >= 0, "exact_divide: division by zero polynomial");
  const int128 lead = den[static_cast<size_t>(dn)];
  int nn = static_cast<int>(r.size()) - 1;
  while (nn >= 0 && r[static_cast<size_t>(nn)] == 0) --nn;
  if (nn < dn) {
    if (nn >= 0) throw std::domain_error("exact_divide: nonzero remainder");
    return {0};
  }
  std::vector<std::int64_t> q(static_cast<size_t>(nn - dn + 1), 0);
  for (int k = nn - dn; k >= 0; --k) {
    const int128 top = r[static_cast<size_t>(k + dn)];
    if (top % lead != 0) throw std::domain_error("exact_divide: nonzero remainder");
    const int128 f = top / lead;
    if (f > INT64_MAX || f < INT64_MIN) throw std::overflow_error("exact_divide: quotient overflows");
    q[static_cast<size_t>(k)] = static_cast<std::int64_t>(f);
    for (int j = 0; j <= dn; ++j) r[static_cast<size_t>(k + j)] -= f * den[static_cast<size_t>(j)];
  }
  for (auto x : r)
    if (x != 0) throw std::domain_error("exact_divide: nonzero remainder");
  return q;
}

std::vector<std::int64_t> polynomial_determinant(int m, const std::vector<PolyEntry>& entries, int* low_out) {
  require(m >= 0, "polynomial_determinant: negative size");
  if (m == 0) {
    if (low_out) *low_out = 0;
    return {1};
  }
  // Degree range per row, and the Hadamard bound (log2) per row: on |t| = 1,
  // |Σ_j a_j(t)|... bounded by the L1 norms of the entries' coefficients.
  std::vector<int> row_lo(static_cast<size_t>(m), INT32_MAX), row_hi(static_cast<size_t>(m), INT32_MIN);
  std::vector<std::vector<std::pair<int, double>>> row_l1(static_cast<size_t>(m));
  for (const auto& e : entries) {
    require(e.row >= 0 && e.row < m && e.col >= 0 && e.col < m, "polynomial_determinant: entry out of range");
    if (e.coeffs.empty()) continue;
    auto& lo = row_lo[static_cast<size_t>(e.row)];
    auto& hi = row_hi[static_cast<size_t>(e.row)];
    lo = std::min(lo, e.low);
    hi = std::max(hi, e.low + static_cast<int>(e.coeffs.size()) - 1);
    double l1 = 0.0;
    for (auto c : e.coeffs) l1 += std::fabs(static_cast<double>(c));
    auto& cols = row_l1[static_cast<size_t>(e.row)];
    bool merged = false;
    for (auto& [col, v] : cols)
      if (col == e.col) {
        v += l1;
        merged = true;
      }
    if (!merged) cols.emplace_back(e.col, l1);
  }
  int low = 0, degree = 0;
  double log2_bound = 0.0;
  for (int i = 0; i < m; ++i) {
    if (row_lo[static_cast<size_t>(i)] == INT32_MAX) {  // zero row
      if (low_out) *low_out = 0;
      return {0};
    }
    low += row_lo[static_cast<size_t>(i)];
    degree += row_hi[static_cast<size_t>(i)] - row_lo[static_cast<size_t>(i)];
    double sq = 0.0;
    for (auto& [col, v] : row_l1[static_cast<size_t>(i)]) sq += v * v;
    log2_bound += 0.5 * std::log2(std::max(sq, 1.0));
  }
  if (low_out) *low_out = low;
  // Residues of every coefficient for each prime, then CRT.
  const auto primes = modular::primes_for_bound(log2_bound + 2.0);
  std::vector<std::vector<std::uint64_t>> residues;
  for (const auto& prime : primes) {
    std::vector<std::uint64_t> xs, ys;
    std::vector<std::uint64_t> A(static_cast<size_t>(m) * static_cast<size_t>(m));
    for (int k = 0; static_cast<int>(xs.size()) < degree + 1; ++k) {
      const std::uint64_t t = static_cast<std::uint64_t>(k) + 2;
      const std::uint64_t tinv = prime.inverse(t);
      std::fill(A.begin(), A.end(), 0);
      for (const auto& e : entries) {
        if (e.coeffs.empty()) continue;
        // value of t^(e.low - row_lo) Σ c_k t^k, so each row is a polynomial
        std::uint64_t power = 1, v = 0;
        const int shift = e.low - row_lo[static_cast<size_t>(e.row)];
        std::uint64_t base = shift >= 0 ? t : tinv;
        for (int s = 0; s < std::abs(shift); ++s) power = prime.mul(power, base);
        for (auto c : e.coeffs) {
          v = prime.add(v, prime.mul(prime.from_signed(c), power));
          power = prime.mul(power, t);
        }
        auto& slot = A[static_cast<size_t>(e.row) * static_cast<size_t>(m) + static_cast<size_t>(e.col)];
        slot = prime.add(slot, v);
      }
      xs.push_back(t);
      ys.push_back(modular::determinant(A, m, prime));
    }
    residues.push_back(modular::interpolate(xs, ys, prime));
  }
  return modular::crt_symmetric(residues, primes);
}

}  // namespace ek
