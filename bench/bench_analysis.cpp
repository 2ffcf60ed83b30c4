// Microbenchmarks of the analysis module. The target: a 500 x 500
// similarity matrix at n = 400 in at most 2 s on one core
// (taskset -c 1 build/bench/bench_analysis --benchmark_filter=SimilarityMatrix).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/bounding_box.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/analysis/mds.hpp"
#include "ek/analysis/search.hpp"
#include "ek/analysis/similarity.hpp"

namespace {

/// A smooth random closed curve: 4 random Fourier modes, n points.
ek::Points random_curve(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  const int modes = 4;
  Eigen::MatrixXd a(modes, 3), b(modes, 3);
  for (int k = 0; k < modes; ++k)
    for (int c = 0; c < 3; ++c) {
      a(k, c) = N(rng) / (k + 1);
      b(k, c) = N(rng) / (k + 1);
    }
  ek::Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    ek::Vec3 p = ek::Vec3::Zero();
    for (int k = 0; k < modes; ++k) p += (a.row(k) * std::cos((k + 1) * s) + b.row(k) * std::sin((k + 1) * s)).transpose();
    P.row(i) = p.transpose();
  }
  return P;
}

std::vector<ek::Points> curve_set(int count, int n) {
  std::vector<ek::Points> v;
  for (int k = 0; k < count; ++k) v.push_back(random_curve(n, 1000 + static_cast<std::uint64_t>(k)));
  return v;
}

ek::SimilarityOptions options_from(int code) {
  ek::SimilarityOptions o;
  o.reversal = code & 1;
  o.mirror = code & 2;
  return o;
}

const char* label_of(int code) {
  static const char* labels[4] = {"plain", "reversal", "mirror", "reversal+mirror"};
  return labels[code];
}

/// The target (2 s): similarity_matrix(500 curves of 400 vertices), signatures and spectra included.
void BM_SimilarityMatrix(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  const int code = static_cast<int>(state.range(2));
  const std::vector<ek::Points> curves = curve_set(count, n);
  for (auto _ : state) benchmark::DoNotOptimize(ek::similarity_matrix(curves, options_from(code)));
  state.SetLabel(label_of(code));
  state.counters["pairs"] = count * (count - 1) / 2.0;
}
BENCHMARK(BM_SimilarityMatrix)
    ->Args({500, 400, 0})
    ->Args({500, 400, 1})
    ->Args({500, 400, 2})
    ->Args({500, 400, 3})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

/// Pairs only, with cached spectra (the data set's repeated comparisons).
void BM_ComparePair(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), code = static_cast<int>(state.range(1));
  ek::SimilarityEngine engine(n, options_from(code));
  const ek::SignatureSpectrum a = engine.spectrum(random_curve(n, 1)), b = engine.spectrum(random_curve(n, 2));
  for (auto _ : state) benchmark::DoNotOptimize(engine.compare(a, b));
  state.SetLabel(label_of(code));
}
BENCHMARK(BM_ComparePair)->Args({400, 0})->Args({400, 3})->Args({1000, 0});

/// Signature and its two forward FFTs for one curve.
void BM_Spectrum(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  ek::SimilarityEngine engine(n);
  const ek::Points P = random_curve(n, 3);
  for (auto _ : state) benchmark::DoNotOptimize(engine.spectrum(P));
}
BENCHMARK(BM_Spectrum)->Arg(400);

void BM_CompleteLinkage(benchmark::State& state) {
  const int N = static_cast<int>(state.range(0));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Eigen::MatrixXd D(N, N);
  for (int i = 0; i < N; ++i) {
    D(i, i) = 0.0;
    for (int j = i + 1; j < N; ++j) D(i, j) = D(j, i) = U(rng);
  }
  for (auto _ : state) benchmark::DoNotOptimize(ek::complete_linkage(D));
}
BENCHMARK(BM_CompleteLinkage)->Arg(500)->Unit(benchmark::kMillisecond);

void BM_ClassicalMds(benchmark::State& state) {
  const int N = static_cast<int>(state.range(0));
  const Eigen::MatrixXd S = ek::similarity_matrix(curve_set(N, 100));
  for (auto _ : state) benchmark::DoNotOptimize(ek::classical_mds_from_similarity(S, 2));
}
BENCHMARK(BM_ClassicalMds)->Arg(500)->Unit(benchmark::kMillisecond);

void BM_GeometricAttributes(benchmark::State& state) {
  const ek::Points P = random_curve(static_cast<int>(state.range(0)), 7);
  for (auto _ : state) benchmark::DoNotOptimize(ek::geometric_attributes(P));
}
BENCHMARK(BM_GeometricAttributes)->Arg(400)->Unit(benchmark::kMillisecond);

void BM_MinVolumeBox(benchmark::State& state) {
  const ek::Points P = random_curve(static_cast<int>(state.range(0)), 7);
  for (auto _ : state) benchmark::DoNotOptimize(ek::threedim(P));
}
BENCHMARK(BM_MinVolumeBox)->Arg(400)->Unit(benchmark::kMillisecond);

// The same search with every box evaluated over all points instead of the
// convex hull's boundary points (the same box).
void BM_MinVolumeBoxAllPoints(benchmark::State& state) {
  const ek::Points P = random_curve(static_cast<int>(state.range(0)), 7);
  for (auto _ : state) benchmark::DoNotOptimize(ek::min_volume_bounding_box_all_points(P));
}
BENCHMARK(BM_MinVolumeBoxAllPoints)->Arg(400)->Unit(benchmark::kMillisecond);

void BM_AlignCurves(benchmark::State& state) {
  const ek::Points P = random_curve(400, 8), Q = random_curve(400, 9);
  for (auto _ : state) benchmark::DoNotOptimize(ek::align_curves(P, Q));
}
BENCHMARK(BM_AlignCurves)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
