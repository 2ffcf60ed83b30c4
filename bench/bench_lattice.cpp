// Lattice sampling speed: one 400-vertex sample of a 12-crossing
// knot, target <= 20 ms median on one core. Reported:
//  - FirstSample: the whole pipeline from the knot table (embeddings, certified
//    rounding, Alexander checks, grow to 4000 and shrink to 400, the sample's
//    Alexander check);
//  - NextSample: one further sample of a batch (the walk continues from the
//    previous 400-vertex sample: grow to 4000, shrink to 400, Alexander check);
//  - the parts: lattice start, one attempted BFACF move.
// Each repetition uses another seed; read the median of the repetitions.
#include <benchmark/benchmark.h>

#include "ek/knots/alexander.hpp"
#include "ek/lattice/sampling.hpp"

namespace {

using namespace ek;

const char* knot_name(int which) { return which == 0 ? "12a_1019" : "12n_838"; }

void BM_FirstSample(benchmark::State& state) {
  const KnotRecord& k = KnotTable::global().at(knot_name(static_cast<int>(state.range(0))));
  static std::uint64_t seed = 1;
  for (auto _ : state) {
    SampleOptions o;
    o.seed = seed++;
    SampleBatch b = sample_knot(k, o);
    benchmark::DoNotOptimize(b.samples.data());
  }
  state.SetLabel(k.name);
}
BENCHMARK(BM_FirstSample)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(25)
    ->ReportAggregatesOnly(true);

void BM_NextSample(benchmark::State& state) {
  const KnotRecord& k = KnotTable::global().at(knot_name(static_cast<int>(state.range(0))));
  SampleOptions o;
  LatticePoints current = sample_knot(k, o).samples[0];
  const AlexanderPolynomial want = alexander(*k.pd);
  static std::uint64_t seed = 1000;
  for (auto _ : state) {
    o.seed = seed++;
    SampleBatch b = sample_lattice_polygons(current, o, want, k.name);
    current = b.samples[0];
  }
  state.SetLabel(k.name);
}
BENCHMARK(BM_NextSample)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(25)
    ->ReportAggregatesOnly(true);

void BM_LatticeStart(benchmark::State& state) {
  const KnotRecord& k = KnotTable::global().at(knot_name(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    LatticeStart s = lattice_start(k);
    benchmark::DoNotOptimize(s.points.data());
  }
  state.SetLabel(k.name);
}
BENCHMARK(BM_LatticeStart)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Attempted moves on a polygon of about 4000 edges (fugacity 0.3 > β_c with
// the length capped at 4000, so the length stays there); time per move.
void BM_BfacfAttempt(benchmark::State& state) {
  LatticePoints sq(4, 3);
  sq << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  BfacfWalk walk(sq, 3);
  walk.run_to_length(4000, 0.4, 100000000);
  constexpr long long kBlock = 10000;
  for (auto _ : state) benchmark::DoNotOptimize(walk.run(kBlock, 0.3, 4000));
  state.SetItemsProcessed(state.iterations() * kBlock);
  state.SetLabel("length " + std::to_string(walk.length()));
}
BENCHMARK(BM_BfacfAttempt)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
