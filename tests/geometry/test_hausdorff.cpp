// Hausdorff distance between polylines: known answers (also where the maximum
// lies inside an edge, which a vertex-only maximum misses), the stated error
// bound against dense sampling, symmetry and invariances.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/geometry/hausdorff.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points polyline(std::initializer_list<std::array<double, 3>> pts) { return fixtures::rows3<Points>(pts); }

/// max over dense samples of A (spacing <= h) of the distance to B: within h/2 below h(A → B).
double dense_directed(const Points& A, const Points& B, double h) {
  double best = 0.0;
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    const Vec3 a = A.row(i).transpose(), b = A.row((i + 1) % A.rows()).transpose();
    const int k = std::max(1, static_cast<int>(std::ceil((b - a).norm() / h)));
    for (int s = 0; s < k; ++s) best = std::max(best, point_polyline_distance(a + (b - a) * (double(s) / k), B));
  }
  return best;
}

}  // namespace

// A = the segment (0,0)-(2,0); B = the open path (0,0) -> (0,1) -> (2,1) -> (2,0).
// Both vertices of A lie on B, but its midpoint (1,0) is 1 away from B:
// h(A → B) = 1 (attained only there); h(B → A) = 1 (the top side).
TEST(Hausdorff, MaximumInsideAnEdge) {
  const Points A = polyline({{0, 0, 0}, {2, 0, 0}});
  const Points B = polyline({{0, 0, 0}, {0, 1, 0}, {2, 1, 0}, {2, 0, 0}});
  HausdorffOptions o;
  o.closed = false;
  o.tolerance = 1e-9;
  const HausdorffDistance h = hausdorff_distance(A, B, o);
  EXPECT_NEAR(h.forward, 1.0, 1e-9);
  EXPECT_NEAR(h.backward, 1.0, 1e-9);
  EXPECT_NEAR(h.distance, 1.0, 1e-9);
  EXPECT_LE(h.forward, 1.0 + 1e-15);  // never above the true value
  // the vertices alone would give 0
  EXPECT_EQ(point_polyline_distance(A.row(0).transpose(), B, false), 0.0);
  EXPECT_EQ(point_polyline_distance(A.row(1).transpose(), B, false), 0.0);
}

// The segment [0, 1] inside the segment [0, 3] (x axis): h(A → B) = 0, h(B → A) = 2.
TEST(Hausdorff, DirectedDistancesDiffer) {
  HausdorffOptions o;
  o.closed = false;
  const HausdorffDistance h =
      hausdorff_distance(polyline({{0, 0, 0}, {1, 0, 0}}), polyline({{0, 0, 0}, {3, 0, 0}}), o);
  EXPECT_NEAR(h.forward, 0.0, 1e-12);
  EXPECT_NEAR(h.backward, 2.0, 1e-12);
  EXPECT_NEAR(h.distance, 2.0, 1e-12);
  EXPECT_NEAR(h.witness.x(), 3.0, 1e-12);
}

// The unit square and its copy shifted by d < 1/2 along x: d_H = d.
TEST(Hausdorff, ShiftedSquare) {
  const Points A = polyline({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  for (double d : {0.05, 0.3, 0.45}) {
    Points B = A;
    B.col(0).array() += d;
    EXPECT_NEAR(hausdorff_distance(A, B).distance, d, 1e-6) << d;
  }
}

// Concentric regular 400-gons of radii 1 and 1.5 with aligned vertices: the
// circles are 0.5 apart, and the polygons deviate from them by at most their
// sagitta R(1 - cos(π/n)), so d_H = 0.5 within 1.5 (1 - cos(π/n)).
TEST(Hausdorff, ConcentricCircles) {
  const int n = 400;
  const HausdorffDistance h = hausdorff_distance(fixtures::circle(n, 1.0), fixtures::circle(n, 1.5));
  EXPECT_NEAR(h.distance, 0.5, 1.5 * (1.0 - std::cos(M_PI / n)) + 1e-6);
  EXPECT_NEAR(h.backward, h.distance, 1e-12);  // the larger circle's points are the farthest
}

// Against dense sampling of random curves: dense <= exact <= dense + spacing/2 (+ tolerance).
TEST(Hausdorff, WithinTheErrorBoundOfDenseSampling) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Points A = fixtures::random_fourier_curve(60, 3, seed);
    const Points B = fixtures::random_fourier_curve(45, 3, seed + 100);
    HausdorffOptions o;
    o.tolerance = 1e-7;
    const HausdorffDistance h = hausdorff_distance(A, B, o);
    const double spacing = 1e-3;
    const double dense = dense_directed(A, B, spacing);
    EXPECT_GE(h.forward, dense - o.tolerance) << seed;
    EXPECT_LE(h.forward, dense + 0.5 * spacing + o.tolerance) << seed;
    EXPECT_GT(h.forward, 0.0);
    // the witness is a point at the reported distance
    if (h.forward >= h.backward) {
      EXPECT_NEAR(point_polyline_distance(h.witness, B), h.forward, 1e-12);
    }
  }
}

TEST(Hausdorff, SymmetricAndInvariant) {
  const Points A = fixtures::torus_knot(300, 2, 3);
  const Points B = fixtures::random_fourier_curve(200, 4, 7, 2.0);
  EXPECT_NEAR(hausdorff_distance(A, B).distance, hausdorff_distance(B, A).distance, 1e-12);
  // the same set, re-indexed and reversed: 0; moved rigidly together: unchanged
  const Points A2 = fixtures::rigid_copy(A, Mat3::Identity(), Vec3::Zero(), 37).colwise().reverse();
  EXPECT_LT(hausdorff_distance(A, A2).distance, 1e-12);
  const Mat3 R = fixtures::random_rotation(3);
  const Vec3 t(1.0, -2.0, 0.5);
  EXPECT_NEAR(hausdorff_distance(fixtures::rigid_copy(A, R, t, 0), fixtures::rigid_copy(B, R, t, 11)).distance,
              hausdorff_distance(A, B).distance, 1e-6);
}

TEST(Hausdorff, MisuseThrows) {
  const Points P = fixtures::circle(10, 1.0);
  EXPECT_THROW(hausdorff_distance(P, P.topRows(2)), std::invalid_argument);
  HausdorffOptions o;
  o.tolerance = 0.0;
  EXPECT_THROW(hausdorff_distance(P, P, o), std::invalid_argument);
  Points Q = P;
  Q(3, 1) = std::nan("");
  EXPECT_THROW(hausdorff_distance(P, Q), std::invalid_argument);
}
