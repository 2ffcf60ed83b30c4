#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <vector>

#include "ek/embedding/embedding.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/solver/multilevel.hpp"
#include "ek/solver/relax.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points trefoil_coil(int n) {
  EmbeddingOptions eo;
  eo.vertices = n;
  return embed_knot(KnotTable::global().at("3_1"), EmbeddingSource::Braid, eo).points;
}

/// Eight vertices: vertex 1 is a corner in the plane z = 0 that the collapse
/// of the odd vertices cuts off; the straight strand 4-5-6 (vertex 5 on it,
/// so it does not move) passes through that corner at (0.3, 0.3) along z.
Points corner_and_strand() {
  Points P(8, 3);
  P << 0, -1, 0,      //
      1, 1, 0,        //
      -1, 1, 0,       //
      -3, 0, 2.5,     //
      0.3, 0.3, 5,    //
      0.3, 0.3, 0,    //
      0.3, 0.3, -5,   //
      0, -3, -2.5;
  return P;
}

}  // namespace

// Coarsening moves each odd vertex onto its neighbours' segment at the ratio
// of its edges' rest lengths; the coarse curve is the moved curve's even
// vertices with pairwise-summed rest lengths, and refining it gives the moved
// curve back exactly (the same polygon). On a smooth curve the motion is
// certified collision-free.
TEST(Multilevel, CoarsenAndRefineGiveTheSamePolygon) {
  const Points P = fixtures::torus_knot(80, 2, 3);
  VecX rest = edge_lengths(P);
  rest(3) *= 3.0;  // unequal rest lengths: vertex 3 moves to rest(2) / (rest(2) + rest(3)) of the way from 2 to 4
  const CoarseCurve c = coarsen(P, rest, ContactOptions{});
  ASSERT_EQ(c.coarse.rows(), 40);
  EXPECT_EQ(c.certified, 1.0);
  for (int k = 0; k < 40; ++k) {
    EXPECT_EQ(c.coarse.row(k), P.row(2 * k));
    EXPECT_DOUBLE_EQ(c.coarse_rest(k), rest(2 * k) + rest(2 * k + 1));
  }
  const Vec3 a = P.row(2).transpose(), b = P.row(4).transpose();
  const double w = rest(2) / (rest(2) + rest(3));
  EXPECT_LT((c.collapsed.row(3).transpose() - (a + w * (b - a))).norm(), 1e-14);
  EXPECT_LT((refine(c.coarse, rest) - c.collapsed).cwiseAbs().maxCoeff(), 1e-14);
  // a polygon whose odd vertices are already on their segments does not move
  const Points R = refine(c.coarse, rest);
  EXPECT_LT((coarsen(R, rest, ContactOptions{}).collapsed - R).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_THROW(coarsen(P.topRows(79), rest.head(79), ContactOptions{}), std::invalid_argument);
}

// A strand passing through the triangle that a collapse sweeps: the motion is
// not certified (the two edges would pass through each other).
TEST(Multilevel, CoarseningThatWouldCrossAStrandIsNotCertified) {
  const Points P = corner_and_strand();
  const VecX rest = edge_lengths(P);
  const CoarseCurve c = coarsen(P, rest, ContactOptions{});
  EXPECT_LT(c.certified, 1.0);
  EXPECT_EQ(c.collapsed.row(5), P.row(5));
}

// Either parity: where collapsing the odd vertices would pass an edge through
// a strand, the even ones are collapsed instead when that is certified; the
// coarse curve is then the odd vertices, and refining it gives the collapsed
// curve back in the fine curve's own vertex order.
TEST(Multilevel, EitherParityCoarseningKeepsTheFineOrder) {
  const Points P = corner_and_strand();  // vertex 1's collapse cuts through the strand 4-5-6
  const VecX rest = edge_lengths(P);
  EXPECT_FALSE(certified_coarsening(P, rest, ContactOptions{}, false));
  const std::optional<ShiftedCoarsening> c = certified_coarsening(P, rest, ContactOptions{}, true);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->offset, 1);
  EXPECT_EQ(c->curve.certified, 1.0);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(c->curve.coarse.row(k), P.row(2 * k + 1));
    EXPECT_DOUBLE_EQ(c->curve.coarse_rest(k), rest(2 * k + 1) + rest((2 * k + 2) % 8));
  }
  const Points R = refine(c->curve.coarse, rest, 1);
  EXPECT_EQ(R, shift_vertices(c->curve.collapsed, 7));  // the collapsed curve, vertex 0 first again
  EXPECT_EQ(R.row(1), P.row(1));                       // the corner is kept
  EXPECT_EQ(shift_vertices(shift_vertices(P, 3), 5), P);
  EXPECT_EQ(shift_vertices(rest, 2)(0), rest(2));
  EXPECT_THROW(shift_vertices(P, 8), std::invalid_argument);
  // a smooth curve keeps its even vertices
  const Points T = fixtures::torus_knot(80, 2, 3);
  EXPECT_EQ(certified_coarsening(T, edge_lengths(T), ContactOptions{}, true)->offset, 0);
}

// Crowded lattice polygons (the default): a level whose coarsening is not
// certified runs its soft phase in chunks of recheck_iterations and tries again, so the
// coarsest level is reached on samples where the first try fails; the phases
// are reported in the order they ran and the knot type is kept.
TEST(Multilevel, CrowdedLevelsAreCoarsenedAfterSoftIterations) {
  SampleOptions so;
  so.vertices = 200;
  so.count = 4;
  so.seed = 3;
  const SampleBatch batch = sample_knot(KnotTable::global().at("12a_1019"), so);
  int rechecked = 0, coarsened = 0;
  for (const auto& sample : batch.samples) {
    const Points P = to_points(sample);
    RelaxOptions two;
    two.coarsening.min_vertices = kMinCoarseVertices;  // n = 200: down to 50 vertices
    const RelaxResult r = relax(P, two);
    ASSERT_EQ(r.status(), RelaxStatus::ConvergedStable);
    const std::string before = "coarse 100: continuation 0.001000 before coarsening";
    const auto soft = std::find(r.phases.begin(), r.phases.end(), before);
    if (soft == r.phases.end()) continue;
    ++rechecked;
    RelaxOptions once = two;
    once.coarsening.rechecks = 0;
    EXPECT_EQ(relax(P, once).coarse_vertices, (std::vector<int>{100}));  // the first try fails
    if (r.coarse_vertices == std::vector<int>{50, 100}) {                // a later try succeeded
      ++coarsened;
      EXPECT_EQ(*std::prev(std::find(r.phases.begin(), r.phases.end(), "coarse 50: continuation 0.001000")), *soft);
      EXPECT_EQ(r.phases.back(), "final");
    }
    EXPECT_LE(r.continuation_reports.size() + r.coarse_reports.size(), 2u + 6u);
  }
  EXPECT_GE(rechecked, 1);
  EXPECT_GE(coarsened, 1);
}

// The multilevel relaxation solves the coarsest level first (a quarter of
// the vertices when that is at least 100, with the contact-stiffness
// continuation), then half, and ends at n with a converged-stable
// equilibrium of the full model; the knot type is kept; one-level solves
// half the vertices first; models it does not apply to, odd counts and
// Direct relax at n only.
TEST(Multilevel, RelaxesThroughTheCoarseLevels) {
  const Points P = trefoil_coil(200);
  RelaxOptions o;
  o.newton.record_trace = true;
  const RelaxResult r = relax(P, with_method(o, "one-level"));
  ASSERT_EQ(r.status(), RelaxStatus::ConvergedStable);
  EXPECT_TRUE(r.alexander_preserved);
  EXPECT_EQ(r.coarse_vertices, (std::vector<int>{100}));
  ASSERT_EQ(r.coarse_reports.size(), 1u);
  EXPECT_GT(r.coarse_reports[0].iterations, 0);
  EXPECT_TRUE(r.continuation_reports.empty());  // the continuation ran at the coarse level
  EXPECT_EQ(r.phases, (std::vector<std::string>{"coarse 100: continuation 0.001000", "coarse 100: final", "final"}));
  EXPECT_EQ(r.positions.rows(), 200);
  EXPECT_LE(r.report.gradient_norm, 1e-8);
  EXPECT_EQ(r.all_phases().iterations, r.report.iterations + r.coarse_reports[0].iterations);

  EXPECT_EQ(relax(P, o).coarse_vertices, (std::vector<int>{100}));  // 50 < 100
  // the floor is for the levels below n/2: a curve of 120 still gets n/2
  EXPECT_EQ(relax(trefoil_coil(120), o).coarse_vertices, (std::vector<int>{60}));
  RelaxOptions two = o;
  two.coarsening.min_vertices = kMinCoarseVertices;
  const RelaxResult r2 = relax(P, two);
  ASSERT_EQ(r2.status(), RelaxStatus::ConvergedStable);
  EXPECT_TRUE(r2.alexander_preserved);
  EXPECT_EQ(r2.coarse_vertices, (std::vector<int>{50, 100}));
  ASSERT_EQ(r2.coarse_reports.size(), 2u);
  EXPECT_EQ(r2.phases, (std::vector<std::string>{"coarse 50: continuation 0.001000", "coarse 50: final",
                                                 "coarse 100: final", "final"}));
  EXPECT_EQ(r2.all_phases().iterations,
            r2.report.iterations + r2.coarse_reports[0].iterations + r2.coarse_reports[1].iterations);
  RelaxOptions direct = o;
  direct.method = RelaxMethod::Direct;
  EXPECT_TRUE(relax(P, direct).coarse_vertices.empty());
  RelaxOptions linked = o;
  linked.link = 3.0;
  const RelaxResult rl = relax(P, linked);
  EXPECT_TRUE(rl.coarse_vertices.empty());
  EXPECT_TRUE(rl.continuation_reports.empty());  // Direct: no continuation unless asked
  EXPECT_TRUE(relax(trefoil_coil(201), o).coarse_vertices.empty());  // odd: one level, with the continuation
}

// The coarsening rule's fewest vertices: recorded in its name when it is not
// the general minimum, refused below it.
TEST(Multilevel, CoarseLevelFloorIsNamedAndChecked) {
  EXPECT_EQ(to_string(CoarseningOptions::even_only()), "even");
  EXPECT_EQ(to_string(CoarseningOptions{}), "either-parity,recheck-30x6,min-100");
  EXPECT_EQ(to_string(CoarseningOptions::rechecked()), "either-parity,recheck-30x6,min-100");
  CoarseningOptions c;
  c.min_vertices = kMinCoarseVertices - 2;
  EXPECT_THROW(c.validate(), InputError);
  RelaxOptions o;
  o.coarsening = c;
  EXPECT_THROW(relax(trefoil_coil(200), o), InputError);
}
