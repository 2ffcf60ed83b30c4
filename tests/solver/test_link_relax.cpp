// Links relaxed (relax() of a Link, relax.hpp; rod_model.hpp): the
// two-component model's gradient and Hessian against finite differences
// with contact active between the components; a step that sweeps one ring through the other is cut by the
// collision detection; the Hopf link relaxes to two round rings (its energy
// that of the two rings relaxed alone) keeping its unknots and its linking
// number; the (2, 4) torus link keeps its linking number 2 in contact; a
// link of one component is a knot; bad input is an InputError.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/solver/relax.hpp"
#include "ek/solver/rod_model.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

using fixtures::circle;

/// A ring of radius 3 and a small ring (radius 0.35, within d̂ = 0.4 of the
/// first) through it: contact active between the components.
Link tight_hopf() {
  return {circle(48, Vec3::Zero(), 3.0, Vec3::UnitX(), Vec3::UnitY()),
          circle(12, Vec3(3.0, 0.0, 0.0), 0.35, Vec3::UnitX(), Vec3::UnitZ())};
}

/// Component c of the (2, 4) torus link on the torus of radii 6 and 2.5.
Points torus_component(int c, int n) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n, theta = 2.0 * t + c * M_PI;
    P.row(i) << (6.0 + 2.5 * std::cos(theta)) * std::cos(t), (6.0 + 2.5 * std::cos(theta)) * std::sin(t),
        2.5 * std::sin(theta);
  }
  return P;
}

Eigen::MatrixXd dense_hessian(Objective& f) {
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);  // one whole pass (begin ... end)
  const Eigen::SparseMatrix<double> full = A.matrix().selfadjointView<Eigen::Upper>();
  return Eigen::MatrixXd(full);
}

}  // namespace

// Energy, gradient and Hessian of the two rods and the contact between
// them match central differences (h = 1e-6) at a configuration where the
// components are within d̂ of each other; the energy parts sum to E.
TEST(LinkRelax, TwoComponentModelMatchesFiniteDifferences) {
  const Link link = tight_hopf();
  RodModel m(link, RelaxOptions{});
  Objective& f = m.objective();
  ASSERT_GT(f.active_pairs(), 0);
  const VecX x = f.dofs();
  ASSERT_EQ(x.size(), 3 * 60);
  double parts = 0.0;
  for (const EnergyPart& p : f.energy_parts()) parts += p.value;
  EXPECT_NEAR(parts, f.energy(), 1e-12 * f.energy());
  const VecX g = f.gradient();
  const VecX fd = fixtures::fd_gradient(
      [&](const VecX& y) {
        f.set_dofs(y);
        return f.energy();
      },
      x, 1e-6);
  f.set_dofs(x);
  EXPECT_LT((g - fd).norm(), 1e-6 * g.norm()) << "gradient";
  const Eigen::MatrixXd H = dense_hessian(f);
  Eigen::MatrixXd Hfd(x.size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    VecX a = x, b = x;
    a(k) += 1e-6;
    b(k) -= 1e-6;
    f.set_dofs(a);
    const VecX ga = f.gradient();
    f.set_dofs(b);
    Hfd.col(k) = (ga - f.gradient()) / 2e-6;
  }
  f.set_dofs(x);
  EXPECT_LT((H - Hfd).norm(), 1e-5 * H.norm()) << "Hessian";
  // the contact couples the components: a block of H across them is nonzero
  EXPECT_GT(H.block(0, 3 * 48, 3 * 48, 3 * 12).cwiseAbs().maxCoeff(), 0.0);
}

// The small ring moved by 3 along −x would pass through the large ring's
// wire: the certified step is cut below 1, and at the cut the components
// are still apart.
TEST(LinkRelax, SweepingOneComponentThroughAnotherIsCut) {
  const Link link = tight_hopf();
  RodModel m(link, RelaxOptions{});
  Objective& f = m.objective();
  const VecX x = f.dofs();
  VecX dx = VecX::Zero(x.size());
  for (int i = 48; i < 60; ++i) dx(3 * i) = -3.0;
  const double t = f.max_step(x, dx);
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 0.2);  // the wire is 0.35 away: the step stops before it
  const Points moved = as_points(x + t * dx);
  EXPECT_GT(component_distance(moved.topRows(48), moved.bottomRows(12)), 0.0);
}

// The Hopf link of two rings (radius 5, 40 vertices, their planes at right
// angles, each through the other's centre) is already at equilibrium up to
// the discretisation: relaxed, it converges stable, its components stay
// unknots, its linking number stays −1, no contact is active, and its
// energy is the sum of the two rings relaxed alone (to 1e-9 relative).
TEST(LinkRelax, HopfLinkRelaxesToTwoRoundRings) {
  const Link link{circle(40, Vec3::Zero(), 5.0, Vec3::UnitX(), Vec3::UnitY()),
                  circle(40, Vec3(5.0, 0.0, 0.0), 5.0, Vec3::UnitX(), Vec3::UnitZ())};
  const RelaxResult r = relax(link);
  EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
  EXPECT_TRUE(r.alexander_preserved && r.linking_preserved && r.conway_preserved);
  ASSERT_TRUE(r.link_type.has_value());
  EXPECT_EQ(r.link_type->linking_numbers(0, 1), -1);
  EXPECT_EQ(r.link_type->conway.to_string(), "[0, 1]");
  for (const AlexanderPolynomial& a : r.link_type->alexander) EXPECT_EQ(a.to_string(), "[1]");
  EXPECT_EQ(r.component_sizes, (std::vector<int>{40, 40}));
  const double alone = relax(link[0]).energy.total + relax(link[1]).energy.total;
  EXPECT_NEAR(r.energy.total, alone, 1e-9 * alone);
  EXPECT_GT(r.min_distance, 0.4);  // d̂: no contact
}

// The (2, 4) torus link relaxed: its components are drawn together (they
// twist about each other twice) until the contact holds them; converged
// stable, unknots, linking number 2 kept (checked on the result again here),
// the energy lower than at the start, the components at least 0.2·d̂ apart.
TEST(LinkRelax, TorusLinkKeepsItsLinkingNumberInContact) {
  const Link link{torus_component(0, 80), torus_component(1, 80)};
  const double lk = linking_number(link[0], link[1]);
  ASSERT_NEAR(std::abs(lk), 2.0, 1e-9);
  RodModel start(link, RelaxOptions{});
  const double e0 = start.objective().energy();
  const RelaxResult r = relax(link);
  EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
  EXPECT_LT(r.energy.total, e0);
  const Link out = r.components();
  EXPECT_NEAR(linking_number(out[0], out[1]), lk, 1e-9);
  for (const Points& P : out) EXPECT_EQ(alexander(P).to_string(), "[1]");
  EXPECT_GT(r.min_distance, 0.2 * 0.4);
  const double apart = component_distance(out[0], out[1]);
  EXPECT_LT(apart, 0.4);  // in contact
  std::cout << "[ measured ] (2,4) torus link: E " << e0 << " -> " << r.energy.total << " in " << r.report.iterations
            << " iterations, " << r.report.seconds << " s; components " << apart << " apart" << std::endl;
}

// A link of one component is a knot: relax() of it equals relax() of the
// curve, to the iteration and the bit.
TEST(LinkRelax, ALinkOfOneComponentIsAKnot) {
  const Points P = torus_component(0, 80);
  const RelaxResult a = relax(Link{P}), b = relax(P);
  EXPECT_EQ(a.report.iterations, b.report.iterations);
  EXPECT_EQ(a.energy.total, b.energy.total);
  EXPECT_TRUE(a.positions == b.positions);
  EXPECT_EQ(a.component_sizes, (std::vector<int>{80}));
  EXPECT_FALSE(a.link_type.has_value());
}

TEST(LinkRelax, BadInputIsAnInputError) {
  const Link link = tight_hopf();
  EXPECT_THROW(relax(Link{}), InputError);
  RelaxOptions with_lk;
  with_lk.link = 1.0;
  EXPECT_THROW(relax(link, with_lk), InputError);
  RelaxOptions full;
  full.full_model = true;
  EXPECT_THROW(relax(link, full), InputError);
  RelaxOptions eigen;
  eigen.smallest_eigenvalue = true;
  EXPECT_THROW(relax(link, eigen), InputError);
  Link crossing = link;
  crossing[1].col(0).array() -= 0.35;  // the small ring now passes through the wire
  EXPECT_THROW(relax(crossing), InputError);
}
