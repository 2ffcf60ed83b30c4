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
Embedding finish_embedding(const Points& dense, const EmbeddingOptions& options, EmbeddingMethod method,
                           const AlexanderPolynomial* expected);

/// The link of dense closed polylines: about options.vertices vertices in
/// all, shared in proportion to the components' lengths (at least 4 each),
/// every component's edges equal, all scaled together so that the mean edge
/// is options.edge_length; checked for touching components (validate_link).
/// `method` names the embedding in messages. linking_numbers is left empty.
LinkEmbedding finish_link_embedding(const std::vector<Points>& dense, const EmbeddingOptions& options,
                                    const std::string& method);

}  // namespace ek
