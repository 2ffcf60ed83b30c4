#pragma once
/// \file
/// Random embeddings of a link on the cubic lattice: the knot schedule of
/// sampling.hpp run on every component of one BFACF walk whose polygons share
/// their occupied sites (bfacf.hpp), so no component passes through another.
///
/// Schedule of one sample: phase 1 grows each component in turn (moves drawn
/// on that component only, the others standing as obstacles) to growth_factor
/// times its target length at grow_fugacity; phase 2 shrinks each in turn to
/// exactly its target at shrink_fugacity. A component's target is its share
/// of options.vertices in proportion to its length in the start (even, at
/// least 4, at least 24 for a knotted component). A batch continues one walk,
/// as for knots. Every sample is checked against the link type: each
/// component's Alexander polynomial, the linking numbers (Gauss sums) and the
/// link's Conway polynomial (a mismatch is a TopologyError: the walk cannot
/// change the link, so this guards against bugs only).
#include <string>
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/knots/conway.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/lattice/rounding.hpp"
#include "ek/lattice/sampling.hpp"

namespace ek {

/// The polygons as a link (exact: the sites as doubles).
Link to_link(const std::vector<LatticePoints>& polygons);

/// A link's lattice samples.
struct LinkSampleBatch {
  std::vector<std::vector<LatticePoints>> samples;  ///< K links, one polygon per component
  std::vector<int> component_vertices;              ///< [1] each component's target length
  long long attempted_moves = 0;                    ///< [moves] of every phase of every sample
};

/// Runs the schedule from the lattice link `start` (disjoint self-avoiding
/// polygons). Throws InputError for impossible options and when a phase
/// exhausts its budget; TopologyError when a sample is not of `expected`.
LinkSampleBatch sample_lattice_link(const std::vector<LatticePoints>& start, const SampleOptions& options,
                                    const LinkType& expected, const std::string& what = "link");

/// A table link's lattice start: its braid word embedded as the coil
/// (embed_braid_link, 100 vertices per component), rounded onto Z³ with one
/// certified scale (round_link_to_lattice), checked against the table's link
/// type (components' types, linking numbers, ∇).
struct LatticeLinkStart {
  std::vector<LatticePoints> components;  ///< One self-avoiding lattice polygon per component; no two share a site.
  LinkType type;                          ///< The link type the start was checked against (the table's or the curves').
  double scale = 0.0;                     ///< [lattice units / length] of the rounding; 0 when no rounding was needed
};
/// The lattice start of the table link `link` (see LatticeLinkStart). Throws
/// TopologyError when the rounded link's type (the components' Alexander
/// polynomials, the linking numbers, ∇) differs from the embedding's, or its ∇
/// from the table's.
LatticeLinkStart lattice_link_start(const LinkRecord& link, const RoundingOptions& rounding = {});

/// A lattice start of a link given as curves: the curves themselves when
/// every component already is a lattice polygon and none shares a site,
/// otherwise rounded as above; checked against the curves' own link type.
LatticeLinkStart lattice_link_start(const Link& link, const RoundingOptions& rounding = {});

}  // namespace ek
