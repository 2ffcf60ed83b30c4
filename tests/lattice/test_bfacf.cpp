#include <gtest/gtest.h>

#include <map>
#include <set>

#include "ek/core/errors.hpp"
#include "ek/lattice/bfacf.hpp"
#include "lattice_test_util.hpp"

using namespace ek;
using ek::latticetest::unit_square;

namespace {

using SiteTuple = std::array<int, 3>;

std::set<SiteTuple> sites_of(const LatticePoints& L) {
  std::set<SiteTuple> s;
  for (Eigen::Index i = 0; i < L.rows(); ++i) s.insert({L(i, 0), L(i, 1), L(i, 2)});
  return s;
}

int l1(const SiteTuple& a, const SiteTuple& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

}  // namespace

// Every applied move is one of Fig. 4 (checked on the sets of occupied sites)
// and leaves a self-avoiding lattice polygon; all three types occur.
TEST(Bfacf, MovesAreTheThreeTypesOfFig4AndKeepSelfAvoidance) {
  BfacfWalk walk(unit_square(), 11);
  std::map<BfacfMove, int> seen;
  std::set<SiteTuple> before = sites_of(walk.polygon());
  for (int a = 0; a < 30000; ++a) {
    const int n0 = walk.length();
    const BfacfMove m = walk.attempt(a < 15000 ? 0.5 : 0.1);
    ++seen[m];
    if (m == BfacfMove::None) continue;
    const LatticePoints L = walk.polygon();
    const auto check = check_lattice_polygon(L);
    ASSERT_TRUE(check.ok) << check.problem;
    ASSERT_EQ(L.rows(), walk.length());
    const std::set<SiteTuple> after = sites_of(L);
    std::vector<SiteTuple> gone, added;
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(gone));
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(added));
    switch (m) {
      case BfacfMove::I:  // two neighbouring sites removed
        ASSERT_EQ(walk.length(), n0 - 2);
        ASSERT_EQ(gone.size(), 2u);
        ASSERT_TRUE(added.empty());
        EXPECT_EQ(l1(gone[0], gone[1]), 1);
        break;
      case BfacfMove::II:  // two neighbouring sites added
        ASSERT_EQ(walk.length(), n0 + 2);
        ASSERT_EQ(added.size(), 2u);
        ASSERT_TRUE(gone.empty());
        EXPECT_EQ(l1(added[0], added[1]), 1);
        break;
      case BfacfMove::III:  // one site moves across the diagonal of a unit square
        ASSERT_EQ(walk.length(), n0);
        ASSERT_EQ(gone.size(), 1u);
        ASSERT_EQ(added.size(), 1u);
        EXPECT_EQ(l1(gone[0], added[0]), 2);
        {
          int differing = 0;
          for (int k = 0; k < 3; ++k) differing += gone[0][k] != added[0][k];
          EXPECT_EQ(differing, 2);
        }
        break;
      case BfacfMove::None:
        break;
    }
    before = after;
  }
  EXPECT_GT(seen[BfacfMove::I], 100);
  EXPECT_GT(seen[BfacfMove::II], 100);
  EXPECT_GT(seen[BfacfMove::III], 100);
  EXPECT_GE(walk.length(), 4);
}

// The acceptance rule p+ = β²/(1+β²), p- = 1/(1+β²), p0 = 1 has the
// stationary distribution π(ω) ∝ n β^n, so the fraction of time spent at
// length n is ∝ n p_n β^n with p_n the number of polygons of n edges up to
// translation: p_4 = 3, p_6 = 22, p_8 = 207, p_10 = 2412 (OEIS A001413 / 2n).
// All of them are unknots, one ergodicity class of BFACF.
TEST(Bfacf, StationaryLengthDistributionMatchesEnumeration) {
  const double beta = 0.2;
  const double p[] = {3, 22, 207, 2412};
  std::map<int, double> time_at;
  long long total = 0;
  for (std::uint64_t seed : {1, 2, 3, 4}) {
    BfacfWalk walk(unit_square(), seed);
    for (int a = 0; a < 20000; ++a) walk.attempt(beta);  // burn-in
    for (int a = 0; a < 1000000; ++a) {
      walk.attempt(beta);
      time_at[walk.length()] += 1.0;
      ++total;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const int n = 4 + 2 * k;
    const double expected = ((n + 2) * p[k + 1]) / (n * p[k]) * beta * beta;
    const double measured = time_at[n + 2] / time_at[n];
    // 4·10^6 correlated samples: a few per cent statistical error
    EXPECT_NEAR(measured / expected, 1.0, 0.06) << "P(" << n + 2 << ")/P(" << n << ")";
  }
  EXPECT_GT(time_at[4] / total, 0.2);
}

TEST(Bfacf, SameSeedSameWalkDifferentSeedDifferentWalk) {
  BfacfWalk a(unit_square(), 42), b(unit_square(), 42), c(unit_square(), 43);
  a.run(100000, 0.3);
  b.run(100000, 0.3);
  c.run(100000, 0.3);
  EXPECT_EQ(a.polygon(), b.polygon());
  EXPECT_FALSE(a.polygon().rows() == c.polygon().rows() && a.polygon() == c.polygon());
  // seed 0 is not confused with GSL's default seed
  BfacfWalk z(unit_square(), 0), d(unit_square(), 4357);
  z.run(10000, 0.3);
  d.run(10000, 0.3);
  EXPECT_FALSE(z.polygon().rows() == d.polygon().rows() && z.polygon() == d.polygon());
}

TEST(Bfacf, RunToLengthStopsExactlyOnTheTargetOrAtTheBudget) {
  BfacfWalk walk(unit_square(), 5);
  const BfacfRunReport up = walk.run_to_length(300, 0.5, 10000000);
  EXPECT_TRUE(up.reached);
  EXPECT_EQ(walk.length(), 300);
  EXPECT_EQ(up.max_length, 300);
  EXPECT_EQ(up.end_length, 300);
  EXPECT_EQ(up.accepted_II - up.accepted_I, (300 - 4) / 2);
  const BfacfRunReport down = walk.run_to_length(100, 0.1, 10000000);
  EXPECT_TRUE(down.reached);
  EXPECT_EQ(walk.length(), 100);
  EXPECT_EQ(down.min_length, 100);
  // far below β_c the walk does not grow to 2000 in 20000 attempts
  const BfacfRunReport stuck = walk.run_to_length(2000, 0.01, 20000);
  EXPECT_FALSE(stuck.reached);
  EXPECT_EQ(stuck.attempts, 20000);
  EXPECT_LT(stuck.max_length, 2000);
  EXPECT_EQ(stuck.end_length, walk.length());
  // a length cap holds
  const BfacfRunReport capped = walk.run(200000, 0.6, 150);
  EXPECT_LE(capped.max_length, std::max(150, capped.start_length));
  EXPECT_TRUE(check_lattice_polygon(walk.polygon()).ok);
}

TEST(Bfacf, BadInput) {
  LatticePoints L = unit_square();
  L(3, 2) = 5;
  EXPECT_THROW(BfacfWalk(L, 1), InputError);
  BfacfWalk walk(unit_square(), 1);
  EXPECT_THROW(walk.attempt(0.0), std::invalid_argument);
  EXPECT_THROW(walk.attempt(std::nan("")), std::invalid_argument);
  EXPECT_THROW(walk.run_to_length(7, 0.3, 10), std::invalid_argument);
  EXPECT_THROW(walk.run(-1, 0.3), std::invalid_argument);
}
