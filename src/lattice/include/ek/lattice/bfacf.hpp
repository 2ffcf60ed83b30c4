#pragma once
/// \file
/// The BFACF random walk on self-avoiding lattice polygons (Berg and Foerster
/// 1981; Aragão de Carvalho, Caracciolo and Fröhlich 1983; paper Section 5 and
/// Fig.\ 4), with the fugacity parametrisation of Madras and Slade (The
/// Self-Avoiding Walk, 1993, Chapter 9) and Janse van Rensburg and Whittington
/// (J. Phys. A 24:5553, 1991).
///
/// One attempted move: pick an edge (u, v = u + e) uniformly among the n edges
/// and a unit vector w ⟂ e uniformly among the 4 choices; with a the vertex
/// before u and b the vertex after v, look at the plaquette u, v, v + w, u + w:
///  - I   (length −2) a = u + w and b = v + w: the U-turn a, u, v, b becomes the
///        single edge a → b (u and v are removed). Not applied to a square.
///  - III (length ±0) exactly one of a = u + w, b = v + w: the corner at u
///        (resp. v) flips across the plaquette, u → v + w (resp. v → u + w).
///  - II  (length +2) neither: the edge u → v becomes u, u + w, v + w, v.
/// A move is applied only if the new sites are free (an O(1) hash-set
/// lookup; I frees sites and is always self-avoiding), so the polygon stays
/// self-avoiding, and every move is a local isotopy across one unit square
/// that no other part of the polygon meets: the knot type never changes.
///
/// Acceptance (one fugacity β > 0): a move of type II is accepted with
/// probability p₊ = β²/(1 + β²), one of type I with p₋ = 1/(1 + β²), one of
/// type III with probability 1. Derivation: the proposal probability of a
/// particular move from a polygon of n edges is 1/(4n); a type II move at
/// (u → v, w) is undone by exactly one type I proposal, the new middle edge
/// (u + w → v + w) with −w, from the polygon of n + 2 edges, and a corner flip
/// has the same number of proposals (two) in both directions. Detailed
/// balance π(ω) P(ω → ω') = π(ω') P(ω' → ω) for a +2 move therefore reads
///   π(n) / (4n) · β²/(1 + β²) = π(n + 2) / (4(n + 2)) · 1/(1 + β²),
/// so the stationary distribution on the polygons of one knot type (an
/// ergodicity class of BFACF, Janse van Rensburg and Whittington 1991) is
///   π(ω) ∝ n(ω) · β^{n(ω)}.
/// (The classical formulation accepts type III moves with probability 1/2;
/// any constant gives the same π, 1 is the fastest.) For β < β_c = 1/μ ≈ 0.2135
/// (μ = 4.684039931, the connective constant of Z³, Clisby 2013) the mean
/// length is finite and the walk drifts to short polygons; for β > β_c the
/// length grows without bound. The paper's bias towards move II or move I is
/// thus one parameter per phase: a fugacity above β_c to grow, one below β_c
/// to shrink.
#include <cstdint>
#include <memory>
#include <vector>

#include "ek/lattice/lattice_polygon.hpp"

namespace ek {

/// Critical fugacity β_c = 1/μ of self-avoiding polygons on Z³.
constexpr double kCriticalFugacity = 0.21349092124;

/// The three move types of Fig.\ 4 and "no change" (rejected or impossible):
/// I (length −2), II (length +2), III (length ±0) as above, None.
enum class BfacfMove { None, I, II, III };

/// Counts of one run of attempted moves.
struct BfacfRunReport {
  long long attempts = 0;      ///< [moves] attempted moves
  long long accepted_I = 0;    ///< [moves] applied length −2 moves
  long long accepted_II = 0;   ///< [moves] applied length +2 moves
  long long accepted_III = 0;  ///< [moves] applied corner flips
  int start_length = 0;        ///< [edges] length before the run
  int end_length = 0;          ///< [edges] length after the run
  int min_length = 0;          ///< [edges] smallest length during the run
  int max_length = 0;          ///< [edges] largest length during the run
  bool reached = false;        ///< run_to_length(): the target length was reached
};

/// A BFACF walk on one self-avoiding lattice polygon, or on several at once
/// (a link: one polygon per component). The polygon is a doubly
/// linked list of vertices with an array of the live vertices (uniform
/// choice of an edge in O(1)) and a SiteSet of occupied sites, so every
/// attempted move costs O(1) expected time. Random numbers: GSL's MT19937
/// (gsl_rng_mt19937) seeded with a 32-bit hash of `seed`; a given seed and
/// start polygon give the same walk, bit for bit, on the same build.
class BfacfWalk {
 public:
  /// Throws InputError unless `start` is a self-avoiding lattice polygon.
  BfacfWalk(const LatticePoints& start, std::uint64_t seed);

  /// A walk on several polygons (a link) that share one set of occupied
  /// sites: a move is applied only where no polygon is, so no component
  /// passes through another and every component keeps its knot type and every
  /// pair its linking (each move is an isotopy across a unit square that no
  /// other part of the link meets). An attempt picks an edge uniformly among
  /// all edges of all components (run(), attempt()), so the stationary
  /// distribution is π ∝ N·β^N in the total length N; move I never shrinks a
  /// component below 4 edges. One polygon walks exactly as the constructor
  /// above. Throws InputError unless every polygon is a self-avoiding lattice
  /// polygon and no two share a site.
  BfacfWalk(const std::vector<LatticePoints>& components, std::uint64_t seed);
  ~BfacfWalk();  ///< Releases the walk's state.
  /// Moves the walk (its polygons, occupied sites and generator); the walk moved
  /// from may only be destroyed or assigned to.
  BfacfWalk(BfacfWalk&&) noexcept;
  BfacfWalk& operator=(BfacfWalk&&) noexcept;       ///< Moves the walk, as the move constructor.
  BfacfWalk(const BfacfWalk&) = delete;             ///< Not copyable.
  BfacfWalk& operator=(const BfacfWalk&) = delete;  ///< Not copyable.

  /// Current number of vertices (= edges), of all components.
  int length() const;
  /// Number of polygons (components).
  int components() const;
  /// Current number of vertices of component c.
  int component_length(int c) const;

  /// One attempted move at fugacity β (acceptance rule above).
  BfacfMove attempt(double beta);

  /// Exactly `attempts` attempted moves at fugacity β; type II moves that
  /// would exceed `max_length` are rejected (a walk restricted to lengths <=
  /// max_length: detailed balance holds on the restricted set).
  BfacfRunReport run(long long attempts, double beta, int max_length = kMaxLatticeLength);

  /// Attempted moves at fugacity β until the length equals `target` (even,
  /// >= 4) or `max_attempts` moves were attempted; `reached` tells which.
  /// Lengths change by ±2 and keep their parity, so a walk that starts above
  /// (below) the target and ends at or below (above) it stops exactly on it.
  /// With `component` >= 0 the moves are drawn on that component's edges
  /// only and its length is the one that counts (the others stay as they
  /// are, as obstacles); the report's lengths are then the component's.
  BfacfRunReport run_to_length(int target, double beta, long long max_attempts, int component = -1);

  /// The polygon (component 0), starting at a fixed vertex and following the
  /// walk's orientation. n by 3 integer sites.
  LatticePoints polygon() const;
  /// Component c's polygon, as polygon() gives component 0's.
  LatticePoints polygon_of(int c) const;
  /// Every component's polygon, in the order given to the constructor.
  std::vector<LatticePoints> polygons() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ek
