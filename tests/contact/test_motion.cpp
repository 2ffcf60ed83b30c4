// check_linear_motion (`knots ccd`, the Python ccd()): a rigid translation is
// collision free; two strands driven through each other stop before touching.
#include <gtest/gtest.h>

#include "ek/contact/motion.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "testing.hpp"

using namespace ek;

TEST(MotionCheck, TranslationIsCollisionFree) {
  const Points x = fixtures::circle(40, 5.0);
  Points y = x;
  y.col(0).array() += 3.0;
  const MotionCheck m = check_linear_motion(x, y);
  EXPECT_EQ(m.step.t, 1.0);
  EXPECT_EQ(m.step.edge_a, -1);
  EXPECT_EQ(m.vertices, 40);
  EXPECT_EQ(m.dhat, 0.4);
  EXPECT_DOUBLE_EQ(m.clearance_start, clearance(x).distance);
  EXPECT_NEAR(m.clearance_end, m.clearance_start, 1e-12);
  EXPECT_NEAR(m.min_clearance_sampled, m.clearance_start, 1e-12);
}

TEST(MotionCheck, CrossingStrandsStopBeforeTheFloor) {
  // one closed polygon: a square at z = 0, then four vertices at z = 1 whose
  // edge (2, -1) -> (2, 1) passes over the square's edge y = 0; those four
  // vertices move down by 2, so that edge is driven through the square's
  Points x(8, 3);
  x << 0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0,  //
      2, -1, 1, 2, 1, 1, 6, 1, 1, 6, -1, 1;
  Points y = x;
  for (int i = 4; i < 8; ++i) y(i, 2) -= 2.0;
  MotionCheckOptions o;
  o.radius = 0.2;
  o.separation = 0.1;
  const MotionCheck m = check_linear_motion(x, y, o);
  EXPECT_LT(m.step.t, 1.0);
  EXPECT_GE(m.step.edge_a, 0);
  EXPECT_GT(m.min_clearance_sampled, 0.0);
  EXPECT_GE(m.clearance_at_t, o.separation * std::min(m.clearance_start, 2.0 * o.radius) * (1.0 - 1e-9));
}

TEST(MotionCheck, BadInputIsAnInputError) {
  const Points x = fixtures::circle(40, 5.0);
  MotionCheckOptions o;
  o.separation = 1.0;
  EXPECT_THROW(check_linear_motion(x, x, o), InputError);
  o = {};
  o.radius = 0.0;
  EXPECT_THROW(check_linear_motion(x, x, o), InputError);
  EXPECT_THROW(check_linear_motion(x, fixtures::circle(41, 5.0)), InputError);
}
