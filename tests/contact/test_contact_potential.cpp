// Whole-curve contact: active set equal to brute force, finite differences of
// the assembled energy, invariances, the no-contact fast path, Hessian
// structure ids, and collision detection on curves moving towards
// self-intersection (checked pair by pair with the independent reference).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <set>

#include "ccd_reference.hpp"
#include "contact_test_util.hpp"
#include "ek/contact/contact_potential.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "testing.hpp"

using namespace ek;
using namespace ek::contacttest;

namespace {

// Two strands twisted around each other and closed into a ring (a (2, q)
// torus knot on a thin torus): every edge is within d̂ of the other strand.
Points twisted_pair(int n, int q, double R, double separation) {
  return fixtures::torus_knot(n, 2, q, R, 0.5 * separation);
}

// Two interlocked rings (a Hopf link) of m vertices each, radius R, in
// perpendicular planes, their centres `gap` apart (gap = 2R − c: the rings
// pass c apart near (R − c/2, 0, 0)).
Points hopf(int m, double R, double gap) {
  Points P(2 * m, 3);
  for (int i = 0; i < m; ++i) {
    const double s = 2 * M_PI * i / m;
    P.row(i) << R * std::cos(s), R * std::sin(s), 0;
    P.row(m + i) << gap + R * std::cos(s), 0, R * std::sin(s);
  }
  return P;
}

Eigen::MatrixXd dense_hessian(const ContactPotential& cp, const Points& x) {
  SparseAssembler A;
  A.begin(static_cast<int>(3 * x.rows()));
  A.segment(0, cp.hessian_structure());
  cp.add_hessian(x, A);
  A.end();
  Eigen::MatrixXd U = Eigen::MatrixXd(A.matrix());
  Eigen::MatrixXd H = U + U.transpose();
  H.diagonal() = U.diagonal();
  return H;
}

std::vector<EdgePair> active_as_pairs(const ContactPotential& cp) {
  std::vector<EdgePair> out;
  for (const ContactPair& c : cp.active_pairs()) out.push_back({c.edge_a, c.edge_b});
  return out;
}

// Smallest distance over all non-excluded pairs (geometry module), and the
// smallest ratio d(s)/floor over pairs, at time s of the motion x + s dx.
struct Clear {
  double min_distance = 1e300, min_ratio = 1e300;
};
Clear clearance_along(const Points& x, const Points& dx, const CurveTopology& t, double s, const ContactOptions& o) {
  Clear c;
  const int n = static_cast<int>(x.rows());
  const Points y = x + s * dx;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (t.excluded(i, j, o.excluded_neighbors)) continue;
      const double d = std::sqrt(segment_segment_distance_squared(y.row(i), y.row(t.next(i)), y.row(j), y.row(t.next(j))));
      const double d0 = std::sqrt(segment_segment_distance_squared(x.row(i), x.row(t.next(i)), x.row(j), x.row(t.next(j))));
      c.min_distance = std::min(c.min_distance, d);
      c.min_ratio = std::min(c.min_ratio, d / (o.ccd_separation * std::min(d0, o.dhat)));
    }
  return c;
}

// Checks every non-excluded pair on [0, t] with the independent reference.
long reference_violations(const Points& x, const Points& dx, const CurveTopology& t, double step,
                          const ContactOptions& o) {
  long bad = 0;
  const int n = static_cast<int>(x.rows());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (t.excluded(i, j, o.excluded_neighbors)) continue;
      const int i1 = t.next(i), j1 = t.next(j);
      ccdtest::Motion m{x.row(i),  x.row(i1),  x.row(j),  x.row(j1),
                        dx.row(i), dx.row(i1), dx.row(j), dx.row(j1)};
      const double d0 = ccdtest::distance_at(m, 0.0);
      const ccdtest::Verdict v = ccdtest::check(m, step, o.ccd_separation * std::min(d0, o.dhat));
      bad += v.touches || v.below_floor || v.uncertified;
    }
  return bad;
}

}  // namespace

TEST(ContactPotential, OptionsAreValidated) {
  ContactOptions o;
  EXPECT_NO_THROW(o.validate());
  for (auto mutate : std::vector<std::function<void(ContactOptions&)>>{
           [](ContactOptions& p) { p.dhat = 0; }, [](ContactOptions& p) { p.stiffness = -1; },
           [](ContactOptions& p) { p.excluded_neighbors = 0; }, [](ContactOptions& p) { p.ccd_separation = 1; },
           [](ContactOptions& p) { p.ccd_tolerance = 0; }, [](ContactOptions& p) { p.parallel_threshold = 1; },
           [](ContactOptions& p) { p.ccd_max_iterations = 0; }, [](ContactOptions& p) { p.broad_phase_skin = -1; },
           [](ContactOptions& p) { p.ccd_skin = -1; },
           [](ContactOptions& p) { p.ccd_skin = std::numeric_limits<double>::quiet_NaN(); }}) {
    ContactOptions bad;
    mutate(bad);
    EXPECT_THROW(ContactPotential(CurveTopology::single(10), bad), std::invalid_argument);
  }
  ContactPotential cp(CurveTopology::single(10), o);
  EXPECT_THROW(cp.update(Points::Zero(9, 3)), std::invalid_argument);
}

TEST(ContactPotential, ActiveSetEqualsBruteForce) {
  struct Scene {
    Points x;
    CurveTopology t;
  };
  std::vector<Scene> scenes = {
      {twisted_pair(200, 7, 16.0, 0.3), CurveTopology::single(200)},
      {fixtures::random_fourier_curve(300, 6, 3, 6.0), CurveTopology::single(300)},
      {hopf(40, 3.0, 5.7), CurveTopology::from_sizes({40, 40})},
  };
  const Points lat = lattice_loop(80, 2);
  if (lat.rows() > 0) {
    Points scaled = 0.3 * lat;  // lattice contacts at 0.3 < d̂
    scenes.push_back({scaled, CurveTopology::single(static_cast<int>(lat.rows()))});
  }
  for (const Scene& s : scenes) {
    ContactPotential cp(s.t, ContactOptions{});
    cp.update(s.x);
    const auto ref = edge_pairs_within_brute_force(s.x, s.t, 1, cp.options().dhat);
    EXPECT_EQ(active_as_pairs(cp), ref);
    EXPECT_GT(cp.num_active(), 0u);
    double min_active = 1e300;
    for (const ContactPair& c : cp.active_pairs()) {
      EXPECT_LT(c.distance, cp.options().dhat);
      EXPECT_EQ(c.a1, s.t.next(c.a0));
      min_active = std::min(min_active, c.distance);
    }
    EXPECT_EQ(cp.min_distance(), min_active);
  }
  // links: pairs across components are active when close
  ContactPotential link(CurveTopology::from_sizes({40, 40}), ContactOptions{});
  link.update(hopf(40, 3.0, 5.7));
  bool across = false;
  for (const ContactPair& c : link.active_pairs()) across |= (c.edge_a < 40) != (c.edge_b < 40);
  EXPECT_TRUE(across);
}

TEST(ContactPotential, GradientAndHessianFiniteDifferences) {
  struct Scene {
    Points x;
    CurveTopology t;
  };
  std::mt19937_64 rng(12);
  Points tp = twisted_pair(60, 5, 4.8, 0.3);
  for (int i = 0; i < tp.rows(); ++i) tp.row(i) += 0.02 * rand_vec(rng).transpose();
  const std::vector<Scene> scenes = {{tp, CurveTopology::single(60)},
                                     {hopf(30, 2.0, 3.7), CurveTopology::from_sizes({30, 30})}};
  for (const Scene& s : scenes) {
    for (bool psd : {false, true}) {
      ContactOptions o;
      o.project_psd = psd;
      ContactPotential cp(s.t, o);
      auto energy = [&cp](const VecX& v) {
        const Points y = as_points(v);
        cp.update(y);
        return cp.energy(y);
      };
      const VecX x = as_vector(s.x);
      cp.update(s.x);
      ASSERT_GT(cp.num_active(), 3u);
      const VecX g = cp.gradient(s.x);
      const Eigen::MatrixXd H = dense_hessian(cp, s.x);
      ASSERT_GT(g.norm(), 0.0);
      // central differences of the energy (several steps; relative error)
      double eg = 1e300;
      for (double h : {1e-5, 1e-6, 1e-7}) eg = std::min(eg, (fixtures::fd_gradient(energy, x, h) - g).norm() / g.norm());
      EXPECT_LT(eg, 1e-6);
      // central differences of the analytic gradient (unprojected Hessian only)
      if (!psd) {
        double eh = 1e300;
        for (double h : {1e-5, 1e-6, 1e-7}) {
          Eigen::MatrixXd F(x.size(), x.size());
          for (Eigen::Index i = 0; i < x.size(); ++i) {
            VecX p = x, m = x;
            p(i) += h;
            m(i) -= h;
            const Points yp = as_points(p), ym = as_points(m);
            cp.update(yp);
            const VecX gp = cp.gradient(yp);
            cp.update(ym);
            const VecX gm = cp.gradient(ym);
            F.col(i) = (gp - gm) / (2 * h);
          }
          eh = std::min(eh, (F - H).norm() / H.norm());
        }
        EXPECT_LT(eh, 1e-5);  // relative Frobenius error
      } else {
        const double lmin = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues().minCoeff();
        EXPECT_GE(lmin, -1e-9 * H.norm());
      }
      cp.update(s.x);
      // invariances: translation (Σ g_v = 0) and rotation (Σ x_v × g_v = 0)
      Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
      for (int v = 0; v < s.x.rows(); ++v) {
        force += g.segment<3>(3 * v);
        torque += Vec3(s.x.row(v)).cross(Vec3(g.segment<3>(3 * v)));
      }
      EXPECT_LT(force.norm(), 1e-10 * g.norm());
      EXPECT_LT(torque.norm(), 1e-9 * g.norm());
      // energy = ω Σ pair energies
      double sum = 0;
      for (const ContactPair& c : cp.active_pairs())
        sum += edge_edge_barrier(s.x.row(c.a0), s.x.row(c.a1), s.x.row(c.b0), s.x.row(c.b1),
                                 {o.dhat, o.parallel_threshold});
      EXPECT_NEAR(cp.energy(s.x), o.stiffness * sum, 1e-12 * cp.energy(s.x));
    }
  }
}

TEST(ContactPotential, SkinReuseKeepsTheActiveSetExact) {
  // A sequence of small and large random motions: whether update() reruns
  // the broad phase or reuses its list, the active set equals brute force.
  std::mt19937_64 rng(31);
  Points x = twisted_pair(200, 7, 16.0, 0.33);
  const CurveTopology t = CurveTopology::single(200);
  ContactOptions o;
  ContactPotential cp(t, o);
  int updates = 0;
  for (int k = 0; k < 60; ++k) {
    const double size = (k % 7 == 6) ? 0.2 : 0.01;  // mostly below skin/2 = 0.05 in total
    for (int i = 0; i < x.rows(); ++i) x.row(i) += rand_vec(rng, size).transpose();
    cp.update(x);
    ++updates;
    ASSERT_EQ(active_as_pairs(cp), edge_pairs_within_brute_force(x, t, 1, o.dhat)) << k;
  }
  EXPECT_LT(cp.num_broad_phase_runs(), static_cast<size_t>(updates));
  EXPECT_GT(cp.num_broad_phase_runs(), 5u);
  // skin 0: the broad phase runs every time
  o.broad_phase_skin = 0.0;
  ContactPotential fresh(t, o);
  fresh.update(x);
  fresh.update(x);
  EXPECT_EQ(fresh.num_broad_phase_runs(), 2u);
  EXPECT_EQ(active_as_pairs(fresh), edge_pairs_within_brute_force(x, t, 1, o.dhat));
}

// A line search: after max_step(x, dx), trials x + t·dx (t = 1, 1/2, ...,
// and off the path by less than skin/2) reuse the pairs of the collision
// detection's broad phase, and their active sets equal brute force; a point
// farther off the path runs the broad phase again. The collision detection
// gives the same step with the skin as without (its own broad phase).
TEST(ContactPotential, LineSearchTrialsReuseTheCollisionDetectionPairs) {
  std::mt19937_64 rng(41);
  const Points x = twisted_pair(200, 7, 16.0, 0.33);
  const CurveTopology t = CurveTopology::single(200);
  ContactOptions o;
  Points dx(200, 3);
  for (int i = 0; i < 200; ++i) dx.row(i) = rand_vec(rng, 0.3).transpose();
  ContactPotential cp(t, o);
  cp.update(x);
  const size_t runs = cp.num_broad_phase_runs();
  ContactOptions no_skin = o;
  no_skin.broad_phase_skin = 0.0;
  EXPECT_EQ(cp.max_step(x, dx), ContactPotential(t, no_skin).max_step(x, dx));
  int trials = 0;
  for (double s = 1.0; s > 1e-3; s *= 0.5, ++trials) {
    Points y = x + s * dx;
    for (int i = 0; i < 200; ++i) y.row(i) += rand_vec(rng, 0.02).transpose();  // within skin/2 = 0.05 of the path
    cp.update(y);
    ASSERT_EQ(active_as_pairs(cp), edge_pairs_within_brute_force(y, t, 1, o.dhat)) << s;
  }
  EXPECT_EQ(cp.num_broad_phase_runs(), runs) << "trials on the path ran a broad phase";
  EXPECT_GT(trials, 5);
  Points far = x + 0.5 * dx;
  far.row(17) += Vec3(0.3, 0, 0).transpose();
  cp.update(far);
  EXPECT_EQ(cp.num_broad_phase_runs(), runs + 1);
  EXPECT_EQ(active_as_pairs(cp), edge_pairs_within_brute_force(far, t, 1, o.dhat));
}

// Collision detection over a walk of small steps with occasional large ones:
// max_step() keeps its swept broad phase's pairs (ccd_skin) while the motion
// stays within ccd_skin of where they were found, and its reports (step,
// limiting pair, candidates) equal those without (ccd_skin = 0, a swept
// broad phase every query) and those without any skin; the line search's
// trials on each path still find the active set of brute force.
TEST(ContactPotential, CollisionDetectionKeepsItsSweptPairsAcrossSmallSteps) {
  std::mt19937_64 rng(43);
  Points x = twisted_pair(200, 7, 16.0, 0.33);
  const CurveTopology t = CurveTopology::single(200);
  ContactOptions o;
  ContactOptions fresh_sweeps = o, no_skin = o;
  fresh_sweeps.ccd_skin = 0.0;
  no_skin.broad_phase_skin = 0.0;
  ContactPotential cp(t, o), reference(t, fresh_sweeps), plain(t, no_skin);
  const int queries = 40;
  for (int k = 0; k < queries; ++k) {
    const double size = (k % 9 == 8) ? 0.4 : 0.01;  // most steps far inside ccd_skin = 0.3
    Points dx(200, 3);
    for (int i = 0; i < 200; ++i) dx.row(i) = rand_vec(rng, size).transpose();
    const StepReport a = cp.max_step_report(x, dx), b = reference.max_step_report(x, dx);
    const StepReport c = plain.max_step_report(x, dx);
    ASSERT_EQ(a.t, b.t) << k;
    ASSERT_EQ(a.t, c.t) << k;
    ASSERT_EQ(a.candidates, b.candidates) << k;
    ASSERT_EQ(a.edge_a, b.edge_a) << k;
    ASSERT_EQ(a.edge_b, b.edge_b) << k;
    ASSERT_EQ(a.iterations, b.iterations) << k;
    for (const double s : {1.0, 0.5, 0.125}) {  // trials on the path
      const Points y = x + s * a.t * dx;
      cp.update(y);
      ASSERT_EQ(active_as_pairs(cp), edge_pairs_within_brute_force(y, t, 1, o.dhat)) << k << " " << s;
    }
    x += 0.5 * a.t * dx;
  }
  EXPECT_EQ(reference.num_swept_broad_phase_runs(), static_cast<size_t>(queries));
  EXPECT_LT(cp.num_swept_broad_phase_runs(), static_cast<size_t>(queries) / 2);
  EXPECT_GE(cp.num_swept_broad_phase_runs(), 5u);  // at least the large steps (k = 8, 17, 26, 35) and the first
}

TEST(ContactPotential, NoContactCostsNothing) {
  const Points C = fixtures::circle(400, 400 / (2 * M_PI));
  ContactPotential cp(CurveTopology::single(400), ContactOptions{});
  cp.update(C);
  EXPECT_EQ(cp.num_active(), 0u);
  EXPECT_EQ(cp.num_candidates(), 0u);  // the broad phase already finds nothing
  EXPECT_EQ(cp.energy(C), 0.0);
  EXPECT_EQ(cp.gradient(C).norm(), 0.0);
  SparseAssembler A;
  A.begin(1200);
  A.segment(0, cp.hessian_structure());
  cp.add_hessian(C, A);
  EXPECT_EQ(A.entries(), 0u);
  A.end();
  EXPECT_EQ(cp.max_step(C, Points::Constant(400, 3, 0.01)), 1.0);
}

TEST(ContactPotential, HessianStructureFollowsTheActiveSet) {
  Points x = twisted_pair(200, 7, 16.0, 0.3);
  ContactPotential cp(CurveTopology::single(200), ContactOptions{});
  cp.update(x);
  const auto id0 = cp.hessian_structure();
  const auto set0 = active_as_pairs(cp);
  SparseAssembler A;
  for (int pass = 0; pass < 3; ++pass) {
    // small motions that keep the active set: same id, pattern reused
    Points y = x;
    y.col(2) *= 1.0 + 1e-6 * pass;
    cp.update(y);
    EXPECT_EQ(active_as_pairs(cp), set0);
    EXPECT_EQ(cp.hessian_structure(), id0);
    A.begin(600);
    A.segment(0, cp.hessian_structure());
    cp.add_hessian(y, A);
    EXPECT_EQ(A.end(), pass == 0);
  }
  // move one vertex away: its edges' pairs drop out; new id, new pattern
  Points z = x;
  z.row(0) += Vec3(0, 0, 10).transpose();
  cp.update(z);
  ASSERT_NE(active_as_pairs(cp), set0);
  EXPECT_NE(cp.hessian_structure(), id0);
  A.begin(600);
  A.segment(0, cp.hessian_structure());
  cp.add_hessian(z, A);
  EXPECT_TRUE(A.end());
}

// The Hessian plan is built by add_hessian() for the active set of the last
// update(), however many updates with other active sets came between (as the
// line search's trials do): the values equal those of a fresh object.
TEST(ContactPotential, HessianFollowsTheLastUpdateAcrossTrials) {
  const Points x = twisted_pair(200, 7, 16.0, 0.3);
  Points z = x;
  z.row(0) += Vec3(0, 0, 10).transpose();  // its edges' pairs drop out
  Points w = x;
  w.row(50) += Vec3(0, 0, 10).transpose();  // other pairs drop out
  ContactPotential cp(CurveTopology::single(200), ContactOptions{});
  auto fresh_at = [](const Points& y) {  // a new object updated at y
    ContactPotential other(CurveTopology::single(200), ContactOptions{});
    other.update(y);
    return other;
  };
  auto fresh = [&](const Points& y) { return dense_hessian(fresh_at(y), y); };
  cp.update(x);
  EXPECT_EQ(dense_hessian(cp, x), fresh(x));
  // trials with other active sets, then back to x without assembling between
  for (const Points* y : std::vector<const Points*>{&z, &w, &z, &x}) cp.update(*y);
  EXPECT_EQ(dense_hessian(cp, x), fresh(x));
  // assembled at z, then trials, then assembled at w
  cp.update(z);
  EXPECT_EQ(dense_hessian(cp, z), fresh(z));
  for (const Points* y : std::vector<const Points*>{&x, &z, &x, &w}) cp.update(*y);
  ASSERT_NE(cp.num_active(), 0u);
  EXPECT_EQ(dense_hessian(cp, w), fresh(w));
  // the three active sets differ, so each assembly above needed its own plan
  auto active_at = [&](const Points& y) { return active_as_pairs(fresh_at(y)); };
  EXPECT_NE(active_at(x), active_at(z));
  EXPECT_NE(active_at(x), active_at(w));
  EXPECT_NE(active_at(z), active_at(w));
}

TEST(ContactPotential, MaxStepStopsBeforeSelfIntersection) {
  ContactOptions o;
  int limited = 0;
  // (a) a stadium whose two long sides are pushed through each other
  {
    const int m = 20;  // vertices per side
    Points x(2 * m + 2, 3);
    for (int i = 0; i <= m; ++i) x.row(i) << i * 0.5, 0, 0;
    for (int i = 0; i <= m; ++i) x.row(m + 1 + i) << (m - i) * 0.5, 1.0, 0.0;
    Points dx = Points::Zero(x.rows(), 3);
    for (int i = 2; i < m - 1; ++i) dx.row(i) << 0, 2.5, 0.0;  // through the other side
    const CurveTopology t = CurveTopology::single(static_cast<int>(x.rows()));
    ContactPotential cp(t, o);
    const StepReport r = cp.max_step_report(x, dx);
    EXPECT_LT(r.t, 1.0);
    EXPECT_GT(r.t, 0.3);  // the sides start 1 apart and close at 2.5 per unit step
    EXPECT_GE(r.edge_a, 0);
    EXPECT_EQ(reference_violations(x, dx, t, r.t, o), 0);
    EXPECT_LT(clearance_along(x, dx, t, 1.0, o).min_distance, 1e-12);  // the full step would collide
    ++limited;
  }
  // (b) straight-line motions between two random curves: generic homotopies
  // that pass through self-intersections
  for (int seed = 0; seed < 6; ++seed) {
    const int n = 60;
    const Points x0 = fixtures::random_fourier_curve(n, 4, 100 + seed, 4.0);
    const Points x1 = fixtures::random_fourier_curve(n, 4, 200 + seed, 4.0);
    const Points dx = x1 - x0;
    const CurveTopology t = CurveTopology::single(n);
    ContactPotential cp(t, o);
    const double step = cp.max_step(x0, dx);
    EXPECT_EQ(reference_violations(x0, dx, t, step, o), 0) << seed;
    EXPECT_GE(clearance_along(x0, dx, t, step, o).min_ratio, 1.0 - 1e-9) << seed;
    // dense sampling of the whole motion shows whether it really hits itself
    double min_full = 1e300;
    for (int k = 0; k <= 400; ++k) min_full = std::min(min_full, clearance_along(x0, dx, t, k / 400.0, o).min_distance);
    if (min_full < 1e-2) {
      EXPECT_LT(step, 1.0) << seed;
      ++limited;
    }
    // every pair tested without a broad phase can only be more conservative
    double brute = 1.0;
    CcdParams p;
    p.separation = o.ccd_separation;
    p.distance_cap = o.dhat;
    p.tolerance = o.ccd_tolerance;
    p.max_iterations = o.ccd_max_iterations;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (!t.excluded(i, j, 1))
          brute = std::min(brute, edge_edge_ccd(x0.row(i), x0.row(t.next(i)), x0.row(j), x0.row(t.next(j)),
                                                dx.row(i), dx.row(t.next(i)), dx.row(j), dx.row(t.next(j)), 1.0, p)
                                      .t);
    EXPECT_LE(brute, step + 1e-15) << seed;
  }
  // (c) a Hopf link pulled apart through itself
  {
    const Points x = hopf(40, 2.0, 3.7);
    Points dx = Points::Zero(80, 3);
    for (int i = 40; i < 80; ++i) dx.row(i) << 6.0, 0, 0;  // the second ring slides through the first
    const CurveTopology t = CurveTopology::from_sizes({40, 40});
    ContactPotential cp(t, o);
    const double step = cp.max_step(x, dx);
    EXPECT_LT(step, 1.0);
    EXPECT_EQ(reference_violations(x, dx, t, step, o), 0);
    ++limited;
  }
  EXPECT_GE(limited, 4);
  // (d) touching already (vertex 10 exactly on edge 0): no step; 1e-9 from
  // edge 0: whatever step, certified
  {
    Points x = fixtures::circle(20, 3.0);
    x.row(0) << 3, 0, 0;
    x.row(1) << 3, 2, 0;
    x.row(10) << 3, 1, 0;
    const CurveTopology t = CurveTopology::single(20);
    ContactPotential cp(t, o);
    std::mt19937_64 rng(1);
    Points dx(20, 3);
    for (int i = 0; i < 20; ++i) dx.row(i) = rand_vec(rng, 0.1).transpose();
    EXPECT_EQ(cp.max_step(x, dx), 0.0);
    Points y = fixtures::circle(20, 3.0);
    y.row(10) = 0.5 * (y.row(0) + y.row(1)) - 1e-9 * y.row(0).normalized();  // inside: no crossing
    EXPECT_EQ(reference_violations(y, dx, t, cp.max_step(y, dx), o), 0);
  }
}

TEST(ContactPotential, RepeatedStepsNeverCross) {
  // Follow a collision course step by step, as a solver's line search would:
  // x <- x + t dx with a fresh t each time. The two long sides of a stadium
  // are driven into each other (slightly tilted, with a wiggle): the
  // clearance shrinks geometrically but every step is certified.
  const int m = 20;
  Points x(2 * m + 2, 3);
  for (int i = 0; i <= m; ++i) x.row(i) << i * 0.5, 0, 0.05 * std::sin(i);
  for (int i = 0; i <= m; ++i) x.row(m + 1 + i) << (m - i) * 0.5, 1.0, 0.0;
  Points dx = Points::Zero(x.rows(), 3);
  for (int i = 2; i < m - 1; ++i) dx.row(i) << 0.01 * std::cos(i), 2.5, -0.05 * std::sin(i) + 0.01;
  const CurveTopology t = CurveTopology::single(static_cast<int>(x.rows()));
  ContactOptions o;
  ContactPotential cp(t, o);
  const double c0 = clearance_along(x, dx, t, 0.0, o).min_distance;
  double c = c0;
  for (int k = 0; k < 8; ++k) {
    const double step = cp.max_step(x, dx);
    ASSERT_GT(step, 0.0);
    ASSERT_LT(step, 1.0);
    ASSERT_EQ(reference_violations(x, dx, t, step, o), 0) << k;
    x += step * dx;
    c = clearance_along(x, dx, t, 0.0, o).min_distance;
    EXPECT_GT(c, 0.0);
  }
  EXPECT_LT(c, 1e-3 * c0);  // really driven into contact
}

namespace {

// Two coaxial rings of m vertices, radius R, in the planes z = 0 and z = s,
// with aligned vertices: edge i of the first ring is at distance s from edges
// m + i − 1, m + i, m + i + 1 of the second (and farther from all others).
Points coaxial_rings(int m, double R, double s) {
  Points P(2 * m, 3);
  for (int i = 0; i < m; ++i) {
    const double a = 2 * M_PI * i / m;
    P.row(i) << R * std::cos(a), R * std::sin(a), 0;
    P.row(m + i) << R * std::cos(a), R * std::sin(a), s;
  }
  return P;
}

// Pattern of an assembled matrix (stored entries, explicit zeros included).
std::set<std::pair<int, int>> stored_entries(const SparseAssembler& A) {
  std::set<std::pair<int, int>> out;
  const auto& M = A.matrix();
  for (int j = 0; j < M.outerSize(); ++j)
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(M, j); it; ++it)
      out.insert({static_cast<int>(it.row()), static_cast<int>(it.col())});
  return out;
}

// One add_hessian() pass into A; returns whether A's pattern changed.
bool assemble_into(const ContactPotential& cp, const Points& x, SparseAssembler& A) {
  A.begin(static_cast<int>(3 * x.rows()));
  A.segment(0, cp.hessian_structure());
  cp.add_hessian(x, A);
  return A.end();
}

// Energy, gradient and dense Hessian of `cp` equal those of `ref` at x
// (relative 1e-12; both already updated at x).
void expect_same_values(const ContactPotential& cp, const ContactPotential& ref, const Points& x, const char* what) {
  const double e = cp.energy(x), er = ref.energy(x);
  EXPECT_NEAR(e, er, 1e-12 * std::fabs(er)) << what;
  const VecX g = cp.gradient(x), gr = ref.gradient(x);
  EXPECT_LE((g - gr).norm(), 1e-12 * gr.norm()) << what;
  const Eigen::MatrixXd H = dense_hessian(cp, x), Hr = dense_hessian(ref, x);
  EXPECT_LE((H - Hr).norm(), 1e-12 * Hr.norm()) << what;
  EXPECT_EQ(active_as_pairs(cp), active_as_pairs(ref)) << what;
}

}  // namespace

TEST(ContactPotential, HessianMarginIsValidated) {
  ContactOptions o;
  o.hessian_margin = -0.1;
  EXPECT_THROW(ContactPotential(CurveTopology::single(10), o), std::invalid_argument);
  o.hessian_margin = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ContactPotential(CurveTopology::single(10), o), std::invalid_argument);
}

TEST(ContactPotential, HessianMarginKeepsEnergyGradientAndHessianValues) {
  struct Scene {
    Points x;
    CurveTopology t;
  };
  std::mt19937_64 rng(77);
  Points tp = twisted_pair(60, 5, 4.8, 0.34);
  for (int i = 0; i < tp.rows(); ++i) tp.row(i) += 0.03 * rand_vec(rng).transpose();
  const std::vector<Scene> scenes = {{tp, CurveTopology::single(60)},
                                     {hopf(30, 2.0, 3.7), CurveTopology::from_sizes({30, 30})},
                                     {coaxial_rings(24, 2.0, 0.37), CurveTopology::from_sizes({24, 24})}};
  int larger_patterns = 0;
  for (const Scene& s : scenes)
    for (bool psd : {false, true})
      for (double margin : {0.05, 0.1}) {
        ContactOptions o0;
        o0.project_psd = psd;
        ContactOptions om = o0;
        om.hessian_margin = margin;
        ContactPotential ref(s.t, o0), cp(s.t, om);
        ref.update(s.x);
        cp.update(s.x);
        ASSERT_GT(ref.num_active(), 3u);
        expect_same_values(cp, ref, s.x, "same configuration");
        // the margin's pattern holds the active set's pattern (plus explicit zeros)
        SparseAssembler A0, Am;
        assemble_into(ref, s.x, A0);
        assemble_into(cp, s.x, Am);
        const auto p0 = stored_entries(A0), pm = stored_entries(Am);
        EXPECT_TRUE(std::includes(pm.begin(), pm.end(), p0.begin(), p0.end()));
        larger_patterns += pm.size() > p0.size();
        // a sequence of small motions: the margin's pattern is kept (blocks
        // looked up through the kept pattern) and the values stay exact
        Points y = s.x;
        const auto id = cp.hessian_structure();
        int kept = 0;
        for (int k = 0; k < 6; ++k) {
          for (int i = 0; i < y.rows(); ++i) y.row(i) += rand_vec(rng, 0.004).transpose();
          ref.update(y);
          cp.update(y);
          kept += cp.hessian_structure() == id;
          expect_same_values(cp, ref, y, "after a small motion");
        }
        EXPECT_GT(kept, 0);
      }
  EXPECT_GT(larger_patterns, 0);  // some scene has near pairs outside d̂: the margin matters
}

TEST(ContactPotential, HessianMarginKeepsThePatternWhenNearPairsActivate) {
  // Two coaxial rings approached from just outside d̂ (within the margin) to
  // just inside: with a margin the Hessian pattern (and the assembler's
  // pattern) stays; without it, it changes with the active set.
  const int m = 24;
  const double R = 2.0;
  const CurveTopology t = CurveTopology::from_sizes({m, m});
  const double dhat = ContactOptions{}.dhat;
  for (const double margin : {0.04, 0.08}) {
    ContactOptions om;
    om.hessian_margin = margin;
    ContactPotential cp(t, om), ref(t, ContactOptions{});
    SparseAssembler Am, A0;
    const Points outside = coaxial_rings(m, R, dhat + 0.5 * margin);
    cp.update(outside);
    ref.update(outside);
    ASSERT_EQ(cp.num_active(), 0u);
    const auto id = cp.hessian_structure(), id0 = ref.hessian_structure();
    EXPECT_TRUE(assemble_into(cp, outside, Am));  // explicit zero blocks of the near pairs
    EXPECT_GT(Am.matrix().nonZeros(), 0);
    EXPECT_EQ(Eigen::MatrixXd(Am.matrix()).norm(), 0.0);
    assemble_into(ref, outside, A0);
    EXPECT_EQ(A0.matrix().nonZeros(), 0);
    for (const double s : {dhat - 0.01, dhat - 0.05, dhat + 0.25 * margin, dhat - 0.1}) {
      const Points x = coaxial_rings(m, R, s);
      cp.update(x);
      ref.update(x);
      EXPECT_EQ(cp.num_active(), s < dhat ? static_cast<size_t>(3 * m) : 0u) << s;
      EXPECT_EQ(cp.hessian_structure(), id) << "margin " << margin << ", s = " << s;
      EXPECT_FALSE(assemble_into(cp, x, Am)) << "margin " << margin << ", s = " << s;
      expect_same_values(cp, ref, x, "inside the margin");
      EXPECT_EQ(ref.hessian_structure() == id0, s >= dhat) << s;  // margin 0: follows the active set
    }
  }
  // From outside the margin straight into contact: the pattern must be rebuilt.
  ContactOptions om;
  om.hessian_margin = 0.05;
  ContactPotential cp(t, om), ref(t, ContactOptions{});
  const Points far = coaxial_rings(m, R, dhat + 0.2);
  cp.update(far);
  const auto id = cp.hessian_structure();
  SparseAssembler A;
  assemble_into(cp, far, A);
  const Points close = coaxial_rings(m, R, dhat - 0.05);
  cp.update(close);
  ref.update(close);
  ASSERT_EQ(cp.num_active(), static_cast<size_t>(3 * m));
  EXPECT_NE(cp.hessian_structure(), id);
  EXPECT_TRUE(assemble_into(cp, close, A));
  expect_same_values(cp, ref, close, "after a rebuild");
}

TEST(ContactPotential, HessianMarginCoversNearPairsForAnySkin) {
  const int m = 24;
  const CurveTopology t = CurveTopology::from_sizes({m, m});
  const double dhat = ContactOptions{}.dhat;
  for (const double skin : {0.0, 0.1})
    for (const double margin : {0.05, 0.3}) {
      ContactOptions o;
      o.broad_phase_skin = skin;
      o.hessian_margin = margin;
      ContactPotential cp(t, o);
      cp.update(coaxial_rings(m, 2.0, dhat + 0.5 * margin));  // within the margin
      const auto id = cp.hessian_structure();
      cp.update(coaxial_rings(m, 2.0, dhat - 0.01));
      ASSERT_EQ(cp.num_active(), static_cast<size_t>(3 * m));
      EXPECT_EQ(cp.hessian_structure(), id) << "skin " << skin << ", margin " << margin;
    }
}

TEST(ContactPotential, ProjectPsdArgumentOverridesTheOption) {
  // add_hessian(x, A, project_psd) is the Hessian of a potential whose
  // options say project_psd, whatever this one's options say.
  std::mt19937_64 rng(19);
  Points x = twisted_pair(60, 5, 4.8, 0.3);
  for (int i = 0; i < x.rows(); ++i) x.row(i) += 0.02 * rand_vec(rng).transpose();
  const CurveTopology t = CurveTopology::single(60);
  auto with_argument = [&](const ContactPotential& cp, bool psd) {
    SparseAssembler A;
    A.begin(180);
    A.segment(0, cp.hessian_structure());
    cp.add_hessian(x, A, psd ? HessianKind::Projected : HessianKind::Exact);
    A.end();
    return Eigen::MatrixXd(Eigen::MatrixXd(A.matrix()).selfadjointView<Eigen::Upper>());
  };
  ContactOptions exact_o, psd_o;
  psd_o.project_psd = true;
  ContactPotential exact(t, exact_o), projected(t, psd_o);
  exact.update(x);
  projected.update(x);
  ASSERT_GT(exact.num_active(), 3u);
  const Eigen::MatrixXd He = dense_hessian(exact, x), Hp = dense_hessian(projected, x);
  ASSERT_GT((He - Hp).norm(), 1e-6 * He.norm());  // the projection matters here
  EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(He).eigenvalues().minCoeff(), -1e-6 * He.norm());
  EXPECT_LE((with_argument(exact, true) - Hp).norm(), 1e-14 * Hp.norm());
  EXPECT_LE((with_argument(exact, false) - He).norm(), 1e-14 * He.norm());
  EXPECT_LE((with_argument(projected, false) - He).norm(), 1e-14 * He.norm());
  EXPECT_LE((with_argument(projected, true) - Hp).norm(), 1e-14 * Hp.norm());
}
