#pragma once
// summary.json of exp_transitions (docs/results.md, "transitions"): the
// transition graph of 4_1's stable states (paper Section 8.5, an open
// direction): single-ended searches from each state and double-ended
// searches between states of neighbouring energy.
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// One edge of 4_1's transition graph (edges.csv has them all).
struct TransitionEdgeSummary {
  int from = -1, to = -1;             ///< states (rows of states.csv)
  bool inter_state = false;           ///< from != to (else two minima of one state)
  bool double_ended = false;          ///< found by a double-ended search
  double saddle_energy = 0.0;         ///< [energy]
  double barrier_forward = 0.0;       ///< [energy] E_saddle − E_from
  double barrier_backward = 0.0;      ///< [energy] E_saddle − the minimum reached on the `to` side
  double barrier_forward_scaled = 0.0;   ///< [1] divided by EI/L
  double barrier_backward_scaled = 0.0;  ///< [1]
};
EK_JSON_FIELDS(TransitionEdgeSummary, from, to, inter_state, double_ended, saddle_energy, barrier_forward,
               barrier_backward, barrier_forward_scaled, barrier_backward_scaled)

/// One double-ended search (pairs.csv).
struct PairSummary {
  int a = -1, b = -1;                 ///< states
  std::string status;                 ///< transition_search()'s
  std::string seed_statuses;          ///< each seed search's status, separated by ";"
  bool reached = false;               ///< the steered chain reached B
  bool verified = false;              ///< a verified saddle joins A and B
  int stages = 0;                     ///< [1] steering stages
  double path_barrier_scaled = 0.0;   ///< [1] highest chain image − E_A over EI/L (when reached)
  double seconds = 0.0;               ///< [s]
};
EK_JSON_FIELDS(PairSummary, a, b, status, seed_statuses, reached, verified, stages, path_barrier_scaled, seconds)

struct TransitionsSummary {
  std::string scale;
  std::string knot;                   ///< "4_1"
  double cut = 0.0;                   ///< [1] kClusterCut
  int modes = 0;                      ///< [1] soft modes searched per state (both directions)
  int states = 0;                     ///< [1] 4_1's states (clusters of the multistability data set)
  int states_searched = 0;            ///< [1] of them, searched from (lowest energy first)
  int states_refused = 0;             ///< [1] of those, starts that were not stable (no search)
  int new_states = 0;                 ///< [1] minima reached that match no cluster
  int searches = 0;                   ///< [1] single-ended searches
  int verified = 0;                   ///< [1] of them, ending in a verified saddle
  int saddles = 0;                    ///< [1] distinct verified saddles in the graph
  int edges = 0;                      ///< [1]
  int inter_state_edges = 0;          ///< [1] edges between two different states
  int pairs = 0;                      ///< [1] double-ended searches
  int pairs_reached = 0;              ///< [1] of them, whose chain reached B
  int pairs_verified = 0;             ///< [1] of them, with a verified saddle joining A and B
  double seconds_per_search = 0.0;    ///< [s] mean wall time of a single-ended search and its checks
  double seconds_per_pair = 0.0;      ///< [s] mean wall time of a double-ended search
  double energy_scale = 0.0;          ///< [energy] EI/L
  std::vector<TransitionEdgeSummary> edge_list;
  std::vector<PairSummary> pair_list;
  /// [1] puzzle pairs (../puzzles/puzzles.csv) that connect_states() was
  /// run on (puzzle_barriers.csv)
  int puzzle_pairs = 0;
  int puzzles_connected = 0;  ///< [1] of them, joined by a chain of verified saddles
  /// [1] of the double-ended pairs (pair_list), those joined by a chain of
  /// the graph's edges (graph_pairs.csv)
  int graph_pairs_connected_before = 0;
  /// [1] of them, joined after connect_states() on the grown graph
  /// (transitions_4_1_connected.h5)
  int graph_pairs_connected_after = 0;
  double seconds = 0.0;               ///< [s] the whole run
};
EK_JSON_FIELDS(TransitionsSummary, scale, knot, cut, modes, states, states_searched, states_refused, new_states,
               searches, verified, saddles, edges, inter_state_edges, pairs, pairs_reached, pairs_verified,
               seconds_per_search, seconds_per_pair, energy_scale, edge_list, pair_list, puzzle_pairs, puzzles_connected,
               graph_pairs_connected_before, graph_pairs_connected_after, seconds)

}  // namespace ek::results
