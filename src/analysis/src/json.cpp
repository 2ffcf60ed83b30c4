#include "ek/analysis/json.hpp"

namespace ek {

Json similarity_json(const SimilarityResult& r, const SimilarityOptions& options) {
  Json j;
  j["similarity"] = json_number(r.similarity);
  j["curvature_correlation"] = json_number(r.curvature_correlation);
  j["torsion_correlation"] = json_number(r.torsion_correlation);
  j["best_shift"] = r.best_shift;
  j["reversed"] = r.reversed;
  j["mirrored"] = r.mirrored;
  j["samples"] = r.samples;
  j["reverse_allowed"] = options.reversal;
  j["mirror_allowed"] = options.mirror;
  return j;
}

Json attributes_json(const Attributes& a, int vertices, const AttributeOptions& material) {
  Json j;
  j["vertices"] = vertices;
  for (const std::string& name : attribute_names()) {
    const std::optional<double> v = attribute_value(a, name);
    j[name] = v ? json_number(*v) : Json(nullptr);
  }
  j["radius"] = json_number(material.radius);
  j["young_modulus"] = json_number(material.young_modulus);
  return j;
}

}  // namespace ek
