// A knot under load (ek/mechanics/knot_loading.hpp): the loaded model's
// Hessian against finite differences; a trefoil pulled across its diameter
// (its type kept, the device's force positive, the work equal to the change
// of energy, the distance following the control); the same trefoil pressed
// between plates until it snaps (a stable state on each side, the released
// state relaxed again); the stable path through the snapping system's fold
// at its known load and jump; bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/mechanics/knot_loading.hpp"
#include "ek/mechanics/loads.hpp"
#include "ek/solver/saddle.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// A trefoil (96 vertices, wire radius 1 of the default model).
Points trefoil() { return fixtures::torus_knot(96, 2, 3, 12.0, 4.0); }

/// E(x, y; μ) = x⁴/4 − x²/2 − μx + y²/2 (as in test_loads.cpp): stable
/// branches x < −1/√3 and x > 1/√3, folds at μ = ±2/(3√3).
class Snapper : public ParameterizedObjective {
 public:
  int num_dofs() const override { return 2; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override { return std::pow(x_(0), 4) / 4 - x_(0) * x_(0) / 2 - mu_ * x_(0) + x_(1) * x_(1) / 2; }
  VecX gradient() override { return Eigen::Vector2d(x_(0) * x_(0) * x_(0) - x_(0) - mu_, x_(1)); }
  void assemble_hessian(SparseAssembler& A, HessianKind) override {
    A.begin(2);
    A.segment(0, 1);
    A.add(0, 0, 3 * x_(0) * x_(0) - 1);
    A.add(1, 1, 1.0);
    A.end();
  }
  double parameter() const override { return mu_; }
  void set_parameter(double mu) override { mu_ = mu; }
  VecX parameter_gradient() override { return Eigen::Vector2d(-1.0, 0.0); }
  double parameter_derivative() override { return -x_(0); }

 private:
  VecX x_ = Eigen::Vector2d(-1.2, 0.1);
  double mu_ = -0.6;
};

}  // namespace

// The knot model plus a pull: the assembled Hessian against central
// differences of the gradient (h = 1e-6), 1e-5 relative in the Frobenius norm.
TEST(KnotLoading, LoadedKnotHessianMatchesFiniteDifferences) {
  const Points P = fixtures::torus_knot(48, 2, 3, 12.0, 4.0);
  KnotSystem sys(P, edge_lengths(P), RelaxOptions{});
  PullLoad pull(3, 27, 30.0, 0.1);
  LoadedKnot f(sys.objective(), pull);
  const VecX x0 = f.dofs();
  const int n = static_cast<int>(x0.size());
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);
  const Eigen::MatrixXd H = Eigen::MatrixXd(Eigen::SparseMatrix<double>(A.matrix().selfadjointView<Eigen::Upper>()));
  Eigen::MatrixXd fd(n, n);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    VecX xp = x0, xm = x0;
    xp(j) += h;
    xm(j) -= h;
    f.set_dofs(xp);
    const VecX gp = f.gradient();
    f.set_dofs(xm);
    fd.col(j) = (gp - f.gradient()) / (2 * h);
  }
  EXPECT_LT((H - fd).norm(), 1e-5 * H.norm());
  EXPECT_GT(pull.energy(), 0.0);  // the load contributes
}

// The trefoil pulled across its diameter from its relaxed distance to 40:
// the path reaches the target, every point a stable equilibrium with the
// trefoil's Alexander polynomial; the device pulls (reaction >= 0) and the
// stiff spring keeps the measured distance within 1% of the control; the
// work ∫ ∂E/∂μ dμ (trapezoids) equals E_end − E_start + the dissipated
// energy within 1% (the trapezoid rule on the path's steps).
TEST(KnotLoading, PulledTrefoilKeepsItsTypeAndTheWorkIsTheEnergyGained) {
  const Points P = trefoil();
  KnotLoadOptions o;
  o.kind = LoadKind::Pull;
  o.to = 40.0;
  o.stop_at_snap = false;
  const KnotLoadResult r = load_knot(P, edge_lengths(P), o);
  EXPECT_EQ(r.path.status, PathStatus::Reached);
  ASSERT_GE(r.path.points.size(), 10u);
  EXPECT_TRUE(r.alexander_preserved);
  EXPECT_EQ(r.parameter_name, "distance");
  EXPECT_NE(r.vertices[0], r.vertices[1]);
  EXPECT_NEAR(r.path.points.back().parameter, 40.0, 1e-12);
  for (const PathPoint& p : r.path.points) {
    EXPECT_GE(p.reaction, -1e-9) << "at " << p.parameter;
    EXPECT_NEAR(p.displacement, p.parameter, 0.01 * p.parameter);
    EXPECT_EQ(p.index, 0) << "at " << p.parameter;
  }
  EXPECT_EQ(alexander(as_points(r.path.points.back().dofs)), alexander(P));
  const double gained = r.path.points.back().energy - r.path.points.front().energy;
  EXPECT_GT(gained, 0.0);
  EXPECT_NEAR(r.work, gained + r.dissipated, 0.01 * gained);
  std::cout << "[ measured ] pull to 40: " << r.path.points.size() << " points, work " << r.work << ", ΔE " << gained
            << ", " << r.snaps.size() << " snaps, " << r.path.seconds << " s" << std::endl;
}

// The trefoil (nearly planar once relaxed) pressed between plates along its
// axis of least extent: it snaps once before the gap reaches 0.3 wire radii,
// with a positive jump and energy drop; the plates push (reaction > 0 before
// the snap); the state it falls into keeps the knot type, and released it
// relaxes to a converged stable state of the trefoil.
TEST(KnotLoading, PressedTrefoilSnapsAndItsReleasedStateIsATrefoil) {
  const Points P = trefoil();
  KnotLoadOptions o;
  o.kind = LoadKind::Plates;
  o.to = 0.6;
  o.stop_at_snap = true;
  const KnotLoadResult r = load_knot(P, edge_lengths(P), o);
  EXPECT_TRUE(r.alexander_preserved);
  EXPECT_EQ(r.parameter_name, "gap");
  ASSERT_EQ(r.snaps.size(), 1u);
  EXPECT_EQ(r.path.status, PathStatus::Stopped);
  const Snap& s = r.snaps.front();
  EXPECT_EQ(r.path.points[static_cast<size_t>(s.point)].event, PathEvent::Snap);
  EXPECT_GT(s.jump, 0.1 * edge_lengths(P).mean());
  EXPECT_GT(s.energy_drop, 0.0);
  EXPECT_GT(s.reaction, 0.0);
  EXPECT_GT(s.parameter, o.to);
  EXPECT_TRUE(s.alexander_preserved);
  EXPECT_EQ(s.released_status, "converged-stable");
  EXPECT_EQ(alexander(s.released), alexander(P));
  std::cout << "[ measured ] plates: snap at gap " << s.parameter << ", force " << s.reaction << ", jump " << s.jump
            << ", energy drop " << s.energy_drop << ", released E " << s.released_energy << std::endl;
}

// The stable path of the snapping system from μ = −0.6 to 0.6: on the left
// branch up to the fold μ = 2/(3√3) (to 1e-3: the smallest step), then one
// snap to the right branch's x = 2/√3 (the double root's partner), a jump
// of √3 in x (to 1e-2), then on to μ = 0.6 with x³ − x = μ at every point.
TEST(Continuation, StablePathSnapsAtTheFoldWithTheKnownJump) {
  Snapper f;
  ContinuationOptions o;
  o.target = 0.6;
  o.minimizer = NewtonOptions{};
  o.minimizer->gradient_tolerance = 1e-10;
  o.max_jump = 0.5;
  o.eigen_count = 0;
  const LoadPath p = follow_path(f, o);
  EXPECT_EQ(p.status, PathStatus::Reached);
  int snaps = 0;
  for (size_t k = 0; k < p.points.size(); ++k) {
    const PathPoint& q = p.points[k];
    const double x = q.dofs(0);
    EXPECT_NEAR(x * x * x - x, q.parameter, 1e-8);
    if (q.event != PathEvent::Snap) continue;
    ++snaps;
    ASSERT_GT(k, 0u);
    const PathPoint& before = p.points[k - 1];
    EXPECT_NEAR(before.parameter, 2.0 / (3.0 * std::sqrt(3.0)), 1e-3);
    EXPECT_NEAR(x, 2.0 / std::sqrt(3.0), 1e-2);
    EXPECT_NEAR(x - before.dofs(0), std::sqrt(3.0), 1e-2);
  }
  EXPECT_EQ(snaps, 1);
}

// Bad input: one clear InputError each.
TEST(KnotLoading, BadInputIsRefused) {
  const Points P = trefoil();
  const VecX rest = edge_lengths(P);
  KnotLoadOptions o;
  o.to = 30.0;
  o.vertices = std::array<int, 2>{3, 3};
  EXPECT_THROW(load_knot(P, rest, o), InputError);
  o.vertices = std::array<int, 2>{3, 500};
  EXPECT_THROW(load_knot(P, rest, o), InputError);
  o.vertices.reset();
  o.relax.full_model = true;
  EXPECT_THROW(load_knot(P, rest, o), InputError);
  o.relax.full_model = false;
  o.kind = LoadKind::Plates;
  o.from = 0.01;  // the curve is not between plates this close
  EXPECT_THROW(load_knot(P, rest, o), InputError);
  o.from.reset();
  o.snap_jump = 0.0;
  EXPECT_THROW(load_knot(P, rest, o), InputError);
  EXPECT_THROW(parse_load_kind("twist"), InputError);
}
