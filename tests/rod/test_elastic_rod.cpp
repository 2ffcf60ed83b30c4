// ElasticRod: finite differences of every term for every model, Hessian
// assembly and pattern replay, state handling, frames, validation.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include "ek/core/errors.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/rod/kernels.hpp"
#include "rod_testing.hpp"

using namespace ek;
using rodtest::rel_error;

namespace {

const TwistModel kModels[] = {TwistModel::TwistFree, TwistModel::FreeTheta, TwistModel::FixedLink};
const EnergyTerm kTerms[] = {EnergyTerm::Stretch, EnergyTerm::Bend, EnergyTerm::Twist, EnergyTerm::All};

const char* name(TwistModel m) {
  return m == TwistModel::TwistFree ? "TwistFree" : (m == TwistModel::FreeTheta ? "FreeTheta" : "FixedLink");
}
const char* name(EnergyTerm t) {
  return t == EnergyTerm::Stretch ? "Stretch"
                                  : (t == EnergyTerm::Bend ? "Bend" : (t == EnergyTerm::Twist ? "Twist" : "All"));
}

/// A generic framed rod: random smooth curve, rest lengths off by a few
/// percent, random material angles and Θ, source frames at an intermediate
/// configuration, current positions moved away from the source (so the
/// reference twists are evaluated away from the source).
ElasticRod generic_rod(TwistModel model, std::uint64_t seed, int n = 24) {
  const Points P0 = rodtest::smooth_random_curve(n, seed, 2.0);
  std::mt19937_64 rng(seed + 100);
  std::normal_distribution<double> N(0.0, 1.0);
  VecX rest(n);
  for (int j = 0; j < n; ++j) rest(j) = (P0.row((j + 1) % n) - P0.row(j)).norm() * (1.0 + 0.05 * N(rng));
  RodMaterial mat;
  mat.radius = 0.3;  // stiffnesses of comparable size: EA ≈ 565, EI ≈ 12.7, GJ ≈ 9.8
  ElasticRod rod(P0, rest, mat, model);
  const double h = rest.mean();
  VecX d = rod.dofs();
  d.head(3 * n) = as_vector(rodtest::perturbed(P0, 0.05 * h, seed + 1));
  if (model != TwistModel::TwistFree)
    for (int j = 0; j < n; ++j) d(3 * n + j) = 0.7 * N(rng);
  if (model == TwistModel::FreeTheta) d(4 * n) = 3.0 * N(rng);
  rod.set_dofs(d);
  if (model == TwistModel::FixedLink) rod.set_link(rod.link() + 1.3);
  rod.update_reference_frames();
  d = rod.dofs();
  d.head(3 * n) = as_vector(rodtest::perturbed(rod.positions(), 0.05 * h, seed + 2));
  rod.set_dofs(d);
  return rod;
}

}  // namespace

TEST(ElasticRod, DofLayoutAndRoundTrip) {
  const Points P = fixtures::torus_knot(30, 2, 3);
  for (TwistModel m : kModels) {
    ElasticRod rod(P, RodMaterial{}, m);
    const int n = 30;
    EXPECT_EQ(rod.num_vertices(), n);
    EXPECT_EQ(rod.num_dofs(), m == TwistModel::TwistFree ? 3 * n : (m == TwistModel::FreeTheta ? 4 * n + 1 : 4 * n));
    VecX d = rod.dofs();
    ASSERT_EQ(d.size(), rod.num_dofs());
    EXPECT_EQ(d.head(3 * n), as_vector(P));
    d.setRandom();
    rod.set_dofs(d);
    EXPECT_EQ(rod.dofs(), d);
    EXPECT_EQ(as_vector(rod.positions()), d.head(3 * n));
    EXPECT_THROW(rod.set_dofs(VecX::Zero(d.size() + 1)), std::invalid_argument);
  }
}

TEST(ElasticRod, ValidatesInput) {
  EXPECT_THROW(ElasticRod(fixtures::circle(2, 1.0), RodMaterial{}, TwistModel::TwistFree), std::invalid_argument);
  Points P = fixtures::circle(10, 1.0);
  P.row(3) = P.row(4);
  EXPECT_THROW(ElasticRod(P, RodMaterial{}, TwistModel::TwistFree), std::invalid_argument);
  const Points C = fixtures::circle(10, 1.0);
  EXPECT_THROW(ElasticRod(C, VecX::Ones(9), RodMaterial{}, TwistModel::TwistFree), std::invalid_argument);
  EXPECT_THROW(ElasticRod(C, -VecX::Ones(10), RodMaterial{}, TwistModel::TwistFree), std::invalid_argument);
  RodMaterial bad;
  bad.poisson = 0.6;
  EXPECT_THROW(ElasticRod(C, bad, TwistModel::TwistFree), InputError);
  bad = RodMaterial{};
  bad.radius = 0.0;
  EXPECT_THROW(bad.validate(), InputError);
  bad = RodMaterial{};
  bad.young = std::nan("");
  EXPECT_THROW(bad.validate(), InputError);
  bad = RodMaterial{};
  bad.poisson = -1.0;
  EXPECT_THROW(bad.validate(), InputError);
  ElasticRod free(C, RodMaterial{}, TwistModel::TwistFree);
  EXPECT_THROW(free.set_link(1.0), std::invalid_argument);
}

TEST(ElasticRod, MaterialStiffnesses) {
  RodMaterial m;  // paper defaults
  EXPECT_DOUBLE_EQ(m.young, 2000.0);
  EXPECT_DOUBLE_EQ(m.poisson, 0.3);
  EXPECT_DOUBLE_EQ(m.radius, 0.2);
  EXPECT_NEAR(m.bending_stiffness(), 2000.0 * M_PI * std::pow(0.2, 4) / 4, 1e-12);
  EXPECT_NEAR(m.twisting_stiffness(), 2000.0 / 2.6 * M_PI * std::pow(0.2, 4) / 2, 1e-12);
  EXPECT_NEAR(m.stretching_stiffness(), 2000.0 * M_PI * 0.04, 1e-12);
  // EI / GJ = 1 + ν for a circular cross-section.
  EXPECT_NEAR(m.bending_stiffness() / m.twisting_stiffness(), 1.3, 1e-14);
}

TEST(ElasticRod, EnergyTermsAddUpAndMatchFormulas) {
  for (TwistModel m : kModels) {
    ElasticRod rod = generic_rod(m, 11);
    const double s = rod.energy(EnergyTerm::Stretch), b = rod.energy(EnergyTerm::Bend);
    const double t = rod.energy(EnergyTerm::Twist);
    EXPECT_GT(s, 0.0);
    EXPECT_GT(b, 0.0);
    if (m == TwistModel::TwistFree)
      EXPECT_EQ(t, 0.0);
    else
      EXPECT_GT(t, 0.0);
    EXPECT_NEAR(rod.energy(), s + b + t, 1e-12 * (s + b + t));
    // Independent evaluation of the three sums from the positions.
    const Points& P = rod.positions();
    const int n = rod.num_vertices();
    const RodMaterial& mat = rod.material();
    double S = 0, B = 0, T = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 a = P.row(i) - P.row((i + n - 1) % n), c = P.row((i + 1) % n) - P.row(i);
      const double l = rod.rest_edge_lengths()(i), lv = rod.rest_voronoi_lengths()(i);
      EXPECT_NEAR(lv, 0.5 * (rod.rest_edge_lengths()((i + n - 1) % n) + l), 1e-15);
      S += 0.5 * mat.stretching_stiffness() * std::pow(c.norm() / l - 1, 2) * l;
      const double phi = std::atan2(a.cross(c).norm(), a.dot(c));
      B += 0.5 * mat.bending_stiffness() * std::pow(2 * std::tan(phi / 2), 2) / lv;
      T += 0.5 * mat.twisting_stiffness() * std::pow(rod.twist_angle(i), 2) / lv;
    }
    EXPECT_NEAR(s, S, 1e-12 * S);
    EXPECT_NEAR(b, B, 1e-10 * B);
    EXPECT_NEAR(t, T, 1e-12 * (1 + T));
  }
}

// The main finite-difference test: every term, every model, three step sizes.
// Errors are relative (2-norm for gradients, Frobenius norm for Hessians),
// measured separately on the position and angle blocks so that a small block
// cannot hide behind a large one; each must be <= 1e-6.
TEST(ElasticRod, FiniteDifferencesEveryTermEveryModel) {
  double worst = 0.0;  // largest relative error seen, printed for the record
  auto check = [&worst](double err) {
    worst = std::max(worst, err);
    return err;
  };
  for (TwistModel m : kModels)
    for (std::uint64_t seed : {1, 2}) {
      ElasticRod rod = generic_rod(m, seed);
      const int n = rod.num_vertices(), N = rod.num_dofs(), nx = 3 * n, na = N - nx;
      for (EnergyTerm term : kTerms) {
        SCOPED_TRACE(std::string(name(m)) + " " + name(term) + " seed " + std::to_string(seed));
        const VecX g = rod.gradient(term);
        const Eigen::MatrixXd H = Eigen::MatrixXd(rod.hessian(term));
        ASSERT_EQ(g.size(), N);
        ASSERT_EQ(H.rows(), N);
        EXPECT_LT((H - H.transpose()).norm(), 1e-12 * (1 + H.norm()));
        const bool twist_only = term == EnergyTerm::Twist;
        const bool has_angles = m != TwistModel::TwistFree;
        if (twist_only && !has_angles) {
          EXPECT_EQ(g.norm(), 0.0);
          EXPECT_EQ(H.norm(), 0.0);
          continue;
        }
        // Non-trivial values (the test can fail).
        EXPECT_GT(g.head(nx).norm(), 1e-3);
        EXPECT_GT(H.topLeftCorner(nx, nx).norm(), 1e-3);
        const bool angle_blocks = has_angles && (term == EnergyTerm::Twist || term == EnergyTerm::All);
        if (has_angles && !angle_blocks) {
          // Stretching and bending do not depend on θ, Θ: exact zeros.
          EXPECT_EQ(g.tail(na).norm(), 0.0);
          EXPECT_EQ(H.rightCols(na).norm(), 0.0);
        }
        if (angle_blocks) {
          EXPECT_GT(g.tail(na).norm(), 1e-3);
          EXPECT_GT(H.bottomLeftCorner(na, nx).norm(), 1e-3);
        }
        for (double h : {1e-4, 1e-5, 1e-6}) {
          SCOPED_TRACE("h = " + std::to_string(h));
          const VecX gf = rodtest::fd_gradient(rod, term, h);
          const Eigen::MatrixXd Hf = rodtest::fd_hessian(rod, term, h);
          EXPECT_LT(check(rel_error(gf.head(nx), g.head(nx))), 1e-6);  // relative error <= 1e-6
          EXPECT_LT(check(rel_error(Hf.topLeftCorner(nx, nx), H.topLeftCorner(nx, nx))), 1e-6);  // <= 1e-6
          if (angle_blocks) {
            EXPECT_LT(check(rel_error(gf.tail(na), g.tail(na))), 1e-6);  // relative error <= 1e-6
            EXPECT_LT(check(rel_error(Hf.bottomLeftCorner(na, nx), H.bottomLeftCorner(na, nx))), 1e-6);  // <= 1e-6
            EXPECT_LT(check(rel_error(Hf.bottomRightCorner(na, na), H.bottomRightCorner(na, na))), 1e-6);  // <= 1e-6
          } else if (has_angles) {
            EXPECT_LT(gf.tail(na).norm(), 1e-6 * g.norm());  // zero up to rounding
            EXPECT_LT(Hf.rightCols(na).norm(), 1e-6 * H.norm());
          }
        }
      }
    }
  std::cout << "largest relative finite-difference error: " << worst << "\n";
}

TEST(ElasticRod, FiniteDifferencesSmallRodsAndLargeTwist) {
  // n = 3 and 4 (stencils wrap onto themselves) and a strongly twisted rod.
  for (int n : {3, 4, 5})
    for (TwistModel m : kModels) {
      ElasticRod rod = generic_rod(m, 40 + n, n);
      SCOPED_TRACE(std::string(name(m)) + " n = " + std::to_string(n));
      const VecX g = rod.gradient();
      const Eigen::MatrixXd H = Eigen::MatrixXd(rod.hessian());
      for (double h : {1e-5, 1e-6}) {
        EXPECT_LT(rel_error(rodtest::fd_gradient(rod, EnergyTerm::All, h), g), 1e-6);  // relative error <= 1e-6
        EXPECT_LT(rel_error(rodtest::fd_hessian(rod, EnergyTerm::All, h), H), 1e-6);   // relative error <= 1e-6
      }
    }
}

TEST(ElasticRod, HessianPatternIsReplayedForEveryTerm) {
  for (TwistModel m : kModels) {
    ElasticRod rod = generic_rod(m, 5);
    SparseAssembler A;
    int pass = 0;
    for (EnergyTerm term : {EnergyTerm::All, EnergyTerm::Stretch, EnergyTerm::Bend, EnergyTerm::Twist, EnergyTerm::All}) {
      A.begin(rod.num_dofs());
      A.segment(0, rod.hessian_structure());
      rod.add_hessian(A, term);
      const bool changed = A.end();
      EXPECT_EQ(changed, pass == 0) << name(m) << " " << name(term);
      const Eigen::MatrixXd full = Eigen::MatrixXd(A.matrix()).selfadjointView<Eigen::Upper>();
      EXPECT_LT((full - Eigen::MatrixXd(rod.hessian(term))).norm(), 1e-12 * (1 + full.norm()));
      ++pass;
    }
    // Sum of the terms equals All.
    const Eigen::MatrixXd sum = Eigen::MatrixXd(rod.hessian(EnergyTerm::Stretch)) +
                                Eigen::MatrixXd(rod.hessian(EnergyTerm::Bend)) +
                                Eigen::MatrixXd(rod.hessian(EnergyTerm::Twist));
    EXPECT_LT((sum - Eigen::MatrixXd(rod.hessian())).norm(), 1e-12 * sum.norm());
    const VecX gsum = rod.gradient(EnergyTerm::Stretch) + rod.gradient(EnergyTerm::Bend) + rod.gradient(EnergyTerm::Twist);
    EXPECT_LT((gsum - rod.gradient()).norm(), 1e-12 * gsum.norm());
  }
}

TEST(ElasticRod, TranslationInvarianceAndTranslationNullModes) {
  for (TwistModel m : kModels) {
    ElasticRod rod = generic_rod(m, 6);
    const double E = rod.energy();
    const Eigen::MatrixXd H = Eigen::MatrixXd(rod.hessian());
    const int n = rod.num_vertices();
    for (int c = 0; c < 3; ++c) {
      VecX v = VecX::Zero(rod.num_dofs());
      for (int i = 0; i < n; ++i) v(3 * i + c) = 1.0;
      EXPECT_LT((H * v).norm(), 1e-10 * H.norm() * v.norm()) << name(m);
      ElasticRod moved = rod;
      moved.set_dofs(rod.dofs() + 0.37 * v);
      EXPECT_NEAR(moved.energy(), E, 1e-12 * E);
    }
  }
}

TEST(ElasticRod, RigidRotationLeavesEnergyUnchanged) {
  // Rotating a twist-free rod, or re-building any rod from a rotated curve,
  // changes no energy term.
  const Points P = fixtures::torus_knot(40, 2, 3);
  const Mat3 R = fixtures::random_rotation(9);
  const Points Q = fixtures::rigid_copy(P, R, Vec3(1, -2, 0.5), 0);
  for (TwistModel m : kModels) {
    ElasticRod a(P, RodMaterial{}, m), b(Q, a.rest_edge_lengths(), RodMaterial{}, m);
    if (m == TwistModel::FixedLink) {
      a.set_link(3.0);
      b.set_link(3.0);
      a.relax_twist();
      b.relax_twist();
    }
    for (EnergyTerm t : kTerms) EXPECT_NEAR(a.energy(t), b.energy(t), 1e-10 * (1 + a.energy(t))) << name(m);
  }
}

TEST(ElasticRod, InitialFramingIsTwistFree) {
  const Points P = fixtures::torus_knot(60, 2, 5);
  for (TwistModel m : kModels) {
    ElasticRod rod(P, RodMaterial{}, m);
    EXPECT_NEAR(rod.twist(), 0.0, 1e-14);
    EXPECT_NEAR(rod.energy(EnergyTerm::Twist), 0.0, 1e-25);
    EXPECT_NEAR(rod.link(), rod.writhe(), 1e-14);
    EXPECT_NEAR(rod.theta_total() + rod.total_reference_twist(), 0.0, 1e-14);
    // Space-parallel transport: no reference twist except at the closing vertex.
    for (int i = 1; i < 60; ++i) EXPECT_NEAR(rod.reference_twist(i), 0.0, 1e-14);
    EXPECT_LE(std::fabs(rod.reference_twist(0)), M_PI);
    // Frames are adapted and orthonormal.
    for (int j = 0; j < 60; ++j) {
      const Vec3 t = (P.row((j + 1) % 60) - P.row(j)).normalized();
      EXPECT_NEAR(rod.reference_director(j).dot(t), 0.0, 1e-14);
      EXPECT_NEAR(rod.material_director(j).norm(), 1.0, 1e-14);
    }
  }
}

TEST(ElasticRod, ReferenceTwistMatchesTransportedDirectors) {
  // After many accepted steps, the reference twist from the holonomy formula
  // equals the angle between the (time-transported) reference directors of
  // consecutive edges, measured directly (mod 2π).
  ElasticRod rod(rodtest::smooth_random_curve(30, 3), RodMaterial{}, TwistModel::FixedLink);
  const int n = 30;
  for (int step = 0; step < 30; ++step) {
    VecX d = rod.dofs();
    d.head(3 * n) = as_vector(rodtest::perturbed(rod.positions(), 0.02, 1000 + step));
    rod.set_dofs(d);
    for (int i = 0; i < n; ++i) {
      const int a = (i + n - 1) % n;
      const Vec3 ta = (rod.positions().row(i) - rod.positions().row(a)).normalized();
      const Vec3 ti = (rod.positions().row((i + 1) % n) - rod.positions().row(i)).normalized();
      const double direct =
          rod::signed_angle(rod::parallel_transport(ta, ti, rod.reference_director(a)), rod.reference_director(i), ti);
      EXPECT_NEAR(std::remainder(rod.reference_twist(i) - direct, 2 * M_PI), 0.0, 1e-10);
    }
    if (step % 2 == 0) rod.update_reference_frames();
  }
}

TEST(ElasticRod, SaveRestore) {
  for (TwistModel m : kModels) {
    ElasticRod rod = generic_rod(m, 8);
    const VecX d0 = rod.dofs();
    const double E0 = rod.energy(), Tw0 = rod.twist();
    const VecX g0 = rod.gradient();
    const ElasticRod::State s = rod.save();
    VecX d = d0;
    d.head(3 * rod.num_vertices()) = as_vector(rodtest::perturbed(rod.positions(), 0.1, 77));
    rod.set_dofs(d);
    rod.update_reference_frames();
    EXPECT_NE(rod.energy(), E0);
    rod.restore(s);
    EXPECT_EQ(rod.dofs(), d0);
    EXPECT_EQ(rod.energy(), E0);
    EXPECT_EQ(rod.gradient(), g0);
    EXPECT_EQ(rod.twist(), Tw0);
  }
}

TEST(ElasticRod, RelaxTwistMinimisesTwistingEnergy) {
  const Points P = rodtest::smooth_random_curve(40, 12, 3.0);
  for (TwistModel m : {TwistModel::FreeTheta, TwistModel::FixedLink}) {
    ElasticRod rod(P, RodMaterial{}, m);
    rod.set_link(rod.writhe() + 2.5);
    const double Lk = rod.link();
    VecX d = rod.dofs();
    d.head(3 * 40) = as_vector(rodtest::perturbed(P, 0.05, 3));
    rod.set_dofs(d);
    const double Lk_moved = rod.link();  // deformation (no crossing) keeps the link
    EXPECT_NEAR(Lk_moved, Lk, 1e-8);
    rod.relax_twist();
    const VecX g = rod.gradient();
    const int na = rod.num_dofs() - 120;
    EXPECT_LT(g.tail(na).norm(), 1e-10 * (1 + g.norm()));
    if (m == TwistModel::FreeTheta) {
      EXPECT_NEAR(rod.energy(EnergyTerm::Twist), 0.0, 1e-20);
      EXPECT_NEAR(rod.twist(), 0.0, 1e-12);
    } else {
      // Uniform twist density: E_twist = GJ/2 (2π Tw)² / Σ l̄^V, and the link is kept.
      const double Tw = rod.twist();
      EXPECT_NEAR(rod.link(), Lk, 1e-8);
      EXPECT_GT(std::fabs(Tw), 1.0);
      const double expected = 0.5 * rod.material().twisting_stiffness() * std::pow(2 * M_PI * Tw, 2) /
                              rod.rest_voronoi_lengths().sum();
      EXPECT_NEAR(rod.energy(EnergyTerm::Twist), expected, 1e-10 * expected);
    }
  }
}

namespace {

/// The full symmetric matrix of one add_hessian() pass into A (A's pattern
/// is kept between calls, so a replay can be detected by the caller).
Eigen::MatrixXd assembled_hessian(const ElasticRod& rod, EnergyTerm term, bool project_stretch, SparseAssembler& A,
                                  bool* pattern_changed = nullptr) {
  A.begin(rod.num_dofs());
  A.segment(0, rod.hessian_structure());
  rod.add_hessian(A, term, project_stretch ? HessianKind::Projected : HessianKind::Exact);
  const bool changed = A.end();
  if (pattern_changed) *pattern_changed = changed;
  return Eigen::MatrixXd(A.matrix()).selfadjointView<Eigen::Upper>();
}

/// A rod on a smooth random curve whose rest length of edge j is
/// factor(j) times its current length (factor > 1: compressed edge).
ElasticRod rod_with_strains(TwistModel model, std::uint64_t seed, const std::function<double(int)>& factor,
                            int n = 20) {
  const Points P = rodtest::smooth_random_curve(n, seed, 2.0);
  VecX rest(n);
  for (int j = 0; j < n; ++j) rest(j) = factor(j) * (P.row((j + 1) % n) - P.row(j)).norm();
  RodMaterial mat;
  mat.radius = 0.3;
  ElasticRod rod(P, rest, mat, model);
  if (model != TwistModel::TwistFree) {
    std::mt19937_64 rng(seed + 7);
    std::normal_distribution<double> N(0.0, 0.5);
    VecX d = rod.dofs();
    for (int j = 0; j < n; ++j) d(3 * n + j) = N(rng);  // some twist, so the twist blocks are not zero
    rod.set_dofs(d);
  }
  return rod;
}

}  // namespace

TEST(ElasticRod, ProjectedStretchHessianEqualsExactWhenAllEdgesAreStretched) {
  for (TwistModel m : kModels) {
    // every rest length 0.9 or 0.97 times the edge: all edges stretched
    ElasticRod rod = rod_with_strains(m, 41, [](int j) { return j % 2 ? 0.9 : 0.97; });
    const Points& x = rod.positions();
    for (int j = 0; j < rod.num_vertices(); ++j)
      ASSERT_GT((x.row((j + 1) % rod.num_vertices()) - x.row(j)).norm(), rod.rest_edge_lengths()(j));
    for (EnergyTerm term : kTerms) {
      SparseAssembler A;
      const Eigen::MatrixXd H = assembled_hessian(rod, term, false, A);
      bool changed = true;
      const Eigen::MatrixXd P = assembled_hessian(rod, term, true, A, &changed);
      EXPECT_FALSE(changed) << name(m) << " " << name(term) << ": projection must replay the same pattern";
      if (term != EnergyTerm::Twist || m != TwistModel::TwistFree) {
        ASSERT_GT(H.norm(), 0.0);
      }
      EXPECT_LE((P - H).norm(), 1e-15 * H.norm()) << name(m) << " " << name(term);
      EXPECT_LT((H - Eigen::MatrixXd(rod.hessian(term))).norm(), 1e-12 * (1 + H.norm()));
    }
  }
}

TEST(ElasticRod, ProjectedStretchHessianChangesOnlyCompressedStretchBlocks) {
  for (TwistModel m : kModels) {
    // every third edge compressed by 12%, the others stretched by 10%
    ElasticRod rod = rod_with_strains(m, 43, [](int j) { return j % 3 == 0 ? 1.12 : 0.9; });
    const int n = rod.num_vertices();
    const double EA = rod.material().stretching_stiffness();
    const Points& x = rod.positions();
    // expected difference: Σ over compressed edges j of [K, −K; −K, K] at
    // vertices (j, j+1), K = projected − exact edge kernel
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(rod.num_dofs(), rod.num_dofs());
    int compressed = 0;
    for (int j = 0; j < n; ++j) {
      const int j1 = (j + 1) % n;
      const Vec3 e = x.row(j1) - x.row(j);
      const double l = rod.rest_edge_lengths()(j);
      const Mat3 K = rod::stretch_hessian_projected(e, l, EA) - rod::stretch_hessian(e, l, EA);
      if (e.norm() < l) {
        ++compressed;
        ASSERT_GT(K.norm(), 1e-3 * EA / l);
      } else {
        ASSERT_EQ(K.norm(), 0.0);
      }
      D.block<3, 3>(3 * j, 3 * j) += K;
      D.block<3, 3>(3 * j1, 3 * j1) += K;
      D.block<3, 3>(3 * j, 3 * j1) -= K;
      D.block<3, 3>(3 * j1, 3 * j) -= K;
    }
    ASSERT_EQ(compressed, (n + 2) / 3);
    SparseAssembler A;
    for (EnergyTerm term : kTerms) {
      const Eigen::MatrixXd H = assembled_hessian(rod, term, false, A);
      bool changed = true;
      const Eigen::MatrixXd P = assembled_hessian(rod, term, true, A, &changed);
      EXPECT_FALSE(changed) << name(m) << " " << name(term);
      const bool has_stretch = term == EnergyTerm::Stretch || term == EnergyTerm::All;
      const Eigen::MatrixXd expected = has_stretch ? D : Eigen::MatrixXd::Zero(D.rows(), D.cols());
      EXPECT_LT((P - H - expected).norm(), 1e-12 * (1 + H.norm())) << name(m) << " " << name(term);
      if (has_stretch) {
        // the change only removes negative curvature: P − H is PSD and non-zero
        EXPECT_GT((P - H).norm(), 1e-3 * EA);
        const double dmin = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P - H).eigenvalues().minCoeff();
        EXPECT_GE(dmin, -1e-12 * D.norm()) << name(m) << " " << name(term);
      }
      if (term == EnergyTerm::Stretch) {
        // the exact stretching Hessian is indefinite here, the projected one is not
        const double hmin = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues().minCoeff();
        const double pmin = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues().minCoeff();
        EXPECT_LT(hmin, -1e-3 * EA) << name(m);
        EXPECT_GE(pmin, -1e-12 * P.norm()) << name(m);
      }
    }
  }
}
