// Segment-pair CCD: known motions, and random adversarial motions (crossing,
// grazing, parallel, endpoint, nearly touching, rotating, sliding) checked
// against the independent reference in ccd_reference.cpp. The million-motion
// run is test_contact_stress (label stress-long).
#include <gtest/gtest.h>

#include "ccd_reference.hpp"
#include "ek/contact/ccd.hpp"

using namespace ek;
using namespace ek::ccdtest;

namespace {
CcdResult ccd(const Motion& m, double t_max = 1.0, const CcdParams& p = {}) {
  return edge_edge_ccd(m.a0, m.a1, m.b0, m.b1, m.da0, m.da1, m.db0, m.db1, t_max, p);
}
}  // namespace

TEST(Ccd, HeadOnApproach) {
  // parallel unit segments 1 apart closing at relative speed 2: contact at s = 0.5
  Motion m{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, -1, 0}, {0, -1, 0}};
  const CcdParams p;  // separation 0.1, tolerance 0.1
  const CcdResult r = ccd(m);
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  EXPECT_DOUBLE_EQ(r.floor, 0.1);
  // certified: d(t) = 1 − 2t >= 0.1  ->  t <= 0.45; stops once d <= 0.1 + 0.1·0.9 = 0.19 -> t >= 0.405
  EXPECT_LE(r.t, 0.45 + 1e-15);
  EXPECT_GE(r.t, 0.405 - 1e-15);
  EXPECT_LE(r.iterations, 3);  // pure translation: the Lipschitz bound is exact
  // crossing at right angles, 0.5 apart, one passes through the other
  Motion x{{-1, 0, 0}, {1, 0, 0}, {0, -1, 0.5}, {0, 1, 0.5}, {0, 0, 0}, {0, 0, 0}, {0, 0, -1}, {0, 0, -1}};
  const CcdResult rx = ccd(x);
  EXPECT_LE(rx.t, 0.45 + 1e-15);
  EXPECT_GE(rx.t, 0.405 - 1e-15);
}

TEST(Ccd, TrivialMotions) {
  Motion still{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  EXPECT_EQ(ccd(still).t, 1.0);
  Motion rigid = still;  // common translation: no relative motion
  rigid.da0 = rigid.da1 = rigid.db0 = rigid.db1 = Vec3(5, -3, 2);
  EXPECT_EQ(ccd(rigid).t, 1.0);
  Motion apart = still;
  apart.db0 = apart.db1 = Vec3(0, 3, 0);
  EXPECT_EQ(ccd(apart).t, 1.0);
  Motion touching = still;
  touching.b0 = Vec3(0.5, 0, 0);  // b0 on a
  touching.db0 = Vec3(0, 0, 1);
  EXPECT_EQ(ccd(touching).t, 0.0);
  // t_max caps the answer
  Motion m{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, -1, 0}, {0, -1, 0}};
  EXPECT_EQ(ccd(m, 0.2).t, 0.2);
  EXPECT_LE(ccd(m, 0.9).t, 0.45);
}

TEST(Ccd, ReferenceDetectsCrossings) {
  // Negative control: the checker must flag a step past a real crossing.
  std::mt19937_64 rng(99);
  int flagged = 0, total = 0;
  for (int k = 0; k < 2000; ++k) {
    const Motion m = random_motion(rng, 0);  // intersecting at some s* in (0.02, 1.3)
    // find s* from the sampled distance minimum
    double best = 1e300, s_best = 0;
    for (int i = 0; i <= 4000; ++i) {
      const double s = 1.3 * i / 4000.0;
      const double d = distance_at(m, s);
      if (d < best) {
        best = d;
        s_best = s;
      }
    }
    if (s_best > 1.25) continue;
    ++total;
    const Verdict v = check(m, std::min(1.3, s_best + 0.01), 0.0);
    flagged += v.touches;
  }
  EXPECT_GT(total, 1500);
  EXPECT_GE(flagged, total * 0.99);  // a crossing at a coplanarity root is found
  // parallel segments meeting collinearly, and a planar X crossing (the cubic
  // vanishes identically: found through the endpoint-on-line times)
  const Motion collinear{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {1.5, 1, 0}, {0, 0, 0}, {0, 0, 0}, {0, -2, 0}, {0, -2, 0}};
  EXPECT_TRUE(check(collinear, 0.7, 0.0).touches);
  EXPECT_FALSE(check(collinear, 0.4, 0.0).touches);
  const Motion planar{{-1, 0, 0}, {1, 0, 0}, {0, 0.5, 0}, {0.3, 2, 0}, {0, 0, 0}, {0, 0, 0}, {0, -1, 0}, {0, -1, 0}};
  EXPECT_TRUE(check(planar, 0.8, 0.0).touches);
  EXPECT_FALSE(check(planar, 0.45, 0.0).touches);
}

TEST(Ccd, AdversarialMotionsNeverTouch) {
  // 20,000 motions (2,000 per category) in the unit test; 1,000,000 in stress-long.
  const Stats st = run_adversarial(2024, 20000, CcdParams{});
  RecordProperty("summary", st.summary());
  std::cout << st.summary() << "\n";
  EXPECT_EQ(st.touches, 0);      // never a touch or pass-through before the returned t
  EXPECT_EQ(st.below_floor, 0);  // and never below the floor δ at any sampled time
  EXPECT_EQ(st.uncertified, 0);
  EXPECT_LT(st.capped, st.motions / 50);  // the iteration cap is rare
  EXPECT_GT(st.full_step, st.motions / 10);
  EXPECT_GT(st.roots, st.motions / 10);  // coplanarity times inside [0, t] were checked
}

TEST(Ccd, StopsNearTheFloorUnlessCapped) {
  // Tightness: a result t < t_max that is not capped has d(t) within the stop
  // band δ + tolerance·(d0 − δ) — the pair really was about to reach the floor.
  std::mt19937_64 rng(5);
  const CcdParams p;
  int checked = 0;
  for (int k = 0; k < 5000; ++k) {
    const Motion m = random_motion(rng, k % kCategories);
    const CcdResult r = ccd(m, 1.0, p);
    if (r.t >= 1.0 || r.t == 0.0 || r.iterations >= p.max_iterations) continue;
    const double stop = r.floor + p.tolerance * (r.distance - r.floor);
    EXPECT_LE(distance_at(m, r.t), stop * (1 + 1e-9) + 1e-14) << category_name(k % kCategories);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}
