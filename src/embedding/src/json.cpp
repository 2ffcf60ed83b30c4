#include "ek/embedding/json.hpp"

namespace ek {

Json embedding_json(const std::string& name, const Embedding& e, const std::optional<std::string>& output) {
  Json j;
  j["name"] = name;
  j["from"] = to_string(e.method);
  if (output) j["output"] = *output;
  j["vertices"] = e.points.rows();
  j["edge_length"] = json_number(e.edge_length);
  j["max_edge_deviation"] = json_number(e.max_edge_deviation);
  j["clearance"] = json_number(e.clearance);
  j["alexander"] = e.alexander ? Json(e.alexander->coefficients) : Json(nullptr);
  return j;
}

Json link_embedding_json(const std::string& name, const std::string& from, const LinkEmbedding& e,
                         const ConwayPolynomial& conway, const std::optional<std::string>& output) {
  Eigen::Index vertices = 0;
  for (const Points& P : e.components) vertices += P.rows();
  Json j;
  j["name"] = name;
  j["from"] = from;
  j["components"] = e.components.size();
  j["vertices"] = vertices;
  j["edge_length"] = json_number(e.edge_length);
  j["max_edge_deviation"] = json_number(e.max_edge_deviation);
  j["linking_numbers"] = integer_matrix_json(e.linking_numbers);
  j["conway"] = conway.coefficients;
  if (output) j["output"] = *output;
  return j;
}

}  // namespace ek
