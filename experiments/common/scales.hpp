#pragma once
// The experiments' parameters per scale, in one place (docs/reproducing.md
// lists them). Times are estimates from measured per-relaxation
// costs on the reference machine (2 cores).
#include <cmath>
#include <string>
#include <vector>

#include "ek/dataset/pipeline.hpp"
#include "ek/embedding/embedding.hpp"
#include "experiment.hpp"
#include "thresholds.hpp"

namespace ek::exp {

/// [s] measured median wall time of one relaxation at n = 400 on one core
/// by the default method (exp_bench_solver, docs/performance.md), used for
/// the run-time estimates printed before a run.
inline constexpr double kSecondsPerRelaxation = 0.3;

// The thresholds (kClusterCut, kPlanarThreedim, ...) are shared with the
// paper checks and written into the summaries: experiments/schema/thresholds.hpp.
using namespace ek::results;

/// Options of the data-set runs shared by the experiments.
inline ExploreOptions base_options(const Args& a) {
  ExploreOptions o;
  o.relax = with_method(o.relax, a.method);
  o.jobs = a.jobs;
  o.novelty_distance = kClusterCut;
  o.seed = a.seed;
  return o;
}

/// The multi-covered circle of a braid (paper Fig. 13): n unit edges, the
/// strands one edge length apart radially (the coil radius is n/(2π·strands)
/// edge lengths; strand_spacing is in units of it).
inline EmbeddingOptions multicovered_circle(int vertices, int strands) {
  EmbeddingOptions o;
  o.vertices = vertices;
  o.strand_spacing = 1.0 / (vertices / (2.0 * M_PI * strands));
  return o;
}

}  // namespace ek::exp
