#include <gtest/gtest.h>

#include <cmath>

#include "ek/geometry/polyline.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "testing.hpp"

using namespace ek;

TEST(Resample, ArclengthOnCircle) {
  const Points C = fixtures::circle(1000, 1.0);
  const Points Q = resample_arclength(C, 37);
  const VecX len = edge_lengths(Q);
  EXPECT_LT(len.maxCoeff() - len.minCoeff(), 1e-6);
  EXPECT_EQ(Q.rows(), 37);
}

TEST(Resample, EquilateralGivesEqualChords) {
  for (int seed = 0; seed < 5; ++seed) {
    const Points P = fixtures::torus_knot(500, 2, 3 + 2 * seed);
    for (int m : {50, 123, 400}) {
      const auto r = resample_equilateral(P, m);
      ASSERT_EQ(r.points.rows(), m);
      const VecX len = edge_lengths(r.points);
      EXPECT_LT((len.array() - r.edge_length).abs().maxCoeff(), 1e-9 * r.edge_length) << seed << " " << m;
      EXPECT_LE(r.max_deviation, 1e-9 * r.edge_length);
      // every point lies on the input polygon
      for (int k = 0; k < m; ++k) {
        double best = 1e300;
        for (int i = 0; i < P.rows(); ++i)
          best = std::min(best, point_segment_distance_squared(r.points.row(k).transpose(), P.row(i).transpose(),
                                                               P.row((i + 1) % P.rows()).transpose()));
        EXPECT_LT(std::sqrt(best), 1e-12) << k;
      }
    }
  }
}

TEST(Resample, RefineKeepsShape) {
  Points S(4, 3);
  S << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  const Points R = refine(S, 0.3);
  EXPECT_EQ(R.rows(), 16);
  EXPECT_NEAR(curve_length(R), 4.0, 1e-14);
  EXPECT_LE(edge_lengths(R).maxCoeff(), 0.3);
}
