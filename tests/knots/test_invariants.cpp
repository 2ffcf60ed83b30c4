// table_alexander and curve_invariants (`knots info`, `knots invariants`, the
// Python knot() and invariants()).
#include <gtest/gtest.h>

#include <cmath>

#include "ek/knots/invariants.hpp"
#include "ek/knots/table.hpp"

using namespace ek;

TEST(Invariants, TableAlexander) {
  const KnotTable& t = KnotTable::global();
  EXPECT_EQ(table_alexander(t.at("0_1")).coefficients, (std::vector<std::int64_t>{1}));
  EXPECT_EQ(table_alexander(t.at("3_1")).coefficients, (std::vector<std::int64_t>{1, -1, 1}));
  // 8_19 = T(3, 4): (t^12 - 1)(t - 1) / ((t^3 - 1)(t^4 - 1))
  EXPECT_EQ(table_alexander(t.at("8_19")).coefficients, (std::vector<std::int64_t>{1, -1, 0, 1, 0, -1, 1}));
}

TEST(Invariants, OfATorusTrefoil) {
  const int n = 150;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n, r = 2.0 + std::cos(3.0 * s);
    P.row(i) << r * std::cos(2.0 * s), r * std::sin(2.0 * s), std::sin(3.0 * s);
  }
  const CurveInvariants c = curve_invariants(P);
  EXPECT_EQ(c.vertices, n);
  EXPECT_EQ(c.alexander.coefficients, (std::vector<std::int64_t>{1, -1, 1}));
  EXPECT_GT(c.total_curvature, 4.0 * M_PI);  // Milnor: > 2π · bridge index 2
  EXPECT_GT(c.clearance.distance, 0.0);
  EXPECT_GT(c.length, 0.0);
  Points mirror = P;
  mirror.col(2) *= -1.0;
  EXPECT_NEAR(curve_invariants(mirror).writhe, -c.writhe, 1e-12);
}
