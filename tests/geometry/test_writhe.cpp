#include <gtest/gtest.h>

#include <cmath>

#include "ek/geometry/writhe.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Sum of the signed crossings of the projection along d (independent,
/// brute-force computation): the over strand is the one with larger height
/// d·x, sign = sign((t_over × t_under) · d).
int directional_writhe(const Points& P, const Vec3& d) {
  const int n = static_cast<int>(P.rows());
  int sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      const Vec3 a0 = P.row(i), a1 = P.row((i + 1) % n), b0 = P.row(j), b1 = P.row((j + 1) % n);
      auto proj = [&](const Vec3& x) -> Vec3 { return x - d * d.dot(x); };
      const Vec3 A0 = proj(a0), A1 = proj(a1), B0 = proj(b0), B1 = proj(b1);
      auto o = [&](const Vec3& a, const Vec3& b, const Vec3& c) { return d.dot((b - a).cross(c - a)); };
      const double o1 = o(A0, A1, B0), o2 = o(A0, A1, B1), o3 = o(B0, B1, A0), o4 = o(B0, B1, A1);
      if ((o1 > 0) == (o2 > 0) || (o3 > 0) == (o4 > 0)) continue;
      const double s = o3 / (o3 - o4), t = o1 / (o1 - o2);
      const double ha = d.dot(a0 + s * (a1 - a0)), hb = d.dot(b0 + t * (b1 - b0));
      const Vec3 ta = a1 - a0, tb = b1 - b0;
      const double cr = ha > hb ? d.dot(ta.cross(tb)) : d.dot(tb.cross(ta));
      sum += cr > 0 ? 1 : -1;
    }
  return sum;
}

}  // namespace

TEST(Writhe, PlanarCurvesHaveZeroWrithe) {
  EXPECT_NEAR(writhe(fixtures::circle(50, 1.0)), 0.0, 1e-14);
  Points P = fixtures::random_fourier_curve(80, 3, 7);
  P.col(2).setZero();
  EXPECT_NEAR(writhe(P), 0.0, 1e-12);
}

TEST(Writhe, MirrorFlipsSign) {
  const Points P = fixtures::torus_knot(150, 2, 3);
  Points M = P;
  M.col(2) *= -1.0;
  const double w = writhe(P);
  EXPECT_GT(std::fabs(w), 1.0);
  EXPECT_NEAR(writhe(M), -w, 1e-10);
}

TEST(Writhe, InvariantUnderRigidMotionReindexingAndReversal) {
  const Points P = fixtures::torus_knot(120, 3, 4);
  const double w = writhe(P);
  const Points Q = fixtures::rigid_copy(P, fixtures::random_rotation(3), Vec3(1, 2, 3), 17);
  EXPECT_NEAR(writhe(Q), w, 1e-10);
  const Points R = P.colwise().reverse();
  EXPECT_NEAR(writhe(R), w, 1e-10);
}

TEST(Writhe, EqualsAverageSignedCrossingNumber) {
  // Wr = average over directions of the directional writhe. Directions on a
  // Fibonacci sphere (antipodes give equal values, so a half sphere suffices).
  for (int seed = 0; seed < 3; ++seed) {
    const Points P = seed == 0 ? fixtures::torus_knot(90, 2, 3) : fixtures::random_fourier_curve(70, 3, seed);
    const int m = 3000;
    double avg = 0.0;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < m; ++k) {
      const double z = 1.0 - (k + 0.5) / m;  // upper half sphere
      const double r = std::sqrt(1.0 - z * z);
      avg += directional_writhe(P, Vec3(r * std::cos(golden * k), r * std::sin(golden * k), z));
    }
    avg /= m;
    // Quadrature error of the direction average: tolerance 0.02 (a few times
    // the observed error with 3000 directions).
    EXPECT_NEAR(writhe(P), avg, 0.02) << "seed " << seed;
  }
}

TEST(Writhe, SegmentPairMatchesGaussIntegralQuadrature) {
  // Two skew segments: exact formula vs. midpoint rule of the Gauss integrand.
  const Vec3 p1(0, 0, 0), p2(1, 0.2, 0), p3(0.3, -0.5, 0.4), p4(0.6, 0.9, 0.1);
  const int k = 600;
  double sum = 0.0;
  const Vec3 a = p2 - p1, b = p4 - p3;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const Vec3 x = p1 + a * ((i + 0.5) / k), y = p3 + b * ((j + 0.5) / k);
      const Vec3 r = x - y;
      sum += r.dot(a.cross(b)) / std::pow(r.norm(), 3);
    }
  // (1/4π) ∫∫ over the ordered pair (s on 1, t on 2); the writhe counts both orders.
  const double quad = sum / (k * double(k)) / (4.0 * M_PI);
  EXPECT_NEAR(segment_pair_writhe(p1, p2, p3, p4), quad, 1e-5);
}
