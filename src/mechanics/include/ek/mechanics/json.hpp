#pragma once
/// \file
/// JSON description of a knot under load (docs/cli.md, `knots load`): the
/// summary's keys without those that name files (the command adds `input`
/// first and `output` before `seconds`); the Python module's load() returns
/// the same keys.
#include <vector>

#include "ek/core/json.hpp"
#include "ek/mechanics/knot_loading.hpp"

namespace ek {

/// load, parameter, from, to, vertices (null for plates), normal (null
/// unless plates), pull_stiffness (null unless pull), status, points,
/// start_energy, end_energy and end_parameter (null for a path without a
/// point), work, dissipated, alexander_preserved, start_match, snaps (each:
/// point, parameter, reaction, jump, energy_drop, loaded_energy,
/// released_status, released_energy, released_match), seconds. The matches
/// are given (closest_equilibrium_json() of the data-set module, or null):
/// the start's and one per snap.
Json knot_load_json(const KnotLoadOptions& options, const KnotLoadResult& result, const Json& start_match,
                    const std::vector<Json>& released_matches);

}  // namespace ek
