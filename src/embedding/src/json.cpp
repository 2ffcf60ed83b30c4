#include "ek/embedding/json.hpp"

namespace ek {

Json embedding_json(const std::string& name, const Embedding& e, const std::optional<std::string>& output) {
  Json j;
  j["name"] = name;
  j["from"] = e.method;
  if (output) j["output"] = *output;
  j["vertices"] = e.points.rows();
  j["edge_length"] = json_number(e.edge_length);
  j["max_edge_deviation"] = json_number(e.max_edge_deviation);
  j["clearance"] = json_number(e.clearance);
  j["alexander"] = e.alexander ? Json(e.alexander->coefficients) : Json(nullptr);
  return j;
}

}  // namespace ek
