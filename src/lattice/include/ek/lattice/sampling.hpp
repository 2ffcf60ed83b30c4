#pragma once
/// \file
/// Random embeddings of a knot type on the cubic lattice (paper Section 5,
/// Fig.\ 4): an initial polygon from the knot table is rounded onto Z³
/// (rounding.hpp), then a biased BFACF walk (bfacf.hpp) produces samples with
/// exactly n vertices.
///
/// Schedule of one sample (Scharein et al. 2009, as in the paper): phase 1
/// runs at the fugacity grow_fugacity (> β_c: type II moves win) until the
/// polygon has growth_factor·n vertices; phase 2 runs at shrink_fugacity
/// (< β_c: type I moves win) until it has exactly n vertices. A batch of K
/// samples continues one walk: sample k + 1 starts from sample k and runs the
/// same two phases, so every sample is separated from the previous one by a
/// full excursion n -> growth_factor·n -> n (about 2·10⁵ attempted moves for
/// n = 400); `decorrelation_moves` adds attempted moves at the peak (growth
/// fugacity, length capped at the peak) between phase 1 and phase 2 of every
/// sample after the first. Every sample is a self-avoiding lattice
/// polygon with n unit edges and integer coordinates, translated by an integer
/// vector so that its centroid lies in [-1/2, 1/2]³.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ek/embedding/embedding.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/bfacf.hpp"
#include "ek/lattice/rounding.hpp"

namespace ek {

/// Default number of vertices of a sample (paper Section 5: n = 400).
constexpr int kDefaultLatticeVertices = 400;

/// Options of the BFACF schedule.
struct SampleOptions {
  int vertices = kDefaultLatticeVertices;  ///< [1] n, even, >= 4 (>= 24 for a knotted type)
  int count = 1;                           ///< [1] K samples in the batch
  std::uint64_t seed = 1;                  ///< seed of the walk's random numbers
  double grow_fugacity = 0.40;             ///< [1] β of phase 1 (> β_c ≈ 0.2135)
  double shrink_fugacity = 0.10;           ///< [1] β of phase 2 (< β_c)
  double growth_factor = 10.0;             ///< [1] phase 1 ends at growth_factor·n vertices (>= 1)
  /// Extra attempted moves at the peak (grow_fugacity, length capped at the
  /// peak) in every sample after the first.
  long long decorrelation_moves = 0;  ///< [moves]
  /// Attempted-move budget of one phase, in units of the phase's target
  /// length (0 never ends: not allowed). A phase that does not reach its
  /// target within it throws InputError with the smallest length reached.
  double max_attempts_per_vertex = 20000.0;  ///< [moves / vertex]
  /// Check every sample's Alexander polynomial (TopologyError on mismatch; the
  /// walk cannot change the knot type, so this only guards against bugs).
  bool verify = true;
};

/// What happened while making one sample.
struct SampleReport {
  BfacfRunReport decorrelation;  ///< empty for the first sample
  BfacfRunReport grow;           ///< phase 1
  BfacfRunReport shrink;         ///< phase 2
};

/// Result of sample_lattice_knot().
struct SampleBatch {
  std::vector<LatticePoints> samples;  ///< K polygons, n by 3 each
  std::vector<SampleReport> reports;   ///< one per sample

  /// [moves] attempted BFACF moves of every phase of every sample.
  long long attempted_moves() const;
};

/// Runs the schedule from the self-avoiding lattice polygon `start`. When
/// `expected` is given (and options.verify), every sample's Alexander
/// polynomial is compared with it. `what` names the knot in messages. Throws
/// InputError for impossible options (odd n, n < 4, n < 24 for a knotted
/// type: the minimal lattice knot has 24 edges, Diao 1993) and when a phase
/// exhausts its budget (message: the smallest length reached).
SampleBatch sample_lattice_polygons(const LatticePoints& start, const SampleOptions& options,
                                    const std::optional<AlexanderPolynomial>& expected = std::nullopt,
                                    const std::string& what = "lattice polygon");

/// How a table knot's initial lattice polygon is made: every listed (source,
/// vertex count) embedding is built, checked against the table's Alexander
/// polynomial, and rounded (rounding.hpp); the shortest lattice polygon is
/// used. The PD drawing with a large crossing height usually wins for knots
/// with many crossings, the braid coil for torus-like knots.
struct LatticeStartOptions {
  /// (source, vertex count) of the embeddings tried.
  std::vector<std::pair<EmbeddingSource, int>> candidates = {{EmbeddingSource::PD, 128}, {EmbeddingSource::Braid, 256}};
  /// EmbeddingOptions::pd_crossing_height of the PD drawings (the embedding's
  /// default 0.3 gives a smaller clearance relative to the length).
  double pd_crossing_height = 1.0;  ///< [shortest piece]
  RoundingOptions rounding;         ///< How each embedding is rounded onto Z³ (rounding.hpp).
};

/// How a lattice start was obtained: a table knot's PD or braid embedding
/// rounded onto the lattice, or the square (the unknot); a curve that was
/// already a lattice polygon (Lattice) or was rounded (Rounded).
enum class StartMethod { PD, Braid, Square, Lattice, Rounded };
std::string to_string(StartMethod method);  ///< "pd", "braid", "square", "lattice", "rounded"

/// A table knot's initial lattice polygon and how it was obtained.
struct LatticeStart {
  LatticePoints points;           ///< self-avoiding lattice polygon of the knot type
  RoundingResult rounding;        ///< the rounding (its points are `points`)
  /// PD, Braid or Square (the unknot) for a table knot; Lattice or Rounded
  /// for a curve (lattice_start(const Points&)).
  StartMethod method = StartMethod::PD;
  int embedding_vertices = 0;     ///< [1] vertex count of the rounded embedding (the curve's)
  AlexanderPolynomial alexander;  ///< the table's (or the curve's) polynomial (checked on `points`)

  /// [lattice units / length] the rounding's scale; none when nothing was
  /// rounded ("square", "lattice").
  std::optional<double> rounding_scale() const;
};

/// The initial lattice polygon of a table knot (unknot: the unit square).
/// Embeddings whose own Alexander polynomial differs from the table's (too
/// coarse) are skipped; none left: InputError.
LatticeStart lattice_start(const KnotRecord& knot, const LatticeStartOptions& options = {});

/// The initial lattice polygon of a closed curve (n by 3): the curve itself
/// when it already is a self-avoiding lattice polygon (method "lattice",
/// as_lattice_polygon()), otherwise the curve rounded onto Z³ at a proven-safe
/// scale (method "rounded", round_to_lattice() checked against the curve's
/// own polynomial). InputError for a curve that cannot be rounded.
LatticeStart lattice_start(const Points& curve, const RoundingOptions& rounding = {});

/// The table knot's samples: lattice_start() then sample_lattice_polygons().
SampleBatch sample_knot(const KnotRecord& knot, const SampleOptions& options,
                        const LatticeStartOptions& start_options = {}, LatticeStart* start_out = nullptr);

}  // namespace ek
