// Microbenchmarks of the discrete elastic rod at the paper's size (n = 400,
// unit edges): energy, gradient and Hessian assembly, per twist model.
// Target: energy + gradient + Hessian assembly <= 100 µs median on
// one core (taskset -c 1 build/bench/bench_rod).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/geometry/writhe.hpp"
#include "ek/rod/elastic_rod.hpp"

namespace {

using namespace ek;

/// A random smooth closed curve (a few Fourier modes) resampled to 400 unit
/// edges, like a relaxed lattice sample.
Points test_curve(int n) {
  std::mt19937_64 rng(42);
  std::normal_distribution<double> N(0.0, 1.0);
  const int modes = 5, m = 4000;
  Eigen::MatrixXd a(modes, 3), b(modes, 3);
  for (int k = 0; k < modes; ++k)
    for (int c = 0; c < 3; ++c) {
      a(k, c) = N(rng) / (k + 1);
      b(k, c) = N(rng) / (k + 1);
    }
  Points P(m, 3);
  for (int i = 0; i < m; ++i) {
    const double s = 2.0 * M_PI * i / m;
    for (int c = 0; c < 3; ++c) {
      double v = 0;
      for (int k = 0; k < modes; ++k) v += a(k, c) * std::cos((k + 1) * s) + b(k, c) * std::sin((k + 1) * s);
      P(i, c) = v;
    }
  }
  const EquilateralResult r = resample_equilateral(P, n);
  return r.points / r.edge_length;
}

TwistModel model_of(const benchmark::State& state) { return static_cast<TwistModel>(state.range(0)); }

/// A rod with non-trivial twist and the source frames slightly behind the
/// current configuration (as during a Newton iteration).
ElasticRod make_rod(TwistModel model) {
  const Points P = test_curve(400);
  ElasticRod rod(P, RodMaterial{}, model);
  if (model != TwistModel::TwistFree) {
    rod.set_link(rod.writhe() + 1.5);
    rod.relax_twist();
  }
  VecX d = rod.dofs();
  std::mt19937_64 rng(1);
  std::normal_distribution<double> N(0.0, 1e-3);
  for (Eigen::Index i = 0; i < 3 * 400; ++i) d(i) += N(rng);
  rod.set_dofs(d);
  return rod;
}

void label(benchmark::State& state) {
  const TwistModel m = model_of(state);
  state.SetLabel(m == TwistModel::TwistFree ? "twist-free" : (m == TwistModel::FreeTheta ? "free-theta" : "fixed-link"));
}

void BM_SetDofs(benchmark::State& state) {
  ElasticRod rod = make_rod(model_of(state));
  const VecX d = rod.dofs();
  for (auto _ : state) {
    rod.set_dofs(d);
    benchmark::ClobberMemory();
  }
  label(state);
}

void BM_Energy(benchmark::State& state) {
  ElasticRod rod = make_rod(model_of(state));
  for (auto _ : state) benchmark::DoNotOptimize(rod.energy());
  label(state);
}

void BM_Gradient(benchmark::State& state) {
  ElasticRod rod = make_rod(model_of(state));
  for (auto _ : state) benchmark::DoNotOptimize(rod.gradient());
  label(state);
}

void BM_HessianAssembly(benchmark::State& state) {
  ElasticRod rod = make_rod(model_of(state));
  SparseAssembler A;
  auto assemble = [&] {
    A.begin(rod.num_dofs());
    A.segment(0, rod.hessian_structure());
    rod.add_hessian(A);
    A.end();
  };
  assemble();  // first pass records the pattern; later passes replay it
  for (auto _ : state) {
    assemble();
    benchmark::DoNotOptimize(A.matrix().valuePtr());
  }
  label(state);
}

/// One Newton iteration's evaluation: set_dofs + energy + gradient + Hessian.
void BM_EnergyGradientHessian(benchmark::State& state) {
  ElasticRod rod = make_rod(model_of(state));
  const VecX d = rod.dofs();
  SparseAssembler A;
  auto assemble = [&] {
    A.begin(rod.num_dofs());
    A.segment(0, rod.hessian_structure());
    rod.add_hessian(A);
    A.end();
  };
  assemble();
  for (auto _ : state) {
    rod.set_dofs(d);
    benchmark::DoNotOptimize(rod.energy());
    benchmark::DoNotOptimize(rod.gradient());
    assemble();
    benchmark::DoNotOptimize(A.matrix().valuePtr());
  }
  label(state);
}

void BM_UpdateReferenceFrames(benchmark::State& state) {
  ElasticRod rod = make_rod(model_of(state));
  for (auto _ : state) {
    rod.update_reference_frames();
    benchmark::ClobberMemory();
  }
  label(state);
}

void BM_StraightRodMinEigenvalue(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(straight_rod_min_eigenvalue(400, 1.0, RodMaterial{}, TwistModel::TwistFree));
}

/// The writhe of the curve (the exact Gauss double sum over its edge pairs),
/// which every relaxation reports for its result.
void BM_Writhe(benchmark::State& state) {
  const Points P = test_curve(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(writhe(P));
}

#define EK_ROD_MODELS ->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true)
BENCHMARK(BM_SetDofs) EK_ROD_MODELS;
BENCHMARK(BM_Energy) EK_ROD_MODELS;
BENCHMARK(BM_Gradient) EK_ROD_MODELS;
BENCHMARK(BM_HessianAssembly) EK_ROD_MODELS;
BENCHMARK(BM_EnergyGradientHessian) EK_ROD_MODELS;
BENCHMARK(BM_UpdateReferenceFrames) EK_ROD_MODELS;
BENCHMARK(BM_StraightRodMinEigenvalue)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Writhe)->Arg(400)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
