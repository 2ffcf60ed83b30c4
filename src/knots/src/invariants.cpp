#include "ek/knots/invariants.hpp"

#include <stdexcept>

#include "ek/core/errors.hpp"

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

LinkInvariants link_invariants(const Link& link) {
  require_input(link.size() >= 2, "link invariants: a link needs at least 2 components");
  LinkInvariants out;
  out.component_clearance = validate_link(link, "link");
  for (const Points& P : link) out.components.push_back(curve_invariants(P));
  out.linking = linking_matrix(link);
  out.linking_numbers = out.linking.array().round().cast<int>();
  out.linking_error = (out.linking - out.linking_numbers.cast<double>()).cwiseAbs().maxCoeff();
  out.conway = conway(link);
  out.milnor_triple = milnor_triple_linking(out.conway, out.linking_numbers);
  return out;
}

}  // namespace ek
