#include "ek/knots/invariants.hpp"

#include <stdexcept>

#include "ek/geometry/writhe.hpp"
#include "ek/knots/alexander.hpp"

namespace ek {

AlexanderPolynomial table_alexander(const KnotRecord& knot) {
  AlexanderPolynomial alex;
  if (knot.pd) alex = alexander(*knot.pd);
  if (knot.braid && alexander(*knot.braid) != alex)
    throw std::runtime_error("the table's braid word and PD code of " + knot.name +
                             " give different Alexander polynomials");
  return alex;
}

CurveInvariants curve_invariants(const Points& P) {
  CurveInvariants c;
  c.vertices = static_cast<int>(P.rows());
  c.alexander = alexander(P);
  c.writhe = writhe(P);
  c.total_curvature = total_curvature(P);
  c.clearance = clearance(P);
  c.length = curve_length(P);
  return c;
}

}  // namespace ek
