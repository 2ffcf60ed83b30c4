// Paper Section 7.1, Fig. 5: the Hausdorff distance "has difficulties
// distinguishing between the pairs of states 1-2 and 3-4, which are
// geometrically close, but have distinctly different contact patterns. Our
// correlation-based measure more easily separates these embeddings."
// On 6_1's unique equilibria (those that several samples reach counted
// once: members of one state closer than ek::kIdenticalHausdorff = 1e-3 edge
// lengths are one equilibrium): at least one pair in different clusters
// (distinct states at the cut) whose Hausdorff distance after rigid
// alignment is below the median Hausdorff distance of the pairs within one
// state (asserted). The same rule over every equilibrium, duplicates
// included, and the count of the stricter pairs whose own similarity
// distance is above the cut are reported, not asserted (docs/reproducing.md:
// the median over all pairs falls with how often a relaxation method lands
// on the same equilibrium, not with the spread of a state). The shown pairs
// are recomputed from the stored curves, the Hausdorff distance also by an
// independent dense sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ek/analysis/search.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/dataset/states.hpp"
#include "ek/geometry/hausdorff.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "ek/knots/table.hpp"
#include "hausdorff_summary.hpp"
#include "results.hpp"

namespace {

/// max over points of A sampled every `h` along its edges of the distance to
/// the polygon B: within h/2 below the directed Hausdorff distance (the
/// distance to B is 1-Lipschitz along A).
double dense_directed(const ek::Points& A, const ek::Points& B, double h) {
  double best = 0.0;
  const Eigen::Index n = A.rows(), m = B.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    const ek::Vec3 a = A.row(i).transpose(), b = A.row((i + 1) % n).transpose();
    const int k = std::max(1, static_cast<int>(std::ceil((b - a).norm() / h)));
    for (int s = 0; s < k; ++s) {
      const ek::Vec3 x = a + (b - a) * (static_cast<double>(s) / k);
      double d2 = 1e300;
      for (Eigen::Index j = 0; j < m; ++j)
        d2 = std::min(d2, ek::point_segment_distance_squared(x, B.row(j).transpose(), B.row((j + 1) % m).transpose()));
      best = std::max(best, std::sqrt(d2));
    }
  }
  return best;
}

}  // namespace

TEST(PaperHausdorff, SimilaritySeparatesStatesTheHausdorffDistanceDoesNot) {
  const auto s = ek::paper::summary<ek::results::HausdorffSummary>("hausdorff");
  std::cout << "[ measured ] " << s.knot << ": " << s.equilibria << " equilibria, " << s.clusters << " clusters, "
            << s.pairs << " pairs; median same-cluster Hausdorff " << ek::paper::or_na(s.median_same_cluster_hausdorff)
            << "; below it " << s.below_median_pairs << " of " << s.different_cluster_pairs
            << " pairs of different clusters, " << s.separated_pairs << " of " << s.distinct_pairs
            << " pairs also farther apart than the cut (reported)" << std::endl;
  std::cout << "[ measured ] unique equilibria " << s.unique_equilibria << " (" << s.identical_pairs
            << " identical same-cluster pairs below " << s.identical_hausdorff << "); median same-cluster Hausdorff "
            << ek::paper::or_na(s.median_unique_same_cluster_hausdorff) << "; below it "
            << s.below_unique_median_pairs << " of " << s.unique_different_cluster_pairs
            << " pairs of different clusters, " << s.separated_below_unique_median
            << " also farther apart than the cut (reported)" << std::endl;
  EXPECT_DOUBLE_EQ(s.cut, ek::results::kClusterCut);
  EXPECT_DOUBLE_EQ(s.identical_hausdorff, ek::kIdenticalHausdorff);
  ASSERT_TRUE(s.median_unique_same_cluster_hausdorff.has_value()) << "no state with two unique equilibria: no median";
  EXPECT_GE(s.below_unique_median_pairs, 1);  // the claim: at least one pair (no tolerance: a count)
  // the summary's counts from pairs.csv: over the unique equilibria by the
  // library's rule (tested on known pairs), over all of them written out here
  const auto rows = ek::paper::csv(ek::paper::results("hausdorff") + "/pairs.csv");
  EXPECT_EQ(static_cast<long>(rows.size()), s.pairs);
  EXPECT_EQ(s.pairs, s.equilibria * (s.equilibria - 1) / 2);
  std::vector<ek::StatePair> stored;
  for (const auto& r : rows)
    stored.push_back({std::atoi(r.at("a").c_str()), std::atoi(r.at("b").c_str()),
                      std::atoi(r.at("cluster_a").c_str()), std::atoi(r.at("cluster_b").c_str()),
                      std::atof(r.at("similarity_distance").c_str()), std::atof(r.at("hausdorff").c_str()),
                      std::atof(r.at("icp_distance").c_str())});
  const ek::HausdorffSeparation u = ek::hausdorff_separation(stored, s.cut);
  EXPECT_EQ(u.identical_pairs, s.identical_pairs);
  EXPECT_EQ(u.unique_equilibria, s.unique_equilibria);
  EXPECT_EQ(u.unique_same_cluster_pairs, s.unique_same_cluster_pairs);
  EXPECT_NEAR(u.median_unique_same_cluster_hausdorff, *s.median_unique_same_cluster_hausdorff, 1e-9);
  EXPECT_EQ(u.unique_different_cluster_pairs, s.unique_different_cluster_pairs);
  EXPECT_EQ(u.below_unique_median_pairs, s.below_unique_median_pairs);
  EXPECT_EQ(u.separated_below_unique_median, s.separated_below_unique_median);
  ASSERT_TRUE(s.median_same_cluster_hausdorff.has_value());
  std::vector<double> same;
  int below = 0, separated = 0;
  for (const auto& r : rows)
    if (ek::paper::flag(r.at("same_cluster"))) same.push_back(std::atof(r.at("hausdorff").c_str()));
  ASSERT_FALSE(same.empty());
  std::sort(same.begin(), same.end());
  const size_t h = same.size() / 2;
  const double median = same.size() % 2 ? same[h] : 0.5 * (same[h - 1] + same[h]);
  EXPECT_NEAR(median, *s.median_same_cluster_hausdorff, 1e-9);
  for (const auto& r : rows) {
    const bool other = !ek::paper::flag(r.at("same_cluster")), low = std::atof(r.at("hausdorff").c_str()) < median;
    below += other && low;
    separated += other && std::atof(r.at("similarity_distance").c_str()) > s.cut && low;
  }
  EXPECT_EQ(below, s.below_median_pairs);
  EXPECT_EQ(separated, s.separated_pairs);
}

// The shown pairs (Fig. 5) recomputed from the stored curves: different
// clusters of the stored dendrogram at the cut, similarity distance above the
// cut (recomputed with the knot's symmetry options), Hausdorff distance after
// alignment equal to the reported one (1e-9) and, by dense sampling every
// 0.01 edge lengths, within 1e-6 above and 0.005 + 1e-6 below it (the library's tolerance
// 1e-6, the sampling's error h/2).
TEST(PaperHausdorff, ShownPairsHoldOnTheStoredCurves) {
  const auto s = ek::paper::summary<ek::results::HausdorffSummary>("hausdorff");
  ASSERT_FALSE(s.shown.empty());
  const ek::DatasetReader reader(ek::paper::results("hausdorff") + "/hausdorff.h5");
  const ek::KnotEntry e = reader.read(s.knot);
  std::vector<int> rank;
  ek::clusters_at_cut(e, s.cut, &rank);
  const ek::ExploreOptions o = ek::options_for_knot(ek::ExploreOptions{}, ek::KnotTable::global().at(s.knot));
  for (const auto& p : s.shown) {
    const ek::Points& A = e.equilibria.at(static_cast<size_t>(p.a));
    const ek::Points& B = e.equilibria.at(static_cast<size_t>(p.b));
    EXPECT_NE(rank[static_cast<size_t>(p.a)], rank[static_cast<size_t>(p.b)]) << p.a << "/" << p.b;
    const double sim_distance = 1.0 - ek::similarity(A, B, o.similarity);
    EXPECT_NEAR(sim_distance, p.similarity_distance, 1e-9);
    EXPECT_GT(sim_distance, s.cut);
    const ek::Points moved = ek::aligned_candidate(B, ek::align_curves(A, B));
    const double hd = ek::hausdorff_distance(A, moved).distance;
    EXPECT_NEAR(hd, p.hausdorff, 1e-9);
    const double dense = std::max(dense_directed(A, moved, 0.01), dense_directed(moved, A, 0.01));
    EXPECT_LE(dense, hd + 1e-6);
    EXPECT_GE(dense, hd - 0.005 - 1e-6);
    std::cout << "[ measured ] pair " << p.a << "/" << p.b << " (clusters " << p.cluster_a << ", " << p.cluster_b
              << "): Hausdorff " << hd << " (dense " << dense << "), 1 - similarity " << sim_distance << std::endl;
  }
}
