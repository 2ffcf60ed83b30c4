#pragma once
/// \file
/// Knot diagrams as signed Gauss codes, and their simplification.
#include <cstdint>
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"
#include "ek/knots/codes.hpp"

namespace ek {

/// A knot diagram as a signed Gauss code: the sequence of crossing visits
/// along the oriented knot. Each crossing is visited twice, once on the over
/// strand and once on the under strand.
struct GaussDiagram {
  /// One passage of the knot through a crossing.
  struct Visit {
    int crossing;  ///< index into `signs`
    bool over;     ///< true on the over strand
  };
  std::vector<Visit> visits;  ///< 2c visits in traversal order
  std::vector<int> signs;     ///< crossing signs ±1 (right-handed = +1), size c

  int crossings() const { return static_cast<int>(signs.size()); }  ///< c, the number of crossings.
  /// Sum of the crossing signs (the diagram's writhe).
  int writhe() const;
};

/// A link diagram: the crossings' visits along each component, in traversal
/// order (a component without crossings has none); a knot's diagram is one
/// of a single component.
struct LinkDiagram {
  std::vector<std::vector<GaussDiagram::Visit>> components;  ///< m lists of visits
  std::vector<int> signs;                                    ///< crossing signs ±1, size c

  int crossings() const { return static_cast<int>(signs.size()); }  ///< c, the number of crossings.
};

/// The Gauss code of a PD code: edges are traversed in label order 1..2c.
GaussDiagram diagram_from_pd(const PDCode& pd);

/// The Gauss code of the closure of a braid word (σ_i^{±1}: a crossing of the
/// strands at positions i and i+1 with sign ±1).
GaussDiagram diagram_from_braid(const BraidWord& word);

/// Options for diagram_from_curve().
struct ProjectionOptions {
  int directions = 8;         ///< candidate projection directions tried; the one with fewest crossings wins
  std::uint64_t seed = 1;     ///< seed of the deterministic direction sequence
  double degeneracy = 1e-9;   ///< [1] relative tolerance for a non-generic projection
};

/// Diagram of a closed polygon P (n by 3) projected along a generic direction.
/// Candidate directions come from a fixed pseudo-random sequence; a direction
/// is rejected when the projection is not generic within `degeneracy` (a
/// vertex projects onto another edge, two crossings coincide, edges project
/// nearly parallel at a crossing, or the two strands have nearly equal height
/// there). Among the accepted directions the one with fewest crossings is used.
/// The over strand is the one nearer the viewer, who looks against the
/// direction. Throws InputError when no direction is generic (the curve
/// intersects itself).
GaussDiagram diagram_from_curve(const Points& P, const ProjectionOptions& options = {});

/// The diagram of a link (validate_link; each component simple) projected as
/// diagram_from_curve() projects a curve: one direction for all components,
/// the generic one with fewest crossings. Throws InputError as
/// diagram_from_curve() does, naming the component.
LinkDiagram link_diagram_from_curves(const Link& link, const ProjectionOptions& options = {});

/// The diagram of the closure of a braid word, one component per cycle of its
/// permutation (closure_cycles(), in that order), crossings numbered by the
/// word's letters as in diagram_from_braid().
LinkDiagram link_diagram_from_braid(const BraidWord& word);

/// The diagram of a knot's or link's PD code (parse_pd_link): one component
/// per label range, visits in label order (each crossing where a label's edge
/// ends), signs from the over strands' orientation.
LinkDiagram link_diagram_from_pd(const PDLinkCode& pd);

/// The PD code of a braid's closure (LinkInfo's convention, so that
/// parse_pd_link reads it back): the components in the order of
/// closure_cycles(), each labelled in a row along its orientation from the
/// edge that enters its first visit in the word. InputError when a component
/// meets no letter (a split circle has no PD code).
PDLinkCode pd_from_braid(const BraidWord& word);

/// Component k of a link diagram alone: its visits with the crossings it
/// shares with other components dropped and the rest renumbered densely.
GaussDiagram component_diagram(const LinkDiagram& diagram, int k);

/// The diagram's linking numbers: half the signed crossings between two
/// components (m by m, symmetric, zero diagonal).
Eigen::MatrixXi linking_numbers(const LinkDiagram& diagram);

/// Number of crossings of the projection of P along `direction` (for tests
/// of the projection code against an independent count).
int projection_crossing_count(const Points& P, const Vec3& direction);

/// One crossing of a projection: where the two strands pass over each other.
struct ProjectedCrossing {
  Vec3 over;        ///< point of the over strand (nearer the viewer)
  Vec3 under;       ///< point of the under strand
  ///@{
  /// Edges of the over and the under strand (edge i joins vertex i to i + 1).
  int over_edge = -1, under_edge = -1;
  ///@}
  int sign = 0;     ///< +1 right-handed, -1 left-handed
};

/// Every crossing of the projection of P along `direction` (viewer at
/// +direction); empty and `generic` = false when the projection is not generic.
std::vector<ProjectedCrossing> projection_crossings(const Points& P, const Vec3& direction, bool* generic = nullptr);

/// Simplifies the diagram without changing the knot group's presentation up
/// to Tietze moves (so every Alexander-type invariant is unchanged):
///  - a crossing whose over-arc is its own incoming or outgoing under-arc
///    (a Reidemeister I loop, also one that passes over other strands);
///  - two crossings visited consecutively as under-crossings whose over-visits
///    lie on the same arc and whose signs are opposite (a Reidemeister II
///    bigon, also a strand that slides under an arc).
/// Repeats until neither applies. Returns the number of crossings removed.
int simplify(GaussDiagram& diagram);

}  // namespace ek
