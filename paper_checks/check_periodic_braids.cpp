// Paper Section 8.4, Fig. 16: periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p
// relaxed from their multi-covered circles (experiments/periodic_braids.cpp).
// The claims this project does not reproduce (3D states for every p, the two
// regular p-gons) are in open_claims.cpp.
#include <gtest/gtest.h>

#include "results.hpp"

namespace {
const nlohmann::json& members() {
  static const nlohmann::json s = ek::paper::summary("periodic_braids");
  return s.at("members");
}
std::string label(const nlohmann::json& m) {
  return m.at("family").get<std::string>() + " p=" + std::to_string(m.at("p").get<int>());
}
}  // namespace

// The family as in the issue: 5 members of (σ1σ2⁻¹)^p and 3 of (σ1σ2⁻¹σ3)^p,
// all knots; the tabulated ones (4_1, 8_18, 10_123, 9_40) carry the table's
// Alexander polynomial after relaxation. Tolerance: exact (integer polynomials).
TEST(PaperPeriodicBraids, TabulatedMembersKeepTheTablesKnotType) {
  ASSERT_EQ(members().size(), 8u);
  int tabulated = 0;
  for (const auto& m : members()) {
    EXPECT_TRUE(m.at("alexander_preserved").get<bool>()) << label(m);
    if (m.at("knot").get<std::string>().empty()) continue;
    ++tabulated;
    std::cout << "[ measured ] " << label(m) << " (" << m.at("knot").get<std::string>()
              << "): Alexander polynomial matches the table: " << m.at("alexander_matches_table") << std::endl;
    EXPECT_EQ(m.at("alexander_matches_table").get<std::string>(), "1") << label(m);
  }
  EXPECT_EQ(tabulated, 4);
}

// Every member relaxes to a stable equilibrium (gradient below tolerance,
// Hessian positive semidefinite up to the rigid motions).
TEST(PaperPeriodicBraids, EveryMemberIsAStableEquilibrium) {
  for (const auto& m : members()) {
    std::cout << "[ measured ] " << label(m) << ": " << m.at("status").get<std::string>() << ", 3D-ness "
              << m.at("threedim") << std::endl;
    EXPECT_EQ(m.at("status").get<std::string>(), "converged-stable") << label(m);
  }
}

// "The observed topological pattern also manifests itself in geometric
// symmetry": p-fold rotational symmetry about a principal axis. Error: mean
// distance from each rotated vertex to the curve over the radius of gyration.
// Tolerance 0.1, and at most a third of the control error of a (p+1)-fold
// rotation about the same axis (what a state without the symmetry scores).
// Measured at n = 100·p: coils ~1e-13; 4_1 0.058 and 9_40 0.024 (their 3D
// states are not exactly symmetric at this resolution and thickness).
TEST(PaperPeriodicBraids, EveryStateHasPFoldSymmetry) {
  for (const auto& m : members()) {
    const double err = m.at("symmetry_error").get<double>(), control = m.at("control_error").get<double>();
    std::cout << "[ measured ] " << label(m) << ": p-fold symmetry error " << err << ", (p+1)-fold control " << control
              << std::endl;
    EXPECT_LE(err, 0.1) << label(m);
    EXPECT_LE(3.0 * err, control) << label(m);
  }
}
