#include "ek/knots/invariants.hpp"

#include <limits>
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
  validate_link(link, "link");
  LinkInvariants out;
  for (const Points& P : link) out.components.push_back(curve_invariants(P));
  out.linking = linking_matrix(link);
  out.linking_numbers = out.linking.array().round().cast<int>();
  out.linking_error = (out.linking - out.linking_numbers.cast<double>()).cwiseAbs().maxCoeff();
  out.component_clearance = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < link.size(); ++a)
    for (size_t b = a + 1; b < link.size(); ++b)
      out.component_clearance = std::min(out.component_clearance, component_distance(link[a], link[b]));
  return out;
}

}  // namespace ek
