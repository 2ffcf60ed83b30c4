#pragma once
/// \file
/// JSON descriptions of data-set results (docs/cli.md): the objects of
/// `knots cluster --json`, `knots query --json` and `knots describe --json`
/// (the latter without the key `file`, which the command adds first).
#include <string>
#include <vector>

#include "ek/core/json.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/dataset/query.hpp"

namespace ek {

/// name, cut, equilibria (count), clusters: [{size, representative,
/// energy_min, energy_max, members}] in the order given (clusters_at_cut():
/// by energy).
Json clusters_json(const std::string& name, double cut, int equilibria, const std::vector<StateCluster>& clusters);

/// {samples, found, estimated, lower, upper (95%), new_state_probability,
/// good_turing}: an estimate of the states not seen yet (unseen.hpp).
Json unseen_json(const UnseenEstimate& estimate);

/// The states of a knot's entry at `cut` and what they leave unseen
/// (prefix_unseen() of every sample): unseen and unseen_low_energy (the
/// states within kLowEnergyFactor of the lowest energy), as unseen_json.
Json entry_unseen_json(const KnotEntry& entry, double cut);
/// `knots cluster --json` of an entry: clusters_json of clusters_at_cut with
/// entry_unseen_json's keys after them.
Json entry_clusters_json(const KnotEntry& entry, double cut);
/// One line of the same: "D states found at cut C (estimated S, L–U; next
/// sample new P, new and within 1.1 of the lowest energy Q)".
std::string entry_unseen_text(const KnotEntry& entry, double cut);

/// rows: [{knot, index, one key per column}], count.
Json query_json(const QueryResult& result);

/// parameters (DatasetMetadata::json(): attribute name -> value, null when
/// not recorded), knots (names in table order).
Json describe_json(const DatasetReader& reader);

/// A ledger (`knots describe LEDGER --json`): parameters (as describe_json),
/// provenance {cut, commit, created, source, cores, jobs, wall_seconds,
/// cpu_seconds; null when not recorded}, knots: [{name, crossing_number,
/// bridge_index, braid_index, samples_used, stable, statuses {status:
/// count}, run_seconds, equilibria, unseen and unseen_low_energy (the
/// estimates of ledger_unseen over every state and over the states within
/// kLowEnergyFactor of the lowest energy: {samples, found, estimated, lower,
/// upper (95%), new_state_probability, good_turing}), states: [{members,
/// representative, and per attribute {value (the representative's), min,
/// median, max}}]}].
Json ledger_json(const Ledger& ledger);

/// The ledger's totals (`knots describe LEDGER --summary`): knots, links,
/// equilibria, states, runs, statuses {status: count}, the provenance's
/// wall and CPU seconds (null when not recorded), estimated_states (the
/// sum of the knots' Chao1 estimates), median_new_state_probability and
/// median_new_low_energy_state_probability over the knots (ledger_unseen;
/// absent for a ledger without states), and for knots (links left
/// out) the sampling cost against 500 samples per knot (sampling_cost.hpp):
/// median_samples, mean_samples, max_samples, knots_at_500,
/// stopped_before_500_share, saving_vs_500,
/// run_core_seconds, by_crossing_number [{crossing_number, knots,
/// median_samples, mean_samples, seconds_per_run, mean_states}].
Json ledger_summary_json(const Ledger& ledger);

/// The same as text: the parameters, the provenance, and one line per knot
/// (samples, stable runs, states with their estimated number, its 95%
/// interval and the next sample's chance of a new state, the lowest state's
/// energy), then with
/// `states` one line per state (members, energy of the representative and
/// its spread).
std::string ledger_text(const Ledger& ledger, bool states);

/// The data set's equilibrium closest to x (n by 3; ICP after the
/// pre-filter, as `knots search`): knot, index, distance; null without a
/// reader or a hit (`knots load --dataset`'s matches).
Json closest_equilibrium_json(const DatasetReader* reader, const Points& x);

}  // namespace ek
