// Deploying a flat coil at a prescribed link (ek/mechanics/deploy.hpp) on a
// case with a known answer: a single ring of unit edges (the unknot's flat
// 1-covered circle) is stable at link Lk up to Michell's threshold
// Lk_c = √3·B/C = √3·(1 + ν) (B = EI, C = GJ = EI/(1 + ν) for a circular
// cross-section) and buckles above it, trading twist for writhe.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/mechanics/deploy.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

constexpr int kVertices = 40;

/// A flat ring of unit edges in z = 0.
Points ring() { return fixtures::unit_ring(kVertices); }

}  // namespace

// Below the threshold the released ring is the flat ring, stable, with the
// prescribed link carried as twist (Wr = 0 for a planar curve).
TEST(Deploy, RingBelowMichellThresholdStaysFlat) {
  const DeployRun r = deploy_at_link(ring(), 1.0);
  EXPECT_EQ(r.flat_status, RelaxStatus::ConvergedStable);
  EXPECT_EQ(r.status, RelaxStatus::ConvergedStable);
  EXPECT_TRUE(r.stable);
  EXPECT_FALSE(r.three_d);
  EXPECT_LT(r.threedim, 1e-6);
  EXPECT_FALSE(r.buckled);
  EXPECT_NEAR(r.writhe, 0.0, 1e-9);
  EXPECT_NEAR(r.flat_writhe, 0.0, 1e-9);
  EXPECT_LT(r.link_error, 1e-9);
  EXPECT_EQ(r.positions.rows(), kVertices);
}

// The bisected onset of buckling lies within 0.05 turns of Michell's
// Lk_c = √3·1.3 = 2.2517 (ν = 0.3, the default material) for the 40-edge
// polygon (the bracket after 4 bisections of [2.25, 2.5] is 1/64 wide;
// measured (2.281, 2.297]). Above it the ring leaves the plane with
// |Wr| > 1 (measured 1.24 at the onset, 3D-ness 0.14) and folds towards a
// nearly flat figure eight (Wr ~ 2, 3D-ness 0.03 at Lk 2.5). At negative
// links the mirror images: the onset bracket mirrored.
TEST(Deploy, RingBucklesAtMichellThreshold) {
  LinkScanOptions scan;
  scan.grid = {-2.5, -2.25, 0.0, 1.0, 2.0, 2.25, 2.5, 2.75, 3.0, 3.25};
  scan.center = 0.0;  // the flat ring's writhe
  scan.refinements = 4;
  const LinkScan s = scan_links(ring(), scan);
  ASSERT_TRUE(s.buckled_above && s.flat_high && s.three_d_above);
  // the mirror side (Lk -> -Lk mirrors the ring's states): the same onset
  ASSERT_TRUE(s.buckled_below && s.flat_low);
  EXPECT_NEAR(-*s.buckled_below, *s.buckled_above, 0.25 / 16.0 + 1e-12);
  EXPECT_EQ(s.runs.size(), 10u + 2u * 4u);
  EXPECT_TRUE(std::is_sorted(s.runs.begin(), s.runs.end(),
                             [](const DeployRun& a, const DeployRun& b) { return a.link < b.link; }));
  EXPECT_NEAR(*s.buckled_above - *s.flat_high, 0.25 / 16.0, 1e-12);
  for (const DeployRun& r : s.runs)
    std::cout << "[ measured ] Lk " << r.link << ": flat " << r.flat_status << ", released " << r.status
              << ", 3D-ness " << r.threedim << ", writhe " << r.writhe << ", energy " << r.energy << std::endl;
  const double michell = std::sqrt(3.0) * 1.3;
  std::cout << "[ measured ] ring of " << kVertices << " edges: onset in (" << *s.flat_high << ", "
            << *s.buckled_above << "], Michell " << michell << "; first 3D state at Lk " << *s.three_d_above
            << "; mirror onset in [" << *s.buckled_below << ", " << *s.flat_low << ")" << std::endl;
  EXPECT_NEAR(0.5 * (*s.flat_high + *s.buckled_above), michell, 0.05);
  EXPECT_GE(*s.three_d_above, *s.buckled_above);
  for (const DeployRun& r : s.runs) {
    EXPECT_EQ(r.buckled, r.link > *s.flat_high || r.link < *s.flat_low) << r.link;
    EXPECT_LT(r.link_error, 1e-6) << r.link;
    if (r.buckled) {
      EXPECT_GT(std::fabs(r.writhe), 1.0) << r.link;
    }
  }
}

TEST(Deploy, MisuseThrows) {
  LinkScanOptions scan;
  EXPECT_THROW(scan_links(ring(), scan), InputError);  // empty grid
  scan.grid = {2.0, 1.0};
  EXPECT_THROW(scan_links(ring(), scan), InputError);  // not ascending
  Points lifted = ring();
  lifted.col(2).array() += 5.0;
  EXPECT_THROW(deploy_at_link(lifted, 1.0), InputError);  // outside the slab
}
