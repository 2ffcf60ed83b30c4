#include "ek/knots/json.hpp"

namespace ek {
namespace {

Json optional_int(const std::optional<int>& v) { return v ? Json(*v) : Json(nullptr); }

}  // namespace

Json knot_info_json(const KnotRecord& k, const KnotTable& table) {
  const AlexanderPolynomial alex = table_alexander(k);
  Json j;
  j["name"] = k.name;
  j["crossing_number"] = k.crossing_number;
  j["bridge_index"] = optional_int(k.bridge_index);
  j["braid_index"] = optional_int(k.braid_index);
  j["unknotting_number"] = optional_int(k.unknotting_number);
  j["alternating"] = k.alternating ? Json(*k.alternating) : Json(nullptr);
  j["symmetry_type"] = k.symmetry_type;
  j["dt"] = k.dt ? Json(to_string(*k.dt)) : Json(nullptr);
  j["pd"] = k.pd ? Json(to_string(*k.pd)) : Json(nullptr);
  j["braid"] = k.braid ? Json(to_string(*k.braid)) : Json(nullptr);
  j["braid_strands"] = k.braid ? Json(k.braid->strands) : Json(nullptr);
  j["alexander"] = alex.coefficients;
  j["determinant"] = alex.determinant();
  j["table"] = table.path();
  return j;
}

Json link_info_json(const LinkRecord& l) {
  Json j;
  j["name"] = l.name;
  j["aliases"] = l.aliases;
  j["description"] = l.description;
  j["components"] = l.components();
  j["crossing_number"] = l.crossing_number;
  j["braid"] = to_string(l.braid);
  j["braid_strands"] = l.braid.strands;
  j["pd"] = to_string(l.pd().code);
  j["component_types"] = l.component_types;
  j["linking_numbers"] = integer_matrix_json(l.linking_matrix());
  j["conway"] = l.conway.coefficients;
  j["milnor_triple"] = optional_int(l.milnor_triple());
  j["table"] = "built-in links";
  return j;
}

Json invariants_json(const CurveInvariants& c) {
  Json j;
  j["vertices"] = c.vertices;
  j["length"] = json_number(c.length);
  j["alexander"] = c.alexander.coefficients;
  j["determinant"] = c.alexander.determinant();
  j["writhe"] = json_number(c.writhe);
  j["total_curvature"] = json_number(c.total_curvature);
  j["clearance"] = json_number(c.clearance.distance);
  return j;
}

Json link_invariants_json(const LinkInvariants& l) {
  Json j;
  j["components"] = l.components.size();
  int vertices = 0;
  Json each = Json::array();
  for (const CurveInvariants& c : l.components) {
    vertices += c.vertices;
    each.push_back(invariants_json(c));
  }
  j["vertices"] = vertices;
  j["component"] = each;
  j["linking_numbers"] = integer_matrix_json(l.linking_numbers);
  j["linking_error"] = json_number(l.linking_error);
  j["component_clearance"] = json_number(l.component_clearance);
  j["conway"] = l.conway.coefficients;
  j["milnor_triple"] = optional_int(l.milnor_triple);
  return j;
}

}  // namespace ek
