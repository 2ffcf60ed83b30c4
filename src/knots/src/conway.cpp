#include "ek/knots/conway.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

#include "ek/core/errors.hpp"
#include "ek/core/int128.hpp"
#include "ek/knots/alexander.hpp"

namespace ek {
namespace {

/// Arc of every visit, per component: a new arc starts at every under visit;
/// a component without one is a single arc.
std::vector<std::vector<int>> arcs_of(const LinkDiagram& d, int* count) {
  std::vector<std::vector<int>> arc(d.components.size());
  int id = 0;
  for (size_t k = 0; k < d.components.size(); ++k) {
    const auto& visits = d.components[k];
    const int n = static_cast<int>(visits.size());
    arc[k].assign(static_cast<size_t>(n), id);
    const auto first = std::find_if(visits.begin(), visits.end(), [](const auto& v) { return !v.over; });
    if (first == visits.end()) {
      ++id;
      continue;
    }
    const int start = static_cast<int>(first - visits.begin());
    --id;
    for (int j = 0; j < n; ++j) {
      const int p = (start + j) % n;
      if (!visits[static_cast<size_t>(p)].over) ++id;
      arc[k][static_cast<size_t>(p)] = id;
    }
    ++id;
  }
  *count = id;
  return arc;
}

/// (t + 1/t − 2)^j = Σ_{i=0}^{2j} C(2j, i) (−1)^i t^{j−i}: coefficient of t^e.
int128 z2_power_coefficient(int j, int e) {
  const int i = j - e;
  if (i < 0 || i > 2 * j) return 0;
  int128 binom = 1;
  for (int r = 1; r <= i; ++r) binom = binom * (2 * j - r + 1) / r;
  return (i % 2 == 0) ? binom : -binom;
}

}  // namespace

std::string ConwayPolynomial::to_string() const { return coefficients_string(coefficients); }

ConwayPolynomial conway_from_alexander(std::vector<std::int64_t> delta, int components) {
  require(components >= 1, "conway_from_alexander: a link has at least one component");
  strip_zeros(delta);
  ConwayPolynomial out;
  if (delta.empty()) return out;
  int odd = 0;  // 1 when Δ = (t − 1)·Δ' (an even number of components)
  if ((delta.size() - 1) % 2 == 1) {
    delta = exact_divide(delta, {-1, 1});
    strip_zeros(delta);
    odd = 1;
  }
  if (odd != (components - 1) % 2)
    throw std::logic_error("conway_from_alexander: Δ's degree does not fit a link of " + std::to_string(components) +
                           " components");
  // t^{-h}·Δ' (h = D/2) as Σ_j b_j (t + 1/t − 2)^j, peeled from the top degree.
  const int h = static_cast<int>(delta.size() - 1) / 2;
  std::vector<int128> rest(delta.begin(), delta.end());  // rest[e + h]: coefficient of t^e
  std::vector<int128> b(static_cast<size_t>(h + 1), 0);
  for (int j = h; j >= 0; --j) {
    b[static_cast<size_t>(j)] = rest[static_cast<size_t>(j + h)];
    for (int e = -j; e <= j; ++e) rest[static_cast<size_t>(e + h)] -= b[static_cast<size_t>(j)] * z2_power_coefficient(j, e);
  }
  if (std::any_of(rest.begin(), rest.end(), [](int128 x) { return x != 0; }))
    throw std::logic_error("conway_from_alexander: Δ is not symmetric, not the polynomial of a link");
  out.coefficients.assign(static_cast<size_t>(2 * h + 1 + odd), 0);
  for (int j = 0; j <= h; ++j) {
    const int128 v = b[static_cast<size_t>(j)];
    if (v > INT64_MAX || v < INT64_MIN) throw std::overflow_error("conway_from_alexander: coefficient overflow");
    out.coefficients[static_cast<size_t>(2 * j + odd)] = static_cast<std::int64_t>(v);
  }
  while (!out.coefficients.empty() && out.coefficients.back() == 0) out.coefficients.pop_back();
  const auto lowest = std::find_if(out.coefficients.begin(), out.coefficients.end(), [](std::int64_t x) { return x != 0; });
  if (*lowest < 0)
    for (auto& c : out.coefficients) c = -c;
  return out;
}

std::vector<std::int64_t> alexander_coefficients(const LinkDiagram& d) {
  const int c = d.crossings();
  if (c == 0) return d.components.size() == 1 ? std::vector<std::int64_t>{1} : std::vector<std::int64_t>{};
  int a = 0;
  const auto arc = arcs_of(d, &a);
  if (a - 1 > c) return {};  // two components without an under-crossing: split
  std::vector<int> under_arc_in(static_cast<size_t>(c)), under_arc_out(static_cast<size_t>(c)),
      over_arc(static_cast<size_t>(c));
  for (size_t k = 0; k < d.components.size(); ++k) {
    const auto& visits = d.components[k];
    const size_t n = visits.size();
    for (size_t p = 0; p < n; ++p) {
      const size_t x = static_cast<size_t>(visits[p].crossing);
      if (visits[p].over) {
        over_arc[x] = arc[k][p];
      } else {
        under_arc_in[x] = arc[k][(p + n - 1) % n];
        under_arc_out[x] = arc[k][p];
      }
    }
  }
  const int rows = a - 1;  // z = 0: drop the last row and column; z = 1: the last column
  std::vector<PolyEntry> entries;
  auto add = [&](int row, int col, int low, std::vector<std::int64_t> coeffs) {
    if (row < rows && col < a - 1) entries.push_back({row, col, low, std::move(coeffs)});
  };
  for (int x = 0; x < c; ++x) {
    const size_t xs = static_cast<size_t>(x);
    add(x, over_arc[xs], 0, {1, -1});
    const bool positive = d.signs[xs] > 0;
    add(x, under_arc_in[xs], positive ? 1 : 0, {positive ? 1 : -1});
    add(x, under_arc_out[xs], positive ? 0 : 1, {positive ? -1 : 1});
  }
  if (rows == 0) return {1};
  int low = 0;
  std::vector<std::int64_t> det = polynomial_determinant(rows, entries, &low);
  strip_zeros(det);
  return det;
}

ConwayPolynomial conway(const LinkDiagram& diagram) {
  return conway_from_alexander(alexander_coefficients(diagram), static_cast<int>(diagram.components.size()));
}

ConwayPolynomial conway(const Link& link, const ProjectionOptions& options) {
  return conway(link_diagram_from_curves(link, options));
}

ConwayPolynomial conway(const BraidWord& braid) {
  return conway_from_alexander(alexander_coefficients(braid), closure_components(braid));
}

std::optional<int> milnor_triple_linking(const ConwayPolynomial& conway, const Eigen::MatrixXi& linking) {
  if (linking.rows() != 3 || linking.cols() != 3 || linking.cwiseAbs().maxCoeff() != 0) return std::nullopt;
  const std::int64_t c4 = conway.coefficients.size() > 4 ? conway.coefficients[4] : 0;
  const auto root = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(c4))));
  if (c4 < 0 || root * root != c4)
    throw std::logic_error("milnor_triple_linking: c_4 = " + std::to_string(c4) +
                           " is not a square, so the polynomial is not of a link with vanishing linking numbers");
  return static_cast<int>(root);
}

std::int64_t hoste_coefficient(const Eigen::MatrixXi& linking) {
  const Eigen::Index m = linking.rows();
  require(m >= 1 && linking.cols() == m, "hoste_coefficient: the linking matrix must be square");
  if (m == 1) return 1;
  Eigen::MatrixXd lambda = -linking.cast<double>();
  for (Eigen::Index i = 0; i < m; ++i) lambda(i, i) = linking.row(i).sum() - linking(i, i);
  return std::llround(lambda.topLeftCorner(m - 1, m - 1).determinant());
}

}  // namespace ek
