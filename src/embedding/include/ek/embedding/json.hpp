#pragma once
/// \file
/// JSON description of an embedding: the object of `knots embed --json`
/// (docs/cli.md).
#include <optional>
#include <string>

#include "ek/core/json.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/knots/conway.hpp"

namespace ek {

/// name, from (the embedding's method), output (when given), vertices,
/// edge_length, max_edge_deviation, clearance, alexander (null unless the
/// embedding was verified).
Json embedding_json(const std::string& name, const Embedding& embedding,
                    const std::optional<std::string>& output = std::nullopt);

/// A link's embedding (`knots embed --json` of a link): name, from, components,
/// vertices (all components), edge_length, max_edge_deviation,
/// linking_numbers (m by m), conway (the Conway polynomial of the polygons,
/// given), output (when given).
Json link_embedding_json(const std::string& name, const std::string& from, const LinkEmbedding& embedding,
                         const ConwayPolynomial& conway, const std::optional<std::string>& output = std::nullopt);

}  // namespace ek
