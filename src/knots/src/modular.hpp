#pragma once
// Private: arithmetic modulo primes below 2^62, dense determinants,
// interpolation and Chinese remaindering for exact polynomial invariants.
#include <cstdint>
#include <vector>

#include "ek/core/int128.hpp"

namespace ek::modular {

struct Prime {
  std::uint64_t p;
  bool mersenne61;  // p = 2^61 - 1: reduction without division

  std::uint64_t reduce(uint128 x) const {
    if (mersenne61) {
      std::uint64_t lo = static_cast<std::uint64_t>(x & p) + static_cast<std::uint64_t>(x >> 61);
      // x < p² < 2^122, so x >> 61 < 2^61 and the sum < 2^62: subtract twice at most
      lo = (lo & p) + (lo >> 61);
      return lo >= p ? lo - p : lo;
    }
    return static_cast<std::uint64_t>(x % p);
  }
  std::uint64_t mul(std::uint64_t a, std::uint64_t b) const {
    return reduce(static_cast<uint128>(a) * b);
  }
  std::uint64_t add(std::uint64_t a, std::uint64_t b) const {
    std::uint64_t s = a + b;
    return s >= p ? s - p : s;
  }
  std::uint64_t sub(std::uint64_t a, std::uint64_t b) const { return a >= b ? a - b : a + p - b; }
  std::uint64_t from_signed(std::int64_t c) const {
    if (c >= 0) return static_cast<std::uint64_t>(c) % p;
    std::uint64_t m = static_cast<std::uint64_t>(-(c + 1)) % p;  // avoids overflow at INT64_MIN
    return sub(p - 1, m);
  }
  std::uint64_t pow(std::uint64_t a, std::uint64_t e) const {
    std::uint64_t r = 1;
    while (e) {
      if (e & 1) r = mul(r, a);
      a = mul(a, a);
      e >>= 1;
    }
    return r;
  }
  std::uint64_t inverse(std::uint64_t a) const { return pow(a, p - 2); }
};

/// Primes whose product exceeds 2^bits (first is 2^61 - 1).
std::vector<Prime> primes_for_bound(double bits);

/// Determinant of the m by m row-major matrix A modulo the prime (A is destroyed).
std::uint64_t determinant(std::vector<std::uint64_t>& A, int m, const Prime& prime);

/// Coefficients (lowest first) of the polynomial of degree < xs.size() through (xs, ys).
std::vector<std::uint64_t> interpolate(const std::vector<std::uint64_t>& xs, const std::vector<std::uint64_t>& ys,
                                       const Prime& prime);

/// Combines residues (one vector per prime, equal lengths) into integers in
/// the symmetric range; throws std::overflow_error beyond 64 bits.
std::vector<std::int64_t> crt_symmetric(const std::vector<std::vector<std::uint64_t>>& residues,
                                        const std::vector<Prime>& primes);

}  // namespace ek::modular
