#pragma once
// The checks of a converged saddle search shared by the single-ended
// (saddles.cpp) and double-ended (double_ended.cpp) searches: items 2-4 of
// saddles.hpp's file comment without the classification of the minima.
#include <optional>

#include "ek/knots/polynomial.hpp"
#include "ek/solver/rod_model.hpp"
#include "ek/transitions/saddles.hpp"

namespace ek::detail {

/// The model's direct method (with_method(o.relax, "hybrid")).
RelaxOptions direct(const KnotSaddleOptions& o);

/// The Alexander polynomial of a curve, {0} when it cannot be computed.
AlexanderPolynomial alexander_or_zero(const Points& x);

/// At x_s (dofs of `sys`): the index (r.index, eigenvalues) and, when it is
/// one, the descents from x_s ± δ·v₁ into r.minima (+v₁ first; their
/// start_similarity is left 0) with every image's Alexander polynomial
/// compared with `alexander`, and r.link. Returns nothing when both descents
/// ended converged-stable with the topology kept, else the failure
/// (DegenerateHessian, Index, TopologyChanged, DescentFailed).
std::optional<SearchStatus> descend_saddle(const AlexanderPolynomial& alexander, const VecX& rest,
                                           const KnotSaddleOptions& o, RodModel& sys, const VecX& xs,
                                           SaddleRecord& r);

/// One search_saddle() from the dofs of `sys` along `direction` with the
/// tolerances of `sys` (gradient tolerance, base shift) and the energy rise
/// bound `max_rise` set into `search`; fills r's energy, gradient norm,
/// negative eigenvalue, iterations, rejected steps and saddle positions, and
/// its status when the search stopped without converging (a converged
/// search's status comes from its checks).
SaddleSearchResult search_into(RodModel& sys, const VecX& direction, SaddleSearchOptions search, double max_rise,
                               SaddleRecord& r);

}  // namespace ek::detail
