// Paper Section 7.4: adaptive sampling (initial batch, batches, stop when the
// importance score S <= 0.1). Checked here: the score, not the budget cap,
// ends the sampling for at least 95% of the knots (the paper: 95%), and the
// paper's rule (50 + 10, budget 500) saves at least 60% of the simulations
// (the paper: 70%). The paper claims no coverage of the low-energy states
// (a truncated run's states "remain candidates for further exploration"):
// the coverage is measured and printed, not asserted.
#include <gtest/gtest.h>

#include "adaptive_summary.hpp"
#include "results.hpp"

using ek::results::AdaptiveSummary;

TEST(PaperAdaptive, ScoreEndsTheSamplingForMostKnots) {
  const auto s = ek::paper::summary<AdaptiveSummary>("adaptive");
  std::cout << "[ measured ] score stopped the sampling for a share " << s.stopped_by_score_share << " of the "
            << s.knots << " knots (budget " << s.budget << ", " << s.adaptive << "); saved " << s.saved_share
            << ", median " << s.median_samples << " samples per knot" << std::endl;
  EXPECT_GE(s.stopped_by_score_share, 0.95);  // paper: 95% of the knot types
  EXPECT_LT(s.adaptive_simulations, s.fixed_simulations);  // it saves something
}

// The savings are the paper's rule (first 50 samples, batches of 10, stop when
// S <= 0.1, at most 500) against 500 samples per knot, replayed on the stored
// runs (exact where the rule stops within them; a knot it would sample past
// them counts as 500 for the lower bound and as one more sample for the upper
// bound). Tolerance: the saved share >= 0.6 (the paper measured 0.7).
// At the default and paper scales every knot must stop within the stored runs,
// so the lower bound is the exact share and is asserted; at the ci scale (60
// stored samples) only the upper bound is, i.e. that the claim is not refuted.
TEST(PaperAdaptive, PaperRuleSavesAtLeastSixtyPercent) {
  const auto s = ek::paper::summary<AdaptiveSummary>("adaptive");
  const auto& pr = s.paper_rule;
  std::cout << "[ measured ] " << pr.adaptive << " against " << pr.budget << " per knot: saves between "
            << pr.saved_share_lower_bound << " and " << pr.saved_share_upper_bound << " ("
            << pr.knots_stopped_within_stored << " of " << s.knots << " knots stop within the " << pr.stored_samples
            << " stored samples; median " << pr.median_samples_of_stopped
            << " samples where exact; the paper: 0.7 and a median of 90)" << std::endl;
  EXPECT_GE(pr.saved_share_upper_bound, 0.6);
  if (s.scale != "ci") {
    EXPECT_EQ(pr.knots_stopped_within_stored, s.knots) << "the stored runs must decide every knot at scale " << s.scale;
    EXPECT_GE(pr.saved_share_lower_bound, 0.6);
  }
}

// Coverage of the low-energy states (clusters of the full budget within the
// low_energy_factor of the knot's lowest energy), reported as measured values:
// found by the scaled rule, by the paper's rule, over random sample orders,
// and the share of the full budget's samples that ended in the missed
// clusters. Asserted: only that the reported numbers are consistent with each
// other (a count of missed clusters and samples that add up).
TEST(PaperAdaptive, ReportsLowEnergyCoverage) {
  const auto s = ek::paper::summary<AdaptiveSummary>("adaptive");
  std::cout << "[ measured ] " << s.low_energy_clusters_found << " of " << s.low_energy_clusters
            << " clusters within " << s.low_energy_factor << " x the minimum energy found (" << s.adaptive
            << "); the missed ones hold " << s.missed_samples << " of " << s.fixed_simulations
            << " full-budget samples (share " << s.missed_sample_share << "); with the paper's rule "
            << s.paper_rule.low_energy_clusters_found << "; mean over random sample orders "
            << s.shuffled.low_energy_clusters_found_mean << std::endl;
  EXPECT_GT(s.low_energy_clusters, 0);
  EXPECT_LE(s.low_energy_clusters_found, s.low_energy_clusters);
  ASSERT_EQ(static_cast<int>(s.missed.size()), s.low_energy_clusters - s.low_energy_clusters_found);
  long in_missed = 0;
  for (const auto& m : s.missed) {
    EXPECT_GE(m.samples, 1) << m.knot;  // a cluster of the full budget holds a sample
    EXPECT_LE(m.cluster_energy, s.low_energy_factor * m.knot_min_energy) << m.knot;
    in_missed += m.samples;
  }
  EXPECT_EQ(in_missed, s.missed_samples);
  EXPECT_NEAR(s.missed_sample_share, static_cast<double>(in_missed) / static_cast<double>(s.fixed_simulations),
              1e-12);
}

// Ours, not the paper's: the unseen stopping rule (docs/models.md, "Stopping
// when no low-energy state is likely to be missing") beside the score on the
// same random orders of the stored samples. At every scale the replays'
// numbers must be consistent (found at most the states there are, shares in
// [0, 1]). Against the ground truth (budget 500: make stopping-truth) the
// unseen rule must use at most 90 samples per knot in the median (the
// paper's median) and find at least as many of the low-energy states as the
// score does, on average over the same orders (no tolerance).
TEST(StoppingRules, UnseenRuleAgainstTheScoreOnTheSameOrders) {
  const auto s = ek::paper::summary<AdaptiveSummary>("adaptive");
  ASSERT_EQ(s.rules.size(), 2u);
  const auto& score = s.rules[0];
  const auto& unseen = s.rules[1];
  EXPECT_EQ(score.rule, "score");
  EXPECT_EQ(unseen.rule, "unseen");
  for (const auto& r : s.rules) {
    std::cout << "[ measured ] " << r.adaptive << ": median " << r.median_samples << " samples (mean "
              << r.mean_samples << ", " << r.capped_share << " at the cap, saves " << r.saved_share << "), finds "
              << r.states_found_mean << " of " << r.states << " states and " << r.low_energy_states_found_mean
              << " of " << r.low_energy_states << " low-energy ones; its 95% interval at the stop holds the count "
              << r.interval_coverage << " (low-energy " << r.low_energy_interval_coverage << ")" << std::endl;
    EXPECT_LE(r.states_found_mean, r.states + 1e-9);
    EXPECT_LE(r.low_energy_states_found_mean, r.low_energy_states + 1e-9);
    EXPECT_GE(r.low_energy_states_found_mean, 0.0);
    for (double share : {r.capped_share, r.saved_share, r.interval_coverage, r.low_energy_interval_coverage}) {
      EXPECT_GE(share, 0.0);
      EXPECT_LE(share, 1.0);
    }
  }
  EXPECT_EQ(score.states, unseen.states);
  EXPECT_EQ(score.low_energy_states, unseen.low_energy_states);
  if (s.budget >= 500) {
    EXPECT_LE(unseen.median_samples, 90.0);
    EXPECT_GE(unseen.low_energy_states_found_mean, score.low_energy_states_found_mean);
  }
}
