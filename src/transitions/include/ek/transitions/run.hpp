#pragma once
/// \file
/// The transition graph of one knot of a data set (`knots transitions`, the
/// transitions experiment; paper Section 8.5). The representative of every
/// cluster at the cut (clusters_at_cut(), by increasing energy) is a state;
/// from each of the first `max_states` states, find_knot_saddles() (the
/// single-ended searches); then transition_search() (double-ended) for the
/// pairs of those states whose energy ranks differ by at most `pair_gap`
/// (i, i+1, ..., i+pair_gap: each state to its nearest states in energy),
/// at most `max_pairs` of them, in the order (0,1), (0,2), ..., (1,2), ...;
/// add_searches() and add_pair() join the results into the graph, one unit
/// (a state's searches, a double-ended search) at a time. Resumable: after
/// every unit `checkpoint` receives the graph so far, and a run given that
/// graph back (`resume`) goes on with the next unit; the result equals an
/// uninterrupted run's (the units do not depend on each other's results).
#include <functional>
#include <string>
#include <vector>

#include "ek/dataset/dataset_file.hpp"
#include "ek/transitions/double_ended.hpp"
#include "ek/transitions/graph.hpp"

namespace ek {

/// What knot_transitions() searches: the cut, the single-ended and
/// double-ended searches' options and limits, and the progress and checkpoint
/// callbacks.
struct TransitionRunOptions {
  double cut = 0.05;              ///< [1] clustering cut of the states (the experiments' cut)
  KnotSaddleOptions saddles;      ///< modes, search options (the model comes from the data set)
  /// The double-ended searches' options (their `saddle` is replaced by `saddles` with the data set's model).
  TransitionSearchOptions pair;
  int max_states = 0;             ///< [1] states searched from, lowest energy first (0: every state)
  int pair_gap = 1;               ///< [1] double-ended searches between states whose ranks differ by <= this (0: none)
  int max_pairs = 8;              ///< [1] double-ended searches at most
  /// Called before each unit of work with a line that names it, the units
  /// done (resumed ones included) and the run's units in all.
  std::function<void(const std::string& what, int done, int total)> progress;
  /// Called after each unit with the graph so far and the number of states
  /// searched from (`knots transitions` writes it as a checkpoint).
  std::function<void(const TransitionGraph& graph, int states_searched)> checkpoint;
  void validate() const;          ///< InputError for impossible values
};

/// The relaxation model of a data set (material, contact, tolerance,
/// iteration cap from its metadata). InputError unless twist-free.
RelaxOptions dataset_model(const DatasetMetadata& metadata);

/// The similarity used to compare states of `knot`: orientation reversal,
/// and the mirror image when the knot table lists the knot as amphicheiral.
CurveSimilarity knot_similarity(const std::string& knot);

/// The text that identifies a run's options (recorded in the transitions file).
std::string transition_run_key(const std::string& knot, const TransitionRunOptions& options, double rest_length);

/// The double-ended pairs (a < b, state indices) of `states` states.
std::vector<std::pair<int, int>> transition_pairs(int states, const TransitionRunOptions& options);

/// A run's checkpoint: the graph after `states_searched` states' searches and
/// graph.pairs.size() double-ended searches.
struct TransitionResume {
  TransitionGraph graph;    ///< the graph so far
  int states_searched = 0;  ///< [1]
};

/// The graph of `entry` (a knot of a data set with `metadata`), from
/// `resume` on when given: InputError when the checkpoint does not belong to
/// this knot's states (its first states must be the clusters' representatives,
/// its pairs the first of transition_pairs()).
TransitionGraph knot_transitions(const KnotEntry& entry, const DatasetMetadata& metadata,
                                 const TransitionRunOptions& options, const TransitionResume* resume = nullptr);

}  // namespace ek
