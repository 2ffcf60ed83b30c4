#pragma once
/// \file
/// Joining two states of a transition graph by a chain of verified saddles
/// (paper Section 8.5: the transitions between stable states and the
/// barriers separating them are left open there).
///
/// A double-ended search between A and B (double_ended.hpp) on a rugged
/// landscape rarely finds one saddle whose two descents end in A and in B:
/// the saddles it finds usually join other minima, intermediate states on
/// the way. The approach of Wales' OPTIM / discrete path sampling for such
/// "missing connections" is to keep every saddle found, with the minima its
/// descents reach, as part of a growing graph of minima and transition
/// states, and to choose the next double-ended search by a shortest-path
/// calculation over every minimum known: a missing link between two minima
/// costs a growing function of their distance, a link already made by a
/// saddle costs nothing, and the first missing link on the cheapest route
/// from A to B is searched next. Searches between close minima succeed
/// more often, so the route prefers several short hops through
/// intermediate minima to one long jump. Here:
///
/// ~~~{.unparsed}
///   while minimax_path(g, a, b) is nullopt and attempts < max_searches:
///     weights on the complete graph of g's states: 0 for u, v joined by an
///       inter-state edge (either direction; an edge from == to joins two
///       minima of one state and is no step), d(u, v)² for a pair not tried
///       before (as {u, v}: either order counts), d the aligned RMS vertex
///       distance of align_vertices() [length] (pairs of different vertex
///       counts and tried pairs without an edge: no link; g.pairs, the
///       double-ended searches recorded in g before the call, count as
///       tried: the search is deterministic);
///     the least-weight path from a to b (Dijkstra); (u, v) = its first
///       missing link from a's side (while only a and b are known: a, b;
///       with the states C_a joined to a and C_b joined to b only, the
///       closest untried pair u ∈ C_a, v ∈ C_b);
///     transition_search(u, v) (an InputError — u or v not a stable
///     equilibrium — becomes the status Refused, "refused: <reason>"), and
///     add_pair(g, u, v, ...): its verified saddle joins u and v, and its
///     other saddles join the states their minima match (at `threshold`),
///     new minima become new states of g (and candidates for later links).
/// ~~~
///
/// The loop also ends when no path with an untried link is left
/// (Exhausted). When a and b are joined, the chain is minimax_path(g, a, b)
/// (the path whose highest saddle is lowest) and its barrier, seen from a, is
///     ΔE_a = max_{e ∈ chain} E_saddle(e) − E_a,   ΔE_b = max E_saddle − E_b,
/// E_a, E_b the energies stored in g.states. Every edge's own barriers (from
/// the minima its descents reached) are positive, but ΔE_a or ΔE_b can be
/// negative: a chain may enter a state at a minimum that matches it
/// (similarity >= threshold) and lies lower than the state's stored energy
/// (a cluster's representative, the lowest member the data set has, need
/// not be the lowest minimum of the cluster). Every saddle of g passed the
/// checks of saddles.hpp (index one, gradient, two converged-stable
/// descents, the knot type kept), so the chain is a sequence of verified
/// saddles through intermediate states, not one continuous path (see
/// chain_profile()).
///
/// When a and b stay apart, the steered chain of a search between a and b
/// themselves that reached b (TransitionSearch::path_barrier, the highest
/// accepted iterate along a path whose steps the CCD cleared) bounds the
/// barrier of the best a–b path from above: upper_bound is the lowest such
/// value over the attempts (u, v) = {a, b}; absent when none reached.
#include <optional>
#include <string>
#include <vector>

#include "ek/transitions/double_ended.hpp"
#include "ek/transitions/graph.hpp"

namespace ek {

/// The search budget and the double-ended searches' options of
/// connect_states().
struct ConnectOptions {
  int max_searches = 6;             ///< [1] double-ended searches at most (>= 1)
  /// The double-ended searches' options (the model is its saddle.relax).
  TransitionSearchOptions search;
  void validate() const;            ///< InputError for impossible values
};

/// One double-ended search of connect_states().
struct ConnectAttempt {
  ///@{
  /// States searched from (u) and towards (v).
  int u = -1, v = -1;
  ///@}
  double distance = 0.0;            ///< [length] aligned RMS vertex distance of u and v
  SearchStatus status;              ///< transition_search()'s, or Refused (search_pair())
  bool reached = false;             ///< the steered chain reached v
  double path_barrier = 0.0;        ///< [energy] highest chain iterate − E_u (when reached; else 0)
  int edges_added = 0;              ///< [1] inter-state edges the search added to the graph
  int states_added = 0;             ///< [1] new states (minima no state matched)
  double seconds = 0.0;             ///< [s]
};

/// What connect_states() returns: whether a chain of verified saddles joins the
/// two states, its barriers, and every search it ran.
struct ConnectResult {
  bool connected = false;           ///< a chain of verified saddles joins a and b
  /// Connected, Budget (max_searches spent), Exhausted (no untried pair)
  ConnectStatus status = ConnectStatus::Budget;
  int attempts = 0;                 ///< [1] double-ended searches run (<= max_searches)
  std::vector<int> chain;           ///< edges of g from a to b (minimax_path()); empty unless connected
  double barrier_forward = 0.0;     ///< [energy] highest saddle on the chain − E_a (when connected)
  double barrier_backward = 0.0;    ///< [energy] highest saddle on the chain − E_b (when connected)
  double barrier_forward_scaled = 0.0;   ///< [1] barrier_forward / g.energy_scale
  double barrier_backward_scaled = 0.0;  ///< [1] barrier_backward / g.energy_scale
  /// [energy] when not connected: the lowest steered-chain path_barrier of
  /// the searches between a and b that reached b (an upper-bound estimate of
  /// the barrier, no saddle); absent when none reached
  std::optional<double> upper_bound;
  std::optional<double> upper_bound_scaled;  ///< [1] upper_bound / g.energy_scale
  std::vector<ConnectAttempt> attempt_list;  ///< in order
  double seconds = 0.0;             ///< [s]
};

/// The states joined to `state` by inter-state edges of g (itself
/// included), by increasing index.
std::vector<int> connected_states(const TransitionGraph& g, int state);

/// Joins states a and b of g (see the file comment); g grows by the searches'
/// pairs, saddles, edges and states. `rest` [length], one rest length per
/// edge of the curves (their vertex count). Throws std::invalid_argument when
/// a == b or either is not a state of g, InputError for invalid options.
ConnectResult connect_states(TransitionGraph& g, int a, int b, const VecX& rest, const ConnectOptions& options,
                             const CurveSimilarity& similarity, double threshold);

}  // namespace ek
