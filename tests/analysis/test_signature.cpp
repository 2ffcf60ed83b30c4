#include <gtest/gtest.h>

#include <cmath>

#include "ek/analysis/signature.hpp"
#include "ek/geometry/polyline.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Open helix (R cos θ, R sin θ, h θ), θ = i·dθ, i = 0..m-1 (closed by its chord as a polygon).
Points helix(int m, double R, double h, double dtheta) {
  Points P(m, 3);
  for (int i = 0; i < m; ++i) {
    const double t = i * dtheta;
    P.row(i) << R * std::cos(t), R * std::sin(t), h * t;
  }
  return P;
}

}  // namespace

TEST(Signature, CircleCurvatureIsExactAndTorsionZero) {
  const int n = 50;
  const double R = 1.7;
  const Points C = fixtures::circle(n, R);
  const CurveSignature s = curve_signature(C);
  // turning angle 2π/n over the edge length 2R sin(π/n)
  const double kappa = (2 * M_PI / n) / (2 * R * std::sin(M_PI / n));
  for (int i = 0; i < n; ++i) EXPECT_NEAR(s.curvature(i), kappa, 1e-13 * kappa);
  EXPECT_EQ(s.torsion.cwiseAbs().maxCoeff(), 0.0);  // planar convex: exactly zero
  // a rigidly moved copy: binormal rotation angles are snapped to exactly 0
  const Points Q = fixtures::rigid_copy(C, fixtures::random_rotation(3), Vec3(1, -2, 3), 7);
  EXPECT_EQ(curve_signature(Q).torsion.cwiseAbs().maxCoeff(), 0.0);
}

TEST(Signature, HelixConvergesToContinuousCurvatureAndTorsion) {
  // κ = R/(R² + h²), τ = h/(R² + h²) for (R cos θ, R sin θ, hθ); right-handed (h > 0): τ > 0.
  const double R = 1.3;
  for (double h : {0.4, -0.4}) {
    const double kappa = R / (R * R + h * h), tau = h / (R * R + h * h);
    double err_prev = 0.0;
    for (double dtheta : {0.2, 0.1, 0.05}) {
      const int m = static_cast<int>(std::round(4 * M_PI / dtheta));  // two turns
      const Points P = helix(m, R, h, dtheta);
      const VecX k = discrete_curvature(P);
      const VecX t = discrete_torsion(P);
      const CurveSignature s = curve_signature(P);
      // interior nodes/edges, away from the closing chord; all equal by screw symmetry
      const int i = m / 2;
      EXPECT_NEAR(k(i), k(i + 1), 1e-12 * kappa);
      EXPECT_NEAR(t(i), t(i + 1), 1e-10 * std::abs(tau));
      EXPECT_NEAR(s.torsion(i), k(i) * t(i), 1e-10 * kappa * std::abs(tau));
      EXPECT_GT(t(i) * h, 0.0);  // sign: right-handed positive
      const double err = std::max(std::abs(k(i) - kappa) / kappa, std::abs(t(i) - tau) / std::abs(tau));
      EXPECT_LT(err, 0.2 * dtheta * dtheta);  // O(dθ²): measured 0.15 dθ² (torsion), 0.03 dθ² (curvature)
      if (err_prev > 0.0) {
        EXPECT_NEAR(err_prev / err, 4.0, 0.5);  // second order
      }
      err_prev = err;
    }
  }
}

TEST(Signature, RigidMotionCyclicShiftScaleMirrorAndReversal) {
  const int n = 120;
  const Points P = fixtures::torus_knot(n, 2, 3);
  const CurveSignature s = curve_signature(P);
  const double ks = s.curvature.cwiseAbs().maxCoeff(), ts = s.torsion.cwiseAbs().maxCoeff();
  ASSERT_GT(ts, 0.1 * ks * ks);  // a genuinely 3D curve

  // rotation, translation, cyclic shift: Q_i = R P_{i+shift} + t
  const int shift = 17;
  const Points Q = fixtures::rigid_copy(P, fixtures::random_rotation(11), Vec3(3, 1, -2), shift);
  const CurveSignature q = curve_signature(Q);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(q.curvature(i), s.curvature((i + shift) % n), 1e-12 * ks);
    EXPECT_NEAR(q.torsion(i), s.torsion((i + shift) % n), 1e-11 * ts);
  }
  // scaling by c: K / c, T / c²
  const double c = 2.5;
  const CurveSignature sc = curve_signature(Points(c * P));
  EXPECT_LT((sc.curvature - s.curvature / c).norm(), 1e-12 * s.curvature.norm());
  EXPECT_LT((sc.torsion - s.torsion / (c * c)).norm(), 1e-12 * s.torsion.norm());
  // mirror image: K unchanged, T negated
  const CurveSignature m = curve_signature(fixtures::mirror_x(P));
  const CurveSignature mm = mirrored(s);
  EXPECT_LT((m.curvature - mm.curvature).norm(), 1e-12 * s.curvature.norm());
  EXPECT_LT((m.torsion - mm.torsion).norm(), 1e-12 * s.torsion.norm());
  // reversed orientation Q_i = P_{n-1-i}: both profiles reversed (torsion is orientation-free)
  const Points Prev = P.colwise().reverse();
  const CurveSignature r = curve_signature(Prev);
  const CurveSignature rr = reversed(s);
  EXPECT_LT((r.curvature - rr.curvature).norm(), 1e-12 * s.curvature.norm());
  EXPECT_LT((r.torsion - rr.torsion).norm(), 1e-12 * s.torsion.norm());
}

TEST(Signature, StraightNodesGiveNoNaN) {
  // a skew quadrilateral with every edge split in two: 4 straight nodes (κ = 0,
  // binormal undefined) between 4 corners.
  Points corners(4, 3);
  corners << 0, 0, 0, 2, 0, 0, 2, 2, 1, 0, 2, 0;
  Points P(8, 3);
  for (int k = 0; k < 4; ++k) {
    P.row(2 * k) = corners.row(k);
    P.row(2 * k + 1) = 0.5 * (corners.row(k) + corners.row((k + 1) % 4));
  }
  const CurveSignature s = curve_signature(P);
  const VecX tau = discrete_torsion(P);
  ASSERT_TRUE(s.curvature.allFinite());
  ASSERT_TRUE(s.torsion.allFinite());
  ASSERT_TRUE(tau.allFinite());
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(s.curvature(2 * k + 1), 0.0);
    EXPECT_EQ(s.torsion(2 * k + 1), 0.0);
    EXPECT_EQ(tau(2 * k), 0.0);  // every edge touches a straight node
    EXPECT_GT(s.curvature(2 * k), 0.0);
  }
}

TEST(Signature, PlanarInflectionIsDeterministicUnderRotation) {
  // planar figure-eight-like curve (lemniscate of Gerono shifted to avoid the crossing
  // being a vertex... it is planar with inflections); the binormal flips by exactly π.
  const int n = 101;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    P.row(i) << std::cos(t), 0.6 * std::sin(2 * t) + 0.3 * std::sin(t), 0.0;
  }
  const CurveSignature s = curve_signature(P);
  const VecX tau = discrete_torsion(P);
  int flips = 0;
  for (int j = 0; j < n; ++j) {
    const double len = (P.row((j + 1) % n) - P.row(j)).norm();
    if (tau(j) != 0.0) {
      EXPECT_NEAR(tau(j) * len, M_PI, 1e-15);  // exactly +π, never -π
      ++flips;
    }
  }
  EXPECT_GE(flips, 2);  // a planar closed curve with inflections has an even number
  EXPECT_EQ(flips % 2, 0);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const CurveSignature q = curve_signature(fixtures::rigid_copy(P, fixtures::random_rotation(seed), Vec3(1, 2, 3), 0));
    EXPECT_LT((q.torsion - s.torsion).cwiseAbs().maxCoeff(), 1e-9 * s.torsion.cwiseAbs().maxCoeff()) << seed;
  }
}

TEST(Signature, RejectsBadInput) {
  Points two(2, 3);
  two << 0, 0, 0, 1, 0, 0;
  EXPECT_THROW(curve_signature(two), std::invalid_argument);
  Points dup = fixtures::circle(6, 1.0);
  dup.row(3) = dup.row(2);
  EXPECT_THROW(curve_signature(dup), std::invalid_argument);
  Points nan = fixtures::circle(6, 1.0);
  nan(1, 1) = std::nan("");
  EXPECT_THROW(curve_signature(nan), std::invalid_argument);
}
