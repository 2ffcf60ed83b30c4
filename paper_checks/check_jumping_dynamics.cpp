// Beyond the paper (Section 8, jumping knots: "our simulation neither
// accounts for dynamics nor friction, we have to validate this prediction
// with physical models"): 12a_1019, released from its flat coil with
// inertia, air drag and no friction, leaves the plane by itself and comes to
// rest in a 3D state, its knot type and link kept; with enough friction
// between the touching wires it comes to rest flat. At the default scale the jump's
// end does not depend on the time step (the same state at h/2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "jumping_dynamics_summary.hpp"
#include "results.hpp"
#include "thresholds.hpp"

using ek::paper::number;

namespace {
std::map<std::string, std::string> row(const std::string& knot, double mu, double h) {
  for (const auto& r : ek::paper::csv(ek::paper::results("jumping_dynamics") + "/dynamics.csv"))
    if (r.at("knot") == knot && std::atof(r.at("mu").c_str()) == mu && std::atof(r.at("time_step").c_str()) == h) return r;
  throw std::runtime_error("dynamics.csv has no row for " + knot);
}
}  // namespace

TEST(PaperJumpingDynamics, TwelveA1019JumpsWithoutFrictionAndStaysFlatWithIt) {
  using namespace ek::results;
  const auto s = ek::paper::summary<JumpingDynamicsSummary>("jumping_dynamics");
  const auto free = row("12a_1019", 0.0, s.time_step);
  const double mu_max = *std::max_element(s.mu_grid.begin(), s.mu_grid.end());
  const auto held = row("12a_1019", mu_max, s.time_step);
  std::cout << "[ measured ] 12a_1019 at mu = 0: " << free.at("outcome") << ", at rest at t = " << free.at("rest_time")
            << ", 3D-ness " << free.at("end_threedim") << ", max speed " << free.at("max_speed")
            << ", similarity to the static release " << free.at("similarity_static") << "; at mu = " << mu_max << ": "
            << held.at("outcome") << " (3D-ness " << held.at("end_threedim") << ")" << std::endl;
  EXPECT_DOUBLE_EQ(s.threedim_threshold, kJumpThreedim);  // the shared thresholds
  EXPECT_DOUBLE_EQ(s.planar_threshold, kPlanarThreedim);
  EXPECT_EQ(free.at("status"), "rest");                   // it comes to rest within the duration
  EXPECT_EQ(free.at("outcome"), "jumped");                // 3D-ness at least 0.3 at rest
  EXPECT_GE(number(free, "end_threedim"), kJumpThreedim);
  EXPECT_LT(number(free, "end_energy"), number(free, "start_energy"));  // it released stored energy
  EXPECT_TRUE(ek::paper::flag(free.at("alexander_preserved")));   // the knot type kept at every step
  EXPECT_LE(number(free, "link_error"), 1e-6);                    // Lk_B fixed throughout (Appendix C), 1e-6
  EXPECT_EQ(held.at("outcome"), "flat");                  // enough friction holds it: 3D-ness below 0.1
  EXPECT_TRUE(ek::paper::flag(held.at("alexander_preserved")));
  EXPECT_NE(std::find(s.jumping_without_friction.begin(), s.jumping_without_friction.end(), "12a_1019"),
            s.jumping_without_friction.end());
  if (s.step_check) {  // [cut 0.05] the same state at h/2
    std::cout << "[ measured ] step check: similarity " << s.step_check->similarity << " at h = "
              << s.step_check->time_step << ", rest at t = " << s.step_check->rest_time << " (h: "
              << s.step_check->rest_time_full << ")" << std::endl;
    EXPECT_LE(1.0 - s.step_check->similarity, kClusterCut);
  }
}
