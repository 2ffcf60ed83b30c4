#include "modular.hpp"

#include <stdexcept>
#include <utility>

namespace ek::modular {

std::vector<Prime> primes_for_bound(double bits) {
  // 2^61 - 1, 2^62 - 57, 2^60 - 93 (checked with Miller-Rabin), then further
  // primes below 2^60 found by trial division on demand.
  static const std::uint64_t known[] = {(1ULL << 61) - 1, (1ULL << 62) - 57, (1ULL << 60) - 93};
  std::vector<Prime> out;
  double have = 0.0;
  auto is_prime = [](std::uint64_t n) {
    Prime q{n, false};
    std::uint64_t d = n - 1;
    int s = 0;
    while (d % 2 == 0) {
      d /= 2;
      ++s;
    }
    for (std::uint64_t a : {2ULL, 3ULL, 5ULL, 7ULL, 11ULL, 13ULL, 17ULL, 19ULL, 23ULL, 29ULL, 31ULL, 37ULL}) {
      std::uint64_t x = q.pow(a, d);
      if (x == 1 || x == n - 1) continue;
      bool composite = true;
      for (int r = 1; r < s; ++r) {
        x = q.mul(x, x);
        if (x == n - 1) {
          composite = false;
          break;
        }
      }
      if (composite) return false;
    }
    return true;
  };
  size_t k = 0;
  std::uint64_t candidate = (1ULL << 60) - 95;
  while (have <= bits + 1.0) {
    std::uint64_t p;
    if (k < 3) {
      p = known[k++];
    } else {
      while (!is_prime(candidate)) candidate -= 2;
      p = candidate;
      candidate -= 2;
    }
    out.push_back(Prime{p, p == (1ULL << 61) - 1});
    have += 59.9;
  }
  return out;
}

std::uint64_t determinant(std::vector<std::uint64_t>& A, int m, const Prime& q) {
  std::uint64_t det = 1;
  const size_t M = static_cast<size_t>(m);
  for (size_t col = 0; col < M; ++col) {
    size_t piv = col;
    while (piv < M && A[piv * M + col] == 0) ++piv;
    if (piv == M) return 0;
    if (piv != col) {
      for (size_t j = col; j < M; ++j) std::swap(A[piv * M + j], A[col * M + j]);
      det = q.sub(0, det);
    }
    const std::uint64_t pv = A[col * M + col];
    det = q.mul(det, pv);
    const std::uint64_t inv = q.inverse(pv);
    for (size_t r = col + 1; r < M; ++r) {
      std::uint64_t f = A[r * M + col];
      if (f == 0) continue;
      f = q.mul(f, inv);
      for (size_t j = col + 1; j < M; ++j)
        if (A[col * M + j] != 0) A[r * M + j] = q.sub(A[r * M + j], q.mul(f, A[col * M + j]));
    }
  }
  return det;
}

std::vector<std::uint64_t> interpolate(const std::vector<std::uint64_t>& xs, const std::vector<std::uint64_t>& ys,
                                       const Prime& q) {
  const size_t n = xs.size();
  // Newton divided differences.
  std::vector<std::uint64_t> c(ys);
  for (size_t j = 1; j < n; ++j)
    for (size_t i = n - 1; i >= j; --i) {
      c[i] = q.mul(q.sub(c[i], c[i - 1]), q.inverse(q.sub(xs[i], xs[i - j])));
      if (i == j) break;
    }
  // Expand Σ c_j Π_{i<j} (t - x_i) by Horner from the top.
  std::vector<std::uint64_t> poly(n, 0);
  for (size_t j = n; j-- > 0;) {
    // poly = poly * (t - x_j) + c_j
    std::vector<std::uint64_t> next(n, 0);
    for (size_t k = 0; k + 1 < n; ++k) {
      next[k + 1] = q.add(next[k + 1], poly[k]);
      next[k] = q.sub(next[k], q.mul(poly[k], xs[j]));
    }
    next[0] = q.add(next[0], c[j]);
    poly.swap(next);
  }
  return poly;
}

std::vector<std::int64_t> crt_symmetric(const std::vector<std::vector<std::uint64_t>>& residues,
                                        const std::vector<Prime>& primes) {
  const size_t n = residues.front().size();
  std::vector<std::int64_t> out(n);
  for (size_t k = 0; k < n; ++k) {
    // Garner: x = a0 + a1 p0 + a2 p0 p1 + ..., mixed radix digits a_i < p_i.
    std::vector<std::uint64_t> digits;
    for (size_t i = 0; i < primes.size(); ++i) {
      const Prime& q = primes[i];
      std::uint64_t x = residues[i][k] % q.p;
      // subtract the value of the previous digits modulo p_i, divide by their radix
      std::uint64_t value = 0, radix = 1;
      for (size_t j = 0; j < digits.size(); ++j) {
        value = q.add(value, q.mul(digits[j] % q.p, radix));
        radix = q.mul(radix, primes[j].p % q.p);
      }
      x = q.mul(q.sub(x, value), q.inverse(radix));
      digits.push_back(x);
    }
    // Evaluate with 128-bit arithmetic; the symmetric lift: if x > P/2 use x - P.
    // Only values within 64 bits are accepted, which the first two digits decide
    // when more primes were used (the others must be 0 or all p_i - 1).
    long double approx = 0.0L, radix = 1.0L;
    for (size_t i = 0; i < digits.size(); ++i) {
      approx += static_cast<long double>(digits[i]) * radix;
      radix *= static_cast<long double>(primes[i].p);
    }
    const bool negative = approx > radix / 2;
    // Exact reconstruction of x, or of P - x = Σ (p_i - 1 - d_i) R_i + 1 when
    // x > P/2, in 128 bits. A value within 64 bits has zero digits beyond the
    // second (R_2 = p_0 p_1 > 2^120).
    uint128 mag = 0;
    bool fits = true;
    for (size_t i = 0; i < digits.size(); ++i) {
      const std::uint64_t d = negative ? (primes[i].p - 1 - digits[i]) : digits[i];
      if (i == 0) mag = d;
      else if (i == 1) mag += static_cast<uint128>(d) * primes[0].p;
      else if (d != 0) fits = false;
    }
    if (negative) mag += 1;
    if (!fits || mag > static_cast<uint128>(INT64_MAX))
      throw std::overflow_error("polynomial coefficient does not fit in 64 bits");
    out[k] = negative ? -static_cast<std::int64_t>(mag) : static_cast<std::int64_t>(mag);
  }
  return out;
}

}  // namespace ek::modular
