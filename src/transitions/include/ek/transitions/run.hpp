#pragma once
/// The transition graph of one knot of a data set (`knots transitions`, the
/// transitions experiment; paper Section 8.5). The representative of every
/// cluster at the cut (clusters_at_cut(), by increasing energy) is a state;
/// from each of the first `max_states` states, find_knot_saddles() (the
/// single-ended searches); then transition_search() (double-ended) for the
/// pairs of those states whose energy ranks differ by at most `pair_gap`
/// (i, i+1, ..., i+pair_gap: each state to its nearest states in energy),
/// at most `max_pairs` of them, in the order (0,1), (0,2), ..., (1,2), ...;
/// add_searches() and add_pair() join the results into the graph. Not
/// resumable: an interrupted run starts again.
#include <functional>
#include <string>
#include <vector>

#include "ek/dataset/dataset_file.hpp"
#include "ek/transitions/double_ended.hpp"
#include "ek/transitions/graph.hpp"

namespace ek {

struct TransitionRunOptions {
  double cut = 0.05;              ///< [1] clustering cut of the states (the experiments' cut)
  KnotSaddleOptions saddles;      ///< modes, search options (the model comes from the data set)
  /// The double-ended searches' options (their `saddle` is replaced by `saddles` with the data set's model).
  TransitionSearchOptions pair;
  int max_states = 0;             ///< [1] states searched from, lowest energy first (0: every state)
  int pair_gap = 1;               ///< [1] double-ended searches between states whose ranks differ by <= this (0: none)
  int max_pairs = 8;              ///< [1] double-ended searches at most
  /// Called before each unit of work with a line that names it.
  std::function<void(const std::string&)> progress;
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

/// The graph of `entry` (a knot of a data set with `metadata`).
TransitionGraph knot_transitions(const KnotEntry& entry, const DatasetMetadata& metadata,
                                 const TransitionRunOptions& options);

}  // namespace ek
