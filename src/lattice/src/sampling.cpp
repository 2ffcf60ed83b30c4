#include "ek/lattice/sampling.hpp"

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/knots/alexander.hpp"
#include "schedule.hpp"

namespace ek {

using schedule::budget;
using schedule::centered;
using schedule::even_floor;
using schedule::validate;

SampleBatch sample_lattice_polygons(const LatticePoints& start, const SampleOptions& o,
                                    const std::optional<AlexanderPolynomial>& expected, const std::string& what) {
  validate(o);
  const bool knotted = expected && *expected != AlexanderPolynomial{};
  if (knotted && o.vertices < 24)
    throw InputError("sampling " + what + ": a knotted lattice polygon has at least 24 vertices (Diao 1993), " +
                     std::to_string(o.vertices) + " requested");
  BfacfWalk walk(start, o.seed);
  const int n = o.vertices;
  const int peak = std::max(n, even_floor(o.growth_factor * n));
  SampleBatch batch;
  batch.samples.reserve(static_cast<size_t>(o.count));
  for (int k = 0; k < o.count; ++k) {
    SampleReport rep;
    // Phase 1: grow to the peak (skipped when the walk is already that long).
    if (walk.length() < peak) {
      rep.grow = walk.run_to_length(peak, o.grow_fugacity, budget(o, peak));
      if (!rep.grow.reached)
        throw InputError("sampling " + what + ": the walk did not grow to " + std::to_string(peak) +
                         " vertices within " + std::to_string(rep.grow.attempts) +
                         " attempted moves (largest length reached " + std::to_string(rep.grow.max_length) + ")");
    }
    // Between samples: extra moves at the peak (length capped at the peak).
    if (k > 0 && o.decorrelation_moves > 0)
      rep.decorrelation = walk.run(o.decorrelation_moves, o.grow_fugacity, std::max(peak, walk.length()));
    // Phase 2: shrink to exactly n.
    rep.shrink = walk.run_to_length(n, o.shrink_fugacity, budget(o, peak));
    if (!rep.shrink.reached)
      throw InputError("sampling " + what + ": the walk did not shrink to " + std::to_string(n) + " vertices within " +
                       std::to_string(rep.shrink.attempts) + " attempted moves: smallest length reached " +
                       std::to_string(rep.shrink.min_length) +
                       " (this knot type may need more lattice edges; use a larger vertex count)");
    LatticePoints L = centered(walk.polygon());
    if (o.verify && expected) {
      const AlexanderPolynomial got = alexander(to_points(L));
      if (got != *expected)
        throw TopologyError("sampling " + what + ": sample " + std::to_string(k) + " has Alexander polynomial " +
                            got.to_string() + " instead of " + expected->to_string());
    }
    batch.samples.push_back(std::move(L));
    batch.reports.push_back(rep);
  }
  return batch;
}

std::string to_string(StartMethod method) {
  switch (method) {
    case StartMethod::PD: return "pd";
    case StartMethod::Braid: return "braid";
    case StartMethod::Square: return "square";
    case StartMethod::Lattice: return "lattice";
    case StartMethod::Rounded: return "rounded";
  }
  return "?";
}

LatticeStart lattice_start(const KnotRecord& knot, const LatticeStartOptions& o) {
  require(!o.candidates.empty(), "lattice_start: no embedding candidates");
  LatticeStart best;
  best.alexander = knot.pd ? alexander(*knot.pd) : (knot.braid ? alexander(*knot.braid) : AlexanderPolynomial{});
  if (knot.crossing_number == 0) {
    best.points.resize(4, 3);
    best.points << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
    best.method = StartMethod::Square;
    best.rounding.points = best.points;
    return best;
  }
  std::string skipped;
  for (const auto& [src, m] : o.candidates) {
    EmbeddingOptions eo;
    eo.vertices = m;
    eo.pd_crossing_height = o.pd_crossing_height;
    eo.verify = false;
    Embedding e;
    try {
      e = embed_knot(knot, src, eo);
    } catch (const InputError& err) {
      skipped += std::string(skipped.empty() ? "" : "; ") + err.what();
      continue;
    }
    // A coarse drawing can cross itself (no generic projection: alexander()
    // throws InputError) or change type; either way this candidate is skipped,
    // it says nothing about the user's input.
    std::string why = e.clearance > 0.0 ? "" : "has zero clearance";
    if (why.empty()) try {
        if (alexander(e.points) != best.alexander) why = "is too coarse to keep the knot type";
      } catch (const InputError& err) {
        why = std::string("crosses itself (") + err.what() + ")";
      }
    if (!why.empty()) {
      skipped += std::string(skipped.empty() ? "" : "; ") + to_string(e.method) + " embedding with " + std::to_string(m) +
                 " vertices " + why;
      continue;
    }
    RoundingOptions ro = o.rounding;
    ro.verify = false;  // the chosen rounding is verified below
    RoundingResult r;
    try {
      r = round_to_lattice(e.points, ro);
    } catch (const InputError& err) {
      skipped += std::string(skipped.empty() ? "" : "; ") + err.what();
      continue;
    }
    if (best.points.rows() == 0 || r.points.rows() < best.points.rows()) {
      best.points = r.points;
      best.rounding = std::move(r);
      best.method = e.method == EmbeddingMethod::Braid ? StartMethod::Braid : StartMethod::PD;
      best.embedding_vertices = m;
    }
  }
  if (best.points.rows() == 0)
    throw InputError("no usable embedding of " + knot.name + " to round onto the lattice: " + skipped);
  if (o.rounding.verify) {
    const AlexanderPolynomial got = alexander(to_points(best.points));
    if (got != best.alexander)
      throw TopologyError("lattice rounding of " + knot.name + ": Alexander polynomial " + got.to_string() +
                          " differs from the table's " + best.alexander.to_string());
  }
  return best;
}

LatticeStart lattice_start(const Points& curve, const RoundingOptions& rounding) {
  LatticeStart start;
  start.alexander = alexander(curve);
  start.embedding_vertices = static_cast<int>(curve.rows());
  if (as_lattice_polygon(curve, &start.points)) {
    start.method = StartMethod::Lattice;
    start.rounding.points = start.points;
    return start;
  }
  start.rounding = round_to_lattice(curve, rounding, start.alexander);
  start.points = start.rounding.points;
  start.method = StartMethod::Rounded;
  return start;
}

std::optional<double> LatticeStart::rounding_scale() const {
  if (method == StartMethod::Square || method == StartMethod::Lattice) return std::nullopt;
  return rounding.scale;
}

long long SampleBatch::attempted_moves() const {
  long long moves = 0;
  for (const SampleReport& r : reports) moves += r.decorrelation.attempts + r.grow.attempts + r.shrink.attempts;
  return moves;
}

SampleBatch sample_knot(const KnotRecord& knot, const SampleOptions& options, const LatticeStartOptions& start_options,
                        LatticeStart* start_out) {
  if (knot.crossing_number > 0 && options.vertices < 24)  // also for knots with Δ = 1
    throw InputError("sampling " + knot.name + ": a knotted lattice polygon has at least 24 vertices (Diao 1993), " +
                     std::to_string(options.vertices) + " requested");
  LatticeStart start = lattice_start(knot, start_options);
  SampleBatch batch = sample_lattice_polygons(start.points, options, start.alexander, knot.name);
  if (start_out) *start_out = std::move(start);
  return batch;
}

}  // namespace ek
