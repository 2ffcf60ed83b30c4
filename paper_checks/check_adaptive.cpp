// Paper Section 7.4: adaptive sampling (initial batch, batches, stop when the
// importance score S <= 0.1). Checked here: the score, not the budget cap,
// ends the sampling for at least 95% of the knots (the paper: 95%), and the
// paper's rule (50 + 10, budget 500) saves at least 60% of the simulations
// (the paper: 70%). "Every low-energy state is still
// found" is asserted in open_claims.cpp.
#include <gtest/gtest.h>

#include "results.hpp"

TEST(PaperAdaptive, ScoreEndsTheSamplingForMostKnots) {
  const auto s = ek::paper::summary("adaptive");
  const double stopped = s.at("stopped_by_score_share").get<double>();
  std::cout << "[ measured ] score stopped the sampling for a share " << stopped << " of the " << s.at("knots")
            << " knots (budget " << s.at("budget") << ", " << s.at("adaptive") << "); saved "
            << s.at("saved_share") << ", median " << s.at("median_samples") << " samples per knot" << std::endl;
  EXPECT_GE(stopped, 0.95);  // paper: 95% of the knot types
  EXPECT_LT(s.at("adaptive_simulations").get<long>(), s.at("fixed_simulations").get<long>());  // it saves something
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
  const auto s = ek::paper::summary("adaptive");
  const auto& pr = s.at("paper_rule");
  const double lower = pr.at("saved_share_lower_bound").get<double>();
  const double upper = pr.at("saved_share_upper_bound").get<double>();
  const int exact = pr.at("knots_stopped_within_stored").get<int>(), knots = s.at("knots").get<int>();
  std::cout << "[ measured ] " << pr.at("adaptive") << " against " << pr.at("budget") << " per knot: saves between "
            << lower << " and " << upper << " (" << exact << " of " << knots << " knots stop within the "
            << pr.at("stored_samples") << " stored samples; median " << pr.at("median_samples_of_stopped")
            << " samples where exact; the paper: 0.7 and a median of 90)" << std::endl;
  EXPECT_GE(upper, 0.6);
  const std::string scale = s.at("scale").get<std::string>();
  if (scale != "ci") {
    EXPECT_EQ(exact, knots) << "the stored runs must decide every knot at scale " << scale;
    EXPECT_GE(lower, 0.6);
  }
}
