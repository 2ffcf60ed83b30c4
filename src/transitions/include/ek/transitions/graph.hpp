#pragma once
/// \file
/// The transition graph of a knot's stable states (paper Section 8.5):
/// nodes are states with their energies (the data set's clusters at a cut,
/// represented by their lowest-energy member, and minima that the descents
/// reached and no cluster matches), edges are verified saddles with the
/// barrier seen from each side, and the path between two states that
/// minimises the highest saddle on it (a minimax, or bottleneck, path).
///
/// Saddles come from the single-ended searches of each state (saddles.hpp:
/// the far minimum is matched to the most similar state at similarity >=
/// 1 − cut, or added as a new state) and from double-ended searches between
/// two states (double_ended.hpp: verified only when its descents reach both).
/// An edge whose ends are one state (from == to: the far minimum is another
/// minimum of the same cluster) is kept: inter_state() tells them apart.
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"
#include "ek/transitions/double_ended.hpp"
#include "ek/transitions/saddles.hpp"

namespace ek {

/// A node of the transition graph: a stable state of the knot (see the file's
/// description).
struct TransitionState {
  int cluster = -1;        ///< cluster rank at the cut (-1: a state the data set does not have)
  int equilibrium = -1;    ///< the representative's row in the data set (-1: new)
  double energy = 0.0;     ///< [energy] after the polish (new states: the descent's minimum)
  Points positions;        ///< n by 3
};

/// The single-ended searches from one state.
struct StateSearches {
  int state = -1;                      ///< index in TransitionGraph::states
  double energy = 0.0;                 ///< [energy] the start after the polish
  std::vector<SaddleRecord> records;   ///< find_knot_saddles() (images dropped once in the graph)
  double seconds = 0.0;                ///< [s]
  std::string error;                   ///< non-empty when the start was refused (not stable)
};

/// One double-ended search between two states (its summary).
struct PairSearch {
  ///@{
  /// The two states (indices in TransitionGraph::states), A and B.
  int a = -1, b = -1;
  ///@}
  SearchStatus status;                 ///< transition_search()'s, or Refused (search_pair())
  std::vector<SearchStatus> seed_statuses;  ///< each seed search's status, in order
  bool reached = false;                ///< the steered chain reached B
  bool verified = false;               ///< status is Verified
  int stages = 0;                      ///< [1] steering stages run
  double path_barrier = 0.0;           ///< [energy] highest chain image − E_A (when reached)
  double reached_similarity = 0.0;     ///< [1] chain end to B
  double saddle_energy = 0.0;          ///< [energy] the seed's search result (0 when none ran)
  int saddle = -1;                     ///< the graph's saddle (verified), else -1
  double seconds = 0.0;                ///< [s]
};

/// A verified saddle of the graph, with the minimum energy path through it.
struct TransitionSaddle {
  double energy = 0.0;               ///< [energy]
  double negative_eigenvalue = 0.0;  ///< [energy/length²]
  double second_eigenvalue = 0.0;    ///< [energy/length²]
  int index = 1;                     ///< [1]
  double gradient_norm = 0.0;        ///< [energy/length]
  ///@{
  /// States (from: searched, or A; to: the other minimum's, or B).
  int from = -1, to = -1;
  ///@}
  /// [energy] the minimum the descent on the `from` side reached (single-ended: the state)
  double energy_from = 0.0;
  double energy_to = 0.0;            ///< [energy] the minimum the descent on the `to` side reached
  bool double_ended = false;         ///< found by a double-ended search
  Points positions;                  ///< n by 3
  std::vector<Points> path;          ///< images from `from` over the saddle to `to`
  std::vector<double> path_energies; ///< [energy]
  int saddle_image = 0;              ///< the saddle's position in `path`
};

/// An edge of the graph: two states joined through a verified saddle (equal
/// when both descents reach the same state).
struct TransitionEdge {
  ///@{
  /// The states joined (indices in TransitionGraph::states) and the saddle
  /// (index in TransitionGraph::saddles).
  int from = -1, to = -1, saddle = -1;
  ///@}
  double energy = 0.0;                 ///< [energy] of the saddle
  double barrier_forward = 0.0;        ///< [energy] E_saddle − the energy of the minimum reached on the `from` side
  double barrier_backward = 0.0;       ///< [energy] E_saddle − the energy of the minimum reached on the `to` side
};

/// An edge between two different states.
inline bool inter_state(const TransitionEdge& e) { return e.from != e.to; }

/// The transition graph of one knot: its states, the verified saddles and the
/// edges through them, and the searches that found them.
struct TransitionGraph {
  std::string knot;                    ///< the knot's name
  double cut = 0.0;                    ///< [1] clustering cut
  double energy_scale = 1.0;           ///< [energy] EI / L
  std::vector<TransitionState> states;   ///< the nodes: the data set's states, then states the descents found
  std::vector<TransitionSaddle> saddles;  ///< every distinct verified saddle
  std::vector<TransitionEdge> edges;   ///< one per saddle
  /// the single-ended searches, one entry per searched state, in the order added
  std::vector<StateSearches> searches;
  std::vector<PairSearch> pairs;       ///< the double-ended searches, in order
};

/// Assigns a curve to a state: the index of the most similar state when its
/// similarity is at least `threshold`, else -1.
int match_state(const std::vector<TransitionState>& states, const Points& x, const CurveSimilarity& similarity,
                double threshold);

/// Adds one state's searches: every distinct verified saddle becomes a
/// saddle and an edge (a saddle already in the graph — energy within 1e-8
/// relative, similarity >= 0.99 — is not added twice); the minimum at the far
/// side is matched to a state at `threshold` or appended as a new state.
void add_searches(TransitionGraph& graph, StateSearches searches, const CurveSimilarity& similarity, double threshold);

/// Adds one double-ended search between states a and b: its summary, when
/// verified (and not already in the graph) its saddle and the edge a–b, and
/// its other saddles (TransitionSearch::other_saddles: each minimum matched
/// to a state at `threshold` or appended as a new one) as edges between the
/// states their descents reached.
void add_pair(TransitionGraph& graph, int a, int b, const TransitionSearch& search, const CurveSimilarity& similarity,
              double threshold);

/// transition_search() between states a and b of the graph (rest lengths
/// `rest`), added by add_pair(); an InputError of the search (a or b not a
/// stable equilibrium) becomes its status Refused with the error's message
/// ("refused: <reason>"). Returns the
/// search (its status, reached, path_barrier).
TransitionSearch search_pair(TransitionGraph& graph, int a, int b, const VecX& rest,
                             const TransitionSearchOptions& options, const CurveSimilarity& similarity,
                             double threshold);

/// The path from state a to state b whose highest saddle is lowest (edges
/// in order; empty when a == b); nullopt when no chain of edges joins them.
std::optional<std::vector<int>> minimax_path(const TransitionGraph& graph, int a, int b);

/// The energy profile and images along a chain of edges from state a: each
/// edge's path, reversed when traversed from its `to` side. Consecutive
/// paths meet at minima of one state (the same cluster), not always at one
/// curve: a chain is a sequence of verified saddles, not one continuous path.
void chain_profile(const TransitionGraph& graph, int a, const std::vector<int>& edges, std::vector<Points>& images,
                   std::vector<double>& energies, std::vector<int>& saddle_images);

}  // namespace ek
