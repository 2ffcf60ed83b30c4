#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "ek/analysis/clustering.hpp"
#include "ek/analysis/mds.hpp"
#include "ek/analysis/similarity.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Naive O(N³) complete linkage: merge heights in order (reference).
std::vector<double> naive_complete_linkage_heights(const Eigen::MatrixXd& D) {
  const int N = static_cast<int>(D.rows());
  std::vector<std::vector<int>> clusters;
  for (int i = 0; i < N; ++i) clusters.push_back({i});
  std::vector<double> heights;
  while (clusters.size() > 1) {
    double best = 1e300;
    size_t ba = 0, bb = 1;
    for (size_t a = 0; a < clusters.size(); ++a)
      for (size_t b = a + 1; b < clusters.size(); ++b) {
        double d = 0.0;
        for (int i : clusters[a])
          for (int j : clusters[b]) d = std::max(d, D(i, j));
        if (d < best) {
          best = d;
          ba = a;
          bb = b;
        }
      }
    clusters[ba].insert(clusters[ba].end(), clusters[bb].begin(), clusters[bb].end());
    clusters.erase(clusters.begin() + static_cast<long>(bb));
    heights.push_back(best);
  }
  return heights;
}

Eigen::MatrixXd random_distances(int N, std::uint64_t seed, int dim = 3) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> G(0.0, 1.0);
  Eigen::MatrixXd X(N, dim);
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < dim; ++k) X(i, k) = G(rng);
  Eigen::MatrixXd D(N, N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) D(i, j) = (X.row(i) - X.row(j)).norm();
  return D;
}

void expect_valid(const Dendrogram& d) {
  const int N = d.leaves;
  ASSERT_EQ(static_cast<int>(d.merges.size()), N - 1);
  std::vector<int> used(static_cast<size_t>(2 * N - 1), 0);
  for (size_t k = 0; k < d.merges.size(); ++k) {
    const Merge& m = d.merges[k];
    EXPECT_LT(m.a, m.b);
    EXPECT_LT(m.b, N + static_cast<int>(k));  // only existing clusters
    EXPECT_EQ(used[static_cast<size_t>(m.a)]++, 0);
    EXPECT_EQ(used[static_cast<size_t>(m.b)]++, 0);
    if (k > 0) {
      EXPECT_GE(m.height, d.merges[k - 1].height);  // monotone
    }
    const int sa = m.a < N ? 1 : d.merges[static_cast<size_t>(m.a - N)].size;
    const int sb = m.b < N ? 1 : d.merges[static_cast<size_t>(m.b - N)].size;
    EXPECT_EQ(m.size, sa + sb);
  }
  if (N > 0) {
    EXPECT_EQ(d.merges.empty() ? 1 : d.merges.back().size, N);
  }
}

}  // namespace

TEST(Clustering, HandWorkedExampleInScipyFormat) {
  // points 0, 1, 3, 7 on a line: {0,1} at 1; {0,1,3} at max(3, 2) = 3; all at 7
  const double x[4] = {0, 1, 3, 7};
  Eigen::MatrixXd D(4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) D(i, j) = std::abs(x[i] - x[j]);
  const Dendrogram d = complete_linkage(D);
  Eigen::MatrixXd expected(3, 4);
  expected << 0, 1, 1, 2,  //
      2, 4, 3, 3,          //
      3, 5, 7, 4;
  EXPECT_EQ(d.linkage_matrix(), expected);
  EXPECT_EQ(d.leaf_order(), (std::vector<int>{3, 2, 0, 1}));
  EXPECT_EQ(cut_dendrogram(d, 0.5), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(cut_dendrogram(d, 1.0), (std::vector<int>{0, 0, 1, 2}));  // <= threshold merges
  EXPECT_EQ(cut_dendrogram(d, 5.0), (std::vector<int>{0, 0, 0, 1}));
  EXPECT_EQ(cluster_count(d, 7.0), 1);
  const Eigen::MatrixXd C = cophenetic_distances(d);
  EXPECT_EQ(C(0, 1), 1.0);
  EXPECT_EQ(C(1, 2), 3.0);
  EXPECT_EQ(C(3, 0), 7.0);
}

TEST(Clustering, FromLinkageRoundTripsAndRejectsMalformedMatrices) {
  Eigen::MatrixXd D(5, 5);
  D << 0, 1, 4, 6, 9,  //
      1, 0, 3, 7, 8,   //
      4, 3, 0, 2, 5,   //
      6, 7, 2, 0, 4,   //
      9, 8, 5, 4, 0;
  const Dendrogram d = complete_linkage(D);
  const Dendrogram r = Dendrogram::from_linkage(d.linkage_matrix());
  EXPECT_EQ(r.leaves, 5);
  EXPECT_EQ(r.linkage_matrix(), d.linkage_matrix());
  for (double cut : {0.5, 1.0, 2.5, 4.0, 10.0}) EXPECT_EQ(cut_dendrogram(r, cut), cut_dendrogram(d, cut)) << cut;
  EXPECT_EQ(Dendrogram::from_linkage(Eigen::MatrixXd(0, 4)).leaves, 1);
  Eigen::MatrixXd bad = d.linkage_matrix();
  bad(0, 1) = 42;  // merges a cluster that does not exist yet
  EXPECT_THROW(Dendrogram::from_linkage(bad), std::invalid_argument);
  EXPECT_THROW(Dendrogram::from_linkage(Eigen::MatrixXd::Zero(2, 3)), std::invalid_argument);
}

TEST(Clustering, MatchesNaiveCompleteLinkage) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const int N = 5 + static_cast<int>(seed) * 7;
    const Eigen::MatrixXd D = random_distances(N, seed);
    const Dendrogram d = complete_linkage(D);
    expect_valid(d);
    const std::vector<double> ref = naive_complete_linkage_heights(D);
    ASSERT_EQ(ref.size(), d.merges.size());
    for (size_t k = 0; k < ref.size(); ++k) EXPECT_EQ(d.merges[k].height, ref[k]) << seed << " " << k;
    // complete linkage: every cophenetic distance is at least the original distance
    const Eigen::MatrixXd C = cophenetic_distances(d);
    EXPECT_GE((C - D).minCoeff(), 0.0);
    // leaf order is a permutation, and every cluster of every cut is contiguous in it
    std::vector<int> order = d.leaf_order();
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < N; ++i) ASSERT_EQ(sorted[static_cast<size_t>(i)], i);
    for (const Merge& m : d.merges) {
      const std::vector<int> lab = cut_dendrogram(d, m.height);
      std::set<int> closed;
      for (size_t p = 0; p < order.size(); ++p) {
        const int l = lab[static_cast<size_t>(order[p])];
        if (p > 0 && lab[static_cast<size_t>(order[p - 1])] != l) {
          EXPECT_EQ(closed.count(l), 0u) << "cluster not contiguous";
          closed.insert(lab[static_cast<size_t>(order[p - 1])]);
        }
      }
    }
  }
}

TEST(Clustering, TiesAndDegenerateInputs) {
  // all distances equal: N - 1 merges at the same height, any cut below gives N clusters
  const int N = 9;
  Eigen::MatrixXd D = Eigen::MatrixXd::Constant(N, N, 0.5);
  D.diagonal().setZero();
  const Dendrogram d = complete_linkage(D);
  expect_valid(d);
  for (const Merge& m : d.merges) EXPECT_EQ(m.height, 0.5);
  EXPECT_EQ(cluster_count(d, 0.49), N);
  EXPECT_EQ(cluster_count(d, 0.5), 1);
  EXPECT_EQ(complete_linkage(D).linkage_matrix(), complete_linkage(D).linkage_matrix());  // deterministic
  // one leaf
  const Dendrogram one = complete_linkage(Eigen::MatrixXd::Zero(1, 1));
  EXPECT_EQ(one.merges.size(), 0u);
  EXPECT_EQ(cut_dendrogram(one, 0.0), std::vector<int>{0});
  EXPECT_EQ(one.leaf_order(), std::vector<int>{0});
  // misuse
  Eigen::MatrixXd A = random_distances(5, 1);
  A(0, 1) += 0.1;
  EXPECT_THROW(complete_linkage(A), std::invalid_argument);
  EXPECT_THROW(complete_linkage(Eigen::MatrixXd::Zero(3, 4)), std::invalid_argument);
}

TEST(Clustering, NoisyCopiesOfThreeShapesGiveThreeClusters) {
  // three distinct shapes; 8 copies of each with a smooth random perturbation
  // (3% of the size), vertex noise, a random rotation, translation and cyclic shift
  const int n = 200;
  const std::vector<Points> base = {fixtures::torus_knot(n, 2, 3), fixtures::torus_knot(n, 3, 4, 2.0, 0.8),
                                    fixtures::random_fourier_curve(n, 2, 7)};
  std::mt19937_64 rng(1);
  std::normal_distribution<double> G(0.0, 1.0);
  std::vector<Points> curves;
  std::vector<int> truth;
  for (int g = 0; g < 3; ++g)
    for (int k = 0; k < 8; ++k) {
      const std::uint64_t seed = 1000 + 10 * static_cast<std::uint64_t>(g) + static_cast<std::uint64_t>(k);
      Points P = base[static_cast<size_t>(g)] + fixtures::random_fourier_curve(n, 3, seed, 0.03);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) P(i, c) += 1e-5 * G(rng);
      curves.push_back(fixtures::rigid_copy(P, fixtures::random_rotation(seed), Vec3(G(rng), G(rng), G(rng)),
                                            static_cast<int>(seed % n)));
      truth.push_back(g);
    }
  // shuffle so that the groups are not contiguous in the input
  std::vector<size_t> perm(curves.size());
  for (size_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Points> shuffled;
  std::vector<int> truth_shuffled;
  for (size_t p : perm) {
    shuffled.push_back(curves[p]);
    truth_shuffled.push_back(truth[p]);
  }
  const Eigen::MatrixXd S = similarity_matrix(shuffled);
  const Dendrogram d = complete_linkage_from_similarity(S);
  expect_valid(d);
  // the cut: distance 1 - S = 0.15 (measured: within-group merges end at 0.08,
  // the first merge between groups is at 0.29)
  const std::vector<int> labels = cut_dendrogram(d, 0.15);
  EXPECT_EQ(*std::max_element(labels.begin(), labels.end()), 2);  // three clusters
  for (size_t i = 0; i < labels.size(); ++i)
    for (size_t j = 0; j < labels.size(); ++j)
      EXPECT_EQ(labels[i] == labels[j], truth_shuffled[i] == truth_shuffled[j]) << i << " " << j;
  // the last two merges (between groups) are well above every merge inside a group
  EXPECT_GT(d.merges[d.merges.size() - 2].height, 2.0 * d.merges[d.merges.size() - 3].height);

  // MDS of the same matrix: the three groups are separated in the plane
  const MdsResult mds = classical_mds_from_similarity(S, 2);
  ASSERT_EQ(mds.status, MdsStatus::Converged);
  double within = 0.0, between = 1e300;
  for (size_t i = 0; i < labels.size(); ++i)
    for (size_t j = i + 1; j < labels.size(); ++j) {
      const double dist = (mds.coordinates.row(static_cast<Eigen::Index>(i)) - mds.coordinates.row(static_cast<Eigen::Index>(j))).norm();
      if (truth_shuffled[i] == truth_shuffled[j])
        within = std::max(within, dist);
      else
        between = std::min(between, dist);
    }
  EXPECT_LT(within, between);
}
