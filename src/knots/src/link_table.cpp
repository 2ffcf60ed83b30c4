#include "ek/knots/link_table.hpp"

#include <algorithm>

#include "ek/core/errors.hpp"

namespace ek {

Eigen::MatrixXi LinkRecord::linking_matrix() const {
  const int m = components();
  require(static_cast<int>(linking_numbers.size()) == m * m, "LinkRecord: " + name + " needs m² linking numbers");
  return Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(linking_numbers.data(), m, m);
}

std::optional<int> LinkRecord::milnor_triple() const { return milnor_triple_linking(conway, linking_matrix()); }

PDLinkCode LinkRecord::pd() const { return pd_from_braid(braid); }

const std::vector<LinkRecord>& link_table() {
  // Conway polynomials as the Knot Atlas and LinkInfo list them, and as
  // they follow by hand: T(2, n) from the skein relation
  // ∇(L+) − ∇(L−) = z∇(L0), ∇_n = ∇_{n−2} + z∇_{n−1} (∇_0 = 0, ∇_1 = 1);
  // T(3, 3) from Δ ≐ (t − 1)(t^{pq/d} − 1)^d / ((t^p − 1)(t^q − 1)),
  // d = gcd(p, q), which gives (t − 1)²(t² + t + 1), ∇ = 3z² + z⁴; the
  // connected sum's as the product of its summands' ((1 + z²)·z).
  static const std::vector<LinkRecord> table = {
      {"hopf", {"L2a1", "t2_2"}, "the Hopf link, T(2, 2)", 2, {2, {1, 1}}, {"0_1", "0_1"}, {0, 1, 1, 0}, {{0, 1}}},
      {"t2_4", {"L4a1"}, "the (2, 4) torus link", 4, {2, {1, 1, 1, 1}}, {"0_1", "0_1"}, {0, 2, 2, 0}, {{0, 2, 0, 1}}},
      {"whitehead", {"L5a1"}, "the Whitehead link", 5, {3, {1, -2, 1, -2, -2}}, {"0_1", "0_1"}, {0, 0, 0, 0},
       {{0, 0, 0, 1}}},
      {"trefoil_hopf", {}, "a trefoil linked once with a ring: 3_1 # Hopf link", 5, {3, {1, 1, 1, 2, 2}},
       {"3_1", "0_1"}, {0, 1, 1, 0}, {{0, 1, 0, 1}}},
      {"borromean", {"L6a4"}, "the Borromean rings", 6, {3, {1, -2, 1, -2, 1, -2}}, {"0_1", "0_1", "0_1"},
       {0, 0, 0, 0, 0, 0, 0, 0, 0}, {{0, 0, 0, 0, 1}}},
      {"t2_6", {}, "the (2, 6) torus link", 6, {2, {1, 1, 1, 1, 1, 1}}, {"0_1", "0_1"}, {0, 3, 3, 0},
       {{0, 3, 0, 4, 0, 1}}},
      {"t3_3", {}, "the (3, 3) torus link", 6, {3, {1, 2, 1, 2, 1, 2}}, {"0_1", "0_1", "0_1"},
       {0, 1, 1, 1, 0, 1, 1, 1, 0}, {{0, 0, 3, 0, 1}}},
  };
  return table;
}

const LinkRecord* find_link(const std::string& name) {
  for (const LinkRecord& r : link_table())
    if (r.name == name || std::find(r.aliases.begin(), r.aliases.end(), name) != r.aliases.end()) return &r;
  return nullptr;
}

}  // namespace ek
