// Claims of the paper that this implementation does not reproduce (label
// `paper-open`; not part of `make test`, run by `make paper-open`). Each test
// asserts the claim as the paper states it and prints the measured value; the
// claim table of docs/reproducing.md gives the evidence. A test here
// that starts passing is moved to its check_<experiment>.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "results.hpp"

namespace {
std::string label(const nlohmann::json& m) {
  return m.at("family").get<std::string>() + " p=" + std::to_string(m.at("p").get<int>());
}
}  // namespace

// Fig. 16 shows a 3D state for every p. Measured: the BB members (8_18 and
// 10_123 are BB knots, whose lowest-curvature states are multi-covered
// circles, Fig. 9) and the longer members stay flat coils, stable, also when
// relaxed from the tall start (strands stacked along the axis, 3D-ness
// 0.26-0.31): it returns to the same flat coil. A member counts as deployed
// when either start ends 3D.
// Tolerance: 3D-ness >= 0.1 (the planarity threshold of Section 8.2).
TEST(PaperOpenPeriodicBraids, EveryMemberDeploysTo3D) {
  const auto s = ek::paper::summary("periodic_braids");
  ASSERT_EQ(s.at("members").size(), 8u);
  for (const auto& m : s.at("members")) {
    const auto& tall = m.at("tall_start");
    std::cout << "[ measured ] " << label(m) << ": 3D-ness " << m.at("threedim") << " from the coil, "
              << tall.at("threedim") << " from the tall start (" << tall.at("start_threedim") << ")" << std::endl;
    EXPECT_GE(std::max(m.at("threedim").get<double>(), tall.at("threedim").get<double>()), 0.1) << label(m);
  }
}

// Fig. 8: 8_1 shows at least eight distinct equilibria, of which few (here at
// most a quarter) are distinctly 3D. Distinct: clusters at the documented cut
// 0.05 of 1 - similarity.
TEST(PaperOpenMultistability, EightOneHasAtLeastEightMostlyPlanarEquilibria) {
  const auto s = ek::paper::summary("multistability");
  const int distinct = s.at("8_1").at("distinct").get<int>();
  const int three_d = s.at("8_1").at("distinctly_3d").get<int>();
  std::cout << "[ measured ] 8_1: " << distinct << " distinct equilibria, " << three_d << " distinctly 3D (3D-ness >= "
            << s.at("planar_threshold") << ")" << std::endl;
  EXPECT_GE(distinct, 8);
  EXPECT_LE(4 * three_d, distinct);
}

// Adaptive sampling finds every low-energy state (every cluster of
// the full budget within 20% of the knot's minimum energy). The savings of
// Section 7.4 are checked in check_adaptive.cpp. Measured at default: 11 of
// the 14 missed clusters hold 1-3 of ~150 samples; a rule that runs a share k
// of the samples finds a one-sample cluster with probability k (random
// orders: 87.8 of 100 found), so "every" cannot hold at 60% savings.
TEST(PaperOpenAdaptive, FindsEveryLowEnergyCluster) {
  const auto s = ek::paper::summary("adaptive");
  const int total = s.at("low_energy_clusters").get<int>(), found = s.at("low_energy_clusters_found").get<int>();
  std::cout << "[ measured ] " << found << " of " << total << " clusters within 20% of the minimum energy found ("
            << s.at("adaptive") << "); with the paper's rule " << s.at("paper_rule").at("low_energy_clusters_found")
            << "; mean over random sample orders " << s.at("shuffled").at("low_energy_clusters_found_mean") << std::endl;
  EXPECT_GT(total, 0);
  EXPECT_EQ(found, total) << s.at("missed").dump();
}
