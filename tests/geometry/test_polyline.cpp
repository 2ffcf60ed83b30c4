#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/hash.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "testing.hpp"

using namespace ek;

TEST(Polyline, CircleLengthAndCurvature) {
  const int n = 64;
  const Points C = fixtures::circle(n, 2.0);
  EXPECT_NEAR(curve_length(C), n * 2.0 * 2.0 * std::sin(M_PI / n), 1e-12);
  const VecX a = turning_angles(C);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(a(i), 2.0 * M_PI / n, 1e-12);
  EXPECT_NEAR(total_curvature(C), 2.0 * M_PI, 1e-12);  // convex planar polygon: exactly 2π
  EXPECT_NEAR(centroid(C).norm(), 0.0, 1e-12);
}

TEST(Polyline, DoublyCoveredCircleHasTotalCurvature4Pi) {
  // Two turns with a small radial offset, like the paper's 2-covered circle.
  const int n = 200;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 4.0 * M_PI * i / n;
    const double r = 1.0 + 0.02 * std::sin(s / 2.0);
    P.row(i) << r * std::cos(s), r * std::sin(s), 0.01 * std::sin(s / 2.0);
  }
  EXPECT_NEAR(total_curvature(P), 4.0 * M_PI, 0.02 * 4.0 * M_PI);
}

TEST(Polyline, SquareTurningAngles) {
  Points S(4, 3);
  S << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(turning_angles(S)(i), M_PI / 2, 1e-15);
  // Clearance: opposite edges are 1 apart; adjacent ones excluded.
  auto c = clearance(S);
  EXPECT_NEAR(c.distance, 1.0, 1e-15);
}

// An ellipse with semi-axes 3 and 1 in a rotated plane: the axes in the order
// of ascending spread are its normal, its minor and its major axis.
TEST(Polyline, PrincipalAxesOfARotatedEllipse) {
  const Mat3 R = fixtures::random_rotation(5);
  Points P(64, 3);
  for (int i = 0; i < 64; ++i) {
    const double t = 2 * M_PI * i / 64;
    P.row(i) = (R * Vec3(3 * std::cos(t), std::sin(t), 0.0) + Vec3(1, -2, 0.5)).transpose();
  }
  const Mat3 A = principal_axes(P);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(A.col(k).dot(R.col(k == 0 ? 2 : k == 1 ? 1 : 0))), 1.0, 1e-12) << k;
  EXPECT_NEAR((A.transpose() * A - Mat3::Identity()).norm(), 0.0, 1e-12);
}

TEST(SegmentDistance, KnownConfigurations) {
  double s, t;
  // crossing at right angles, 1 apart in z
  EXPECT_NEAR(segment_segment_distance_squared({-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}, &s, &t), 1.0, 1e-15);
  EXPECT_NEAR(s, 0.5, 1e-15);
  EXPECT_NEAR(t, 0.5, 1e-15);
  // parallel, overlapping
  EXPECT_NEAR(segment_segment_distance_squared({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0}), 1.0, 1e-15);
  // parallel, disjoint along the axis: endpoint to endpoint
  EXPECT_NEAR(segment_segment_distance_squared({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0}), 2.0, 1e-15);
  // point-edge: endpoint of one to the interior of the other
  EXPECT_NEAR(segment_segment_distance_squared({0, 0, 0}, {2, 0, 0}, {1, 0.5, 0}, {1, 3, 0}), 0.25, 1e-15);
  // degenerate segment (a point)
  EXPECT_NEAR(segment_segment_distance_squared({1, 1, 0}, {1, 1, 0}, {0, 0, 0}, {2, 0, 0}), 1.0, 1e-15);
  // nearly parallel
  EXPECT_NEAR(segment_segment_distance_squared({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1 + 1e-12, 0}), 1.0, 1e-11);
}

TEST(SegmentDistance, ParametersNameTheClosestPoints) {
  // Every branch (interior, each endpoint against the other segment,
  // parallel): p(s) and q(t) realise the distance and are the expected points.
  double s = -1, t = -1;
  // endpoint p0 against the interior of q
  EXPECT_NEAR(segment_segment_distance_squared({1, 0.5, 0}, {1, 3, 0}, {0, 0, 0}, {2, 0, 0}, &s, &t), 0.25, 1e-15);
  EXPECT_NEAR(s, 0.0, 1e-15);
  EXPECT_NEAR(t, 0.5, 1e-15);
  // endpoint q1 against the interior of p
  EXPECT_NEAR(segment_segment_distance_squared({0, 0, 0}, {4, 0, 0}, {1, 3, 0}, {1, 0.5, 0}, &s, &t), 0.25, 1e-15);
  EXPECT_NEAR(s, 0.25, 1e-15);
  EXPECT_NEAR(t, 1.0, 1e-15);
  // endpoint to endpoint
  EXPECT_NEAR(segment_segment_distance_squared({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0}, &s, &t), 2.0, 1e-15);
  EXPECT_NEAR(s, 1.0, 1e-15);
  EXPECT_NEAR(t, 0.0, 1e-15);
  std::uint64_t state = 17;
  for (int k = 0; k < 2000; ++k) {
    Vec3 p[4];
    for (Vec3& v : p) v = Vec3(splitmix64_uniform(state), splitmix64_uniform(state), splitmix64_uniform(state)) * 2.0;
    const double d2 = segment_segment_distance_squared(p[0], p[1], p[2], p[3], &s, &t);
    ASSERT_TRUE(s >= 0 && s <= 1 && t >= 0 && t <= 1);
    const Vec3 a = p[0] + s * (p[1] - p[0]), b = p[2] + t * (p[3] - p[2]);
    ASSERT_NEAR((a - b).squaredNorm(), d2, 1e-12) << "case " << k;
  }
}

TEST(SegmentDistance, MatchesDenseSampling) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    Vec3 p0(U(rng), U(rng), U(rng)), p1(U(rng), U(rng), U(rng)), q0(U(rng), U(rng), U(rng)),
        q1(U(rng), U(rng), U(rng));
    const double d2 = segment_segment_distance_squared(p0, p1, q0, q1);
    double best = 1e300;
    const int k = 200;
    for (int i = 0; i <= k; ++i)
      for (int j = 0; j <= k; ++j)
        best = std::min(best, (p0 + (p1 - p0) * i / double(k) - q0 - (q1 - q0) * j / double(k)).squaredNorm());
    EXPECT_LE(d2, best + 1e-14);
    EXPECT_GE(d2, best - 4e-4);  // grid resolution
  }
}

TEST(Polyline, ClearanceEqualsBruteForce) {
  for (int seed = 0; seed < 10; ++seed) {
    const Points P = fixtures::random_fourier_curve(60 + seed, 4, seed);
    const int n = static_cast<int>(P.rows());
    double best = 1e300;
    for (int i = 0; i < n; ++i)
      for (int j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        best = std::min(best, segment_segment_distance_squared(P.row(i).transpose(), P.row((i + 1) % n).transpose(),
                                                               P.row(j).transpose(), P.row((j + 1) % n).transpose()));
      }
    EXPECT_NEAR(clearance(P).distance, std::sqrt(best), 1e-14);
  }
}

TEST(Polyline, ClearanceOfTorusKnot) {
  // T(2,1) on a thin torus (an unknot circling twice): vertices i and i + n/2
  // are exactly 2r apart. With edges (0.63) longer than 2r the clearance is
  // the gap between the two strands, just below 2r.
  const Points P = fixtures::torus_knot(60, 2, 1, 3.0, 0.1);
  const auto c = clearance(P);
  EXPECT_LE(c.distance, 0.2);
  EXPECT_GT(c.distance, 0.19);
  EXPECT_EQ((c.edge_b - c.edge_a + 60) % 30, 0);  // opposite strands
  // Finely sampled, non-adjacent edges i and i+2 are one edge length apart:
  // the clearance is bounded by the edge length.
  const Points F = fixtures::torus_knot(2000, 2, 1, 3.0, 0.1);
  EXPECT_LE(clearance(F).distance, edge_lengths(F).maxCoeff());
  EXPECT_NEAR(clearance(F, 100).distance, 0.2, 0.001);  // far-apart edges only: the strand gap
}
