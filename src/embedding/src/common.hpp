#pragma once
// Private helpers shared by the embeddings.
#include <string>

#include "ek/embedding/embedding.hpp"
#include "ek/knots/polynomial.hpp"

namespace ek {

/// Throws InputError for impossible options.
void validate(const EmbeddingOptions& options);

/// Resamples a dense closed polyline to options.vertices equal edges scaled
/// to options.edge_length, measures the clearance and, when options.verify,
/// checks the Alexander polynomial against `expected`.
Embedding finish_embedding(const Points& dense, const EmbeddingOptions& options, const std::string& method,
                           const AlexanderPolynomial* expected);

}  // namespace ek
