// Contact module microbenchmarks (targets, one core):
//  - broad phase + barrier gradient + Hessian assembly at n = 400: <= 50 µs median
//  - one collision-detection query for a Newton-sized step: <= 100 µs median
//
// There is no relaxed 12-crossing knot in the project yet, so the scenes are
// synthetic compact curves, n = 400, edges of length ~1, contacts at
// distance 0.3-0.4 (d̂ = 0.4, the paper's default wire):
//  - "knot13": the (2, 13) torus knot drawn flat (13 crossings, like a relaxed
//    12-crossing knot lying on a table): a circle of radius 31.8 with a radial
//    wave of amplitude 3 and height ±0.175, so the two strands pass 0.35
//    apart at each crossing, where they touch; plus three "clasps" where the
//    strands run side by side at 0.35 for ~12 edges (the long contacts of
//    relaxed knots);
//  - "pair13": the (2, 13) torus knot on a thin torus (tube radius 0.175):
//    two strands twisted around each other at 0.35 along their whole length,
//    like a doubly covered circle: every edge in contact (a worst case);
//  - "coil3": the (3, 7) torus knot on a tube of radius 0.2 (strands 0.35
//    apart): three strands in contact everywhere (a triply covered circle).
// Newton-sized steps: a smooth random displacement field (8 Fourier modes)
// scaled to a largest vertex displacement of 0.1 (a quarter of d̂) or 0.5.
// "fresh": the broad phase runs on every update (skin 0, the cost after a
// large step); "reuse": the default skin with x unchanged (the cost of a
// Newton iteration that moved every vertex by less than skin/2 = 0.05).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "ek/contact/contact_potential.hpp"

using namespace ek;

namespace {

constexpr int kN = 400;

Points torus_knot(int n, int p, int q, double R, double r) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    const double rr = R + r * std::cos(q * s);
    P.row(i) << rr * std::cos(p * s), rr * std::sin(p * s), r * std::sin(q * s);
  }
  return P;
}

Points knot13() {
  // flat (2, 13) torus knot: radial wave of amplitude a, height ±h
  const int n = kN;
  const double R = n / (4.0 * M_PI), a = 3.0, h = 0.175;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    double rr = R + a * std::cos(13 * s);
    // three clasps: around s = 0, 2π/3, 4π/3 the wave is flattened so that
    // both strands run at R ± 0.175 side by side
    double clasp = 0.0;
    for (int k = 0; k < 3; ++k) {
      double ds = std::remainder(s - 2.0 * M_PI * k / 3.0, M_PI);
      clasp = std::max(clasp, std::exp(-std::pow(ds / 0.09, 2)));
    }
    const double side = std::cos(13 * s) >= 0 ? 1.0 : -1.0;
    rr = (1 - clasp) * rr + clasp * (R + h * side);
    P.row(i) << rr * std::cos(2 * s), rr * std::sin(2 * s), (1 - clasp) * h * std::sin(13 * s);
  }
  return P;
}

Points scene(int kind) {
  switch (kind) {
    case 0: return knot13();
    case 1: return torus_knot(kN, 2, 13, kN / (4.0 * M_PI), 0.175);
    default: return torus_knot(kN, 3, 7, kN / (6.0 * M_PI), 0.2);
  }
}
const char* scene_name(int kind) { return kind == 0 ? "knot13" : (kind == 1 ? "pair13" : "coil3"); }

Points smooth_step(int n, double max_norm, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N;
  Points d = Points::Zero(n, 3);
  for (int k = 1; k <= 8; ++k) {
    const Vec3 a(N(rng), N(rng), N(rng)), b(N(rng), N(rng), N(rng));
    for (int i = 0; i < n; ++i) {
      const double s = 2.0 * M_PI * k * i / n;
      d.row(i) += (a * std::cos(s) + b * std::sin(s)).transpose() / k;
    }
  }
  return d * (max_norm / d.rowwise().norm().maxCoeff());
}

// range(1) = 1: the broad phase runs on every update (skin 0); 0: default
// skin, the broad phase's list is reused (x does not move here).
ContactOptions options_for(int fresh) {
  ContactOptions o;
  if (fresh) o.broad_phase_skin = 0.0;
  return o;
}
std::string label(int kind, int fresh) { return std::string(scene_name(kind)) + (fresh ? " fresh" : " reuse"); }

void BM_UpdateGradientHessian(benchmark::State& st) {
  const Points x = scene(static_cast<int>(st.range(0)));
  ContactPotential cp(CurveTopology::single(kN), options_for(static_cast<int>(st.range(1))));
  SparseAssembler A;
  VecX g = VecX::Zero(3 * kN);
  for (auto _ : st) {
    cp.update(x);
    g.setZero();
    cp.add_gradient(x, g);
    A.begin(3 * kN);
    A.segment(0, cp.hessian_structure());
    cp.add_hessian(x, A);
    A.end();
    benchmark::DoNotOptimize(g.data());
    benchmark::DoNotOptimize(A.matrix().valuePtr());
  }
  st.counters["active"] = static_cast<double>(cp.num_active());
  st.counters["candidates"] = static_cast<double>(cp.num_candidates());
  st.SetLabel(label(static_cast<int>(st.range(0)), static_cast<int>(st.range(1))));
}

void BM_BroadPhase(benchmark::State& st) {
  const Points x = scene(static_cast<int>(st.range(0)));
  ContactPotential cp(CurveTopology::single(kN), options_for(static_cast<int>(st.range(1))));
  for (auto _ : st) {
    cp.update(x);
    benchmark::DoNotOptimize(cp.num_active());
  }
  st.counters["active"] = static_cast<double>(cp.num_active());
  st.SetLabel(label(static_cast<int>(st.range(0)), static_cast<int>(st.range(1))));
}

void BM_Gradient(benchmark::State& st) {
  const Points x = scene(static_cast<int>(st.range(0)));
  ContactPotential cp(CurveTopology::single(kN), ContactOptions{});
  cp.update(x);
  VecX g = VecX::Zero(3 * kN);
  for (auto _ : st) {
    cp.add_gradient(x, g);
    benchmark::DoNotOptimize(g.data());
  }
  st.SetLabel(scene_name(static_cast<int>(st.range(0))));
}

void BM_Hessian(benchmark::State& st) {
  const Points x = scene(static_cast<int>(st.range(0)));
  ContactPotential cp(CurveTopology::single(kN), ContactOptions{});
  cp.update(x);
  SparseAssembler A;
  for (auto _ : st) {
    A.begin(3 * kN);
    A.segment(0, cp.hessian_structure());
    cp.add_hessian(x, A);
    A.end();
    benchmark::DoNotOptimize(A.matrix().valuePtr());
  }
  st.SetLabel(scene_name(static_cast<int>(st.range(0))));
}

// The solver's projected contact Hessian (hybrid Hessian far from
// equilibrium): every active pair's 12 by 12 barrier Hessian and its
// projection to positive semidefinite. Argument 1: 0 = the exact Hessian,
// then the 12 by 12 eigen-decomposition (project_to_psd); 1 = the same in the
// 9-dimensional complement of translations; 2 = the projection computed in
// the Hessian's at most 5-dimensional range (edge_edge_barrier_derivatives
// with project_psd, what add_hessian uses).
void BM_PairHessianProjection(benchmark::State& st) {
  const Points x = scene(static_cast<int>(st.range(0)));
  ContactPotential cp(CurveTopology::single(kN), ContactOptions{});
  cp.update(x);
  const PairBarrierParams params{cp.options().dhat, cp.options().parallel_threshold};
  const int method = static_cast<int>(st.range(1));
  for (auto _ : st) {
    for (const ContactPair& c : cp.active_pairs()) {
      Mat12 h;
      edge_edge_barrier_derivatives(x.row(c.a0).transpose(), x.row(c.a1).transpose(), x.row(c.b0).transpose(),
                                    x.row(c.b1).transpose(), params, nullptr, &h, 1.0, method == 2);
      if (method == 0) project_to_psd(h);
      if (method == 1) project_translation_invariant_to_psd(h);
      benchmark::DoNotOptimize(h.data());
    }
  }
  st.counters["pairs"] = static_cast<double>(cp.num_active());
  static const char* names[] = {" 12x12", " 9x9", " range"};
  st.SetLabel(std::string(scene_name(static_cast<int>(st.range(0)))) + names[method]);
}

/// One collision-detection query: the swept broad phase with the spatial
/// hash (ccd_skin 0), then the per-pair CCD; `kept`: the same query with the
/// pairs of an earlier swept broad phase kept (ccd_skin, the default), as
/// while the Newton steps stay small.
void max_step_query(benchmark::State& st, bool kept) {
  const Points x = scene(static_cast<int>(st.range(0)));
  const double size = st.range(1) / 10.0;
  const Points dx = smooth_step(kN, size, 3);
  ContactOptions o;
  if (!kept) o.ccd_skin = 0.0;
  ContactPotential cp(CurveTopology::single(kN), o);
  StepReport r = cp.max_step_report(x, dx);
  for (auto _ : st) {
    r = cp.max_step_report(x, dx);
    benchmark::DoNotOptimize(r);  // (not r.t: DoNotOptimize on a double lvalue clobbers it)
  }
  if (kept && cp.num_swept_broad_phase_runs() != 1) st.SkipWithError("the kept pairs were not used");
  st.counters["candidates"] = r.candidates;
  st.counters["iterations"] = static_cast<double>(r.iterations);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s step %.1f t=%.3f", scene_name(static_cast<int>(st.range(0))), size, r.t);
  st.SetLabel(buf);
}

void BM_MaxStep(benchmark::State& st) { max_step_query(st, false); }
void BM_MaxStepKept(benchmark::State& st) { max_step_query(st, true); }

void BM_NoContact(benchmark::State& st) {
  Points x(kN, 3);
  for (int i = 0; i < kN; ++i) {
    const double s = 2.0 * M_PI * i / kN;
    x.row(i) << kN / (2 * M_PI) * std::cos(s), kN / (2 * M_PI) * std::sin(s), 0;
  }
  ContactPotential cp(CurveTopology::single(kN), options_for(1));
  SparseAssembler A;
  VecX g = VecX::Zero(3 * kN);
  for (auto _ : st) {
    cp.update(x);
    cp.add_gradient(x, g);
    A.begin(3 * kN);
    A.segment(0, cp.hessian_structure());
    cp.add_hessian(x, A);
    A.end();
    benchmark::DoNotOptimize(g.data());
  }
  st.counters["active"] = static_cast<double>(cp.num_active());
}

// The "off" side of two skips: without the broad phase every pair
// of non-adjacent edges is tested. BM_NoContactAllPairs: the distance test of
// all pairs on the contact-free circle of BM_NoContact; BM_MaxStepAllPairs:
// the collision-detection query of BM_MaxStep over all pairs instead of the
// pairs the swept broad phase keeps (same per-pair CCD and parameters).
template <class F>
void for_all_pairs(F&& f) {
  for (int a = 0; a < kN; ++a)
    for (int b = a + 2; b < kN; ++b)
      if (!(a == 0 && b == kN - 1)) f(a, (a + 1) % kN, b, (b + 1) % kN);
}

Vec3 at(const Points& x, int i) { return x.row(i).transpose(); }

void BM_NoContactAllPairs(benchmark::State& st) {
  Points x(kN, 3);
  for (int i = 0; i < kN; ++i) {
    const double s = 2.0 * M_PI * i / kN;
    x.row(i) << kN / (2 * M_PI) * std::cos(s), kN / (2 * M_PI) * std::sin(s), 0;
  }
  const double dhat = ContactOptions{}.dhat;
  int near = 0;
  for (auto _ : st) {
    near = 0;
    for_all_pairs([&](int a0, int a1, int b0, int b1) {
      near += edge_edge_closest(at(x, a0), at(x, a1), at(x, b0), at(x, b1)).distance_squared < dhat * dhat;
    });
    benchmark::DoNotOptimize(near);
  }
  st.counters["active"] = near;
}

void BM_MaxStepAllPairs(benchmark::State& st) {
  const Points x = scene(static_cast<int>(st.range(0)));
  const double size = st.range(1) / 10.0;
  const Points dx = smooth_step(kN, size, 3);
  const ContactOptions o;
  CcdParams params;
  params.separation = o.ccd_separation;
  params.distance_cap = o.dhat;
  params.tolerance = o.ccd_tolerance;
  params.max_iterations = o.ccd_max_iterations;
  double t = 1.0;
  for (auto _ : st) {
    t = 1.0;
    for_all_pairs([&](int a0, int a1, int b0, int b1) {
      if (t > 0.0)  // as max_step_report: nothing to gain once a pair allows no motion
        t = edge_edge_ccd(at(x, a0), at(x, a1), at(x, b0), at(x, b1), at(dx, a0), at(dx, a1), at(dx, b0),
                          at(dx, b1), t, params)
                .t;
    });
    double sink = t;  // (not t itself: DoNotOptimize on a double lvalue clobbers it)
    benchmark::DoNotOptimize(sink);
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s step %.1f t=%.3f", scene_name(static_cast<int>(st.range(0))), size, t);
  st.SetLabel(buf);
}

}  // namespace

BENCHMARK(BM_UpdateGradientHessian)->ArgsProduct({{0, 1, 2}, {1, 0}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BroadPhase)->ArgsProduct({{0, 1, 2}, {1, 0}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Gradient)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Hessian)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PairHessianProjection)->ArgsProduct({{0, 1}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MaxStep)->Args({0, 1})->Args({0, 5})->Args({1, 1})->Args({1, 5})->Args({2, 1})->Args({2, 5})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MaxStepKept)->Args({0, 1})->Args({0, 5})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NoContact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NoContactAllPairs)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MaxStepAllPairs)->Args({0, 1})->Args({0, 5})->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
