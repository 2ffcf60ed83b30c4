#pragma once
/// \file
/// JSON descriptions of the knots module's results (docs/cli.md): the
/// objects of `knots info --json` and `knots invariants --json`, without the
/// keys that name files (the command adds those).
#include "ek/core/json.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/table.hpp"

namespace ek {

/// `knots info`: name, crossing_number, bridge_index, braid_index,
/// unknotting_number, alternating, symmetry_type, dt, pd, braid,
/// braid_strands (null when unknown), alexander (coefficients, lowest degree
/// first), determinant, table (path of the table read). Computes the
/// polynomial (table_alexander).
Json knot_info_json(const KnotRecord& knot, const KnotTable& table);

/// `knots info` of a link of the link table: name, aliases, description,
/// components, crossing_number, braid, braid_strands, component_types
/// (knot table names), linking_numbers (m by m), conway (c_0, c_1, ...),
/// milnor_triple (null unless defined), table ("built-in links").
Json link_info_json(const LinkRecord& link);

/// `knots invariants` after `file`: vertices, length, alexander,
/// determinant, writhe, total_curvature, clearance.
Json invariants_json(const CurveInvariants& invariants);

/// `knots invariants` of a link after `file`: components (m), vertices (in
/// all), component (m objects as invariants_json), linking_numbers (m by m
/// integers), linking_error, component_clearance, conway (∇'s coefficients
/// c_0, c_1, ...; [] for a split link), milnor_triple (|μ̄(123)|, null
/// unless 3 components with vanishing linking numbers).
Json link_invariants_json(const LinkInvariants& invariants);

}  // namespace ek
