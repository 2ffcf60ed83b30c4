#pragma once
/// \file
/// JSON description of an embedding: the object of `knots embed --json`
/// (docs/cli.md).
#include <optional>
#include <string>

#include "ek/core/json.hpp"
#include "ek/embedding/embedding.hpp"

namespace ek {

/// name, from (the embedding's method), output (when given), vertices,
/// edge_length, max_edge_deviation, clearance, alexander (null unless the
/// embedding was verified).
Json embedding_json(const std::string& name, const Embedding& embedding,
                    const std::optional<std::string>& output = std::nullopt);

}  // namespace ek
