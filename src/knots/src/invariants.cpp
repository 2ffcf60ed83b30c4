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

std::string LinkType::to_string() const {
  std::string s = "components";
  for (size_t c = 0; c < alexander.size(); ++c) s += (c ? ", " : " ") + alexander[c].to_string();
  s += "; linking numbers";
  for (Eigen::Index i = 0; i < linking_numbers.rows(); ++i)
    for (Eigen::Index j = i + 1; j < linking_numbers.cols(); ++j) s += " " + std::to_string(linking_numbers(i, j));
  return s + "; Conway " + conway.to_string();
}

LinkType link_type(const Link& link) {
  validate_link(link, "link");
  LinkType t;
  for (const Points& P : link) t.alexander.push_back(alexander(P));
  t.linking_numbers = linking_matrix(link).array().round().cast<int>();
  t.conway = conway(link);
  return t;
}

LinkType link_type(const LinkDiagram& diagram) {
  LinkType t;
  for (int k = 0; k < static_cast<int>(diagram.components.size()); ++k)
    t.alexander.push_back(alexander(component_diagram(diagram, k)));
  t.linking_numbers = linking_numbers(diagram);
  t.conway = conway(diagram);
  return t;
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
