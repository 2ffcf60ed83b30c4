// Loads (ek/mechanics/loads.hpp) against finite differences, and path
// following (ek/mechanics/continuation.hpp) on problems with known answers:
// a one-dof snapping system with two folds, a thin ring pulled across a
// diameter (the classical diametral stiffness), the energy balance along a
// path, and loading then unloading.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/mechanics/continuation.hpp"
#include "ek/mechanics/loads.hpp"
#include "ek/optim/saddle.hpp"
#include "ek/solver/rod_model.hpp"
#include "snapper.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// A random smooth closed curve (n = 30) as dofs.
VecX curve_dofs() {
  const Points P = fixtures::torus_knot(30, 2, 3, 6.0, 2.0);
  return as_vector(P);
}

/// Finite-difference checks of a load: gradient against the energy,
/// Hessian against the gradient, ∂(∇E)/∂μ and ∂E/∂μ against μ-differences.
void check_load(ControlledLoad& load, const VecX& x0, double h = 1e-6) {
  const int n = static_cast<int>(x0.size());
  const auto energy = [&](const VecX& x) {
    load.set_dofs(x);
    return load.energy();
  };
  const auto gradient = [&](const VecX& x) {
    load.set_dofs(x);
    VecX g = VecX::Zero(n);
    load.add_gradient(g);
    return g;
  };
  const VecX g = gradient(x0);
  EXPECT_LT((g - fixtures::fd_gradient(energy, x0, h)).norm(), 1e-6 * (1.0 + g.norm()));
  EXPECT_GT(g.norm(), 1e-8);  // not trivially zero
  load.set_dofs(x0);
  SparseAssembler A;
  A.begin(n);
  A.segment(0, load.hessian_structure());
  load.add_hessian(A, HessianKind::Exact);
  A.end();
  const Eigen::MatrixXd H = Eigen::MatrixXd(Eigen::SparseMatrix<double>(A.matrix().selfadjointView<Eigen::Upper>()));
  Eigen::MatrixXd fd(n, n);
  for (int j = 0; j < n; ++j) {
    VecX xp = x0, xm = x0;
    xp(j) += h;
    xm(j) -= h;
    fd.col(j) = (gradient(xp) - gradient(xm)) / (2 * h);
  }
  EXPECT_LT((H - fd).norm(), 1e-5 * (1.0 + H.norm()));
  const double mu = load.parameter(), hm = 1e-6 * std::max(1.0, std::abs(mu));
  load.set_parameter(mu + hm);
  const VecX gp = gradient(x0);
  const double ep = energy(x0);
  load.set_parameter(mu - hm);
  const VecX gm = gradient(x0);
  const double em = energy(x0);
  load.set_parameter(mu);
  load.set_dofs(x0);
  EXPECT_LT((load.parameter_gradient(n) - (gp - gm) / (2 * hm)).norm(), 1e-5 * (1.0 + gp.norm()));
  EXPECT_NEAR(load.parameter_derivative(), (ep - em) / (2 * hm), 1e-5 * (1.0 + std::abs(ep)));
}

}  // namespace

TEST(Loads, PullForceAndPlatesMatchFiniteDifferences) {
  const VecX x = curve_dofs();
  PullLoad pull(3, 17, 4.0, 2.5);  // stretched: δ ≈ 8 > D
  check_load(pull, x);
  PullLoad pulled(3, 17, 12.0, 2.5);  // compressed spring: the pull's normal state
  check_load(pulled, x);
  ForceLoad force(5, 20, 0.7);
  check_load(force, x);
  const Points P = as_points(x);
  const Vec3 c = P.colwise().mean().transpose();
  // plates barely wider than the curve along z: vertices within the barrier's reach
  const double extent = 2.0 * (P.col(2).array() - c.z()).abs().maxCoeff();
  PlatesLoad plates(c, Vec3::UnitZ(), extent + 0.3, 0.5, 10.0);
  check_load(plates, x, 1e-7);
  // the reactions: the pull's tension and the plates' pressing force are positive
  pulled.set_dofs(x);
  EXPECT_GT(pulled.reaction(), 0.0);
  plates.set_dofs(x);
  EXPECT_GT(plates.reaction(), 0.0);
  EXPECT_THROW(PullLoad(1, 1, 1.0, 1.0), InputError);
  EXPECT_THROW(PlatesLoad(c, Vec3::Zero(), 1.0, 0.5, 1.0), InputError);
}

TEST(Continuation, PassesBothFoldsOfTheSnapperAtTheirKnownLoads) {
  // from μ = −1 on the lower branch to μ = +1: the parameter rises to the
  // first fold (2/(3√3) = 0.3849), falls along the unstable branch (index
  // 1) to the second (−0.3849) and rises again to the target
  fixtures::Snapper f;
  f.set_parameter(-1.0);
  f.set_dofs(Eigen::Vector2d(-1.3247, 0.0));
  ContinuationOptions o;
  o.target = 1.0;
  o.step = 0.02;
  o.max_step_factor = 1.0;
  o.gradient_tolerance = 1e-12;
  const LoadPath p = follow_path(f, o);
  ASSERT_EQ(p.status, PathStatus::Reached);
  double top = -INFINITY, bottom = INFINITY;
  int limits = 0, unstable = 0;
  for (const PathPoint& q : p.points) {
    EXPECT_LE(q.gradient_norm, 1e-12);
    const double x = q.dofs(0);
    EXPECT_NEAR(q.parameter, x * x * x - x, 1e-12);
    EXPECT_EQ(q.stable, 3 * x * x - 1 > 0) << "x = " << x;
    unstable += !q.stable;
    if (q.event == PathEvent::LimitPoint) ++limits;
    if (x < -0.3) top = std::max(top, q.parameter);
    if (x > 0.3) bottom = std::min(bottom, q.parameter);
  }
  const double fold = 2.0 / (3.0 * std::sqrt(3.0));
  EXPECT_EQ(limits, 2);
  EXPECT_GT(unstable, 3);
  EXPECT_NEAR(top, fold, 2e-3);  // the path's highest point before the first fold (step 0.02)
  EXPECT_NEAR(bottom, -fold, 2e-3);
  EXPECT_NEAR(p.points.back().parameter, 1.0, 1e-15);
  EXPECT_GT(p.points.back().dofs(0), 1.0);  // on the upper branch
}

TEST(Continuation, RingPulledAcrossADiameterHasTheClassicalStiffness) {
  // δ = (π/4 − 2/π) P R³ / (EI): the small-load stiffness P/δ of a thin ring
  // pulled by two opposite point loads, within the discretisation error,
  // which falls with refinement (n = 128 and 256 unit edges; the load's
  // spring 1e4 times stiffer than the ring along the pull)
  double previous_error = INFINITY;
  for (int n : {128, 256}) {
    const Points P = fixtures::unit_ring(n);
    const double R = 0.5 / std::sin(M_PI / n), EI = RodMaterial().bending_stiffness();
    const double expected = EI / ((M_PI / 4.0 - 2.0 / M_PI) * R * R * R);
    RodModel system(P, edge_lengths(P), RelaxOptions{});
    const double D0 = 2.0 * R;
    PullLoad pull(0, n / 2, D0, 1e4 * expected);
    LoadedKnot f(system.objective(), pull);
    ContinuationOptions o;
    o.target = D0 + 1e-3 * R;
    o.gradient_tolerance = 1e-11;
    o.eigen_count = 0;
    const LoadPath path = follow_path(f, o);
    ASSERT_EQ(path.status, PathStatus::Reached);
    const PathPoint &a = path.points.front(), &b = path.points.back();
    const double stiffness = (b.reaction - a.reaction) / (b.displacement - a.displacement);
    const double error = std::abs(stiffness - expected) / expected;
    std::cout << "[ measured ] ring n = " << n << ": stiffness " << stiffness << " (classical " << expected
              << "), relative error " << error << std::endl;
    EXPECT_LT(error, 0.02);
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
}

TEST(Continuation, WorkEqualsTheEnergyChangeAndUnloadingReturnsTheRing) {
  // along a path without snaps, ∫ ∂E/∂D dD (trapezoids) equals the change of
  // E_knot + E_load to the integration error; loading to 1.2·D0 and back
  // returns the ring (similarity >= 0.999, the same energy)
  const int n = 128;
  const Points P = fixtures::unit_ring(n);
  const double R = 0.5 / std::sin(M_PI / n), D0 = 2.0 * R;
  RodModel system(P, edge_lengths(P), RelaxOptions{});
  PullLoad pull(0, n / 2, D0, 10.0);
  LoadedKnot f(system.objective(), pull);
  ContinuationOptions o;
  o.target = 1.2 * D0;
  o.step = 0.005 * D0;
  o.max_step_factor = 1.0;
  o.gradient_tolerance = 1e-10;
  o.eigen_count = 2;
  const LoadPath out = follow_path(f, o);
  ASSERT_EQ(out.status, PathStatus::Reached);
  double work = 0.0;
  for (size_t k = 1; k < out.points.size(); ++k) {
    const PathPoint &a = out.points[k - 1], &b = out.points[k];
    work += 0.5 * (a.parameter_derivative + b.parameter_derivative) * (b.parameter - a.parameter);
    EXPECT_EQ(b.event, PathEvent::Regular);
    EXPECT_TRUE(b.stable);
  }
  const double change = out.points.back().energy - out.points.front().energy;
  std::cout << "[ measured ] work " << work << ", energy change " << change << ", "
            << out.points.size() << " points" << std::endl;
  EXPECT_GT(change, 0.0);
  EXPECT_NEAR(work, change, 1e-3 * change);
  o.target = D0;
  const LoadPath back = follow_path(f, o);
  ASSERT_EQ(back.status, PathStatus::Reached);
  const Points end = as_points(back.points.back().dofs);
  EXPECT_GE(similarity(P, end), 0.999);
  EXPECT_NEAR(back.points.back().energy, out.points.front().energy, 1e-6 * out.points.back().energy);
}
