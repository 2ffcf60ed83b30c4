#pragma once
/// \file
/// JSON descriptions of the analysis results (docs/cli.md): the objects of
/// `knots similarity --json` and `knots attributes --json` without the keys
/// that name files (the command adds them first).
#include "ek/analysis/attributes.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/core/json.hpp"

namespace ek {

/// similarity, curvature_correlation, torsion_correlation, best_shift,
/// reversed, mirrored, samples, reverse_allowed, mirror_allowed.
Json similarity_json(const SimilarityResult& result, const SimilarityOptions& options);

/// vertices, one key per attribute_names() (null when not computed), radius,
/// young_modulus.
Json attributes_json(const Attributes& attributes, int vertices, const AttributeOptions& material);

}  // namespace ek
