#pragma once
/// \file
/// JSON descriptions of the solver's results (docs/cli.md): the objects of
/// `knots energy --json` and `knots relax --json` without the keys that name
/// files (the command adds `file` first, and `output` and `trace` last).
#include <string>

#include "ek/core/json.hpp"
#include "ek/optim/newton.hpp"
#include "ek/solver/energy.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// energy, energy_stretch, energy_bend, energy_twist, energy_contact, energy_slab.
Json energy_parts_json(const EnergyParts& energy);

/// A solver report: status, iterations, seconds, gradient_norm,
/// saddle_escapes, marginal, symbolic_factorizations,
/// numeric_factorizations, failed_factorizations, line_search_trials,
/// time_assembly, time_factorization, time_collision, time_line_search,
/// time_eigen.
Json newton_report_json(const NewtonReport& report);

/// `knots energy`: vertices, model, energy, energy_stretch, energy_bend,
/// energy_twist, energy_contact, gradient_norm, contacts, twist, writhe, link.
Json curve_energy_json(const CurveEnergy& energy);

/// `knots relax`: status, converged, stable, iterations, total_iterations,
/// seconds, the energy parts, gradient_norm, contacts, min_distance, link,
/// twist, writhe, alexander_preserved, alexander, model, vertices,
/// smallest_eigenvalue, method (`method`, the name given to with_method()),
/// phases, report; coarse_reports and coarse_vertices (multilevel),
/// continuation_reports (with continuation), slab_report and slab_energy
/// (after a release) when they apply.
Json relax_json(const RelaxResult& result, const std::string& method);

/// `knots relax` on a link (a relax() result of several components, its
/// link_type set): components, vertices, status, iterations and seconds (of
/// the solve at ω), energy (the total), gradient_norm, min_distance (null when no pair is
/// within reach of the contact), alexander (each component's, of the
/// input), linking_numbers (of the input), alexander_preserved,
/// linking_preserved, conway (the input link's ∇, conway.hpp),
/// conway_preserved.
Json link_relax_json(const RelaxResult& result);

}  // namespace ek
