#pragma once
/// \file
/// The transitions file (HDF5; docs/dataset-format.md, "Transitions file"):
///
/// ~~~{.unparsed}
///   /   attributes: format = "elastic-knots-transitions", format_version = 1,
///       knot, dataset (the source file), cut, energy_scale [energy] (EI/L),
///       options (the search options' text), complete (0/1),
///       states_searched (states whose single-ended searches are in the file;
///       optional: left out when not recorded, as in the experiment's files)
///   states/      energy float64 [s], cluster int64 [s] (-1: not in the data set),
///                equilibrium int64 [s] (-1: new), positions float64 [s, n, 3]
///   saddles/     energy, negative_eigenvalue, second_eigenvalue, gradient_norm float64 [k],
///                energy_from, energy_to float64 [k] (the minima the descents reached),
///                index, from, to, saddle_image, double_ended int64 [k], positions float64 [k, n, 3],
///                path_<j>/ images float64 [p, n, 3], energies float64 [p]
///   edges/       from, to, saddle int64 [e], energy, barrier_forward, barrier_backward,
///                barrier_forward_scaled, barrier_backward_scaled float64 [e]
///   searches/    state, mode, direction, verified, index, iterations int64 [m],
///                status string [m] (to_string(SearchStatus), or "start-refused: <error>"),
///                energy, gradient_norm, seconds float64 [m]
///   pairs/       a, b, reached, verified, stages, saddle int64 [q] (-1: none),
///                status, seed_statuses string [q] (to_string() of the status and of
///                the seeds' list), path_barrier, reached_similarity,
///                saddle_energy, seconds float64 [q] (double-ended searches)
/// ~~~
///
/// Every attribute and column is described once, in the tables of
/// transitions_file.cpp, which the writer and the reader both walk. Written
/// to a temporary name and renamed into place. A run of `knots transitions`
/// checkpoints its graph in this format (complete = 0) after every state's
/// searches and every double-ended search.
///
/// Version policy: the reader accepts format_version 1 only; a file of
/// another version is one InputError line naming the file and both
/// versions. Every column and every other attribute is required.
#include <string>

#include "ek/transitions/graph.hpp"

namespace ek {

/// The attributes of a transitions file besides the graph.
struct TransitionsFileInfo {
  std::string dataset;       ///< the source data set, as given to the run
  std::string options;       ///< the search options' text (transition_run_key())
  bool complete = true;      ///< false: a checkpoint of an unfinished run
  int states_searched = -1;  ///< [1] states whose searches the file holds (-1: not recorded)
};

/// Writes the graph; `dataset` and `options` are recorded as attributes,
/// and `states_searched` when it is >= 0.
void write_transitions(const std::string& path, const TransitionGraph& graph, const std::string& dataset,
                       const std::string& options, bool complete, int states_searched = -1);
/// Reads a transitions file (InputError naming the file for any problem:
/// another format version, a missing attribute or column (named
/// "group/column"), columns of different lengths, an unknown status), the
/// searches included (one StateSearches per state with rows, its records
/// holding the columns of searches/; a "start-refused: " row becomes its
/// error). `options` (optional) receives the recorded options text.
TransitionGraph read_transitions(const std::string& path, std::string* options = nullptr);
/// The same, with every attribute in `info`.
TransitionGraph read_transitions(const std::string& path, TransitionsFileInfo& info);

/// A path as HDF5: attributes format = "elastic-knots-path", format_version = 1,
/// knot; images float64 [p, n, 3], energies float64 [p] (the columns of a
/// saddle's path_<j> group), saddle_images int64 [s].
void write_path_h5(const std::string& path, const std::string& knot, const std::vector<Points>& images,
                   const std::vector<double>& energies, const std::vector<int>& saddle_images);

}  // namespace ek
