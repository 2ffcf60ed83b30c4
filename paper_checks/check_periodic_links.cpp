// A study beside paper Fig. 16 (experiments/periodic_links.cpp): the periodic
// braids' coils relaxed at prescribed links under the slab and released (the
// jumping-knot pipeline of paper Section 8.3, with which the paper says Fig.
// 16's states were computed). Label study: `make test` at the ci scale,
// `make studies` at SCALE.
#include <gtest/gtest.h>

#include <cmath>

#include "periodic_links_summary.hpp"
#include "results.hpp"

using ek::results::PeriodicLinksMember;

namespace {
const std::vector<PeriodicLinksMember>& link_members() {
  static const auto s = ek::paper::summary<ek::results::PeriodicLinksSummary>("periodic_links");
  return s.members;
}
std::string label(const PeriodicLinksMember& m) { return m.family + " p=" + std::to_string(m.p); }
}  // namespace

// Fig. 16's states through the paper's pipeline (Section 8.3): the coil
// relaxed with Θ fixed at prescribed links Lk_0 + t (Lk_0 the coil's
// twist-free link), under the slab |z| < 2 d̂, then released. Every run holds
// its link (|Tw + Wr - Lk| <= 1e-6 turns: the full model with Θ fixed); a run
// is 3D exactly when converged-stable with 3D-ness >= kPlanarThreedim (0.1).
// Printed per member: the stable interval of the flat coil, its onsets and
// the nearest 3D states; a member that deploys at no link of the scan is
// listed with the scan's range.
TEST(StudyPeriodicLinks, LinkScanHoldsTheLinkAndFindsTheOnsets) {
  for (const auto& m : link_members()) {
    const auto& ls = m.link_scan;
    ASSERT_FALSE(ls.runs.empty()) << label(m);
    for (const auto& r : ls.runs) {
      std::cout << "[ measured ] " << label(m) << " Lk " << r.link << ": " << r.status << ", energy " << r.energy
                << ", 3D-ness " << r.threedim << ", writhe " << r.writhe << " (flat " << r.flat_writhe
                << "), p-fold symmetry error " << r.symmetry_error << (r.three_d ? " (3D)" : "")
                << (r.buckled ? " (buckled)" : "") << std::endl;
      EXPECT_LE(r.link_error, 1e-6) << label(m) << " Lk " << r.link;
      EXPECT_EQ(r.three_d, r.status == "converged-stable" && r.threedim >= ek::results::kPlanarThreedim)
          << label(m) << " Lk " << r.link;
    }
    using ek::paper::or_na;
    std::cout << "[ measured ] " << label(m) << ": Lk_0 " << ls.center << ", flat and stable on [" << or_na(ls.flat_low)
              << ", " << or_na(ls.flat_high) << "], buckled at " << or_na(ls.buckled_below) << " and "
              << or_na(ls.buckled_above) << ", nearest 3D states at " << or_na(ls.three_d_below) << " and "
              << or_na(ls.three_d_above) << std::endl;
    if (!ls.deploys())
      std::cout << "[ measured ] " << label(m) << ": no stable 3D state at links " << ls.grid.front() << " to "
                << ls.grid.back() << " (" << ls.runs.size() << " links)" << std::endl;
  }
}

// "The crossing patterns form two regular p-gons, one at the top and one at
// the bottom of each embedding." On every member whose link
// scan has a p-fold symmetric 3D state (the scan's most symmetric 3D states
// averaged over their p periods and relaxed again at their links; the best
// one converged-stable, 3D-ness >= 0.1, p-fold symmetry error <= 1e-6); 4_1
// and 9_40 must be among them (Fig. 16's first two columns; they deploy
// twist-free). Its 2p braid crossings (projection crossings along the axis
// whose strands pass within kCrossingGap = 2 d̂) lie within 5 degrees of two
// regular p-gons whose relative rotation is within 5 degrees of the family's
// (180/p for (σ1σ2⁻¹)^p, 0 for (σ1σ2⁻¹σ3)^p; the paper ties it to the parity
// of p instead: docs/reproducing.md).
TEST(StudyPeriodicLinks, SymmetricDeployedStatesHaveTwoRegularPolygons) {
  bool four_one = false, nine_forty = false;
  for (const auto& m : link_members()) {
    if (!m.link_scan.symmetric) continue;
    const auto& y = *m.link_scan.symmetric;
    const double exp = m.expected_rotation_deg;
    std::cout << "[ measured ] " << label(m) << ": symmetrized 3D state at Lk " << y.link << " " << y.status
              << ", energy " << y.energy << " (" << y.energy_above << " from the scan's state), 3D-ness "
              << y.threedim << ", writhe " << y.writhe << ", symmetry error " << y.symmetry_error << " (from "
              << y.from_symmetry_error << "), " << y.crossings << " braid crossings, p-gon error "
              << y.polygon_error_deg << " deg, rotation " << y.relative_rotation_deg << " deg (expected " << exp
              << ")" << std::endl;
    if (y.status != "converged-stable" || y.threedim < ek::results::kPlanarThreedim || y.symmetry_error > 1e-6)
      continue;
    four_one |= m.tabulated() == "4_1";
    nine_forty |= m.tabulated() == "9_40";
    EXPECT_EQ(y.crossings, 2 * m.p) << label(m);
    EXPECT_LE(y.polygon_error_deg, 5.0) << label(m);
    EXPECT_LE(std::fabs(y.relative_rotation_deg - exp), 5.0) << label(m);
  }
  EXPECT_TRUE(four_one && nine_forty) << "4_1 and 9_40 must have p-fold symmetric 3D states (Fig. 16)";
}
