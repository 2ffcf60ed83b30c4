#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

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

TEST(Writhe, PerpendicularSegmentsSubtendTheRectangleSolidAngle) {
  // Segments [-a, a]·x̂ and (0, 0, h) + [-b, b]·ŷ: the differences x − y fill
  // a 2a × 2b rectangle at distance h, whose solid angle is
  // Ω = 4 atan(ab / (h √(a² + b² + h²))). The Gauss integrand r·(t1 × t2)
  // is negative here (r_z = −h, t1 × t2 along +z), so the pair gives −Ω/(4π);
  // as h → 0 it tends to −1/2 (the near-touching case, where each triangle
  // of the formula subtends nearly a hemisphere).
  const double a = 0.7, b = 1.3;
  for (const double h : {2.0, 1.0, 1e-2, 1e-5, 1e-9}) {
    const double omega = 4.0 * std::atan(a * b / (h * std::sqrt(a * a + b * b + h * h)));
    const double w = segment_pair_writhe(Vec3(-a, 0, 0), Vec3(a, 0, 0), Vec3(0, -b, h), Vec3(0, b, h));
    // Tolerance: 1e-14, plus the conditioning of a near touch: the rounding
    // of the triangles' terms (of size a·b) against their sum (of size h)
    // makes an error of about ε·(a + b)/h (measured 1.8e-12 at h = 1e-5,
    // 5e-10 at h = 1e-9).
    const double tol = 1e-14 + 1e-16 / h;
    EXPECT_NEAR(w, -omega / (4.0 * M_PI), tol) << "h = " << h;
    // the same pair in the other order, and with one segment reversed
    EXPECT_NEAR(segment_pair_writhe(Vec3(0, -b, h), Vec3(0, b, h), Vec3(-a, 0, 0), Vec3(a, 0, 0)), w, tol);
    EXPECT_NEAR(segment_pair_writhe(Vec3(a, 0, 0), Vec3(-a, 0, 0), Vec3(0, -b, h), Vec3(0, b, h)), -w, tol);
  }
}

TEST(Writhe, SegmentPairMatchesTheFourArcsineFormula) {
  // Klenin & Langowski's method 1a written out (unit face normals, four
  // arcsines) in long double, against the two-triangle evaluation, on random
  // skew pairs: generic ones, and pairs 1e-6 apart at their middles.
  std::mt19937 rng(5);
  std::normal_distribution<double> N;
  auto random_vec = [&] { return Vec3(N(rng), N(rng), N(rng)); };
  using V = Eigen::Matrix<long double, 3, 1>;
  auto reference = [](const Vec3& q1, const Vec3& q2, const Vec3& q3, const Vec3& q4) {
    const V p1 = q1.cast<long double>(), p2 = q2.cast<long double>(), p3 = q3.cast<long double>(),
            p4 = q4.cast<long double>();
    const V r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
    const V n[4] = {r13.cross(r14).normalized(), r14.cross(r24).normalized(), r24.cross(r23).normalized(),
                    r23.cross(r13).normalized()};
    long double omega = 0.0L;
    for (int k = 0; k < 4; ++k) omega += std::asin(std::clamp(n[k].dot(n[(k + 1) % 4]), -1.0L, 1.0L));
    const long double orient = (p4 - p3).cross(p2 - p1).dot(r13);
    return static_cast<double>((orient > 0 ? omega : -omega) / (4.0L * static_cast<long double>(M_PI)));
  };
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p1 = random_vec(), p2 = random_vec();
    const Vec3 p3 = k % 2 == 0 ? random_vec() : Vec3(0.5 * (p1 + p2) + 1e-6 * random_vec());
    const Vec3 p4 = p3 + random_vec();
    // Tolerance: 1e-12 for generic pairs (measured at most 1.4e-14 over 3e5
    // pairs); 1e-7 for pairs 1e-6 apart, whose conditioning is about
    // ε·length/distance (measured at most 1.7e-8 over 3e5 pairs, and 3.7e-9
    // for the four arcsines in double).
    EXPECT_NEAR(segment_pair_writhe(p1, p2, p3, p4), reference(p1, p2, p3, p4), k % 2 == 0 ? 1e-12 : 1e-7) << k;
  }
}
