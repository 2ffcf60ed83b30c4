#pragma once
/// \file
/// Alexander polynomial and determinant of knots (exact integer arithmetic).
///
/// Every computed curve is checked against its input's polynomial (a result
/// that changed the knot type is an error): use check_knot_type().
#include <cstdint>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"
#include "ek/knots/codes.hpp"
#include "ek/knots/diagram.hpp"
#include "ek/knots/polynomial.hpp"

namespace ek {

/// From a signed Gauss diagram: the diagram is simplified (simplify()), then
/// Δ is the (c-1)-minor of the Alexander matrix from the Wirtinger
/// presentation (Fox calculus): for a crossing with over-arc o, incoming
/// under-arc i and outgoing under-arc j, the row has 1 - t at o and (t, -1)
/// at (i, j) for a positive crossing, (-1, t) for a negative one.
AlexanderPolynomial alexander(GaussDiagram diagram);

/// From a PD code (via its Gauss diagram).
AlexanderPolynomial alexander(const PDCode& pd);

/// From a braid word on n strands, independently of the diagram route, by the
/// reduced Burau representation ψ: (1 + t + ... + t^{n-1}) Δ(t) = ±t^k det(I - ψ(β)).
AlexanderPolynomial alexander(const BraidWord& braid);

/// The one-variable Alexander polynomial of the closure of a braid word,
/// knot or link, by the same Burau formula: Laurent coefficients up to ±t^k,
/// lowest degree first; empty when it vanishes (for example a split closure).
std::vector<std::int64_t> alexander_coefficients(const BraidWord& braid);

/// From a closed polygon (n by 3): projection along a generic direction
/// (diagram_from_curve), then alexander(GaussDiagram).
AlexanderPolynomial alexander(const Points& curve, const ProjectionOptions& options = {});

/// Throws TopologyError("<what>: Alexander polynomial [..] differs from the
/// expected [..]") unless the curve has the expected polynomial.
void check_knot_type(const Points& curve, const AlexanderPolynomial& expected, const std::string& what);

}  // namespace ek
