// Analyses of a knot's stored states (ek/dataset/states.hpp) on a hand-made
// entry with known clusters: four equilibria, of which 0 and 1 are one state.
#include <gtest/gtest.h>

#include <algorithm>

#include "ek/analysis/clustering.hpp"
#include "ek/dataset/states.hpp"

using namespace ek;

namespace {

/// Equilibria 0..3 (energy, writhe, 3D-ness): (1.0, -3.0, 0.05), (1.05, -3.0,
/// 0.05), (1.1, -2.95, 0.3), (2.0, -3.06, 0.5). Similarity: 0 ~ 1 (0.99);
/// 0 and 3 look alike (0.96) but 1 and 3 do not (0.5), so complete linkage
/// keeps 3 apart. Clusters at cut 0.05 by energy: {0, 1}, {2}, {3}.
/// Runs: samples 0..5 -> equilibria 0, 2, none, 1, 3, 1.
KnotEntry entry() {
  KnotEntry e;
  e.name = "test";
  e.equilibria.assign(4, Points::Zero(3, 3));
  e.attribute_names = {"energy", "writhe", "threedim"};
  e.attributes.resize(4, 3);
  e.attributes << 1.0, -3.0, 0.05, 1.05, -3.0, 0.05, 1.1, -2.95, 0.3, 2.0, -3.06, 0.5;
  e.similarity = Eigen::MatrixXd::Constant(4, 4, 0.5);
  e.similarity.diagonal().setOnes();
  e.similarity(0, 1) = e.similarity(1, 0) = 0.99;
  e.similarity(0, 3) = e.similarity(3, 0) = 0.96;
  e.linkage = complete_linkage_from_similarity(e.similarity).linkage_matrix();
  const int eq[] = {0, 2, -1, 1, 3, 1};
  for (int s = 0; s < 6; ++s) {
    RunRecord r;
    r.sample = s;
    r.equilibrium = eq[s];
    e.runs.push_back(r);
  }
  return e;
}

}  // namespace

TEST(States, ClustersAndTheirThreeDimensionalShare) {
  const KnotEntry e = entry();
  std::vector<int> rank;
  const auto clusters = clusters_at_cut(e, 0.05, &rank);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(rank, (std::vector<int>{0, 0, 1, 2}));
  EXPECT_EQ(count_3d_states(e, clusters, 0.1), 2);   // representatives 2 and 3
  EXPECT_EQ(count_3d_states(e, clusters, 0.4), 1);
  EXPECT_EQ(count_3d_states(e, {}, 0.1), 0);
}

TEST(States, ClustersSeenInAPrefix) {
  const KnotEntry e = entry();
  const std::vector<int> rank = {0, 0, 1, 2};
  EXPECT_EQ(clusters_seen(e, rank, 1), (std::set<int>{0}));
  EXPECT_EQ(clusters_seen(e, rank, 4), (std::set<int>{0, 1}));
  EXPECT_EQ(clusters_seen(e, rank, 6), (std::set<int>{0, 1, 2}));
  EXPECT_TRUE(clusters_seen(e, rank, 0).empty());
}

// Low-energy (factor 1.2 of the minimum 1.0): clusters 0 and 1. The first
// sample finds cluster 0 only; cluster 1 holds one of the six stored runs.
TEST(States, LowEnergyCoverage) {
  const KnotEntry e = entry();
  std::vector<int> rank;
  const auto clusters = clusters_at_cut(e, 0.05, &rank);
  LowEnergyCoverage c = low_energy_coverage(e, clusters, rank, clusters_seen(e, rank, 1), 1.2);
  EXPECT_EQ(c.clusters, 2);
  EXPECT_EQ(c.found, 1);
  ASSERT_EQ(c.missed.size(), 1u);
  EXPECT_EQ(c.missed[0].rank, 1);
  EXPECT_EQ(c.missed[0].samples, 1);
  EXPECT_EQ(c.missed_samples, 1);
  c = low_energy_coverage(e, clusters, rank, clusters_seen(e, rank, 2), 1.2);
  EXPECT_EQ(c.found, 2);
  EXPECT_EQ(c.missed_samples, 0);
  c = low_energy_coverage(e, clusters, rank, {}, 3.0);  // every cluster low, none seen
  EXPECT_EQ(c.clusters, 3);
  EXPECT_EQ(c.missed_samples, 5);  // every run that stored an equilibrium
}

// A permutation of the runs, renumbered, reproducible from the seed.
TEST(States, ShuffledRunsArePermutations) {
  const KnotEntry e = entry();
  std::uint64_t s1 = 42, s2 = 42;
  const KnotEntry a = shuffled_runs(e, s1), b = shuffled_runs(e, s2);
  std::vector<int> orig, got, again;
  bool moved = false;
  for (size_t k = 0; k < e.runs.size(); ++k) {
    EXPECT_EQ(a.runs[k].sample, static_cast<int>(k));
    orig.push_back(e.runs[k].equilibrium);
    got.push_back(a.runs[k].equilibrium);
    again.push_back(b.runs[k].equilibrium);
  }
  EXPECT_EQ(got, again);
  std::uint64_t state = 42;
  for (int t = 0; t < 5; ++t) {  // five successive orders: not all the identity
    const KnotEntry s = shuffled_runs(e, state);
    for (size_t k = 0; k < e.runs.size(); ++k) moved |= s.runs[k].equilibrium != e.runs[k].equilibrium;
  }
  EXPECT_TRUE(moved);
  std::sort(orig.begin(), orig.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(orig, got);
}

// Representatives 0 (W -3.0), 2 (-2.95), 3 (-3.06): 0/2 is a puzzle (link
// -2.975); 2/3 differ by 0.11 in writhe; 0/3 have equal writhe within 0.1
// but look alike (distance 0.04 <= cut), so they are not.
TEST(States, Puzzles) {
  const KnotEntry e = entry();
  const auto p = find_puzzles(e, 0.05, 0.1);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].state_a, 0);
  EXPECT_EQ(p[0].state_b, 2);
  EXPECT_DOUBLE_EQ(p[0].link, -2.975);
  EXPECT_DOUBLE_EQ(p[0].similarity, 0.5);
  EXPECT_EQ(find_puzzles(e, 0.05, 0.2).size(), 2u);  // 2/3 joins
  EXPECT_TRUE(find_puzzles(e, 0.05, 0.01).empty());
}
