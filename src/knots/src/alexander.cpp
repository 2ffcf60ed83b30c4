#include "ek/knots/alexander.hpp"

#include <algorithm>

#include "ek/core/errors.hpp"
#include "ek/core/int128.hpp"
#include "ek/knots/conway.hpp"

namespace ek {

AlexanderPolynomial alexander(GaussDiagram g) {
  simplify(g);
  // a knot's diagram is a link diagram of one component (conway.hpp: the same Fox matrix)
  return normalize_alexander(alexander_coefficients(LinkDiagram{{std::move(g.visits)}, std::move(g.signs)}));
}

AlexanderPolynomial alexander(const PDCode& pd) { return alexander(diagram_from_pd(pd)); }

AlexanderPolynomial alexander(const BraidWord& braid) {
  std::vector<std::int64_t> delta = alexander_coefficients(braid);
  require(!delta.empty(), "alexander(braid): det(I - ψ) vanished; the closure is not a knot");
  return normalize_alexander(std::move(delta));
}

std::vector<std::int64_t> alexander_coefficients(const BraidWord& braid) {
  const int n = braid.strands;
  require(n >= 1, "alexander: braid needs at least one strand");
  if (n == 1) return {1};
  const int d = n - 1;  // reduced Burau matrices are d by d
  const int L = braid.length();
  const int W = 2 * L + 1, off = L;  // coefficient slots per entry
  // B = ψ(β), product of generator matrices, row-major d*d entries of W slots.
  std::vector<int128> B(static_cast<size_t>(d * d * W), 0), T(B.size());
  auto at = [&](std::vector<int128>& M, int r, int c) { return &M[static_cast<size_t>((r * d + c) * W)]; };
  for (int i = 0; i < d; ++i) at(B, i, i)[off] = 1;
  // Generator block entries as (row, col, degree, coeff) in the d by d matrix.
  struct Mono {
    int r, c, deg;
    int coeff;
  };
  for (int letter : braid.letters) {
    const int i = std::abs(letter) - 1;  // σ_{i+1}, 0-based i in 0..n-2
    std::vector<Mono> G;
    // identity outside the block
    const int lo = std::max(0, i - 1), hi = std::min(d - 1, i + 1);
    for (int k = 0; k < d; ++k)
      if (k < lo || k > hi) G.push_back({k, k, 0, 1});
    if (d == 1) {
      G.push_back({0, 0, letter > 0 ? 1 : -1, -1});  // σ1 -> [-t], σ1^-1 -> [-1/t]
    } else if (i == 0) {
      // σ1 -> [[-t, 0], [1, 1]], inverse [[-1/t, 0], [1/t, 1]]
      if (letter > 0)
        G.insert(G.end(), {{0, 0, 1, -1}, {1, 0, 0, 1}, {1, 1, 0, 1}});
      else
        G.insert(G.end(), {{0, 0, -1, -1}, {1, 0, -1, 1}, {1, 1, 0, 1}});
    } else if (i == d - 1) {
      // σ_{n-1} -> [[1, t], [0, -t]] on rows/cols d-2, d-1; inverse [[1, 1], [0, -1/t]]
      const int a = d - 2, b = d - 1;
      if (letter > 0)
        G.insert(G.end(), {{a, a, 0, 1}, {a, b, 1, 1}, {b, b, 1, -1}});
      else
        G.insert(G.end(), {{a, a, 0, 1}, {a, b, 0, 1}, {b, b, -1, -1}});
    } else {
      // σ_i (1 < i+1 < n-1) -> block [[1, t, 0], [0, -t, 0], [0, 1, 1]] at rows i-1..i+1;
      // inverse [[1, 1, 0], [0, -1/t, 0], [0, 1/t, 1]]
      const int a = i - 1, b = i, c = i + 1;
      if (letter > 0)
        G.insert(G.end(), {{a, a, 0, 1}, {a, b, 1, 1}, {b, b, 1, -1}, {c, b, 0, 1}, {c, c, 0, 1}});
      else
        G.insert(G.end(), {{a, a, 0, 1}, {a, b, 0, 1}, {b, b, -1, -1}, {c, b, -1, 1}, {c, c, 0, 1}});
    }
    // T = B * G
    std::fill(T.begin(), T.end(), 0);
    for (const auto& g : G)
      for (int r = 0; r < d; ++r) {
        const int128* src = at(B, r, g.r);
        int128* dst = at(T, r, g.c);
        for (int k = 0; k < W; ++k) {
          if (src[k] == 0) continue;
          const int kk = k + g.deg;
          require(kk >= 0 && kk < W, "alexander(braid): degree out of range");
          dst[kk] += src[k] * g.coeff;
          require(dst[kk] < (static_cast<int128>(1) << 100) && dst[kk] > -(static_cast<int128>(1) << 100),
                  "alexander(braid): Burau coefficient overflow");
        }
      }
    B.swap(T);
  }
  // I - B as polynomial entries
  std::vector<PolyEntry> entries;
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < d; ++c) {
      const int128* src = at(B, r, c);
      int first = -1, last = -1;
      for (int k = 0; k < W; ++k) {
        int128 v = -src[k] + ((r == c && k == off) ? 1 : 0);
        if (v != 0) {
          if (first < 0) first = k;
          last = k;
        }
      }
      if (first < 0) continue;
      PolyEntry e;
      e.row = r;
      e.col = c;
      e.low = first - off;
      for (int k = first; k <= last; ++k) {
        int128 v = -src[k] + ((r == c && k == off) ? 1 : 0);
        require(v <= INT64_MAX && v >= INT64_MIN, "alexander(braid): Burau coefficient overflow");
        e.coeffs.push_back(static_cast<std::int64_t>(v));
      }
      entries.push_back(std::move(e));
    }
  int low = 0;
  auto det = polynomial_determinant(d, entries, &low);
  strip_zeros(det);
  if (det.empty()) return {};
  std::vector<std::int64_t> cyclotomic(static_cast<size_t>(n), 1);  // 1 + t + ... + t^{n-1}
  return exact_divide(det, cyclotomic);
}

AlexanderPolynomial alexander(const Points& curve, const ProjectionOptions& options) {
  return alexander(diagram_from_curve(curve, options));
}

void check_knot_type(const Points& curve, const AlexanderPolynomial& expected, const std::string& what) {
  const AlexanderPolynomial got = alexander(curve);
  if (got != expected)
    throw TopologyError(what + ": Alexander polynomial " + got.to_string() + " differs from the expected " +
                        expected.to_string() + " (the knot type changed)");
}

}  // namespace ek
