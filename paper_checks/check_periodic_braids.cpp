// Paper Section 8.4, Fig. 16: periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p
// (experiments/periodic_braids.cpp): relaxed twist-free from our flat coil
// and from the paper's start (the braid on a tall cylinder), and their p-fold
// symmetric critical points (Newton within the p-fold symmetric subspace)
// with their Morse index. The claim that every member has a stable p-fold
// symmetric 3D state is open (open_claims.cpp). The members whose closure is
// a link are relaxed as links.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/analysis/symmetry.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/conway.hpp"

#include "periodic_braids_summary.hpp"
#include "results.hpp"

using ek::results::PeriodicMember;

namespace {
const std::vector<PeriodicMember>& braid_members() {
  static const auto s = ek::paper::summary<ek::results::PeriodicBraidsSummary>("periodic_braids");
  return s.members;
}
std::string label(const PeriodicMember& m) { return m.family + " p=" + std::to_string(m.p); }
bool is_3d(double threedim) { return threedim >= ek::results::kPlanarThreedim; }
}  // namespace

// The family of paper Fig. 16: 5 members of (σ1σ2⁻¹)^p and 3 of (σ1σ2⁻¹σ3)^p,
// all knots; the tabulated ones (4_1, 8_18, 10_123, 9_40) carry the table's
// Alexander polynomial after relaxation. Tolerance: exact (integer polynomials).
TEST(PaperPeriodicBraids, TabulatedMembersKeepTheTablesKnotType) {
  ASSERT_EQ(braid_members().size(), 8u);
  int tabulated = 0;
  for (const auto& m : braid_members()) {
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
  for (const auto& m : braid_members()) {
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
// stops next to, not on, the symmetric equilibrium; the symmetric critical
// point below is exactly symmetric).
TEST(PaperPeriodicBraids, EveryStateHasPFoldSymmetry) {
  for (const auto& m : braid_members()) {
    const double err = m.symmetry_error, control = m.control_error;
    std::cout << "[ measured ] " << label(m) << ": p-fold symmetry error " << err << ", (p+1)-fold control " << control
              << std::endl;
    EXPECT_LE(err, 0.1) << label(m);
    EXPECT_LE(3.0 * err, control) << label(m);
  }
}

// "We initialized our simulation for these knots from multi-covered circle
// embeddings": from the paper's start (its public code's braid on a tall
// cylinder), 4_1 and 9_40, Fig. 16's first two columns, reach their 3D
// states with both solvers (converged-stable, 3D-ness >= kPlanarThreedim,
// 0.1), and that state is the p-fold symmetric critical point (3D, index 0,
// the same energy to 1e-3 relative: the solver may stop in a slightly
// asymmetric neighbour, 9_40's 3.6e-4 above it).
TEST(PaperPeriodicBraids, FourOneAndNineFortyReachTheirSymmetric3DStatesFromTheCylinder) {
  int found = 0;
  for (const auto& m : braid_members()) {
    if (m.tabulated() != "4_1" && m.tabulated() != "9_40") continue;
    ++found;
    const auto& s = m.symmetric_critical_point;
    for (const auto* e : {&m.equilibrium, &m.equilibrium_paper}) {
      std::cout << "[ measured ] " << label(m) << " (" << m.tabulated() << ") from the cylinder, method " << e->method
                << ": " << e->status << ", energy " << e->energy << ", 3D-ness " << e->threedim << std::endl;
      EXPECT_TRUE(e->stable) << label(m) << " " << e->method;
      EXPECT_TRUE(is_3d(e->threedim)) << label(m) << " " << e->method;
      EXPECT_NEAR(e->energy, s.energy, 1e-3 * s.energy) << label(m) << " " << e->method;
    }
    EXPECT_TRUE(is_3d(s.threedim)) << label(m);
    EXPECT_TRUE(s.index_complete) << label(m);
    EXPECT_EQ(s.index, 0) << label(m);
  }
  EXPECT_EQ(found, 2);
}

// Symmetric criticality: every member's p-fold symmetric critical point,
// found by Newton within the symmetric subspace from the cylinder, is a
// critical point of the full energy: ||∇E|| (full space) <= the model's
// tolerance, the knot type kept, exactly p-fold symmetric (rms distance from
// the symmetry <= 1e-9 edge lengths), its Morse index computed completely
// (some computed eigenvalue non-negative) and its eigenvectors' Fourier
// classes summing to 1. Printed: its energy against the equilibrium's,
// 3D-ness, index, and for each unstable mode its wavenumber (0: symmetric).
TEST(PaperPeriodicBraids, EveryMemberHasAVerifiedSymmetricCriticalPoint) {
  ASSERT_EQ(braid_members().size(), 8u);
  for (const auto& m : braid_members()) {
    const auto& s = m.symmetric_critical_point;
    std::cout << "[ measured ] " << label(m) << ": symmetric critical point (" << s.solve << ") energy " << s.energy
              << " (equilibrium from the cylinder " << m.equilibrium.energy << ", 3D-ness " << m.equilibrium.threedim
              << "), |grad E| " << s.gradient_norm << " (tolerance " << s.tolerance << "), 3D-ness " << s.threedim
              << ", index " << s.index << (s.index_complete ? "" : "+") << " (within the subspace "
              << s.subspace_index << "), unstable modes' wavenumbers:";
    for (const auto& md : s.modes)
      if (md.eigenvalue < -s.threshold) std::cout << " " << md.dominant_class;
    std::cout << std::endl;
    EXPECT_TRUE(s.converged) << label(m) << ": " << s.status;
    EXPECT_LE(s.gradient_norm, s.tolerance) << label(m);
    EXPECT_TRUE(s.alexander_preserved) << label(m);
    EXPECT_LE(s.residual, 1e-9) << label(m);
    EXPECT_TRUE(s.index_complete) << label(m);
    ASSERT_FALSE(s.modes.empty()) << label(m);
    for (const auto& md : s.modes) {
      double sum = 0.0;
      for (double w : md.classes) sum += w;
      EXPECT_NEAR(sum, 1.0, 1e-6) << label(m);
    }
  }
}

// "The crossing patterns form two regular p-gons, one at the top and one at
// the bottom of each embedding." On every member whose p-fold symmetric
// critical point is 3D (4_1 and 9_40 must be among them): its 2p braid
// crossings (projection crossings along the axis whose strands pass within
// kCrossingGap = 2 d̂) lie within 5 degrees of two regular p-gons rotated
// against each other by the family's angle within 5 degrees: 180/p for
// (σ1σ2⁻¹)^p, 0 for (σ1σ2⁻¹σ3)^p. (The paper ties the rotation to the parity
// of p: "for odd p these align, while for even p they are rotated relative
// to each other by π/p"; measured, it follows the family: docs/reproducing.md.)
TEST(PaperPeriodicBraids, Symmetric3DCriticalPointsHaveTwoRegularPolygons) {
  bool four_one = false, nine_forty = false;
  for (const auto& m : braid_members()) {
    const auto& s = m.symmetric_critical_point;
    if (!is_3d(s.threedim)) continue;
    four_one |= m.tabulated() == "4_1";
    nine_forty |= m.tabulated() == "9_40";
    std::cout << "[ measured ] " << label(m) << ": " << s.crossings << " braid crossings, p-gon error "
              << s.polygon_error_deg << " deg, rotation " << s.rotation_deg << " deg (expected "
              << m.expected_rotation_deg << ")" << std::endl;
    EXPECT_EQ(s.crossings, 2 * m.p) << label(m);
    EXPECT_LE(s.polygon_error_deg, 5.0) << label(m);
    EXPECT_LE(std::fabs(s.rotation_deg - m.expected_rotation_deg), 5.0) << label(m);
  }
  EXPECT_TRUE(four_one && nine_forty) << "4_1 and 9_40 must have 3D symmetric critical points (Fig. 16)";
}

// Where the subspace's minimum is flat, the search for a 3D symmetric
// critical point is consistent: the restricted descent from a cylinder as
// tall as it is wide passed through 3D states (3D-ness >= 0.5) and its bottleneck there (the 3D
// image of least gradient norm) is not critical (||∇E|| above the tolerance:
// otherwise it would be the critical point), and Newton–Raphson from it did
// not end at a 3D critical point (or the member would have one). Printed:
// the bottleneck's gradient norm, energy and p-gons (the state Fig. 16 draws
// for these members, labelled "not a critical point").
TEST(PaperPeriodicBraids, FlatMembersBottleneckIsNotCritical) {
  for (const auto& m : braid_members()) {
    if (is_3d(m.symmetric_critical_point.threedim)) {
      // 3D from the subspace's minimum, or found by the search
      if (m.three_d_search) {
        EXPECT_TRUE(m.three_d_search->found) << label(m);
      }
      continue;
    }
    ASSERT_TRUE(m.three_d_search.has_value()) << label(m);
    const auto& b = *m.three_d_search;
    std::cout << "[ measured ] " << label(m) << ": restricted descent of " << b.images << " images; bottleneck image "
              << b.image << ": |grad E| " << b.gradient_norm << ", energy " << b.energy << ", 3D-ness " << b.threedim
              << ", " << b.crossings << " braid crossings, p-gon error " << b.polygon_error_deg << " deg, rotation "
              << b.rotation_deg << " deg; Newton-Raphson from it: " << b.root_status << ", energy " << b.root_energy
              << ", |grad E| " << b.root_gradient_norm << ", 3D-ness " << b.root_threedim << std::endl;
    EXPECT_GE(b.threedim, b.search_threedim) << label(m);
    EXPECT_GT(b.gradient_norm, m.symmetric_critical_point.tolerance) << label(m);
    EXPECT_FALSE(b.found) << label(m);
  }
}

// The symmetry axis recorded in summary.json (which Fig. 16 draws along) is
// the axis of the measured symmetry: recomputed from the written curve about
// the recorded axis and centre, the p-fold error equals the recorded one
// (the curve is written with 17 significant digits; tolerance 1e-9).
TEST(PaperPeriodicBraids, RecordedAxisReproducesTheSymmetryError) {
  for (const auto& m : braid_members()) {
    const ek::Vec3 axis(m.axis[0], m.axis[1], m.axis[2]), c(m.center[0], m.center[1], m.center[2]);
    EXPECT_NEAR(axis.norm(), 1.0, 1e-12) << label(m);
    const ek::Points P = ek::read_curve(ek::paper::results("periodic_braids") + "/" + m.curve);
    EXPECT_NEAR(ek::rotational_symmetry_error(P, c, axis, m.p), m.symmetry_error, 1e-9) << label(m);
  }
}


// (Beyond Fig. 16, which shows knots only; §8.5: links.) The members whose
// closure is a link, one per skipped entry ((σ1σ2⁻¹)^3, the Borromean rings,
// and (σ1σ2⁻¹)^6; (σ1σ2⁻¹σ3)^p for even p), relaxed as links from the coil:
// converged stable, every component's Alexander polynomial, every linking
// number and the link's Conway polynomial kept; the stored link file has the
// recorded component count, linking numbers and Conway polynomial,
// recomputed (exact: integers), the polynomial equal to the braid word's by
// the Burau formula, z⁴ for the Borromean rings (the unlink's is 0). The p-fold symmetry is
// reported beside its (p+1)-fold control, not asserted.
TEST(PaperPeriodicBraids, LinkMembersRelaxAndKeepTheirLinkType) {
  const auto s = ek::paper::summary<ek::results::PeriodicBraidsSummary>("periodic_braids");
  ASSERT_EQ(s.links.size(), s.skipped.size());
  for (const auto& l : s.links) {
    const std::string at = l.family + " p=" + std::to_string(l.p);
    EXPECT_EQ(l.status, "converged-stable") << at;
    EXPECT_TRUE(l.alexander_preserved && l.linking_preserved && l.conway_preserved) << at;
    const ek::Link link = ek::read_link(ek::paper::results("periodic_braids") + "/" + l.curve);
    EXPECT_EQ(ek::conway(link).coefficients, l.conway) << at;  // recomputed from the file
    ek::BraidWord word{l.family == "s1s2i" ? 3 : 4, {}};
    for (int k = 0; k < l.p; ++k)
      for (int letter : l.family == "s1s2i" ? std::vector<int>{1, -2} : std::vector<int>{1, -2, 3})
        word.letters.push_back(letter);
    EXPECT_EQ(ek::conway(word).coefficients, l.conway) << at << ": the braid word's, by the Burau formula";
    if (l.family == "s1s2i" && l.p == 3) {
      EXPECT_EQ(l.conway, (std::vector<std::int64_t>{0, 0, 0, 0, 1})) << "the Borromean rings, not the unlink";
    }
    ASSERT_EQ(static_cast<int>(link.size()), l.components) << at;
    ASSERT_EQ(l.linking_numbers.size(), link.size() * link.size()) << at;
    const Eigen::MatrixXd L = ek::linking_matrix(link);
    for (size_t i = 0; i < link.size(); ++i)
      for (size_t j = 0; j < link.size(); ++j)
        EXPECT_EQ(std::lround(L(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))),
                  l.linking_numbers[i * link.size() + j])
            << at << " (" << i << ", " << j << ")";
    std::cout << "[ measured ] " << at << ": link of " << l.components << ", E " << l.energy << ", 3D-ness "
              << l.threedim << ", p-fold symmetry error " << l.symmetry_error << " (control " << l.control_error
              << ")" << std::endl;
  }
}
