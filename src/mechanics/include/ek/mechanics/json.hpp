#pragma once
/// \file
/// JSON descriptions of the mechanics' results (docs/cli.md). A knot under
/// load (`knots load`): the
/// summary's keys without those that name files (the command adds `input`
/// first and `output` before `seconds`); the Python module's load() returns
/// the same keys.
#include <vector>

#include "ek/core/json.hpp"
#include "ek/mechanics/dynamics.hpp"
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

/// A run of the dynamics (`knots dynamics`, docs/cli.md): model, link (null
/// twist-free), time_step, duration, density, damping, gravity, friction,
/// friction_velocity, envelope (null or its half_thickness), envelope_speed,
/// status, failed_status (null unless step-failed), steps, time, rest_time
/// (null unless at rest), frames, newton_iterations, max_speed,
/// max_kinetic, start_energy and end_energy (elastic), start_threedim,
/// end_threedim, max_threedim (over the frames), dissipated (the total
/// energy lost: kinetic + elastic + gravity at the start less at the end),
/// alexander_preserved, end_match (given: closest_equilibrium_json() of the
/// data-set module, or null), seconds.
Json dynamics_json(const DynamicsOptions& options, const DynamicsResult& result, const Json& end_match,
                   double seconds);

}  // namespace ek
