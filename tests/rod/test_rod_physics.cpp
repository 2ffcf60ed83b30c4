// Known answers of the closed elastic rod: bending energy of multi-covered
// circles, link invariance, Michell's instability of a twisted ring, the
// twist-free fast path, and the straight-rod eigenvalue used by the solver.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>
#include <random>

#include "ek/geometry/polyline.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/rod/kernels.hpp"
#include "rod_testing.hpp"

using namespace ek;

namespace {

/// k-covered circle of radius R, slightly offset so the covers do not meet:
/// x(φ) = ((R + δ cos(φ/k)) cos φ, (R + δ cos(φ/k)) sin φ, δ sin(φ/k)),
/// φ ∈ [0, 2πk), n samples.
Points covered_circle(int n, int k, double R, double delta) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double phi = 2.0 * M_PI * k * i / n;
    const double rr = R + delta * std::cos(phi / k);
    P.row(i) << rr * std::cos(phi), rr * std::sin(phi), delta * std::sin(phi / k);
  }
  return P;
}

double polygon_length(const Points& P) {
  double L = 0;
  for (Eigen::Index i = 0; i < P.rows(); ++i) L += (P.row((i + 1) % P.rows()) - P.row(i)).norm();
  return L;
}

/// Smallest eigenvalue of the symmetric H restricted to the orthogonal
/// complement of the columns of Z.
double min_eigenvalue_excluding(const Eigen::MatrixXd& H, const Eigen::MatrixXd& Z) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Z);
  const Eigen::MatrixXd Q = qr.householderQ();
  const Eigen::MatrixXd C = Q.rightCols(H.rows() - Z.cols());
  const Eigen::MatrixXd Hc = C.transpose() * H * C;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (Hc + Hc.transpose()), Eigen::EigenvaluesOnly)
      .eigenvalues()(0);
}

/// The zero modes of the full model at an equilibrium: three translations,
/// three rotations (positions ω × x_i, material angles θ_j += ω·t_j so that
/// the material frames rotate rigidly with the curve; the reference frames
/// follow by parallel transport, whose angular velocity has no tangential
/// component), and the uniform shift of the material angles (isotropic
/// cross-section). Columns of a (4n [+1]) by 7 matrix.
Eigen::MatrixXd full_model_zero_modes(const ElasticRod& rod) {
  const int n = rod.num_vertices(), N = rod.num_dofs();
  const Points& P = rod.positions();
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(N, 7);
  for (int c = 0; c < 3; ++c) {
    const Vec3 w = Vec3::Unit(c);
    for (int i = 0; i < n; ++i) {
      Z(3 * i + c, c) = 1.0;
      const Vec3 x = P.row(i);
      Z.block<3, 1>(3 * i, 3 + c) = w.cross(x);
      const Vec3 t = (P.row((i + 1) % n) - P.row(i)).normalized();
      Z(3 * n + i, 3 + c) = w.dot(t);
    }
  }
  for (int j = 0; j < n; ++j) Z(3 * n + j, 6) = 1.0;
  return Z;
}

/// A planar circular ring (unit rest edges, at rest) with prescribed link:
/// FixedLink model, uniform twist (relax_twist).
ElasticRod twisted_ring(int n, double Lk, const RodMaterial& mat) {
  const Points P = fixtures::circle(n, 1.0 / (2.0 * std::sin(M_PI / n)));
  ElasticRod rod(P, mat, TwistModel::FixedLink);
  rod.set_link(Lk);
  rod.relax_twist();
  return rod;
}

}  // namespace

TEST(RodPhysics, CoveredCircleBendingEnergyConvergesAtSecondOrder) {
  // E_bend → 2π² k² EI / L; the discrete error is (2/3)(πk/n)² + O(n⁻⁴) for a
  // regular polygon. The offset δ = 1e-3 R changes the limit by O(δ²) only.
  const RodMaterial mat;
  const double EI = mat.bending_stiffness();
  for (int k = 1; k <= 3; ++k) {
    std::vector<double> err;
    std::vector<double> En;
    for (int per_cover : {25, 50, 100, 200}) {
      const int n = per_cover * k;
      const Points P = covered_circle(n, k, 1.0, 1e-3);
      ElasticRod rod(P, mat, TwistModel::TwistFree);
      EXPECT_NEAR(rod.energy(EnergyTerm::Stretch), 0.0, 1e-20);
      const double L = polygon_length(P);
      const double ref = 2.0 * M_PI * M_PI * k * k * EI / L;
      const double E = rod.energy(EnergyTerm::Bend);
      err.push_back(E / ref - 1.0);
      En.push_back(E / ref);
    }
    for (size_t j = 0; j + 1 < err.size(); ++j) {
      const double order = std::log2(err[j] / err[j + 1]);
      std::cout << "k = " << k << ": relative error " << err[j] << " -> " << err[j + 1] << ", order " << order
                << "\n";
      EXPECT_NEAR(order, 2.0, 0.05) << "k = " << k;  // measured convergence order
    }
    // Leading term of the error of a regular polygon: (2/3)(π k / n)².
    EXPECT_NEAR(err.back() / (2.0 / 3.0 * std::pow(M_PI / 200.0, 2)), 1.0, 0.01) << "k = " << k;
    // Richardson extrapolation of the last two levels removes the n⁻² term.
    const double limit = En.back() + (En.back() - En[En.size() - 2]) / 3.0;
    EXPECT_NEAR(limit, 1.0, 1e-5) << "k = " << k;
  }
}

TEST(RodPhysics, LinkIsInvariantWhileTwistAndWritheChange) {
  // A trefoil with prescribed link and random material angles, deformed by a
  // smooth drift plus noise in 300 small steps (no strand passage), frames
  // transported after every step.
  const int n = 150;
  ElasticRod rod(fixtures::torus_knot(n, 2, 3), RodMaterial{}, TwistModel::FixedLink);
  std::mt19937_64 rng(21);
  std::normal_distribution<double> N(0.0, 1.0);
  VecX d = rod.dofs();
  for (int j = 0; j < n; ++j) d(3 * n + j) = N(rng);
  rod.set_dofs(d);
  rod.set_link(rod.writhe() - 2.7);
  const double Lk0 = rod.link(), Tw0 = rod.twist(), Wr0 = rod.writhe();
  // Smooth drift: a random displacement field of low Fourier modes.
  const Points drift = fixtures::random_fourier_curve(n, 3, 5, 0.0015);
  double max_dev = 0.0;
  for (int step = 0; step < 300; ++step) {
    d = rod.dofs();
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) d(3 * i + c) += drift(i, c) * (1.0 + 0.5 * std::sin(0.05 * step)) + 0.002 * N(rng);
    for (int j = 0; j < n; ++j) d(3 * n + j) += 0.01 * N(rng);
    rod.set_dofs(d);
    const double dev = std::fabs(rod.link() - Lk0);
    max_dev = std::max(max_dev, dev);
    if (step % 10 == 0) {
      // Strands stay far apart compared with the per-step displacement (< 0.02):
      // no strand passage, so the exact link cannot jump.
      ASSERT_GT(clearance(rod.positions(), 10).distance, 0.2) << "step " << step;
    }
    ASSERT_LT(dev, 1e-8) << "step " << step;  // link preserved to 1e-8
    rod.update_reference_frames();
  }
  std::cout << "twist " << Tw0 << " -> " << rod.twist() << ", writhe " << Wr0 << " -> " << rod.writhe()
            << ", max |ΔLk| = " << max_dev << "\n";
  EXPECT_GT(std::fabs(rod.twist() - Tw0), 0.05);
  EXPECT_GT(std::fabs(rod.writhe() - Wr0), 0.05);
}

TEST(RodPhysics, ReferenceTwistStaysContinuousUnderLargeRotations) {
  // Two full turns of a rigid rotation in 400 steps: the total reference
  // twist must come back continuously (no 2π jumps), so Tw and Lk are unchanged.
  const int n = 80;
  const Points P0 = fixtures::torus_knot(n, 3, 2);
  ElasticRod rod(P0, RodMaterial{}, TwistModel::FixedLink);
  rod.set_link(rod.writhe() + 0.4);
  const double Tw0 = rod.twist(), Lk0 = rod.link();
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  VecX d = rod.dofs();
  for (int step = 1; step <= 400; ++step) {
    const Mat3 R = Eigen::AngleAxisd(4.0 * M_PI * step / 400, axis).toRotationMatrix();
    d.head(3 * n) = as_vector(fixtures::rigid_copy(P0, R, Vec3::Zero(), 0));
    rod.set_dofs(d);
    rod.update_reference_frames();
    ASSERT_NEAR(rod.twist(), Tw0, 1e-9) << "step " << step;
  }
  EXPECT_NEAR(rod.link(), Lk0, 1e-9);
}

TEST(RodPhysics, MichellInstabilityOfTwistedRing) {
  // Michell (1889): a twisted planar ring is stable for Lk < √3 (1 + ν)
  // (= 2.25 for ν = 0.3) and unstable above. The ring with unit rest edges is
  // an equilibrium (gradient zero by symmetry); its zero modes (translations,
  // rotations with the matching θ change, uniform θ shift) are checked to be
  // null vectors of H and then excluded by restricting H to their orthogonal
  // complement.
  RodMaterial mat;
  mat.poisson = 0.3;
  const int n = 60;
  for (double Lk : {2.0, 2.5}) {
    ElasticRod rod = twisted_ring(n, Lk, mat);
    EXPECT_NEAR(rod.link(), Lk, 1e-12);
    EXPECT_NEAR(rod.twist(), Lk, 1e-12);  // planar: Wr = 0
    const VecX g = rod.gradient();
    const Eigen::MatrixXd H = Eigen::MatrixXd(rod.hessian());
    EXPECT_LT(g.norm(), 1e-10 * H.norm());  // equilibrium
    const Eigen::MatrixXd Z = full_model_zero_modes(rod);
    for (int c = 0; c < 7; ++c)
      EXPECT_LT((H * Z.col(c)).norm(), 1e-9 * H.norm() * Z.col(c).norm()) << "zero mode " << c << ", Lk " << Lk;
    const double lmin = min_eigenvalue_excluding(H, Z);
    std::cout << "Lk = " << Lk << ": smallest eigenvalue without zero modes " << lmin << " (|H| = " << H.norm()
              << ")\n";
    if (Lk < std::sqrt(3.0) * (1.0 + mat.poisson))
      EXPECT_GT(lmin, 1e-9 * H.norm());  // positive definite on the complement
    else
      EXPECT_LT(lmin, -1e-9 * H.norm());  // indefinite
  }
}

TEST(RodPhysics, MichellCriticalLinkMatchesTheory) {
  // Bisection on Lk for the sign change of the smallest non-zero-mode
  // eigenvalue. The discrete critical link converges to √3 (1 + ν) at second
  // order in n; Richardson extrapolation of n = 30 and 60 must hit it.
  RodMaterial mat;
  mat.poisson = 0.3;
  const double theory = std::sqrt(3.0) * 1.3;
  std::vector<double> critical;
  for (int n : {30, 60}) {
    double lo = 1.5, hi = 3.0;
    for (int it = 0; it < 30; ++it) {
      const double mid = 0.5 * (lo + hi);
      ElasticRod rod = twisted_ring(n, mid, mat);
      const Eigen::MatrixXd H = Eigen::MatrixXd(rod.hessian());
      (min_eigenvalue_excluding(H, full_model_zero_modes(rod)) > 0 ? lo : hi) = mid;
    }
    critical.push_back(0.5 * (lo + hi));
    std::cout << "n = " << n << ": critical link " << critical.back() << " (theory " << theory << ")\n";
  }
  EXPECT_LT(std::fabs(critical[1] / theory - 1.0), 0.01);
  const double ratio = (critical[0] - theory) / (critical[1] - theory);
  EXPECT_NEAR(ratio, 4.0, 0.3);  // second-order convergence
  const double extrapolated = critical[1] + (critical[1] - critical[0]) / 3.0;
  EXPECT_NEAR(extrapolated / theory, 1.0, 1e-3);
}

TEST(RodPhysics, TwistFreeFastPathAgreesWithRelaxedFullModel) {
  // Full model with Θ free: minimise over (θ, Θ) for fixed positions. The
  // twisting energy is quadratic in them, so one Newton step on the angle
  // block (pinning θ_0 against the uniform-shift null mode) is exact. The
  // energy and position gradient then equal those of the twist-free model.
  for (std::uint64_t seed : {1, 2, 3}) {
    const int n = 50;
    const Points P0 = rodtest::smooth_random_curve(n, seed, 3.0);
    ElasticRod full(P0, RodMaterial{}, TwistModel::FreeTheta);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> N(0.0, 1.0);
    VecX d = full.dofs();
    for (int j = 0; j <= n; ++j) d(3 * n + j) = N(rng);
    full.set_dofs(d);
    full.update_reference_frames();
    d = full.dofs();
    const Points P = rodtest::perturbed(P0, 0.05, seed + 9);  // away from the source frames
    d.head(3 * n) = as_vector(P);
    full.set_dofs(d);
    ASSERT_GT(full.energy(EnergyTerm::Twist), 1.0);
    // Newton step on the angles: unknowns θ_1..θ_{n-1}, Θ (θ_0 pinned).
    const Eigen::MatrixXd H = Eigen::MatrixXd(full.hessian());
    const VecX g = full.gradient();
    const int na = n;  // θ_1 .. θ_{n-1}, Θ
    const Eigen::MatrixXd Haa = H.block(3 * n + 1, 3 * n + 1, na, na);
    const VecX step = Haa.ldlt().solve(-g.segment(3 * n + 1, na));
    d.segment(3 * n + 1, na) += step;
    full.set_dofs(d);
    const VecX gf = full.gradient();
    EXPECT_LT(gf.tail(n + 1).norm(), 1e-9 * g.tail(n + 1).norm());  // relaxed
    EXPECT_LT(full.energy(EnergyTerm::Twist), 1e-20);
    ElasticRod fast(P, full.rest_edge_lengths(), RodMaterial{}, TwistModel::TwistFree);
    const double Ef = full.energy(), Es = fast.energy();
    EXPECT_NEAR(Ef, Es, 1e-12 * Es);
    const VecX gs = fast.gradient();
    EXPECT_GT(gs.norm(), 1.0);
    EXPECT_LT((gf.head(3 * n) - gs).norm(), 1e-9 * gs.norm());
    // The closed-form relax_twist() reaches the same minimum.
    ElasticRod again = full;
    VecX d2 = again.dofs();
    d2.tail(n + 1).setRandom();
    again.set_dofs(d2);
    again.relax_twist();
    EXPECT_NEAR(again.energy(), Es, 1e-12 * Es);
    EXPECT_LT((again.gradient().head(3 * n) - gs).norm(), 1e-9 * gs.norm());
  }
}

TEST(RodPhysics, StraightRodMinEigenvalueMatchesAssembledHessian) {
  // The open straight rod of n edges of length h assembled from the kernels
  // (stretch per edge; bending and twist at each interior vertex with Voronoi
  // length h; source frames = current), dense eigenvalues, smallest above the
  // zero-mode threshold, against the function.
  RodMaterial mat;
  for (int n : {3, 5, 12, 60})
    for (TwistModel model : {TwistModel::TwistFree, TwistModel::FixedLink}) {
      const double h = 0.8;
      const bool twist = model != TwistModel::TwistFree;
      const int nv = n + 1, nx = 3 * nv, N = nx + (twist ? n : 0);
      Eigen::MatrixXd H = Eigen::MatrixXd::Zero(N, N);
      std::vector<Vec3> x(static_cast<size_t>(nv));
      for (int k = 0; k < nv; ++k) x[static_cast<size_t>(k)] = Vec3(k * h, 0, 0);
      for (int j = 0; j < n; ++j) {
        const Mat3 Hs = rod::stretch_hessian(x[static_cast<size_t>(j + 1)] - x[static_cast<size_t>(j)], h,
                                             mat.stretching_stiffness());
        H.block<3, 3>(3 * j, 3 * j) += Hs;
        H.block<3, 3>(3 * j + 3, 3 * j + 3) += Hs;
        H.block<3, 3>(3 * j, 3 * j + 3) -= Hs;
        H.block<3, 3>(3 * j + 3, 3 * j) -= Hs;
      }
      for (int i = 1; i < n; ++i) {
        const Vec3 a = x[static_cast<size_t>(i)] - x[static_cast<size_t>(i - 1)];
        const Vec3 b = x[static_cast<size_t>(i + 1)] - x[static_cast<size_t>(i)];
        rod::Mat9 Hb = rod::to_vertices(rod::Mat6(0.5 * mat.bending_stiffness() / h * rod::kb_squared_hessian(a, b)));
        H.block<9, 9>(3 * (i - 1), 3 * (i - 1)) += Hb;
        if (twist) {
          // τ = θ_i - θ_{i-1} + m_i, m_i = Δm(a, b) from the straight source (τ = 0 here).
          const double k = mat.twisting_stiffness() / h;
          Eigen::VectorXd dt = Eigen::VectorXd::Zero(N);
          dt.segment<9>(3 * (i - 1)) = rod::to_vertices(rod::reference_twist_change_gradient(a.normalized(), b.normalized(), a, b));
          dt(nx + i) += 1.0;
          dt(nx + i - 1) -= 1.0;
          H += k * dt * dt.transpose();
        }
      }
      const VecX ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly).eigenvalues();
      double expected = 0;
      for (Eigen::Index k = 0; k < ev.size(); ++k)
        if (ev(k) > 1e-9 * ev.maxCoeff()) {
          expected = ev(k);
          break;
        }
      const double got = straight_rod_min_eigenvalue(n, h, mat, model);
      EXPECT_NEAR(got, expected, 1e-7 * expected) << "n = " << n;
      // Zero modes: 3 translations + 2 rigid tilts of the line (+ uniform θ shift).
      EXPECT_EQ((ev.array() < 1e-9 * ev.maxCoeff()).count(), twist ? 6 : 5) << "n = " << n;
    }
  // The paper's wire: n = 400, unit edges (bending dominates, ~EI (4.73/n)⁴).
  const RodMaterial paper;
  const double l400 = straight_rod_min_eigenvalue(400, 1.0, paper, TwistModel::TwistFree);
  EXPECT_NEAR(l400 / (paper.bending_stiffness() * std::pow(4.730040745 / 400.0, 4)), 1.0, 0.02);
  EXPECT_EQ(l400, straight_rod_min_eigenvalue(400, 1.0, paper, TwistModel::FreeTheta));
}

TEST(RodPhysics, NewtonWithFrameUpdatesConvergesQuadratically) {
  // Plain Newton steps (no line search) on a twisted ring
  // (Lk = 1.2, below Michell's threshold) deformed smoothly out of plane and
  // stretched by 1% (tension keeps the Hessian positive definite, as a
  // compressed edge would not), reference frames transported after every
  // step: the exact gradient and Hessian give quadratic convergence to the
  // uniformly twisted regular polygon.
  const int n = 40;
  const double Lk = 1.2;
  ElasticRod ring = twisted_ring(n, Lk, RodMaterial{});
  const double E_ring = ring.energy();
  ElasticRod rod = ring;
  VecX d = rod.dofs();
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * i / n;
    d.segment<3>(3 * i) *= 1.01;
    d(3 * i + 2) += 0.3 * std::cos(2 * phi) + 0.1 * std::sin(3 * phi);
  }
  rod.set_dofs(d);
  std::vector<double> norms;
  for (int it = 0; it < 12; ++it) {
    const VecX g = rod.gradient();
    norms.push_back(g.norm());
    if (g.norm() < 1e-10) break;
    // Newton step in the orthogonal complement of the rigid-motion and
    // θ-shift directions (along which the energy is invariant, so H is
    // singular or nearly so there).
    const Eigen::MatrixXd Z = full_model_zero_modes(rod);
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Z).householderQ();
    const Eigen::MatrixXd C = Q.rightCols(rod.num_dofs() - Z.cols());
    const Eigen::MatrixXd Hc = C.transpose() * Eigen::MatrixXd(rod.hessian()) * C;
    rod.set_dofs(rod.dofs() - C * Hc.ldlt().solve(C.transpose() * g));
    rod.update_reference_frames();
    EXPECT_NEAR(rod.link(), Lk, 1e-9);
  }
  for (double v : norms) std::cout << v << " ";
  std::cout << "\n";
  ASSERT_LT(norms.back(), 1e-10);
  ASSERT_LE(norms.size(), 9u);
  // Quadratic: in the asymptotic regime one step takes |g| from below 1e-2 to
  // below min(1e-3 |g|, 100 |g|²) (a linearly convergent iteration, as with an
  // inexact Hessian, does not).
  bool quadratic = false;
  for (size_t k = 0; k + 1 < norms.size(); ++k)
    if (norms[k] < 1e-2 && norms[k + 1] < std::min(1e-3 * norms[k], 100 * norms[k] * norms[k])) quadratic = true;
  EXPECT_TRUE(quadratic);
  EXPECT_NEAR(rod.energy(), E_ring, 1e-9 * E_ring);
  EXPECT_NEAR(rod.twist(), Lk, 1e-6);  // back to a planar ring: Wr = 0
}
