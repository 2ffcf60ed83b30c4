// The far end of Fig. 9 at the full budget (far_end.hpp): small cases worked
// out by hand, the rounds of the sample-12 situation (a knot that is not
// 2-bridge held its place by having been sampled little), and the
// certificate's rounds against the brute-force answer on random tables
// whose ratios below the budget are upper bounds of the true ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>

#include "ek/analysis/far_end.hpp"

using namespace ek;

namespace {

KnotRatio knot(const std::string& name, double ratio, bool two_bridge, int samples) {
  return {name, ratio, two_bridge, samples};
}

}  // namespace

TEST(FarEnd, AtTheFullBudgetItIsTheTopKItself) {
  const std::vector<KnotRatio> all{knot("a", 1.5, true, 40), knot("b", 1.4, true, 40), knot("c", 1.3, false, 40),
                                   knot("d", 1.2, true, 40)};
  const FarEndCertificate two = far_end_certificate(all, 2, 40);
  EXPECT_TRUE(two.certified);
  EXPECT_EQ(two.certified_two_bridge, 2);
  EXPECT_DOUBLE_EQ(two.other_max_ratio, 1.3);
  EXPECT_EQ(two.other_max_knot, "c");
  EXPECT_TRUE(two.to_sample.empty());
  // the third knot is not 2-bridge: false, and nothing left to sample
  const FarEndCertificate three = far_end_certificate(all, 3, 40);
  EXPECT_FALSE(three.certified);
  EXPECT_TRUE(three.to_sample.empty());
}

TEST(FarEnd, EveryKnotTwoBridgeIsCertifiedAtTheBudget) {
  const FarEndCertificate c = far_end_certificate({knot("a", 1.5, true, 10), knot("b", 1.4, true, 10)}, 2, 10);
  EXPECT_TRUE(c.certified);
  EXPECT_EQ(c.other_max_knot, "");
  EXPECT_DOUBLE_EQ(c.other_max_ratio, 0.0);
}

TEST(FarEnd, RoundsOfTheSample12Situation) {
  // x is not 2-bridge and sits among the 2-bridge knots after 80 samples
  std::vector<KnotRatio> all{knot("a", 1.50, true, 500), knot("b", 1.45, true, 80), knot("x", 1.35, false, 80),
                             knot("c", 1.30, true, 100), knot("y", 1.29, false, 500)};
  FarEndCertificate c = far_end_certificate(all, 3, 500);
  EXPECT_FALSE(c.certified);
  EXPECT_EQ(c.other_max_knot, "x");
  EXPECT_EQ(c.certified_two_bridge, 1);
  // two 2-bridge knots lie above x: x is sampled (only a lower M can certify), then b
  EXPECT_EQ(c.to_sample, (std::vector<std::string>{"x", "b"}));
  all[1] = knot("b", 1.44, true, 500);
  all[2] = knot("x", 1.23, false, 500);
  c = far_end_certificate(all, 3, 500);
  EXPECT_EQ(c.other_max_knot, "y");
  EXPECT_EQ(c.to_sample, (std::vector<std::string>{"c"}));
  // c keeps a ratio above y's at the budget: certified
  all[3] = knot("c", 1.31, true, 500);
  c = far_end_certificate(all, 3, 500);
  EXPECT_TRUE(c.certified);
  EXPECT_EQ(c.certified_two_bridge, 3);
  // c falls below y at the budget: the claim is false, nothing left to sample
  all[3] = knot("c", 1.28, true, 500);
  c = far_end_certificate(all, 3, 500);
  EXPECT_FALSE(c.certified);
  EXPECT_TRUE(c.to_sample.empty());
}

TEST(FarEnd, OnlyAsManyKnotsAsAreMissing) {
  // five 2-bridge knots above M below the budget, one certified, k = 3: the two of largest ratio
  const std::vector<KnotRatio> all{knot("a", 1.5, true, 500), knot("b", 1.41, true, 60), knot("c", 1.49, true, 60),
                                   knot("d", 1.45, true, 60),  knot("e", 1.42, true, 60), knot("x", 1.2, false, 60)};
  const FarEndCertificate c = far_end_certificate(all, 3, 500);
  EXPECT_EQ(c.to_sample, (std::vector<std::string>{"c", "d"}));  // x: four 2-bridge knots lie above it already
}

TEST(FarEnd, MisuseThrows) {
  EXPECT_THROW(far_end_certificate({}, 0, 10), std::invalid_argument);
  EXPECT_THROW(far_end_certificate({}, 1, 0), std::invalid_argument);
}

// Random tables: each knot has a true ratio at the budget; one sampled
// below it shows that ratio plus a positive excess (a minimum over fewer
// samples). Sampling the listed knots (revealing their true ratios) until
// the list is empty must reach the brute-force answer, "the k largest true
// ratios are all 2-bridge", in fewer rounds than there are knots.
TEST(FarEnd, RoundsReachTheBruteForceAnswer) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int certified = 0, refuted = 0;
  for (int table = 0; table < 2000; ++table) {
    const int n = 5 + static_cast<int>(u(rng) * 30), k = 1 + static_cast<int>(u(rng) * 6), budget = 500;
    std::vector<KnotRatio> all;
    std::map<std::string, double> truth;
    for (int i = 0; i < n; ++i) {
      const bool two_bridge = u(rng) < 0.4;
      const double r = 1.0 + 0.5 * u(rng) + (two_bridge ? 0.15 * u(rng) : 0.0);
      const bool full = u(rng) < 0.3;
      const std::string name = "k" + std::to_string(i);
      truth[name] = r;
      all.push_back(knot(name, full ? r : r + 0.2 * u(rng) * u(rng), two_bridge, full ? budget : 60));
    }
    std::vector<KnotRatio> sorted = all;
    for (KnotRatio& r : sorted) r.ratio = truth[r.name];
    std::sort(sorted.begin(), sorted.end(), [](const KnotRatio& a, const KnotRatio& b) { return a.ratio > b.ratio; });
    bool expected = static_cast<int>(sorted.size()) >= k;
    for (int i = 0; i < k && i < static_cast<int>(sorted.size()); ++i) expected = expected && sorted[i].two_bridge;
    FarEndCertificate c;
    int rounds = 0;
    for (;; ++rounds) {
      c = far_end_certificate(all, k, budget);
      if (c.to_sample.empty()) break;
      ASSERT_LT(rounds, n) << "table " << table;
      for (const std::string& name : c.to_sample)
        for (KnotRatio& r : all)
          if (r.name == name) {
            ASSERT_LT(r.samples, budget) << "a knot at the budget listed again";
            r.ratio = truth[name];
            r.samples = budget;
          }
    }
    ASSERT_EQ(c.certified, expected) << "table " << table << " after " << rounds << " rounds";
    (c.certified ? certified : refuted) += 1;
  }
  EXPECT_GT(certified, 200);  // both answers occur often among the tables
  EXPECT_GT(refuted, 200);
}
