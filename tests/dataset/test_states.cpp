// Analyses of a knot's stored states (ek/dataset/states.hpp) on a hand-made
// entry with known clusters: four equilibria, of which 0 and 1 are one state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ek/analysis/clustering.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/states.hpp"
#include "testing.hpp"

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

// The six runs as a run that stopped there sees them: stable runs 0, 1, 3,
// 4, 5 (equilibria 0, 2, 1, 3, 1) in the states {0, 1, 1}, {2}, {3} at energies
// 1.0, 1.1, 2.0: n = 5, D = 3, f1 = 2, f2 = 0, so Chao1 = 3 + (4/5)·2·1/2 =
// 3.8; low energy (factor 1.2): the counts 3 and 1, n = 4, D = 2, one
// singleton and no doubleton: 2. The first two samples: two singletons,
// 2 + (1/2)·2·1/2 = 2.5.
TEST(States, UnseenOfAPrefixClusteredAlone) {
  const KnotEntry e = entry();
  const PrefixUnseen all = prefix_unseen(e, 6, 0.05, 1.2);
  EXPECT_EQ(all.all.samples, 5);
  EXPECT_EQ(all.all.observed, 3);
  EXPECT_EQ(all.all.singletons, 2);
  EXPECT_NEAR(all.all.states, 3.8, 1e-12);
  EXPECT_EQ(all.low_energy.samples, 4);
  EXPECT_EQ(all.low_energy.observed, 2);
  EXPECT_DOUBLE_EQ(all.low_energy.states, 2.0);
  const PrefixUnseen two = prefix_unseen(e, 2, 0.05, 1.2);
  EXPECT_EQ(two.all.observed, 2);
  EXPECT_NEAR(two.all.states, 2.5, 1e-12);
  EXPECT_EQ(prefix_unseen(e, 0, 0.05, 1.2).all.samples, 0);
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

namespace {

/// T(2,3) with a radial ripple of relative size `bump` (5 waves).
Points rippled_trefoil(double bump) {
  Points T = fixtures::torus_knot(200, 2, 3);
  for (Eigen::Index i = 0; i < T.rows(); ++i) T.row(i) *= 1.0 + bump * std::sin(10.0 * M_PI * i / T.rows());
  return T;
}

/// Equilibria: 0 = the trefoil T, 1 = T moved and re-indexed, 2 = T with a
/// ripple of 5%, 3 = T with a ripple of 30%. Similarities: 0 ~ 1 and 2 ~ 3
/// (0.99), the rest 0.5: clusters {0, 1} and {2, 3} at cut 0.05 (energies 1, 1, 2, 2).
KnotEntry shape_entry() {
  KnotEntry e;
  e.name = "shapes";
  e.equilibria = {rippled_trefoil(0.0),
                  fixtures::rigid_copy(rippled_trefoil(0.0), fixtures::random_rotation(4), Vec3(1, 2, 3), 17),
                  rippled_trefoil(0.05), rippled_trefoil(0.3)};
  e.attribute_names = {"energy"};
  e.attributes.resize(4, 1);
  e.attributes << 1.0, 1.0, 2.0, 2.0;
  e.similarity = Eigen::MatrixXd::Constant(4, 4, 0.5);
  e.similarity.diagonal().setOnes();
  e.similarity(0, 1) = e.similarity(1, 0) = 0.99;
  e.similarity(2, 3) = e.similarity(3, 2) = 0.99;
  e.linkage = complete_linkage_from_similarity(e.similarity).linkage_matrix();
  return e;
}

}  // namespace

// Same-cluster pairs: (0,1) at Hausdorff ~0 (a rigid copy, aligned), (2,3)
// far apart (ripples of 5% and 30%): median = half their sum. The pairs
// (0,2), (1,2) (Hausdorff ~5% of the size) lie in different clusters below
// that median: separated; (0,3), (1,3) do not.
TEST(States, HausdorffAgainstSimilarity) {
  const KnotEntry e = shape_entry();
  const auto pairs = pairwise_shape_distances(e, 0.05, {}, 2);
  ASSERT_EQ(pairs.size(), 6u);
  EXPECT_EQ(pairs[0].a, 0);
  EXPECT_EQ(pairs[0].b, 1);
  EXPECT_TRUE(pairs[0].same_cluster());
  EXPECT_LT(pairs[0].hausdorff, 1e-5);
  EXPECT_LT(pairs[0].icp_distance, 1e-6);
  EXPECT_NEAR(pairs[0].similarity_distance, 0.01, 1e-12);
  const auto& p23 = pairs[5];
  EXPECT_EQ(p23.a, 2);
  EXPECT_EQ(p23.b, 3);
  EXPECT_TRUE(p23.same_cluster());
  EXPECT_GT(p23.hausdorff, 0.3);  // the torus knot's radius is ~3, the ripples differ by 25%
  for (const auto& p : pairs) {
    EXPECT_GE(p.hausdorff, p.icp_distance - 1e-9);  // a maximum is at least an RMS of (vertex) distances
    EXPECT_EQ(p.same_cluster(), (p.a < 2) == (p.b < 2));
  }
  const HausdorffSeparation s = hausdorff_separation(pairs, 0.05);
  EXPECT_EQ(s.same_cluster_pairs, 2);
  EXPECT_EQ(s.different_cluster_pairs, 4);
  EXPECT_EQ(s.below_median_pairs, 2);
  EXPECT_EQ(s.distinct_pairs, 4);
  EXPECT_NEAR(s.median_same_cluster_hausdorff, 0.5 * (pairs[0].hausdorff + p23.hausdorff), 1e-12);
  EXPECT_EQ(s.separated_pairs, 2);
  // over the unique equilibria: 1 is 0 reached again, so {0, 2, 3} remain;
  // the only same-cluster pair is (2,3), the median its distance (ripples
  // 5% and 30%: ~25% of the size); of (0,2) and (0,3), only (0,2) (~5%)
  // is below it ((0,3): ~30%)
  EXPECT_EQ(s.identical_pairs, 1);
  EXPECT_EQ(s.unique_equilibria, 3);
  EXPECT_EQ(s.unique_same_cluster_pairs, 1);
  EXPECT_EQ(s.median_unique_same_cluster_hausdorff, p23.hausdorff);
  EXPECT_EQ(s.unique_different_cluster_pairs, 2);
  EXPECT_EQ(s.below_unique_median_pairs, 1);
  EXPECT_EQ(s.separated_below_unique_median, 1);
  // with no distance counted as identical every equilibrium is unique: the two rules agree
  const HausdorffSeparation all = hausdorff_separation(pairs, 0.05, 0.0);
  EXPECT_EQ(all.identical_pairs, 0);
  EXPECT_EQ(all.unique_equilibria, 4);
  EXPECT_EQ(all.median_unique_same_cluster_hausdorff, s.median_same_cluster_hausdorff);
  EXPECT_EQ(all.below_unique_median_pairs, s.below_median_pairs);
  EXPECT_EQ(all.separated_below_unique_median, s.separated_pairs);
  EXPECT_THROW(hausdorff_separation(pairs, 0.05, -1.0), InputError);
  // identity joins transitively: a chain 0 ~ 1 ~ 2 below the threshold is one equilibrium
  std::vector<StatePair> chain = {{0, 1, 0, 0, 0.0, 5e-4, 0.0}, {0, 2, 0, 0, 0.0, 2.0, 0.0},
                                  {1, 2, 0, 0, 0.0, 5e-4, 0.0}, {0, 3, 0, 0, 0.0, 1.0, 0.0},
                                  {1, 3, 0, 0, 0.0, 1.0, 0.0},  {2, 3, 0, 0, 0.0, 1.0, 0.0}};
  const HausdorffSeparation joined = hausdorff_separation(chain, 0.05);
  EXPECT_EQ(joined.unique_equilibria, 2);
  EXPECT_EQ(joined.unique_same_cluster_pairs, 1);  // (0,3)
  EXPECT_EQ(joined.median_unique_same_cluster_hausdorff, 1.0);
  EXPECT_TRUE(std::isnan(hausdorff_separation(chain, 0.05, 10.0).median_unique_same_cluster_hausdorff));
  const auto shown = closest_distinct_pairs(pairs, 0.05, 3);
  ASSERT_EQ(shown.size(), 1u);  // one pair of clusters
  EXPECT_LT(shown[0].a, 2);
  EXPECT_EQ(shown[0].b, 2);
  // the values do not depend on the number of threads
  const auto one = pairwise_shape_distances(e, 0.05, {}, 1);
  for (size_t k = 0; k < pairs.size(); ++k) EXPECT_EQ(one[k].hausdorff, pairs[k].hausdorff);
  EXPECT_TRUE(std::isnan(hausdorff_separation({}, 0.05).median_same_cluster_hausdorff));
  // at a cut above the pairs' similarity distance (0.5) no pair is separated
  // by the similarity, though they lie in different clusters of the entry
  const HausdorffSeparation high = hausdorff_separation(pairs, 0.6);
  EXPECT_EQ(high.distinct_pairs, 0);
  EXPECT_EQ(high.separated_pairs, 0);
  EXPECT_EQ(high.below_median_pairs, 2);
  EXPECT_TRUE(closest_distinct_pairs(pairs, 0.6, 3).empty());
}
