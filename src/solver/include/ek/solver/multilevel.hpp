#pragma once
/// \file
/// Coarse and fine versions of one closed curve for the multilevel
/// relaxation (RelaxMethod::Multilevel, relax.hpp; docs/models.md, "Solver").
///
/// Coarsening drops every odd vertex: vertex 2k+1 moves onto the segment
/// from vertex 2k to vertex 2k+2, at the ratio of the rest lengths of its two
/// edges, l_{2k} / (l_{2k} + l_{2k+1}); the even vertices stay. The coarse
/// curve (n/2 vertices, rest lengths l_{2k} + l_{2k+1}) is the moved fine
/// curve without its odd vertices: the same polygon. The motion of the odd
/// vertices is a straight-line motion of the fine curve, certified by the
/// continuous collision detection of the contact model (contact_potential.hpp):
/// when it is certified for the whole way (t = 1) no two edges touch during
/// it, so the coarse curve has the knot type of the fine one.
///
/// Refinement inserts the odd vertices back on the coarse edges at the same
/// ratios: the refined curve is the coarse polygon itself, so its knot type
/// is the coarse curve's, and its rest lengths are the fine ones.
///
/// Either parity: where the collapse of the odd vertices is not certified,
/// the even ones may be collapsed instead (the curve's vertices shifted by
/// one, shift_vertices()); certified_coarsening() tries both in turn.
#include <optional>

#include "ek/contact/contact_potential.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// The result of coarsen(): the collapsed fine curve, the coarse curve and the
/// certified fraction of the motion between them.
struct CoarseCurve {
  Points collapsed;   ///< n by 3: the fine curve with every odd vertex moved onto its neighbours' segment
  Points coarse;      ///< n/2 by 3: the even vertices of `collapsed`
  VecX coarse_rest;   ///< [length] n/2: l_{2k} + l_{2k+1}
  double certified = 0.0;  ///< [1] certified fraction of the motion fine → collapsed (1: all of it)
};

/// Coarsens `fine` (n by 3, n even and >= 8) with rest edge lengths `rest`
/// (n, edge j from vertex j to j+1). The motion is checked with `contact`'s
/// collision detection (its d̂ and separation).
CoarseCurve coarsen(const Points& fine, const VecX& rest, const ContactOptions& contact);

/// The coarse curve (m by 3) with the odd vertices of a fine curve with rest
/// lengths `fine_rest` (2m) inserted at their rest-length ratios.
Points refine(const Points& coarse, const VecX& fine_rest);

/// The rows of `A` (a curve's vertices, n by 3, or its rest lengths, n)
/// from row `k` on, then its first k rows: vertex j of the result is vertex
/// (j + k) mod n of A; shift_vertices(shift_vertices(A, k), n − k) == A.
/// k in [0, n).
Points shift_vertices(const Points& A, int k);
VecX shift_vertices(const VecX& A, int k);  ///< shift_vertices() of rest lengths

/// A certified coarsening of a curve whose vertices were shifted by `offset`
/// (shift_vertices()): coarse vertex k is fine vertex 2k + offset.
struct ShiftedCoarsening {
  CoarseCurve curve;  ///< coarsen() of the shifted curve and rest lengths
  int offset = 0;     ///< [1] 0: the even vertices kept, 1: the odd ones
};

/// coarsen() of `fine` if its motion is certified (offset 0); else, with
/// `either_parity`, coarsen() of `fine` shifted by one vertex if that one is
/// (offset 1); none when neither is.
std::optional<ShiftedCoarsening> certified_coarsening(const Points& fine, const VecX& rest,
                                                      const ContactOptions& contact, bool either_parity);

/// refine() of the coarse curve of a ShiftedCoarsening with `offset`, in the
/// vertex order of the unshifted fine curve (rest lengths `fine_rest`, 2m,
/// unshifted).
Points refine(const Points& coarse, const VecX& fine_rest, int offset);

}  // namespace ek
