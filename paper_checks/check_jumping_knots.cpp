// Paper Section 8.3, Figs. 12 and 13, Appendix C: 12a_1019 is a jumping knot.
// From the multi-covered circle of its braid with Lk_B = Wr_target, relaxed
// under the planarity slab and then released, it leaves the flat state by
// itself and settles in a 3D state of lower energy, the link unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "jumping_knots_summary.hpp"
#include "results.hpp"

using ek::paper::number;

namespace {
std::map<std::string, std::string> row(const std::string& knot) {
  for (const auto& r : ek::paper::csv(ek::paper::results("jumping_knots") + "/jumping.csv"))
    if (r.at("knot") == knot) return r;
  throw std::runtime_error("jumping.csv has no row for " + knot);
}
}  // namespace

TEST(PaperJumpingKnots, TwelveA1019Jumps) {
  using namespace ek::results;
  const auto s = ek::paper::summary<JumpingKnotsSummary>("jumping_knots");
  const auto r = row("12a_1019");
  std::cout << "[ measured ] 12a_1019: flat " << r.at("flat_status") << " E = " << r.at("flat_energy")
            << " (3D-ness " << r.at("flat_threedim") << ") -> released " << r.at("final_status")
            << " E = " << r.at("final_energy") << " (3D-ness " << r.at("final_threedim") << "), link "
            << r.at("link") << ", link error " << r.at("link_error") << std::endl;
  // Section 8.3: under the slab it relaxes "into a minimal-energy
  // multi-covered-circle state" (a stable equilibrium under the slab) first.
  EXPECT_EQ(r.at("flat_status"), "converged-stable");
  EXPECT_EQ(r.at("final_status"), "converged-stable");
  EXPECT_LT(number(r, "flat_threedim"), kPlanarThreedim);    // flat: 3D-ness below the planarity threshold
  EXPECT_DOUBLE_EQ(s.threedim_threshold, kJumpThreedim);     // the experiment's threshold is the shared one
  EXPECT_GE(number(r, "final_threedim"), kJumpThreedim);     // 3D-ness at least 0.3 after release
  EXPECT_LT(number(r, "final_energy"), number(r, "flat_energy"));  // it releases stored energy
  EXPECT_LE(number(r, "link_error"), 1e-6);                  // Lk_B preserved throughout (Appendix C), 1e-6
  EXPECT_TRUE(ek::paper::flag(r.at("jumps")));               // the experiment's verdict agrees
  EXPECT_NE(std::find(s.jumping.begin(), s.jumping.end(), "12a_1019"), s.jumping.end());  // and its summary
}
