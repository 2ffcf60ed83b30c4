// One million adversarial segment-pair motions against the independent
// reference, and 250,000 with tight settings (label stress-long; a few
// minutes on one core).
#include <gtest/gtest.h>

#include <iostream>

#include "ccd_reference.hpp"

using namespace ek;
using namespace ek::ccdtest;

TEST(CcdStress, MillionAdversarialMotionsNeverTouch) {
  const Stats st = run_adversarial(7, 1000000, CcdParams{});
  std::cout << st.summary() << "\n";
  RecordProperty("summary", st.summary());
  EXPECT_EQ(st.touches, 0);
  EXPECT_EQ(st.below_floor, 0);
  EXPECT_EQ(st.uncertified, 0);
  EXPECT_LT(st.capped, st.motions / 50);
}

TEST(CcdStress, TightSettings) {
  // a small separation and tolerance: the iteration runs much closer to contact
  // (250,000 motions)
  CcdParams p;
  p.separation = 1e-3;
  p.tolerance = 1e-3;
  p.max_iterations = 100000;
  const Stats st = run_adversarial(8, 250000, p);
  std::cout << st.summary() << "\n";
  EXPECT_EQ(st.touches, 0);
  EXPECT_EQ(st.below_floor, 0);
  EXPECT_EQ(st.uncertified, 0);
}
