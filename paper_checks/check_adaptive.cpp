// Paper Section 7.4: adaptive sampling (initial batch, batches, stop when the
// importance score S <= 0.1). Checked here: the score, not the budget cap,
// ends the sampling for at least 95% of the knots (the paper: 95%). The
// savings (paper: 70%; issue 9: at least 60%) and "every low-energy state is
// still found" are asserted in open_claims.cpp: at the ci budget of 60
// samples this implementation measures 57% and 26 of 29.
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
