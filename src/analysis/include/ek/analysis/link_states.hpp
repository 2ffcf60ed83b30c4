#pragma once
/// \file
/// States of a link: when two equilibria of one link type are the same
/// state. This is the comparison that a link's data set clusters on
/// (dataset/pipeline.hpp). The paper's data sets hold knots only. Its
/// Section 8.5 extends the simulation to links but defines no comparison,
/// so the definition below is ours.
///
/// Why not the curvature-torsion similarity of the components
/// (link_similarity.hpp). Components of links with few crossings are
/// nearly planar rings, and the torsion of a nearly planar ring is rounding
/// noise; one such ring against another then scores anywhere in [½, 1].
/// Why not the placement of the components. Rings that do not touch are free
/// round circles, and every placement of them is an equilibrium of the same
/// energy: the relative placement is a family of neutral modes (the Hopf link
/// and T(3,3) of the link table relax to exactly that). Where components
/// touch, the contact changes their shapes, so the shapes carry the contact.
///
/// Definition. Resample component c at q points at equal arc length
/// (resample_arclength). Divide the q(q−1)/2 distances between its points by
/// the link's mean component length L̄. F_c is their distribution, and its
/// quantile function is read at K midpoints:
///
/// ~~~{.unparsed}
///   Q_c[k] = F_c⁻¹((k + ½)/K),  k = 0 .. K−1,
/// ~~~
///
/// the "distance distribution" shape descriptor of Osada et al. (2002), one
/// per component. The distance of links A and B with m components each is
///
/// ~~~{.unparsed}
///   d(A, B) = min_π max_c RMS_k( Q^A_c[k] − Q^B_{π(c)}[k] )   [mean component length],
/// ~~~
///
/// over the m! pairings π. Two links are the same state when every
/// component has the shape of its partner.
///
/// Properties:
/// - d is 0 for a link and any rigid motion, mirror image, re-indexing,
///   reversal or renumbering of its components;
/// - d is 0 for two placements of the same components.
///
/// Mirror images. That d does not see them matches the data sets' convention.
/// A data set holds equilibria of one link type. The mirror image of a state
/// is a state of the mirror link, so it is in the set only when the link is
/// amphicheiral; then it counts as the same state, as for amphicheiral knots
/// (paper Section 7.1, "Symmetries").
///
/// Resolution. Resampling puts q points on a polygon, and their distances
/// shift with where the points fall. With q = 256 and K = 128 this leaves a
/// floor below 2e-4 between copies of one curve that start at different
/// vertices or run the other way (tested on ellipses of 200 vertices).
///
/// Cost: O(q² log q) per component for the descriptor, O(m!·m·K) per pair.
#include <vector>

#include "ek/geometry/link.hpp"

namespace ek {

/// The resolution of the link descriptor: q points per component and K
/// quantiles (see the file's description).
struct LinkShapeOptions {
  int samples = 256;    ///< [1] q, points per component (>= 4)
  int quantiles = 128;  ///< [1] K, quantiles of each distance distribution (>= 1)
  void validate() const;  ///< InputError outside the ranges above
};

/// A link's descriptor: each component's quantile function Q_c (K values,
/// [mean component length]).
struct LinkShape {
  std::vector<Eigen::VectorXd> components;  ///< Q_c, one K-vector per component, in the link's order
};

/// The descriptor of `link` (components of >= 3 vertices, positive length).
LinkShape link_shape(const Link& link, const LinkShapeOptions& options = {});

/// What link_state_distance() returns: d(A, B) and the pairing that realises it.
struct LinkStateDistance {
  double distance = 0.0;     ///< [mean component length] d(A, B)
  std::vector<int> pairing;  ///< component c of A is paired with pairing[c] of B
};

/// d(A, B) of two descriptors. InputError when the component counts or
/// quantile counts differ, or there are more than 8 components (m! pairings).
LinkStateDistance link_state_distance(const LinkShape& a, const LinkShape& b);

/// The m by m matrix 1 − d(i, j) of the data set's `similarity` field
/// (dataset_file.hpp), symmetric with unit diagonal.
Eigen::MatrixXd link_state_similarity_matrix(const std::vector<LinkShape>& shapes);

}  // namespace ek
