// Constructed knots (ek::relax_construction, paper Fig. 15): the trefoil
// built as the pretzel knot P(-1,-1,-1), drawn, relaxed and measured; the
// table lookup of its polynomial; a rerun against its own equilibrium as the
// pattern gives similarity 1 and alignment distance 0.
#include <gtest/gtest.h>

#include <algorithm>

#include "ek/dataset/construction.hpp"
#include "ek/knots/pretzel.hpp"
#include "ek/knots/table.hpp"

using namespace ek;

TEST(Construction, TableKnotsWithPolynomial) {
  const auto trefoil = table_knots_with_polynomial(alexander(*KnotTable::global().at("3_1").pd));
  EXPECT_NE(std::find(trefoil.begin(), trefoil.end(), "3_1"), trefoil.end());
  const auto k935 = table_knots_with_polynomial(alexander(pretzel_pd({3, 3, 3})));
  EXPECT_NE(std::find(k935.begin(), k935.end(), "9_35"), k935.end());
  // P(5,5,5) (15 crossings, determinant 75) has a polynomial no table knot has
  EXPECT_TRUE(table_knots_with_polynomial(alexander(pretzel_pd({5, 5, 5}))).empty());
}

TEST(Construction, RelaxedAndMeasuredAgainstAPattern) {
  const PDCode pd = pretzel_pd({-1, -1, -1});
  ConstructionOptions o;
  const Points start = embed_pd(pd, o.drawing).points;
  const ConstructedKnot first = relax_construction(pd, start, o);
  EXPECT_EQ(first.relaxed.status(), RelaxStatus::ConvergedStable);
  EXPECT_TRUE(first.alexander_preserved);
  EXPECT_EQ(first.alexander, alexander(*KnotTable::global().at("3_1").pd));
  EXPECT_NE(std::find(first.table_knots.begin(), first.table_knots.end(), "3_1"), first.table_knots.end());
  const GeometricAttributes g = geometric_attributes(first.relaxed.positions);
  EXPECT_EQ(first.attributes.threedim, g.threedim);
  EXPECT_EQ(first.attributes.total_curvature, g.total_curvature);
  EXPECT_EQ(first.circles.circles.size(), 3u);
  EXPECT_GT(first.alignment_distance, 0.1);  // the planar drawing is not the equilibrium
  // its own equilibrium as the pattern (the relaxation is deterministic)
  const ConstructedKnot again = relax_construction(pd, first.relaxed.positions, o);
  EXPECT_NEAR(again.similarity, 1.0, 1e-9);
  EXPECT_LT(again.alignment_distance, 1e-6);
  EXPECT_THROW(relax_construction(pd, start.topRows(100), o), std::invalid_argument);
}
