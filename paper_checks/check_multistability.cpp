// Paper Figs. 2, 6 and 8: 4_1, 7_7 and 8_1 are multistable. Distinct: clusters
// of complete linkage cut at the one documented threshold (docs/models.md: 0.05 in
// 1 - similarity). The paper's count for 8_1 (at least eight) is asserted in
// open_claims.cpp: at the ci scale (40 samples) this implementation finds fewer.
#include <gtest/gtest.h>

#include "results.hpp"

// Every knot of the experiment has at least two distinct stable equilibria
// (tolerance: none; a count).
TEST(PaperMultistability, EveryKnotIsMultistable) {
  const auto s = ek::paper::summary("multistability");
  for (const std::string knot : {"4_1", "7_7", "8_1"}) {
    const auto& k = s.at(knot);
    std::cout << "[ measured ] " << knot << ": " << k.at("distinct") << " distinct equilibria (" << k.at("distinctly_3d")
              << " distinctly 3D) from " << k.at("samples") << " samples at cut " << s.at("cut") << std::endl;
    EXPECT_GE(k.at("distinct").get<int>(), 2) << knot;
    EXPECT_GE(k.at("equilibria").get<int>(), k.at("samples").get<int>() / 2) << knot;  // most samples converge
  }
}

// Fig. 2 shows six distinct equilibria of 4_1 (three known before the paper,
// three new). Tolerance: none (a count, at the cut 0.05).
TEST(PaperMultistability, FigureEightHasAtLeastSixEquilibria) {
  const auto s = ek::paper::summary("multistability");
  const int distinct = s.at("4_1").at("distinct").get<int>();
  std::cout << "[ measured ] 4_1: " << distinct << " distinct equilibria from " << s.at("4_1").at("samples")
            << " samples at cut " << s.at("cut") << std::endl;
  EXPECT_GE(distinct, 6);
}
