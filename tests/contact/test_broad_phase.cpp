// Broad phase: equal to brute force on random curves, torus knots, lattice
// curves (a self-avoiding lattice loop and the peer 9_47 lattice curve),
// links, and for swept boxes with small and very large motions.
#include <gtest/gtest.h>

#include <filesystem>

#include "contact_test_util.hpp"
#include "ek/contact/broad_phase.hpp"
#include "ek/geometry/curve_io.hpp"
#include "testing.hpp"

using namespace ek;
using namespace ek::contacttest;

namespace {

// All test curves: (name, points, topology).
struct Scene {
  std::string name;
  Points x;
  CurveTopology topology;
};

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  for (int seed = 0; seed < 6; ++seed) {
    const int n = 50 + 70 * seed;
    out.push_back({"fourier" + std::to_string(seed), fixtures::random_fourier_curve(n, 5, seed, 3.0),
                   CurveTopology::single(n)});
  }
  out.push_back({"torus_knot_3_7", fixtures::torus_knot(300, 3, 7, 4.0, 1.0), CurveTopology::single(300)});
  for (int seed = 1; seed <= 4; ++seed) {
    Points L = lattice_loop(40 + 30 * seed, seed);
    if (L.rows() == 0) continue;
    const int n = static_cast<int>(L.rows());
    out.push_back({"lattice_loop" + std::to_string(seed), L, CurveTopology::single(n)});
  }
  const std::string peer = fixtures::peer_dir() + "/9_47-cubiclattice.txt";
  if (std::filesystem::exists(peer)) {
    Points P = read_curve(peer);
    out.push_back({"peer_9_47_lattice", P, CurveTopology::single(static_cast<int>(P.rows()))});
  }
  {  // a three-component link: circles through each other
    const Points c1 = fixtures::circle(60, 3.0);
    Points c2 = fixtures::rigid_copy(c1, fixtures::random_rotation(1), Vec3(3.0, 0.1, 0), 0);
    Points c3 = fixtures::rigid_copy(c1, fixtures::random_rotation(2), Vec3(-2.9, 0.2, 0.1), 7);
    Points all(180, 3);
    all << c1, c2, c3;
    out.push_back({"link3", all, CurveTopology::from_sizes({60, 60, 60})});
  }
  return out;
}

}  // namespace

TEST(Topology, NextPrevExclusion) {
  const CurveTopology t = CurveTopology::from_sizes({5, 4});
  EXPECT_EQ(t.num_vertices(), 9);
  EXPECT_EQ(t.num_components(), 2);
  EXPECT_EQ(t.next(4), 0);
  EXPECT_EQ(t.prev(0), 4);
  EXPECT_EQ(t.next(8), 5);
  EXPECT_EQ(t.prev(5), 8);
  EXPECT_EQ(t.component(6), 1);
  EXPECT_TRUE(t.excluded(0, 4, 1));   // share vertex 0
  EXPECT_TRUE(t.excluded(0, 1, 1));
  EXPECT_FALSE(t.excluded(0, 2, 1));
  EXPECT_TRUE(t.excluded(0, 2, 2));
  EXPECT_FALSE(t.excluded(4, 5, 1));  // different components: never
  EXPECT_TRUE(t.excluded(5, 8, 1));
  EXPECT_THROW(CurveTopology::from_sizes({5, 2}), std::invalid_argument);
  EXPECT_THROW(CurveTopology::single(2), std::invalid_argument);
  EXPECT_THROW(EdgeBroadPhase(CurveTopology::single(10), 0), std::invalid_argument);
}

TEST(BroadPhase, StaticPairsEqualBruteForce) {
  int nonempty = 0;
  for (const Scene& s : scenes()) {
    for (int excl : {1, 2}) {
      EdgeBroadPhase bp(s.topology, excl);
      for (double dist : {0.4, 1.5, 3.0}) {
        const auto& got = bp.static_pairs(s.x, 0.5 * dist);
        const auto ref = static_pairs_brute_force(s.x, s.topology, excl, 0.5 * dist);
        ASSERT_EQ(got, ref) << s.name << " excl " << excl << " d " << dist;
        // and the distance-level sets (broad + narrow vs every pair with the
        // geometry module's segment distance)
        const auto within = edge_pairs_within(s.x, s.topology, excl, dist);
        const auto within_ref = edge_pairs_within_brute_force(s.x, s.topology, excl, dist);
        ASSERT_EQ(within, within_ref) << s.name << " excl " << excl << " d " << dist;
        if (!within.empty()) ++nonempty;
      }
    }
  }
  EXPECT_GT(nonempty, 20);
}

TEST(BroadPhase, LatticeContactsAtUnitDistance) {
  // The lattice loop's two layers are exactly 1 apart, so every edge has a
  // partner at distance 1: all are found below 1.01 and none below 0.99.
  const Points L = lattice_loop(60, 3);
  ASSERT_GT(L.rows(), 0);
  const CurveTopology t = CurveTopology::single(static_cast<int>(L.rows()));
  EXPECT_TRUE(edge_pairs_within(L, t, 1, 0.99).empty());
  const auto pairs = edge_pairs_within(L, t, 1, 1.01);
  std::vector<int> has(static_cast<size_t>(L.rows()), 0);
  for (const auto& p : pairs) has[static_cast<size_t>(p.a)] = has[static_cast<size_t>(p.b)] = 1;
  for (int i = 0; i < L.rows(); ++i) EXPECT_TRUE(has[static_cast<size_t>(i)]) << i;
}

TEST(BroadPhase, SweptPairsEqualBruteForce) {
  std::mt19937_64 rng(8);
  std::normal_distribution<double> N;
  for (const Scene& s : scenes()) {
    EdgeBroadPhase bp(s.topology, 1);
    for (double scale : {0.0, 0.1, 1.0}) {
      Points dx(s.x.rows(), 3);
      for (int i = 0; i < dx.rows(); ++i) dx.row(i) << scale * N(rng), scale * N(rng), scale * N(rng);
      if (scale == 1.0) dx.row(3) *= 200.0;  // one very large motion: the "large box" path
      const auto& got = bp.swept_pairs(s.x, dx, 0.02);
      const auto ref = swept_pairs_brute_force(s.x, dx, s.topology, 1, 0.02);
      ASSERT_EQ(got, ref) << s.name << " scale " << scale;
    }
  }
}

TEST(BroadPhase, ScalesLinearlyOnSpreadCurves) {
  // A long thin helix: pairs grow linearly with n; no pair is missed.
  for (int n : {500, 4000}) {
    Points P(n, 3);
    for (int i = 0; i < n; ++i) {
      const double s = 0.35 * i;
      P.row(i) << 1.0 * std::cos(s), 1.0 * std::sin(s), 0.06 * i;
    }
    const CurveTopology t = CurveTopology::single(n);
    EdgeBroadPhase bp(t, 1);
    const auto& got = bp.static_pairs(P, 0.2);
    if (n == 500) {
      EXPECT_EQ(got, static_pairs_brute_force(P, t, 1, 0.2));
    }
    EXPECT_LT(got.size(), static_cast<size_t>(20 * n));
  }
}
