#include <gtest/gtest.h>

#include <random>
#include <unordered_set>

#include "ek/lattice/lattice_polygon.hpp"
#include "lattice_test_util.hpp"

using namespace ek;
using ek::latticetest::unit_square;

TEST(SiteSet, AgreesWithStdSetUnderRandomInsertAndErase) {
  // Keys of a small box so that collisions, long probe runs and wrap-around
  // of the table all occur; the set starts tiny so that it rehashes.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(-6, 6);
  SiteSet set(4);
  std::unordered_set<std::uint64_t> ref;
  for (int step = 0; step < 200000; ++step) {
    const std::uint64_t key = site_key(coord(rng), coord(rng), coord(rng));
    if (rng() % 3 == 0) {
      EXPECT_EQ(set.erase(key), ref.erase(key) == 1);
    } else {
      EXPECT_EQ(set.insert(key), ref.insert(key).second);
    }
    ASSERT_EQ(set.size(), ref.size());
    if (step % 1000 == 0)
      for (int x = -6; x <= 6; ++x)
        for (int y = -6; y <= 6; ++y) {
          const std::uint64_t k = site_key(x, y, 3);
          ASSERT_EQ(set.contains(k), ref.count(k) == 1) << "step " << step;
        }
  }
  EXPECT_LE(2 * set.size(), set.capacity());
  set.clear();
  EXPECT_EQ(set.size(), 0u);
  EXPECT_FALSE(set.contains(site_key(0, 0, 0)));
}

TEST(SiteSet, KeysAreUniqueWithinTheModulus) {
  // Sites whose coordinates differ by less than 2^21 never share a key,
  // negative coordinates included; sites 2^21 apart do (by design).
  std::unordered_set<std::uint64_t> keys;
  const int far = (1 << 20) - 1;
  for (int x : {-far, -1, 0, 1, far})
    for (int y : {-far, -1, 0, 1, far})
      for (int z : {-far, -1, 0, 1, far}) EXPECT_TRUE(keys.insert(site_key(x, y, z)).second);
  EXPECT_EQ(site_key(5, -3, 7), site_key(5 + (1 << 21), -3, 7));
  EXPECT_LT(site_key(-1, -1, -1), std::uint64_t{1} << 63);
}

TEST(LatticePolygon, Check) {
  EXPECT_TRUE(check_lattice_polygon(unit_square()).ok);
  LatticePoints L = unit_square();
  L(2, 2) = 1;  // (1,1,1): not a unit step from (1,0,0)
  const auto bad = check_lattice_polygon(L);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.problem.find("edge 1"), std::string::npos) << bad.problem;
  LatticePoints rep(6, 3);  // goes out and back along one line: repeated site
  rep << 0, 0, 0, 1, 0, 0, 2, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0, 0;
  EXPECT_FALSE(check_lattice_polygon(rep).ok);
  LatticePoints two(2, 3);
  two << 0, 0, 0, 1, 0, 0;
  EXPECT_FALSE(check_lattice_polygon(two).ok);
  EXPECT_EQ(to_points(unit_square())(2, 1), 1.0);
}

TEST(LatticePolygon, RecognisedFromDoubles) {
  LatticePoints out;
  Points P = to_points(unit_square());
  ASSERT_TRUE(as_lattice_polygon(P, &out));
  EXPECT_EQ(out, unit_square());
  P(1, 0) = 1.25;
  EXPECT_FALSE(as_lattice_polygon(P, &out));
  P(1, 0) = std::nan("");
  EXPECT_FALSE(as_lattice_polygon(P, &out));
  EXPECT_EQ(out, unit_square());  // untouched on failure
}
