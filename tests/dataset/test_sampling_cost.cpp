// The sampling cost of a data set and its extrapolation, on hand-made knots
// whose medians, savings and fitted lines are known in closed form.
#include <gtest/gtest.h>

#include <stdexcept>

#include "ek/dataset/sampling_cost.hpp"

using namespace ek;

namespace {
KnotCost k(int c, int samples, double seconds) { return {"k", c, samples, seconds}; }
}  // namespace

TEST(SamplingCost, KnotCostSumsItsRuns) {
  KnotEntry e;
  e.name = "5_2";
  e.crossing_number = 5;
  for (double s : {0.5, 0.25, 1.0}) {
    RunRecord r;
    r.seconds = s;
    e.runs.push_back(r);
  }
  const KnotCost c = knot_cost(e);
  EXPECT_EQ(c.name, "5_2");
  EXPECT_EQ(c.crossing_number, 5);
  EXPECT_EQ(c.samples, 3);
  EXPECT_DOUBLE_EQ(c.run_seconds, 1.75);
}

TEST(SamplingCost, MedianSavingAndPerCrossingRows) {
  // samples 60, 60, 100, 500: median (60 + 100) / 2 = 80; 720 of 4 · 500 = 2000 runs -> saving 0.64
  const SamplingCost s = sampling_cost({k(3, 60, 6.0), k(4, 60, 12.0), k(4, 100, 28.0), k(5, 500, 250.0)}, 500);
  EXPECT_EQ(s.knots, 4);
  EXPECT_EQ(s.samples, 720);
  EXPECT_DOUBLE_EQ(s.median_samples, 80.0);
  EXPECT_EQ(s.max_samples, 500);
  EXPECT_EQ(s.knots_at_budget, 1);
  EXPECT_DOUBLE_EQ(s.saving_vs_budget, 0.64);
  EXPECT_DOUBLE_EQ(s.run_seconds, 296.0);
  ASSERT_EQ(s.by_crossing_number.size(), 3u);
  const CrossingCost& four = s.by_crossing_number[1];
  EXPECT_EQ(four.crossing_number, 4);
  EXPECT_EQ(four.knots, 2);
  EXPECT_DOUBLE_EQ(four.median_samples, 80.0);
  EXPECT_DOUBLE_EQ(four.mean_samples, 80.0);
  EXPECT_DOUBLE_EQ(four.seconds_per_run, 40.0 / 160.0);
  // odd count: the middle value
  EXPECT_DOUBLE_EQ(sampling_cost({k(3, 7, 1), k(3, 1, 1), k(3, 5, 1)}, 10).median_samples, 5.0);
}

TEST(SamplingCost, EstimateUsesMeasuredRowsAndExtrapolatesTheLine) {
  // mean samples 50 + 10 (c - 3) and seconds per run 0.1 (c - 2): one knot each at c = 3, 4, 5
  std::vector<KnotCost> ks;
  for (int c = 3; c <= 5; ++c) {
    const int n = 50 + 10 * (c - 3);
    ks.push_back(k(c, n, n * 0.1 * (c - 2)));
  }
  const SamplingCost s = sampling_cost(ks, 500);
  const RunEstimate measured = estimate_run(s, {3, 4, 4});
  EXPECT_EQ(measured.knots, 3);
  EXPECT_DOUBLE_EQ(measured.samples, 50 + 60 + 60);
  EXPECT_NEAR(measured.core_seconds, 50 * 0.1 + 2 * 60 * 0.2, 1e-12);
  // c = 7 lies on both lines: 90 samples at 0.5 s
  const RunEstimate beyond = estimate_run(s, {7, 7});
  EXPECT_NEAR(beyond.samples, 180.0, 1e-9);
  EXPECT_NEAR(beyond.core_seconds, 2 * 90 * 0.5, 1e-9);
}

TEST(SamplingCost, ExtrapolationNeverFallsBelowTheLargestMeasured) {
  // falling samples and seconds with c: the extrapolation is floored at c = 4's values
  const SamplingCost s = sampling_cost({k(3, 100, 50.0), k(4, 60, 12.0)}, 500);
  const RunEstimate e = estimate_run(s, {9});
  EXPECT_DOUBLE_EQ(e.samples, 60.0);
  EXPECT_DOUBLE_EQ(e.core_seconds, 12.0);
}

TEST(SamplingCost, MisuseThrows) {
  EXPECT_THROW(sampling_cost({}, 500), std::invalid_argument);
  EXPECT_THROW(sampling_cost({k(3, 1, 1)}, 0), std::invalid_argument);
  const SamplingCost one = sampling_cost({k(3, 60, 6.0)}, 500);
  EXPECT_DOUBLE_EQ(estimate_run(one, {3}).samples, 60.0);
  EXPECT_THROW(estimate_run(one, {4}), std::invalid_argument);
}
