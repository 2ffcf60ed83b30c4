// Finite-difference and known-answer tests of the local rod kernels.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "ek/rod/kernels.hpp"
#include "testing.hpp"

using namespace ek;
using namespace ek::rod;

namespace {

Vec3 random_vec(std::mt19937_64& rng, double scale = 1.0) {
  std::normal_distribution<double> N(0.0, scale);
  return Vec3(N(rng), N(rng), N(rng));
}

/// Two edge vectors with a turning angle well below π (so |κb| stays moderate).
std::pair<Vec3, Vec3> random_edges(std::mt19937_64& rng) {
  for (;;) {
    const Vec3 a = random_vec(rng), b = random_vec(rng);
    if (a.norm() > 0.3 && b.norm() > 0.3 && a.normalized().dot(b.normalized()) > -0.5) return {a, b};
  }
}

/// A unit vector within angle ~0.3 of t.
Vec3 nearby_unit(std::mt19937_64& rng, const Vec3& t) { return (t.normalized() + random_vec(rng, 0.2)).normalized(); }

using Fn6 = std::function<double(const Vec6&)>;
using Gr6 = std::function<Vec6(const Vec6&)>;

/// Central differences of a function of 6 variables.
Vec6 fd6(const Fn6& f, const Vec6& y, double h) {
  VecX g = fixtures::fd_gradient([&](const VecX& z) { return f(z); }, y, h);
  return g;
}

Mat6 fd6_hessian(const Gr6& g, const Vec6& y, double h) {
  Mat6 H;
  for (int k = 0; k < 6; ++k) {
    Vec6 yp = y, ym = y;
    yp(k) += h;
    ym(k) -= h;
    H.col(k) = (g(yp) - g(ym)) / (2.0 * h);
  }
  return H;
}

Vec6 join(const Vec3& a, const Vec3& b) {
  Vec6 y;
  y << a, b;
  return y;
}

/// Checks gradient and Hessian of a 6-variable kernel at y against central
/// differences with three step sizes: relative error (2-norm of the gradient,
/// Frobenius norm of the Hessian) at most 1e-6, and non-trivial values.
void check_kernel6(const Fn6& f, const Gr6& g, const std::function<Mat6(const Vec6&)>& H, const Vec6& y,
                   const char* what) {
  const Vec6 g0 = g(y);
  const Mat6 H0 = H(y);
  ASSERT_GT(g0.norm(), 1e-6) << what;
  ASSERT_GT(H0.norm(), 1e-6) << what;
  EXPECT_LT((H0 - H0.transpose()).norm(), 1e-12 * H0.norm()) << what;
  for (double h : {1e-4, 1e-5, 1e-6}) {
    const double eg = (fd6(f, y, h) - g0).norm() / g0.norm();
    const double eh = (fd6_hessian(g, y, h) - H0).norm() / H0.norm();
    EXPECT_LT(eg, 1e-6) << what << " gradient, h = " << h;  // relative error <= 1e-6
    EXPECT_LT(eh, 1e-6) << what << " Hessian, h = " << h;   // relative error <= 1e-6
  }
}

}  // namespace

TEST(RodKernels, StretchDerivatives) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 e = random_vec(rng);
    // rest length 0.6 to 0.9 or 1.1 to 1.4 times |e|: a non-trivial strain
    const double u = std::uniform_real_distribution<double>(0.1, 0.4)(rng);
    const double l = e.norm() * (trial % 2 ? 1.0 + u : 1.0 - u), EA = 3.7;
    EXPECT_NEAR(stretch_energy(e, l, EA), 0.5 * EA * std::pow(e.norm() / l - 1.0, 2) * l, 1e-14);
    const Vec3 g = stretch_gradient(e, l, EA);
    const Mat3 H = stretch_hessian(e, l, EA);
    ASSERT_GT(g.norm(), 1e-8);
    for (double h : {1e-4, 1e-5, 1e-6}) {
      const VecX gf = fixtures::fd_gradient([&](const VecX& z) { return stretch_energy(z, l, EA); }, e, h);
      EXPECT_LT((gf - g).norm() / g.norm(), 1e-6);  // relative error <= 1e-6
      Mat3 Hf;
      for (int k = 0; k < 3; ++k) {
        Vec3 ep = e, em = e;
        ep(k) += h;
        em(k) -= h;
        Hf.col(k) = (stretch_gradient(ep, l, EA) - stretch_gradient(em, l, EA)) / (2 * h);
      }
      EXPECT_LT((Hf - H).norm() / H.norm(), 1e-6);  // relative error <= 1e-6
    }
  }
}

TEST(RodKernels, CurvatureBinormalKnownValues) {
  // |κb| = 2 tan(φ/2), direction a × b, independent of the edge lengths.
  for (double phi : {0.0, 0.1, 1.0, 2.0, 3.0}) {
    const Vec3 a(2.0, 0.0, 0.0), b(0.5 * std::cos(phi), 0.5 * std::sin(phi), 0.0);
    const Vec3 kb = curvature_binormal(a, b);
    EXPECT_NEAR(kb.norm(), 2.0 * std::tan(phi / 2), 1e-12 * (1 + kb.norm()));
    EXPECT_NEAR(kb.x(), 0.0, 1e-15);
    EXPECT_NEAR(kb.y(), 0.0, 1e-15);
    EXPECT_GE(kb.z(), 0.0);
    EXPECT_NEAR(kb_squared(a, b), kb.squaredNorm(), 1e-12 * (1 + kb.squaredNorm()));
  }
}

TEST(RodKernels, BendingDerivatives) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const auto [a, b] = random_edges(rng);
    check_kernel6([](const Vec6& y) { return kb_squared(y.head<3>(), y.tail<3>()); },
                  [](const Vec6& y) { return kb_squared_gradient(y.head<3>(), y.tail<3>()); },
                  [](const Vec6& y) { return kb_squared_hessian(y.head<3>(), y.tail<3>()); }, join(a, b),
                  "kb_squared");
  }
}

TEST(RodKernels, SolidAngleKnownValuesAndDerivatives) {
  // The octant triangle has area 4π/8 = π/2; reversing the orientation flips the sign.
  const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();
  EXPECT_NEAR(solid_angle(X, Y, Z), M_PI / 2, 1e-14);
  EXPECT_NEAR(solid_angle(X, Z, Y), -M_PI / 2, 1e-14);
  EXPECT_NEAR(solid_angle(Y, Z, X), M_PI / 2, 1e-14);  // cyclic invariance
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 a = random_vec(rng).normalized();
    const Vec3 b = nearby_unit(rng, a), c = nearby_unit(rng, a);
    check_kernel6([&](const Vec6& y) { return solid_angle(a, y.head<3>(), y.tail<3>()); },
                  [&](const Vec6& y) { return solid_angle_gradient(a, y.head<3>(), y.tail<3>()); },
                  [&](const Vec6& y) { return solid_angle_hessian(a, y.head<3>(), y.tail<3>()); }, join(b, c),
                  "solid_angle");
  }
}

TEST(RodKernels, ParallelTransportIsTheMinimalRotation) {
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 a = random_vec(rng).normalized(), b = nearby_unit(rng, a);
    const Vec3 axis = a.cross(b).normalized();
    const Vec3 v = random_vec(rng);
    const Vec3 u = (v - a * a.dot(v)).normalized();
    const Vec3 Pu = parallel_transport(a, b, u);
    // Transport fixes the axis, keeps unit length, and maps the normal plane of a to that of b.
    EXPECT_NEAR((parallel_transport(a, b, axis) - axis).norm(), 0.0, 1e-14);
    EXPECT_NEAR(Pu.norm(), 1.0, 1e-14);
    EXPECT_NEAR(Pu.dot(b), 0.0, 1e-14);
    // Equals the rotation about the axis by the angle between a and b.
    const double ang = std::atan2(a.cross(b).norm(), a.dot(b));
    const Vec3 R = Eigen::AngleAxisd(ang, axis) * u;
    EXPECT_NEAR((Pu - R).norm(), 0.0, 1e-13);
  }
}

TEST(RodKernels, ReferenceTwistChangeMatchesTransportedDirectors) {
  // Direct computation: transport source directors u_a, u_b in time to t_a,
  // t_b, transport d_a in space to t_b, measure the angle to d_b; subtract the
  // same at the source. The holonomy formula must agree (mod 2π; here the
  // changes are small so exactly).
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    const auto [sa_raw, sb_raw] = random_edges(rng);
    const Vec3 sa = sa_raw.normalized(), sb = sb_raw.normalized();
    const Vec3 ua = (random_vec(rng).cross(sa)).normalized();
    const Vec3 ub = (random_vec(rng).cross(sb)).normalized();
    const double m_src = signed_angle(parallel_transport(sa, sb, ua), ub, sb);
    const Vec3 a = 1.3 * nearby_unit(rng, sa), b = 0.7 * nearby_unit(rng, sb);
    const Vec3 ta = a.normalized(), tb = b.normalized();
    const Vec3 da = parallel_transport(sa, ta, ua), db = parallel_transport(sb, tb, ub);
    const double m = signed_angle(parallel_transport(ta, tb, da), db, tb);
    const double dm = reference_twist_change(sa, sb, a, b);
    EXPECT_GT(std::fabs(dm), 1e-4);  // the configuration really moved
    EXPECT_NEAR(std::remainder(m - (m_src + dm), 2 * M_PI), 0.0, 1e-12) << "trial " << trial;
    EXPECT_NEAR(reference_twist_change(sa, sb, sa, sb), 0.0, 1e-15);
  }
}

TEST(RodKernels, ReferenceTwistGradientAtSourceIsBergouFormula) {
  // At the source configuration ∂m/∂e_{i-1} = κb/(2|e_{i-1}|), ∂m/∂e_i = κb/(2|e_i|)
  // (Bergou et al. 2010, eq. 9) — an independent check of sign and scale.
  std::mt19937_64 rng(6);
  for (int trial = 0; trial < 20; ++trial) {
    const auto [a, b] = random_edges(rng);
    const Vec6 g = reference_twist_change_gradient(a.normalized(), b.normalized(), a, b);
    const Vec3 kb = curvature_binormal(a, b);
    EXPECT_NEAR((g.head<3>() - kb / (2 * a.norm())).norm(), 0.0, 1e-12 * (1 + kb.norm()));
    EXPECT_NEAR((g.tail<3>() - kb / (2 * b.norm())).norm(), 0.0, 1e-12 * (1 + kb.norm()));
  }
}

TEST(RodKernels, ReferenceTwistDerivativesAwayFromSource) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const auto [sa_raw, sb_raw] = random_edges(rng);
    const Vec3 sa = sa_raw.normalized(), sb = sb_raw.normalized();
    const Vec3 a = 1.2 * nearby_unit(rng, sa), b = 0.8 * nearby_unit(rng, sb);
    check_kernel6([&](const Vec6& y) { return reference_twist_change(sa, sb, y.head<3>(), y.tail<3>()); },
                  [&](const Vec6& y) { return reference_twist_change_gradient(sa, sb, y.head<3>(), y.tail<3>()); },
                  [&](const Vec6& y) { return reference_twist_change_hessian(sa, sb, y.head<3>(), y.tail<3>()); },
                  join(a, b), "reference_twist_change");
  }
}

TEST(RodKernels, EdgeToVertexMaps) {
  // f(x0, x1, x2) = φ(x1 - x0, x2 - x1) for a quadratic φ(y) = yᵀ S y / 2 + cᵀ y.
  std::mt19937_64 rng(8);
  Mat6 S;
  for (int i = 0; i < 36; ++i) S(i) = std::normal_distribution<double>()(rng);
  S = (S + S.transpose()).eval();
  Vec6 c;
  for (int i = 0; i < 6; ++i) c(i) = std::normal_distribution<double>()(rng);
  Vec9 x;
  for (int i = 0; i < 9; ++i) x(i) = std::normal_distribution<double>()(rng);
  auto edges = [](const Vec9& z) {
    Vec6 y;
    y << z.segment<3>(3) - z.segment<3>(0), z.segment<3>(6) - z.segment<3>(3);
    return y;
  };
  const Vec6 y = edges(x);
  const Vec9 g = to_vertices(Vec6(S * y + c));
  const VecX gf = fixtures::fd_gradient(
      [&](const VecX& z) {
        const Vec6 w = edges(z);
        return 0.5 * w.dot(S * w) + c.dot(w);
      },
      x, 1e-5);
  EXPECT_LT((gf - g).norm() / g.norm(), 1e-8);  // quadratic: FD exact up to rounding
  // Hessian Mᵀ S M, compared with an explicit M.
  Eigen::Matrix<double, 6, 9> M = Eigen::Matrix<double, 6, 9>::Zero();
  M.block<3, 3>(0, 0) = -Mat3::Identity();
  M.block<3, 3>(0, 3) = Mat3::Identity();
  M.block<3, 3>(3, 3) = -Mat3::Identity();
  M.block<3, 3>(3, 6) = Mat3::Identity();
  EXPECT_LT((to_vertices(S) - M.transpose() * S * M).norm(), 1e-13 * S.norm());
}

TEST(RodKernels, ProjectedStretchHessianIsTheNearestPsdMatrix) {
  // stretch_hessian() has eigenvalues EA/l̄ along ê and EA/l̄ (1 − l̄/|e|)
  // (twice) across; the projection clamps the transverse ones at 0.
  std::mt19937_64 rng(21);
  int compressed = 0, stretched = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Vec3 e = random_vec(rng);
    if (e.norm() < 0.2) continue;
    // strain −40% .. +40% (|e| = l̄ (1 + strain)), both signs
    const double strain = std::uniform_real_distribution<double>(-0.4, 0.4)(rng);
    const double l = e.norm() / (1.0 + strain), EA = 2.3;
    const double scale = EA / l;
    const Mat3 H = stretch_hessian(e, l, EA);
    const Mat3 P = stretch_hessian_projected(e, l, EA);
    EXPECT_LT((P - P.transpose()).norm(), 1e-14 * scale);
    const Vec3 t = e.normalized();
    // along ê: EA/l̄ for both; ê is an eigenvector
    EXPECT_NEAR(t.dot(P * t), scale, 1e-12 * scale);
    EXPECT_LT((P * t - scale * t).norm(), 1e-12 * scale);
    // across: two unit vectors orthogonal to ê and to each other
    const Vec3 u = (std::fabs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(t).normalized();
    const Vec3 w = t.cross(u);
    const double across_exact = scale * (1.0 - l / e.norm());
    EXPECT_NEAR(u.dot(H * u), across_exact, 1e-12 * scale);  // the exact kernel's transverse eigenvalue
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(P);
    const Vec3 lam = eig.eigenvalues();  // ascending
    if (e.norm() >= l) {
      ++stretched;
      EXPECT_LT((P - H).norm(), 1e-14 * scale) << "stretched edge: unchanged";
      EXPECT_NEAR(u.dot(P * u), across_exact, 1e-12 * scale);
    } else {
      ++compressed;
      ASSERT_LT(across_exact, -1e-3 * scale);  // the exact Hessian really is indefinite
      EXPECT_GE(lam(0), -1e-12 * scale);        // PSD
      EXPECT_NEAR(lam(0), 0.0, 1e-12 * scale);
      EXPECT_NEAR(lam(1), 0.0, 1e-12 * scale);
      EXPECT_NEAR(lam(2), scale, 1e-12 * scale);
      EXPECT_LT((P * u).norm(), 1e-12 * scale);
      EXPECT_LT((P * w).norm(), 1e-12 * scale);
      // the projection is H with its negative eigenvalues clamped: H = V Λ Vᵀ, P = V max(Λ, 0) Vᵀ
      const Eigen::SelfAdjointEigenSolver<Mat3> eh(H);
      const Mat3 clamped =
          eh.eigenvectors() * eh.eigenvalues().cwiseMax(0.0).asDiagonal() * eh.eigenvectors().transpose();
      EXPECT_LT((P - clamped).norm(), 1e-12 * scale);
      // and it differs from H exactly by the clamped part −EA/l̄ (1 − l̄/|e|)(I − ê êᵀ)
      EXPECT_LT((P - H + across_exact * (Mat3::Identity() - t * t.transpose())).norm(), 1e-12 * scale);
    }
  }
  EXPECT_GE(compressed, 10);
  EXPECT_GE(stretched, 10);
  // exactly at rest length: the transverse eigenvalues are 0 either way
  const Vec3 e(0.3, -0.4, 1.2);
  EXPECT_LT((stretch_hessian_projected(e, e.norm(), 5.0) - stretch_hessian(e, e.norm(), 5.0)).norm(), 1e-13);
}
