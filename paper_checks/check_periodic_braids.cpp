// Paper Section 8.4, Fig. 16: periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p
// relaxed from their multi-covered circles (experiments/periodic_braids.cpp).
// The claim this project does not reproduce (a 3D state for every p) is in
// open_claims.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/analysis/symmetry.hpp"
#include "ek/geometry/curve_io.hpp"

#include "periodic_braids_summary.hpp"
#include "results.hpp"

using ek::results::PeriodicMember;

namespace {
const std::vector<PeriodicMember>& members() {
  static const auto s = ek::paper::summary<ek::results::PeriodicBraidsSummary>("periodic_braids");
  return s.members;
}
std::string label(const PeriodicMember& m) { return m.family + " p=" + std::to_string(m.p); }
}  // namespace

// The family of paper Fig. 16: 5 members of (σ1σ2⁻¹)^p and 3 of (σ1σ2⁻¹σ3)^p,
// all knots; the tabulated ones (4_1, 8_18, 10_123, 9_40) carry the table's
// Alexander polynomial after relaxation. Tolerance: exact (integer polynomials).
TEST(PaperPeriodicBraids, TabulatedMembersKeepTheTablesKnotType) {
  ASSERT_EQ(members().size(), 8u);
  int tabulated = 0;
  for (const auto& m : members()) {
    EXPECT_TRUE(m.alexander_preserved) << label(m);
    if (m.tabulated().empty()) {
      EXPECT_FALSE(m.alexander_matches_table.has_value()) << label(m);  // nothing to compare with
      continue;
    }
    ++tabulated;
    std::cout << "[ measured ] " << label(m) << " (" << m.tabulated()
              << "): Alexander polynomial matches the table: " << ek::paper::or_na(m.alexander_matches_table)
              << std::endl;
    EXPECT_EQ(m.alexander_matches_table, std::optional<bool>(true)) << label(m);
  }
  EXPECT_EQ(tabulated, 4);
}

// Every member relaxes to a stable equilibrium (gradient below tolerance,
// Hessian positive semidefinite up to the rigid motions).
TEST(PaperPeriodicBraids, EveryMemberIsAStableEquilibrium) {
  for (const auto& m : members()) {
    std::cout << "[ measured ] " << label(m) << ": " << m.status << ", 3D-ness " << m.threedim << std::endl;
    EXPECT_EQ(m.status, "converged-stable") << label(m);
  }
}

// "The observed topological pattern also manifests itself in geometric
// symmetry": p-fold rotational symmetry about a principal axis. Error: mean
// distance from each rotated vertex to the curve over the radius of gyration.
// Tolerance 0.1, and at most a third of the control error of a (p+1)-fold
// rotation about the same axis (what a state without the symmetry scores).
// Measured at n = 100·p: coils ~1e-13; 4_1 0.019 and 9_40 0.028 (the solver
// stops next to, not on, the symmetric equilibrium: see the next test).
TEST(PaperPeriodicBraids, EveryStateHasPFoldSymmetry) {
  for (const auto& m : members()) {
    const double err = m.symmetry_error, control = m.control_error;
    std::cout << "[ measured ] " << label(m) << ": p-fold symmetry error " << err << ", (p+1)-fold control " << control
              << std::endl;
    EXPECT_LE(err, 0.1) << label(m);
    EXPECT_LE(3.0 * err, control) << label(m);
  }
}

// "The crossing patterns form two regular p-gons, one at the top and one at
// the bottom of each embedding. For odd p these align, while for even p they
// are rotated relative to each other by π/p." Checked on every member whose
// relaxed state is 3D (3D-ness >= kPlanarThreedim, 0.1; Fig. 16's first two columns, 4_1 and
// 9_40, must be among them), at the p-fold symmetric equilibrium next to it:
// the relaxed state's p-fold average relaxed again (experiments/
// periodic_braids.cpp). It must be converged-stable, p-fold symmetric
// (error <= 1e-6), within 1e-3 relative energy of the relaxed state, and its
// braid crossings (projection crossings along the axis whose strands pass
// within kCrossingGap = 2 d̂) must lie within 5 degrees of two regular p-gons whose relative
// rotation is within 5 degrees of 0 (odd p) or 180/p (even p).
TEST(PaperPeriodicBraids, SymmetricStatesHaveTwoRegularPolygons) {
  int three_d = 0;
  bool four_one = false, nine_forty = false;
  for (const auto& m : members()) {
    if (m.threedim < ek::results::kPlanarThreedim) continue;
    ++three_d;
    four_one |= m.tabulated() == "4_1";
    nine_forty |= m.tabulated() == "9_40";
    const auto& sy = m.symmetric;
    const double rot = sy.relative_rotation_deg, exp = m.expected_rotation_deg;
    std::cout << "[ measured ] " << label(m) << ": symmetric equilibrium " << sy.status << ", energy "
              << sy.energy_above << " from the relaxed state's, symmetry error " << sy.symmetry_error << ", "
              << sy.crossings << " braid crossings, p-gon error " << sy.polygon_error_deg << " deg, rotation " << rot
              << " deg (expected " << exp << "); relaxed state: p-gon error " << m.polygon_error_deg
              << " deg, rotation " << m.relative_rotation_deg << " deg" << std::endl;
    EXPECT_EQ(sy.status, "converged-stable") << label(m);
    EXPECT_LE(sy.symmetry_error, 1e-6) << label(m);
    EXPECT_LE(std::fabs(sy.energy_above), 1e-3 * m.energy) << label(m);
    EXPECT_EQ(sy.crossings, 2 * m.p) << label(m);  // one p-gon at each end
    EXPECT_LE(sy.polygon_error_deg, 5.0) << label(m);
    EXPECT_LE(std::fabs(rot - exp), 5.0) << label(m);
  }
  EXPECT_TRUE(four_one && nine_forty) << three_d << " 3D members; 4_1 and 9_40 must be 3D (Fig. 16)";
}

// The symmetry axis recorded in summary.json (which Fig. 16 draws along) is
// the axis of the measured symmetry: recomputed from the written curve about
// the recorded axis and centre, the p-fold error equals the recorded one
// (the curve is written with 17 significant digits; tolerance 1e-9).
TEST(PaperPeriodicBraids, RecordedAxisReproducesTheSymmetryError) {
  for (const auto& m : members()) {
    ASSERT_TRUE(m.axis && m.center && m.curve) << label(m) << ": summary.json predates the axis: rerun the experiment";
    const ek::Vec3 axis((*m.axis)[0], (*m.axis)[1], (*m.axis)[2]), c((*m.center)[0], (*m.center)[1], (*m.center)[2]);
    EXPECT_NEAR(axis.norm(), 1.0, 1e-12) << label(m);
    const ek::Points P = ek::read_curve(ek::paper::results("periodic_braids") + "/" + *m.curve);
    EXPECT_NEAR(ek::rotational_symmetry_error(P, c, axis, m.p), m.symmetry_error, 1e-9) << label(m);
  }
}
