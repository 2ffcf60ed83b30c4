#pragma once
/// \file
/// Exact integer polynomials for knot invariants.
#include <cstdint>
#include <string>
#include <vector>

namespace ek {

/// Alexander polynomial Δ(t) in normal form: integer coefficients from the
/// lowest to the highest degree, the lowest coefficient nonzero (the factor
/// t^k is removed), palindromic for a knot, and Δ(1) = +1.
/// Examples: unknot [1], 3_1 [1, -1, 1], 4_1 [-1, 3, -1].
struct AlexanderPolynomial {
  std::vector<std::int64_t> coefficients{1};  ///< Lowest degree first; [1] (the unknot) by default.

  /// |Δ(-1)|, the knot determinant (odd for a knot).
  std::int64_t determinant() const;
  /// Degree span (highest minus lowest degree) = 2·genus lower bound.
  int span() const { return static_cast<int>(coefficients.size()) - 1; }
  bool palindromic() const;  ///< Whether the coefficients read the same backwards (Δ(t) = Δ(1/t) up to t^k).
  /// "[1, -1, 1]"
  std::string to_string() const;
  /// Equal coefficient lists (both in normal form: the same polynomial).
  bool operator==(const AlexanderPolynomial& o) const { return coefficients == o.coefficients; }
  bool operator!=(const AlexanderPolynomial& o) const { return !(*this == o); }  ///< Different coefficient lists.
};

/// Removes the zero coefficients at both ends (the factor t^k and the unused
/// top degrees); the zero polynomial becomes empty.
void strip_zeros(std::vector<std::int64_t>& coefficients);

/// "[1, -1, 1]", "[]" for none: how polynomials print.
std::string coefficients_string(const std::vector<std::int64_t>& coefficients);

/// Normal form of a Laurent polynomial equal to ±t^k Δ(t): strips zero
/// coefficients at both ends and fixes the sign so that the value at t = 1 is
/// positive. Throws std::invalid_argument for the zero polynomial.
AlexanderPolynomial normalize_alexander(std::vector<std::int64_t> coefficients);

/// A matrix entry that is a Laurent polynomial Σ_k coeffs[k] t^(low + k).
struct PolyEntry {
  ///@{
  /// Position in the matrix (0-based).
  int row = 0, col = 0;
  ///@}
  int low = 0;                       ///< Degree of coeffs[0] (may be negative).
  std::vector<std::int64_t> coeffs;  ///< Coefficients of t^low, t^(low+1), ...
};

/// Exact determinant of the m by m matrix whose nonzero entries are listed
/// (entries at the same position add up), as a Laurent polynomial
/// Σ_k out[k] t^(low_out + k).
///
/// Method: evaluation at D + 1 points and interpolation, modulo as many
/// 60-bit primes as the Hadamard bound on the coefficients requires
/// (|coefficient| <= max_{|t|=1} |det| <= Π_rows ||row||₂), then Chinese
/// remaindering into the symmetric range. Exact; throws std::overflow_error if
/// a coefficient does not fit in 64 bits.
std::vector<std::int64_t> polynomial_determinant(int m, const std::vector<PolyEntry>& entries, int* low_out);

/// Exact division of integer polynomials (lowest degree first); throws
/// std::domain_error if the remainder is not zero.
std::vector<std::int64_t> exact_divide(const std::vector<std::int64_t>& num, const std::vector<std::int64_t>& den);

}  // namespace ek
