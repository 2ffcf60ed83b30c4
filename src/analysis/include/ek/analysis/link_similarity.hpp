#pragma once
/// \file
/// Similarity of two links of the same number of components: the
/// curvature-torsion similarity of their components (similarity.hpp, paper
/// Section 7.1) under the best pairing of components.
///
/// Definition. With S_ij the similarity of component i of A and component j
/// of B (options as for curves: `reversal` lets each pair be compared with
/// B_j's orientation reversed), the link similarity is
///
/// ~~~{.unparsed}
///   S(A, B) = max_π (1/m) Σ_i S_{i π(i)}
/// ~~~
///
/// over the bijections π of the m components. With `mirror`, B's mirror image
/// is compared too, as a whole (every component mirrored at once, never some
/// of them), and the better of the two is taken. S is 1 for a link and
/// itself, invariant under rigid motions, cyclic re-indexing of each
/// component and renumbering of the components.
///
/// The components' shapes do not see how they sit relative to each other;
/// `placement` reports that apart, not folded into S: under the best pairing,
/// the largest difference between the two links' distances of component
/// centroids, each divided by that link's mean component length.
#include <vector>

#include "ek/analysis/similarity.hpp"
#include "ek/geometry/link.hpp"

namespace ek {

/// What compare_links() returns: the link similarity, the best pairing of
/// components and each pair's curve similarity.
struct LinkSimilarityResult {
  double similarity = 0.0;                 ///< [1] S(A, B) in [0, 1]
  std::vector<int> pairing;                ///< component i of A is paired with pairing[i] of B
  std::vector<SimilarityResult> components;  ///< per component of A, against its partner
  bool mirrored = false;                   ///< the best pairing is with B's mirror image
  double placement = 0.0;                  ///< [1] largest difference of relative centroid distances
};

/// Compares links A and B (validate_link). Throws InputError when their
/// numbers of components differ or exceed 8 (the pairing is searched over
/// all m! bijections).
LinkSimilarityResult compare_links(const Link& a, const Link& b, const SimilarityOptions& options = {});

}  // namespace ek
