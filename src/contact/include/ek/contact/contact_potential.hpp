#pragma once
/// \file
/// Self-contact of closed polylines that can never change the knot type
/// (paper Section 6, "Contact Handling", eq.\ 1: E_rod + ω E_contact; the
/// variational contact of Li et al.\ 2020 "Incremental Potential Contact" and
/// Li et al.\ 2021 "Codimensional IPC", here for closed curves).
///
/// Energy:  E(x) = ω Σ_{active pairs (i, j)} e_ij(x)
///   over pairs of edges that are not excluded (edges sharing a vertex are;
///   pairs across components never are) and whose segment distance is below
///   d̂; e_ij is the pair barrier of barrier.hpp: b(d) = −(d − d̂)² ln(d/d̂)
///   of the segment distance d, mollified for nearly parallel segments.
///   Units: b is a length², ω an energy per length², E an energy.
///
/// Collision detection: max_step(x, dx) is the largest t ∈ [0, 1] such that,
/// along x + s·dx for every s ∈ [0, t], every non-excluded pair keeps a
/// distance >= ccd_separation · min(d_ij(x), d̂) (> 0 whenever d_ij(x) > 0).
/// It is certified (ccd.hpp), so a solver that only ever moves by
/// x + t·dx with t <= max_step(x, dx) never lets two edges touch or pass
/// through each other, and the knot (or link) type cannot change; the barrier
/// stays finite. Only pairs whose swept boxes (inflated by
/// ccd_separation · d̂ / 2) overlap are tested; the others cannot come closer
/// than ccd_separation · d̂.
///
/// Guarantee and excluded_neighbors: with excluded_neighbors = 1 (default)
/// only edges sharing a vertex are excluded, and two such edges can only meet
/// by folding onto each other at their common vertex, which does not change
/// the knot type. Larger values also skip pairs that can pass through each
/// other, so the guarantee holds only for 1.
///
/// Stiffness scaling. b(d) = d̂² φ(d/d̂) with φ(ρ) = −(ρ − 1)² ln ρ, so a
/// pair's contact force is ω |b'(d)| = ω d̂ |φ'(ρ)|; it balances elastic
/// forces that scale with the bending stiffness EI = E π r⁴/4 (paper defaults
/// E = 2000, r = 0.2: EI ≈ 2.51, unit rest edges). To keep the same relative
/// penetration ρ = d/d̂ at the same curve shape, scale ω ∝ EI/d̂ ∝ E r³:
/// ~~~{.unparsed}
///   ω = 1e3 · (E / 2000) · (r / 0.2)³.
/// ~~~
///
/// Cost: update() is the broad phase (spatial hash over the n edges, O(n) for
/// edges of similar length) plus one segment distance per candidate pair; with
/// no pair within d̂ energy(), add_gradient() and add_hessian() do nothing.
/// Skin (Verlet list): the broad phase collects the pairs within d̂ + skin;
/// while every vertex stays within skin/2 of where it was then (checked in
/// O(n) by update()), no other pair can come within d̂ (segment points move at
/// most skin/2 each), so update() re-filters that list instead of rerunning
/// the broad phase. Newton iterations near convergence move far less. The
/// same holds along the last max_step(x, dx) query: its broad phase collects
/// the pairs whose swept boxes come within d̂ + hessian_margin + skin, and update() reuses
/// them while every vertex is within skin/2 of its path x_i + s·dx_i (so the
/// line search's trials x + t·dx run no broad phase). That swept broad phase
/// itself keeps its pairs with ccd_skin more inflation: while every vertex's
/// start and end points x_i, x_i + dx_i of a later query lie within ccd_skin
/// of the box of that vertex's start and end points when it ran, each edge's
/// swept box of the later query lies within its box then, and the pairs are
/// those of the kept list whose boxes overlap (the same list, filtered in
/// O(n + pairs) without the spatial hash).
///
/// Hessian pattern: add_hessian() writes into a fixed set of vertex blocks,
/// identified by hessian_structure(), so that a solver keeps its symbolic
/// factorisation while the identifier stays the same. With hessian_margin = 0
/// the blocks are those of the active pairs and change whenever the active
/// set does. With hessian_margin > 0 they are those of the "pattern pairs":
/// the pairs within d̂ + hessian_margin when the pattern was last built; it is
/// rebuilt (all pairs then within d̂ + margin) only when an active pair is not
/// a pattern pair, and blocks of inactive pattern pairs are explicit zeros.
/// Values, energy and gradient are the same either way; pairs approaching
/// from within the margin then do not change the pattern when they activate.
///
/// Not thread-safe: const methods use scratch buffers of the object.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "ek/contact/barrier.hpp"
#include "ek/contact/broad_phase.hpp"
#include "ek/contact/ccd.hpp"
#include "ek/contact/topology.hpp"
#include "ek/core/hessian_kind.hpp"
#include "ek/core/sparse_assembler.hpp"

namespace ek {

/// Defaults (paper Section 6).
inline constexpr double kDefaultDhat = 0.4;          ///< 2r with r = 0.2
/// [energy/length²] ω for the paper's material (E = 2000, r = 0.2) at
/// d̂ = 0.4; default_contact_stiffness() (solver/relax.hpp) scales it for
/// another material ("Stiffness scaling" above).
inline constexpr double kDefaultContactStiffness = 1e3;

/// The parameters of the contact potential: barrier distance and stiffness,
/// the collision detection and the broad phase.
struct ContactOptions {
  double dhat = kDefaultDhat;  ///< [length] barrier distance d̂ = wire diameter 2r (paper defaults: r = 0.2)
  double stiffness = kDefaultContactStiffness;  ///< [energy/length²] ω (see "Stiffness scaling" above)
  /// [edges] edges within this index distance along a component are excluded; 1 = only edges sharing a vertex (the only
  /// setting that keeps the guarantee)
  int excluded_neighbors = 1;
  bool project_psd = false;    ///< project each pair's 12 by 12 barrier Hessian to positive semidefinite
  /// [bool] the Hessian of HessianKind::Projected: each pair's Gauss–Newton
  /// term b''∇d∇dᵀ (PairHessian::GaussNewton, barrier.hpp) instead of its
  /// eigen-projection. The exact Hessian is unchanged.
  bool gauss_newton_projection = false;
  double parallel_threshold = 1e-3;  ///< [1] ε: pairs with sin²(angle) < ε use the mollified energy (barrier.hpp)
  /// [1] CCD keeps every pair at >= this fraction of min(current distance, d̂); in (0, 1)
  double ccd_separation = 0.1;
  /// [1] per-pair CCD stops within this fraction of the gap to the floor (ccd.hpp); in (0, 1]
  double ccd_tolerance = 0.1;
  int ccd_max_iterations = 1000;  ///< [1] per-pair cap on CCD distance evaluations (result stays certified)
  /// [length] update() keeps the broad phase's pairs within d̂ + skin while no vertex has moved skin/2 since it ran (0:
  /// run it every time)
  double broad_phase_skin = 0.1;
  /// [length] max_step() keeps its swept broad phase's pairs with this much
  /// more inflation, for later queries whose motion stays within it (see
  /// "Skin" above; 0: a swept broad phase every query). Used when
  /// broad_phase_skin > 0; the results are the same for every value.
  double ccd_skin = 0.3;
  /// [length] Hessian pattern with hysteresis (see "Hessian pattern" above):
  /// 0 = the pattern is the active set; > 0 = the pairs within d̂ + margin at
  /// the last rebuild, kept until an active pair falls outside them.
  double hessian_margin = 0.0;

  /// Throws std::invalid_argument naming the first bad field.
  void validate() const;
};

/// One pair of edges within d̂.
struct ContactPair {
  ///@{
  /// Edge indices, edge_a < edge_b.
  int edge_a = -1, edge_b = -1;
  ///@}
  ///@{
  /// Vertex indices of the endpoints: edge_a joins a0 to a1, edge_b joins b0 to b1.
  int a0 = -1, a1 = -1, b0 = -1, b1 = -1;
  ///@}
  EdgeEdgeDistanceType type = EdgeEdgeDistanceType::EA_EB;  ///< closest features at update()
  double distance = 0.0;  ///< [length] segment distance at update()
};

/// Report of one collision-detection query.
struct StepReport {
  double t = 1.0;          ///< [1] certified step (max_step)
  int candidates = 0;      ///< pairs whose swept boxes overlap (tested)
  ///@{
  /// The pair of edges that limits t (-1 when t = 1).
  int edge_a = -1, edge_b = -1;
  ///@}
  double start_distance = 0.0;   ///< [length] that pair's distance at s = 0
  double floor = 0.0;            ///< [length] that pair's floor δ
  long long iterations = 0;      ///< distance evaluations over all pairs
};

/// The contact energy ω Σ e_ij of the curves' edge pairs within d̂, its
/// gradient and Hessian, and the certified collision-free step (see the
/// file's description). Keeps the active set of the last update(), the broad
/// phase's buffers and the Hessian pattern between calls.
class ContactPotential {
 public:
  /// For curves of these components; validates the options (std::invalid_argument).
  ContactPotential(CurveTopology topology, ContactOptions options);

  const CurveTopology& topology() const { return broad_.topology(); }  ///< The components of the curves.
  const ContactOptions& options() const { return options_; }           ///< The options as given.
  int num_vertices() const { return n_; }                              ///< n, the vertices of all components.

  /// Broad phase and active set at positions x (n by 3): pairs of
  /// non-excluded edges with segment distance < d̂, sorted by (edge_a, edge_b).
  void update(const Points& x);
  size_t num_active() const { return active_.size(); }  ///< Number of active pairs (within d̂ at the last update()).
  /// The active pairs of the last update(), sorted by (edge_a, edge_b).
  const std::vector<ContactPair>& active_pairs() const { return active_; }
  /// Pairs tested by the last update() (boxes within d̂ + hessian_margin).
  size_t num_candidates() const { return candidates_; }
  /// How many times update() has run the broad phase (the rest reused it).
  size_t num_broad_phase_runs() const { return broad_phase_runs_; }
  /// How many times max_step() has run its swept broad phase with the spatial
  /// hash (the rest filtered the pairs it kept, see ccd_skin).
  size_t num_swept_broad_phase_runs() const { return swept_broad_phase_runs_; }
  /// [length] smallest segment distance among those candidates (+∞ if none).
  double min_distance() const { return min_distance_; }

  /// ω Σ e_ij over the active pairs, at x (the positions given to update();
  /// the pairs' distances are recomputed from x). +∞ if a pair touches.
  double energy(const Points& x) const;
  /// Gradient (length 3n, vertex-major x, y, z).
  VecX gradient(const Points& x) const;
  /// Adds the gradient to g (length 3n).
  void add_gradient(const Points& x, Eigen::Ref<VecX> g) const;
  /// Adds the Hessian into the position dofs 0..3n−1 of A. The pairs' 12 by
  /// 12 blocks are first summed per pair of vertices (pairs along a contact
  /// share vertices), then each vertex block of the pattern (see "Hessian
  /// pattern") is added once, in an order that depends only on the pattern
  /// (so A replays its pattern while hessian_structure() is unchanged). Call A.segment(id, hessian_structure()) first.
  void add_hessian(const Points& x, SparseAssembler& A) const;
  /// As above, with each pair's 12 by 12 Hessian projected to positive
  /// semidefinite for HessianKind::Projected (instead of options().project_psd).
  void add_hessian(const Points& x, SparseAssembler& A, HessianKind kind) const;
  /// Identifies the Hessian pattern (a 64-bit hash of n and the sorted pattern
  /// pairs; with hessian_margin = 0 the active pairs): it changes iff the
  /// pattern changes (up to hash collisions, probability ~2⁻⁶⁴), for
  /// SparseAssembler::segment.
  std::uint64_t hessian_structure() const { return structure_; }

  /// Largest certified step t ∈ [0, 1] of the motion x + s·dx (see the file
  /// comment). 0 if two non-excluded edges already touch at x.
  double max_step(const Points& x, const Points& dx) const;
  /// The same with a report (candidates, limiting pair).
  StepReport max_step_report(const Points& x, const Points& dx) const;

 private:
  ContactOptions options_;
  int n_ = 0;
  EdgeBroadPhase broad_;
  mutable EdgeBroadPhase ccd_broad_;
  std::vector<ContactPair> active_;
  std::vector<EdgePair> near_;       // pairs within d̂ + hessian_margin (scratch of update())
  std::vector<EdgePair> pattern_;    // pairs whose blocks the Hessian pattern holds (sorted)
  std::vector<int> active_slot_;     // index in pattern_ of each active pair
  bool have_pattern_ = false;
  size_t candidates_ = 0;
  size_t broad_phase_runs_ = 0;
  Points x_ref_;                   // positions at the last broad phase
  std::vector<EdgePair> verlet_;   // its pairs (boxes within d̂ + skin)
  bool verlet_valid_ = false;
  // the last max_step()'s motion x + s·dx, s ∈ [0, 1], and the pairs whose
  // swept boxes come within d̂ + hessian_margin + skin (a second Verlet list)
  mutable Points path_x_, path_dx_;
  mutable std::vector<EdgePair> path_pairs_;
  mutable bool path_valid_ = false;
  // the kept swept broad phase: its pairs (swept boxes within d̂ + hessian_margin
  // + skin + 2·ccd_skin), and each vertex's box of its start and end points then
  mutable std::vector<EdgePair> sweep_pairs_;
  mutable std::vector<double> sweep_box_;  // 6 per vertex: lo xyz, hi xyz (empty: none kept yet)
  mutable size_t swept_broad_phase_runs_ = 0;
  bool sweep_covers(const Points& x, const Points& dx) const;  // the query lies within ccd_skin of those boxes
  // the swept broad phase of x + s·dx with `inflation`, kept with its points' boxes
  void keep_sweep(const Points& x, const Points& dx, double inflation) const;
  double min_distance_ = 0.0;
  std::uint64_t structure_ = 0;
  // Hessian plan, a cache rebuilt by add_hessian() after the pattern changed:
  // the distinct vertex pairs (u <= v) touched by the pattern pairs, and for
  // each pattern pair and each of its 10 vertex pairs (k <= l) the block it
  // adds to (bit 30 set: add the transpose).
  mutable std::vector<std::pair<int, int>> blocks_;
  mutable std::vector<std::array<int, 10>> pair_blocks_;
  mutable std::vector<Mat3> block_values_;
  mutable std::uint64_t plan_structure_ = 0;  // structure_ the plan was built for (0: none yet)
  void build_hessian_plan() const;
  // The steps of update(): the broad phase's pairs (reused while the Verlet
  // list or the last motion's path still holds them); whether x is within
  // sqrt(limit) of that path; the active pairs, near_ and min_distance_ from
  // them; whether pattern_ holds every active pair (sets active_slot_ as far
  // as it does); the pattern and structure_ rebuilt from the active pairs.
  const std::vector<EdgePair>& candidate_pairs(const Points& x);
  bool on_path(const Points& x, double limit) const;
  void narrow_phase(const Points& x, const std::vector<EdgePair>& list);
  bool pattern_covers_active();
  void rebuild_pattern();
  PairBarrierParams pair_params() const { return {options_.dhat, options_.parallel_threshold}; }
};

/// One-shot collision detection: ContactPotential(topology, options).max_step(x, dx).
double max_step(const Points& x, const Points& dx, const CurveTopology& topology,
                const ContactOptions& options = {});

}  // namespace ek
