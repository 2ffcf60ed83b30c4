// The model of a relaxation (rod_model.hpp) on curves with known answers:
// a regular polygon's bending energy (n·EI/2·(2 tan(π/n))²/ℓ) for one
// component and twice it for a Hopf link of two such rings; the resolved
// model and λ_min of relax(); the contact factor scaling the barrier alone;
// the slab as a term only when asked, with the slab's three rigid modes;
// the same objective while the arguments are the same; and what the model
// refuses.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/solver/rod_model.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

using fixtures::circle;

/// [energy] the bending energy of a regular n-gon with edge ℓ (elastic_rod.hpp).
double polygon_bending(int n, double edge, const RodMaterial& m) {
  const double kb = 2.0 * std::tan(M_PI / n);
  return n * 0.5 * m.bending_stiffness() * kb * kb / edge;
}

double part(Objective& f, const std::string& name) {
  for (const EnergyPart& p : f.energy_parts())
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no part " << name;
  return 0.0;
}

Link hopf(int n) {
  return {circle(n, Vec3::Zero(), 5.0, Vec3::UnitX(), Vec3::UnitY()),
          circle(n, Vec3(5.0, 0.0, 0.0), 5.0, Vec3::UnitX(), Vec3::UnitZ())};
}

/// A ring of radius 3 and a small ring (radius 0.35, within d̂ = 0.4 of the
/// first) through it: contact active between the components.
Link ring_through_ring() {
  return {circle(48, Vec3::Zero(), 3.0, Vec3::UnitX(), Vec3::UnitY()),
          circle(12, Vec3(3.0, 0.0, 0.0), 0.35, Vec3::UnitX(), Vec3::UnitZ())};
}

}  // namespace

// One ring of 40 vertices: the model's energy is the polygon's bending
// (to 1e-12 relative), stretch, twist and contact 0; d̂, ω, the tolerance,
// the twist model and λ_min are those relax() resolves.
TEST(RodModel, ARingHasThePolygonsBendingEnergy) {
  const Points P = circle(40, 5.0);
  const RelaxOptions o;
  RodModel m(Link{P}, o);
  const double edge = edge_lengths(P).mean();
  Objective& f = m.objective();
  const double expected = polygon_bending(40, edge, o.material);
  EXPECT_NEAR(part(f, "bend"), expected, 1e-12 * expected);
  EXPECT_NEAR(part(f, "stretch"), 0.0, 1e-12 * expected);
  EXPECT_EQ(part(f, "twist"), 0.0);
  EXPECT_EQ(part(f, "contact"), 0.0);
  EXPECT_NEAR(f.energy(), expected, 1e-12 * expected);
  const ResolvedModel r = resolve_model(o, edge);
  EXPECT_EQ(m.resolved().dhat, r.dhat);
  EXPECT_EQ(m.resolved().contact_stiffness, r.contact_stiffness);
  EXPECT_EQ(m.tolerance(), r.tolerance);
  EXPECT_EQ(m.resolved().model, TwistModel::TwistFree);
  EXPECT_EQ(m.lambda_min(), cached_lambda_min(40, edge, o.material, TwistModel::TwistFree));
  EXPECT_EQ(m.newton().max_iterations, o.max_iterations);
  EXPECT_EQ(f.num_dofs(), 120);
  EXPECT_EQ(f.rigid_modes().cols(), 6);
}

// A Hopf link of two such rings: twice the bending energy, the dofs the
// components back to back, λ_min that of the straight rod with all 80
// vertices, six rigid modes of the whole link.
TEST(RodModel, AHopfLinkIsTwoRingsBackToBack) {
  const Link link = hopf(40);
  RodModel m(link, RelaxOptions{});
  ASSERT_EQ(m.num_components(), 2);
  EXPECT_EQ(m.num_vertices(), 80);
  Objective& f = m.objective();
  const double edge = edge_lengths(link[0]).mean();
  const double expected = 2.0 * polygon_bending(40, edge, RodMaterial{});
  EXPECT_NEAR(f.energy(), expected, 1e-12 * expected);
  EXPECT_EQ(f.num_dofs(), 240);
  EXPECT_TRUE(f.dofs().tail(120) == as_vector(link[1]));
  EXPECT_TRUE(m.positions().bottomRows(40) == link[1]);
  EXPECT_TRUE(m.components()[0] == link[0]);
  EXPECT_EQ(m.lambda_min(), cached_lambda_min(80, edge, RodMaterial{}, TwistModel::TwistFree));
  EXPECT_EQ(f.rigid_modes().cols(), 6);
  EXPECT_GT(m.min_distance(), 0.4);
}

// With contact active, the objective at factor f has f times the contact
// energy (to 1e-12 relative) and the same rod parts; asking again with the
// same arguments returns the same object, with others a new one.
TEST(RodModel, TheContactFactorScalesTheBarrierOnly) {
  RodModel m(ring_through_ring(), RelaxOptions{});
  CompositeObjective& full = m.objective();
  ASSERT_GT(full.active_pairs(), 0);
  const double contact = part(full, "contact"), bend = part(full, "bend");
  EXPECT_EQ(&m.objective(), &full);
  Objective& soft = m.objective(0.25);
  EXPECT_NEAR(part(soft, "contact"), 0.25 * contact, 1e-12 * contact);
  EXPECT_EQ(part(soft, "bend"), bend);
  EXPECT_NEAR(part(m.objective(1.0), "contact"), contact, 1e-12 * contact);
  EXPECT_THROW(m.objective(0.0), std::invalid_argument);
}

// A ring in the plane z = 0 inside the slab |z| < 0.5: the slab is a term
// (part "slab") with the slab's own rigid modes (x, y translations and the
// turn about z) only when asked.
TEST(RodModel, TheSlabIsATermOnlyWhenAsked) {
  RelaxOptions o;
  o.slab = SlabOptions{};
  RodModel m(Link{circle(40, 5.0)}, o);
  ASSERT_NE(m.slab(), nullptr);
  CompositeObjective& with = m.objective(1.0, true);
  EXPECT_EQ(with.terms().size(), 3u);
  EXPECT_EQ(with.energy_parts().back().name, "slab");
  EXPECT_EQ(with.rigid_modes().cols(), 3);
  CompositeObjective& without = m.objective(1.0, false);
  EXPECT_EQ(without.terms().size(), 2u);
  EXPECT_EQ(without.rigid_modes().cols(), 6);
}

// What the model does not have is an InputError: a link with a slab, the
// full model, a prescribed Lk or given rest lengths; a curve that touches
// itself; a curve of 3 vertices; a start outside the slab.
TEST(RodModel, RefusesWhatItDoesNotModel) {
  const Link link = hopf(40);
  RelaxOptions slab, full, lk, rest;
  slab.slab = SlabOptions{};
  full.full_model = true;
  lk.link = 1.0;
  rest.rest_lengths = VecX::Ones(40);
  for (const RelaxOptions& o : {slab, full, lk, rest}) EXPECT_THROW(RodModel(link, o), InputError);
  Points folded = circle(40, 5.0);
  folded.row(20) = folded.row(0);  // vertex 20 on vertex 0
  EXPECT_THROW(RodModel(Link{folded}, RelaxOptions{}), InputError);
  EXPECT_THROW(RodModel(Link{circle(3, 5.0)}, RelaxOptions{}), InputError);
  Points tilted = circle(40, 5.0);
  tilted.col(2) = tilted.col(0);  // |z| up to 5
  EXPECT_THROW(RodModel(Link{tilted}, slab), InputError);
}
