#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/writhe.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/optim/eigen_analysis.hpp"
#include "ek/solver/relax.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Planar ring of n unit edges.
Points unit_ring(int n) {
  const double R = 0.5 / std::sin(M_PI / n);
  return fixtures::circle(n, R);
}

}  // namespace

// Michell's instability (paper Appendix C): critical link √3 (1 + ν) = 2.2517 at ν = 0.3.
TEST(Relax, MichellRingStaysFlatBelowCriticalLink) {
  RelaxOptions o;
  o.link = 2.0;
  const RelaxResult r = relax(unit_ring(100), o);
  EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
  EXPECT_NEAR(r.link, 2.0, 1e-8);                            // link preserved (tolerance: round-off of Tw + Wr)
  EXPECT_LT(r.positions.col(2).cwiseAbs().maxCoeff(), 1e-6);  // still planar
  EXPECT_NEAR(total_curvature(r.positions), 2 * M_PI, 1e-6);  // still a circle
}

TEST(Relax, MichellRingLeavesThePlaneAboveCriticalLink) {
  RelaxOptions o;
  o.link = 2.5;
  const RelaxResult r = relax(unit_ring(100), o);
  EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
  EXPECT_GE(r.report.saddle_escapes, 1);  // the flat ring is a saddle: left along negative curvature
  EXPECT_NEAR(r.link, 2.5, 1e-8);         // link preserved while twist turns into writhe
  EXPECT_GT(std::fabs(r.writhe), 0.5);    // measured ≈ 2.1: it left the plane
  EXPECT_GT(r.positions.col(2).cwiseAbs().maxCoeff(), 1.0);
  // lower energy than the twisted flat ring (GJ/2 · (2π Lk)² / L + bending of the circle)
  RelaxOptions flat = o;
  flat.max_iterations = 0;
  flat.stop_at_critical_point = true;
  const RelaxResult f = relax(unit_ring(100), flat);
  EXPECT_LT(r.energy.total, f.energy.total);
}

TEST(Relax, StopsAtSaddleWhenAsked) {
  RelaxOptions o;
  o.link = 2.5;
  o.stop_at_critical_point = true;
  const RelaxResult r = relax(unit_ring(100), o);
  EXPECT_EQ(r.status(), RelaxStatus::ConvergedUnstable);
  EXPECT_FALSE(r.stable());
}

TEST(Relax, PeerFilesRelaxAsTheyAre) {
  for (const char* f : {"4_1-smooth.obj", "9_47-cubiclattice.txt"}) {
    const Points P = read_curve(fixtures::peer_dir() + "/" + f);
    const RelaxResult r = relax(P);
    EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable) << f;
    EXPECT_TRUE(r.alexander_preserved) << f;
    EXPECT_LE(r.report.gradient_norm, 1e-8) << f;
    // no two non-adjacent edges closer than half the wire diameter at equilibrium
    EXPECT_GT(r.min_distance, 0.2) << f;
    // rest lengths are the input's: unit lattice edges stay nearly unit
    EXPECT_NEAR(edge_lengths(r.positions).mean(), edge_lengths(P).mean(), 1e-3 * edge_lengths(P).mean()) << f;
  }
}

TEST(Relax, FastPathAndFullModelReachTheSameEnergy) {
  // The twist-free fast path and the full model with Θ free reach
  // the same energy to solver tolerance. From the same lattice start they may
  // follow different paths into different nearby minima of a flat landscape,
  // so each model is started from the other's equilibrium: it must already be
  // an equilibrium there, with the same energy and zero twist.
  const Points P = read_curve(fixtures::peer_dir() + "/4_1-smooth.obj");
  const RelaxResult fast = relax(P);
  ASSERT_EQ(fast.status(), RelaxStatus::ConvergedStable);
  RelaxOptions full_options;
  full_options.full_model = true;
  full_options.rest_lengths = edge_lengths(P);
  const RelaxResult full = relax(fast.positions, full_options);
  ASSERT_EQ(full.status(), RelaxStatus::ConvergedStable);
  EXPECT_EQ(full.model, TwistModel::FreeTheta);
  EXPECT_NEAR(full.energy.twist, 0.0, 1e-12);
  // same rest lengths: equal to 1e-8 relative (gradient tolerance 1e-8 times displacements of order 1)
  EXPECT_NEAR(full.energy.total, fast.energy.total, 1e-8 * fast.energy.total);
  EXPECT_LE(full.report.iterations, 20);
  RelaxOptions fast_options;
  fast_options.rest_lengths = edge_lengths(P);
  const RelaxResult back = relax(full.positions, fast_options);
  ASSERT_EQ(back.status(), RelaxStatus::ConvergedStable);
  EXPECT_NEAR(back.energy.total, full.energy.total, 1e-8 * full.energy.total);
}

TEST(Relax, BadInputIsInputError) {
  Points P = unit_ring(20);
  RelaxOptions o;
  o.material.radius = -1;
  EXPECT_THROW(relax(P, o), InputError);
  o = {};
  Points Q = P;
  Q.row(3) = Q.row(2);
  EXPECT_THROW(relax(Q, o), InputError);
  // a self-intersecting curve
  Points X(8, 3);
  X << 1, 1, 0, 2, 0, 0, 1, -1, 0, 0, 0, 0, -1, 1, 0, -2, 0, 0, -1, -1, 0, 0, 0, 0;
  EXPECT_THROW(relax(X, o), InputError);
  // continuation factors must lie in (0, 1)
  for (const double f : {0.0, 1.0, -0.5, 2.0}) {
    o = {};
    o.contact_continuation = {f};
    EXPECT_THROW(relax(P, o), InputError) << f;
  }
  o = {};
  // slab too thin for the curve
  o.slab = SlabOptions{};
  o.slab->half_thickness = 0.1;
  EXPECT_THROW(relax(fixtures::torus_knot(60, 2, 3, 10, 3), o), InputError);
}

TEST(Relax, PlanaritySlabFlattensAndReleaseKeepsLink) {
  // 3_1 as a doubly covered circle (braid coil with small strand spacing)
  // under a slab: relaxes flat; released, it stays at its link.
  EmbeddingOptions eo;
  eo.vertices = 120;
  eo.strand_spacing = 0.1;
  const Points P = embed_knot(KnotTable::global().at("3_1"), EmbeddingSource::Braid, eo).points;
  RelaxOptions o;
  o.link = writhe(P);  // Lk = Wr of the start: zero initial twist
  SlabOptions s;
  s.half_thickness = 1.2 * P.col(2).cwiseAbs().maxCoeff() + 0.4;
  o.slab = s;
  o.release_slab = true;
  o.newton.record_trace = true;
  const RelaxResult r = relax(P, o);
  ASSERT_TRUE(r.slab_report.has_value());
  // the two phases share one solver and one trace
  ASSERT_EQ(r.phases, (std::vector<std::string>{"slab", "final"}));
  const auto in_phase = [&](int p) {
    return std::count_if(r.trace.begin(), r.trace.end(), [p](const IterationRecord& i) { return i.phase == p; });
  };
  EXPECT_EQ(in_phase(0), r.slab_report->iterations + 1);
  EXPECT_EQ(in_phase(1), r.report.iterations + 1);
  EXPECT_EQ(r.trace.front().parts.back().name, "slab");  // the slab is a term of the first phase only
  EXPECT_EQ(r.trace.back().parts.size(), 4u);
  EXPECT_EQ(r.report.symbolic_factorizations + r.slab_report->symbolic_factorizations,
            r.all_phases().symbolic_factorizations);
  EXPECT_TRUE(r.alexander_preserved);
  EXPECT_NEAR(r.link, *o.link, 1e-6);  // the link stays Lk_B throughout (1e-6)
  EXPECT_EQ(to_string(r.slab_report->status), "converged-stable");
  EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
  EXPECT_LE(r.energy.total, r.slab_energy->total + 1e-9);
}

TEST(Relax, FlatCoilOfTwelveCrossingsConvergesUnderTheSlab) {
  // Regression (jumping knots): the 5-strand coil of 12a_1019
  // (n = 400, the data set's wire) under the slab |z| < 2 d̂. Removing all
  // six rigid motions from the Newton steps removed the slab's curvature
  // along z and the x/y tilts: the flat stage stalled at ||g|| ≈ 2e-2 after
  // ~1000 iterations of t = 2⁻⁹. With only the slab's own symmetries
  // removed it converges in under 200 iterations; the budget leaves room.
  const KnotRecord& k = KnotTable::global().at("12a_1019");
  EmbeddingOptions eo;
  eo.vertices = 400;
  eo.strand_spacing = 2.0 * M_PI * k.braid->strands / 400.0;  // one edge length between strands
  eo.crossing_height = 0.35;
  const Points P = embed_knot(k, EmbeddingSource::Braid, eo).points;
  for (const bool fixed_link : {false, true}) {  // Θ free (twist-free path) and Θ fixed, as exp_jumping_knots
    RelaxOptions o;
    SlabOptions s;
    s.half_thickness = 0.8;
    o.slab = s;
    o.max_iterations = 600;
    if (fixed_link) o.link = 0.5;
    const RelaxResult r = relax(P, o);
    EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable)
        << (fixed_link ? "fixed link: " : "free: ") << r.report.iterations << " iterations, |g| "
        << r.report.gradient_norm;
    EXPECT_TRUE(r.alexander_preserved);
    if (fixed_link) {
      EXPECT_NEAR(r.link, 0.5, 1e-6);
    }
  }
}

TEST(Relax, RigidModesAreZeroModesOfTheTwistedRing) {
  // At a uniformly twisted ring (an equilibrium) the rotations, with the
  // material angles turned by ω·t_j, and the uniform θ shift are exact null
  // vectors of the full model's Hessian (positions-only rotations are not:
  // ‖Hv‖ ≈ 2e-3 there, larger than the smallest true eigenvalue).
  const Points P = unit_ring(60);
  ElasticRod rod(P, RodMaterial{}, TwistModel::FixedLink);
  rod.set_link(2.0);
  rod.relax_twist();
  const Eigen::MatrixXd H = Eigen::MatrixXd(rod.hessian());
  const Eigen::MatrixXd Q = rigid_modes(rod.positions(), rod.num_dofs(), 3 * 60);
  ASSERT_EQ(Q.cols(), 7);
  for (int k = 0; k < Q.cols(); ++k) EXPECT_LT((H * Q.col(k)).norm(), 1e-9 * H.norm()) << "mode " << k;
}

TEST(Relax, DefaultAndPaperNewtonOptionsReachStableEquilibriaOfTheSameKnot) {
  // The hybrid default (projected Hessians far from equilibrium, rigid-mode
  // removal) and the paper's exact Newton (NewtonOptions::paper()) both end
  // converged-stable without changing the knot; the paper's iterations all
  // use the exact Hessian. (They may stop in different nearby minima of a
  // flat landscape, so the energies are not compared.)
  struct Case {
    const char* name;
    Points curve;
  };
  const std::vector<Case> cases = {
      {"4_1-smooth", read_curve(fixtures::peer_dir() + "/4_1-smooth.obj")},
      {"trefoil", fixtures::torus_knot(48, 2, 3, 4.0, 1.6)},
  };
  for (const Case& c : cases) {
    const AlexanderPolynomial input = alexander(c.curve);
    ASSERT_NE(input, alexander(unit_ring(12)));  // a real knot
    const double ell = edge_lengths(c.curve).mean();
    const double tol = 1e-8 / (ell * ell);  // RelaxOptions::tolerance's default for the paper's material
    RelaxOptions start;
    start.max_iterations = 0;  // the input's energy
    const double E0 = relax(c.curve, start).energy.total;
    RelaxOptions paper;
    paper.newton = NewtonMethodOptions::paper();
    RelaxOptions defaults;
    std::vector<RelaxResult> results;
    for (const RelaxOptions* o : {&paper, &defaults}) {
      const RelaxResult r = relax(c.curve, *o);
      const char* which = o == &paper ? "paper" : "default";
      EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable) << c.name << " " << which;
      EXPECT_TRUE(r.alexander_preserved) << c.name << " " << which;
      EXPECT_EQ(r.result_alexander, input) << c.name << " " << which;
      EXPECT_LE(r.report.gradient_norm, tol) << c.name << " " << which;
      EXPECT_LT(r.energy.total, E0) << c.name << " " << which;
      EXPECT_GT(r.min_distance, 0.0) << c.name << " " << which;
      results.push_back(r);
    }
    const NewtonReport& rp = results[0].report;
    const NewtonReport& rd = results[1].report;
    EXPECT_EQ(rp.exact_iterations, rp.iterations - rp.saddle_escapes) << c.name;
    EXPECT_LT(rd.exact_iterations, rd.iterations) << c.name;  // the hybrid default projected some
    EXPECT_EQ(results[0].result_alexander, results[1].result_alexander) << c.name;
  }
}

// The contact pairs' Gauss–Newton Hessians in the projected iterations
// (contact_gauss_newton) change the path, not the model: the peer's 4_1 and
// lattice 9_47 end converged-stable, knot kept, with contacts active, at
// the energy of the eigen-projected run up to the spread of nearby minima in
// a flat landscape (tolerance 1e-3 relative; measured 3e-6 and 2e-4).
TEST(Relax, GaussNewtonContactHessiansEndStableAtNearbyEquilibria) {
  for (const char* name : {"4_1-smooth.obj", "9_47-cubiclattice.txt"}) {
    const Points P = read_curve(fixtures::peer_dir() + "/" + name);
    const RelaxOptions gauss_newton, projected = with_method(gauss_newton, "eigen-projected");
    ASSERT_TRUE(resolve_model(gauss_newton, 1.0).contact_gauss_newton);
    ASSERT_FALSE(resolve_model(projected, 1.0).contact_gauss_newton);
    const RelaxResult a = relax(P, projected), b = relax(P, gauss_newton);
    for (const RelaxResult* r : {&a, &b}) {
      EXPECT_EQ(r->status(), RelaxStatus::ConvergedStable) << name;
      EXPECT_TRUE(r->alexander_preserved) << name;
      EXPECT_GT(r->report.exact_iterations, 0) << name;
    }
    EXPECT_GT(a.contacts, 0) << name;
    EXPECT_NEAR(b.energy.total, a.energy.total, 1e-3 * a.energy.total) << name;
    std::printf("[ measured ] %s: %d iterations with the projected pair Hessians, %d with Gauss-Newton; E %.10g, %.10g\n",
                name, a.report.iterations, b.report.iterations, a.energy.total, b.energy.total);
  }
}

// An ellipse of the circle's length relaxes to the circle, whose bending
// energy is 2π²EI/L (up to the O(1/n²) discretisation error). The default
// hybrid mode takes few Newton iterations: it must not stay on projected
// (linearly converging) directions near a smooth minimum (regression: with the
// projection alone it took > 2000 iterations at n = 400; the exact Hessian
// every iteration, indefinite at the start, takes ~700 with shifted steps).
TEST(Relax, EllipseRelaxesToTheCircleQuickly) {
  const int n = 400;
  const double L = 100.0;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    P.row(i) << 1.2 * std::cos(a), std::sin(a) / 1.2, 0.0;
  }
  P *= L / curve_length(P);
  for (const HessianMode mode : {HessianMode::Hybrid, HessianMode::Exact}) {
    RelaxOptions o;
    o.rest_lengths = VecX::Constant(n, L / n);
    o.newton.hessian = mode;
    const RelaxResult r = relax(P, o);
    EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable) << to_string(mode);
    if (mode == HessianMode::Hybrid) {
      EXPECT_LE(r.report.iterations, 100);
    }
    const double exact = 2.0 * M_PI * M_PI * RodMaterial{}.bending_stiffness() / L;
    EXPECT_NEAR(r.energy.bend / exact, 1.0, 1e-3) << to_string(mode);  // O(1/n²) at n = 400: ~1e-5
  }
}

// Contact-stiffness continuation (RelaxOptions::contact_continuation): the
// soft solve ends with the contacts pressed deeper than the model at ω
// allows, and the final solve at ω pushes them back out: the result has the
// clearance of a direct solve at ω, not of the soft one. Checked on a
// lattice-like start (a trefoil braid coil) that the soft phase tightens.
TEST(Relax, ContinuationEndsAtTheStiffModel) {
  EmbeddingOptions eo;
  eo.vertices = 200;
  const Points curve = embed_knot(KnotTable::global().at("3_1"), EmbeddingSource::Braid, eo).points;
  const AlexanderPolynomial input = alexander(curve);
  RelaxOptions direct;
  direct.method = RelaxMethod::Direct;
  const RelaxResult d = relax(curve, direct);
  ASSERT_EQ(d.status(), RelaxStatus::ConvergedStable);

  RelaxOptions cont = direct;
  cont.contact_continuation = {1e-3};
  const RelaxResult c = relax(curve, cont);
  ASSERT_EQ(c.status(), RelaxStatus::ConvergedStable);
  EXPECT_EQ(c.result_alexander, input);
  ASSERT_EQ(c.continuation_reports.size(), 1u);
  const NewtonReport all = c.all_phases();
  EXPECT_EQ(all.iterations, c.report.iterations + c.continuation_reports[0].iterations);
  EXPECT_EQ(all.numeric_factorizations,
            c.report.numeric_factorizations + c.continuation_reports[0].numeric_factorizations);
  EXPECT_EQ(all.failed_factorizations,
            c.report.failed_factorizations + c.continuation_reports[0].failed_factorizations);
  EXPECT_NEAR(all.seconds, c.report.seconds + c.continuation_reports[0].seconds, 1e-12);
  EXPECT_EQ(all.status, c.report.status);
  EXPECT_EQ(all.gradient_norm, c.report.gradient_norm);

  // the soft model alone: the same start with ω·1e-3
  RelaxOptions soft = direct;
  soft.contact_stiffness = 1e-3 * 1e3;  // the default ω for r = 0.2, E = 2000 is 1e3
  const RelaxResult s = relax(curve, soft);
  ASSERT_EQ(s.status(), RelaxStatus::ConvergedStable);
  const double dhat = 2.0 * direct.material.radius;
  const double pen_soft = dhat - s.min_distance, pen_direct = dhat - d.min_distance, pen_cont = dhat - c.min_distance;
  ASSERT_GT(pen_soft, 0.0);  // the soft solve ends in contact
  // the final phase removes the soft penetration: within a factor 2 of the
  // direct solve's and at least 5x below the soft one (measured, n = 200: 6.9e-5 with
  // and without continuation, 1.5e-3 soft)
  EXPECT_LT(pen_cont, 2.0 * pen_direct + 1e-6);
  EXPECT_LT(5.0 * pen_cont, pen_soft);
  // both reach an equilibrium of the same model: the energies agree when
  // they land in the same state (the doubly covered circle)
  EXPECT_NEAR(c.energy.total, d.energy.total, 1e-3 * d.energy.total);
}

// NewtonOptions::shift_hint searches the shift ladder from the rung below the
// last shift of the same kind of Hessian instead of climbing from the first
// rung; it finds the same (lowest) rung, so the iterates are the same bit for
// bit, with fewer failed factorisations. Checked on the trefoil braid coil,
// whose Hessians need raised shifts (measured: 29 iterations, 27 failed rungs
// without the hint, 18 with it).
TEST(Relax, ShiftHintFindsTheSameShiftsWithFewerFactorisations) {
  EmbeddingOptions eo;
  eo.vertices = 200;
  const Points curve = embed_knot(KnotTable::global().at("3_1"), EmbeddingSource::Braid, eo).points;
  RelaxOptions with, without;
  with.newton.shift_skip_proven = without.newton.shift_skip_proven = false;  // the hint alone
  without.newton.shift_hint = false;
  const RelaxResult a = relax(curve, with), b = relax(curve, without);
  ASSERT_EQ(a.status(), RelaxStatus::ConvergedStable);
  EXPECT_EQ(a.report.iterations, b.report.iterations);
  EXPECT_EQ(a.energy.total, b.energy.total);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.report.final_shift, b.report.final_shift);
  EXPECT_LT(a.report.failed_factorizations, b.report.failed_factorizations);
  std::printf("[ measured ] %d iterations; factorisations %d (%d failed) with the hint, %d (%d failed) without\n",
              a.report.iterations, a.report.numeric_factorizations, a.report.failed_factorizations,
              b.report.numeric_factorizations, b.report.failed_factorizations);
}

// NewtonOptions::shift_skip_proven skips the rungs of the shift ladder that a
// failed block factorisation proves to fail (and then climbs from the warm
// start without the hint); the same rungs are found, so the iterates are the
// same bit for bit, with fewer factorisations. On the
// trefoil braid coil (raised shifts) and the peer's lattice curve of 9_47
// (the multilevel method's phases).
TEST(Relax, ShiftSkipFindsTheSameShiftsWithFewerFactorisations) {
  EmbeddingOptions eo;
  eo.vertices = 200;
  const Points coil = embed_knot(KnotTable::global().at("3_1"), EmbeddingSource::Braid, eo).points;
  const Points lattice = read_curve(fixtures::peer_dir() + "/9_47-cubiclattice.txt");
  for (const Points* curve : {&coil, &lattice}) {
    RelaxOptions with, without;
    without.newton.shift_skip_proven = false;
    const RelaxResult a = relax(*curve, with), b = relax(*curve, without);
    ASSERT_EQ(a.status(), RelaxStatus::ConvergedStable);
    const NewtonReport ra = a.all_phases(), rb = b.all_phases();
    EXPECT_EQ(ra.iterations, rb.iterations);
    EXPECT_EQ(a.energy.total, b.energy.total);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.report.final_shift, b.report.final_shift);
    EXPECT_LT(ra.numeric_factorizations, rb.numeric_factorizations);
    std::printf("[ measured ] %d iterations; factorisations %d (%d failed) skipping, %d (%d failed) climbing\n",
                ra.iterations, ra.numeric_factorizations, ra.failed_factorizations, rb.numeric_factorizations,
                rb.failed_factorizations);
  }
}

// resolve_model() is the one place where the model's defaults are computed:
// the paper's values at the paper's material (ω = 1e3, d̂ = 2r, tolerance
// 1e-8 for unit edges), ω ∝ E r³, tolerance ∝ EI / ℓ², and given values kept.
TEST(Relax, ResolveModelComputesThePapersDefaultsAndTheirScaling) {
  RelaxOptions o;
  const ResolvedModel paper = resolve_model(o, 1.0);
  EXPECT_DOUBLE_EQ(paper.contact_stiffness, 1e3);
  EXPECT_DOUBLE_EQ(paper.dhat, 0.4);
  EXPECT_NEAR(paper.tolerance, 1e-8, 1e-22);
  EXPECT_EQ(paper.model, TwistModel::TwistFree);
  o.material.radius = 0.4;
  o.material.young = 4000.0;
  const ResolvedModel scaled = resolve_model(o, 2.0);
  EXPECT_NEAR(scaled.contact_stiffness, 1e3 * 2.0 * 8.0, 1e-9);         // (E/2000)(r/0.2)³
  EXPECT_NEAR(scaled.tolerance, 1e-8 * 2.0 * 16.0 / 4.0, 1e-20);         // (EI/EI_ref)/ℓ²
  EXPECT_DOUBLE_EQ(scaled.dhat, 0.8);
  EXPECT_DOUBLE_EQ(default_contact_stiffness(o.material), scaled.contact_stiffness);
  o.contact_stiffness = 7.0;
  o.dhat = 0.3;
  o.tolerance = 1e-6;
  o.link = 2.0;
  const ResolvedModel given = resolve_model(o, 1.0);
  EXPECT_EQ(given.contact_stiffness, 7.0);
  EXPECT_EQ(given.dhat, 0.3);
  EXPECT_EQ(given.tolerance, 1e-6);
  EXPECT_EQ(given.model, TwistModel::FixedLink);
  EXPECT_THROW(resolve_model(o, 0.0), std::exception);
}

// The status's text at the boundary: every status reads back from its text,
// and a lost topology wins over the solver's status.
TEST(Relax, StatusTextRoundTripAndTopologyFirst) {
  for (RelaxStatus s : {RelaxStatus::ConvergedStable, RelaxStatus::ConvergedUnstable, RelaxStatus::MaxIterations,
                        RelaxStatus::Stalled, RelaxStatus::TopologyChanged})
    EXPECT_EQ(parse_relax_status(to_string(s)), s) << s;
  EXPECT_EQ(to_string(RelaxStatus::TopologyChanged), "topology-changed");
  EXPECT_EQ(relax_status(SolverStatus::ConvergedStable, false), RelaxStatus::TopologyChanged);
  EXPECT_EQ(relax_status(SolverStatus::MaxIterations, true), RelaxStatus::MaxIterations);
  for (SolverStatus s : {SolverStatus::ConvergedStable, SolverStatus::ConvergedUnstable, SolverStatus::MaxIterations,
                         SolverStatus::Stalled})
    EXPECT_EQ(to_string(relax_status(s, true)), to_string(s));  // the same texts as the solver's
  EXPECT_THROW(parse_relax_status("converged"), InputError);
}
