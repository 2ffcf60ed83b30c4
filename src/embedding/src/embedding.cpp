#include <algorithm>
#include <cmath>
#include <vector>

#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/knots/alexander.hpp"

namespace ek {

std::string to_string(EmbeddingMethod method) {
  switch (method) {
    case EmbeddingMethod::Braid: return "braid";
    case EmbeddingMethod::PD: return "pd";
    case EmbeddingMethod::Circle: return "circle";
  }
  return "?";
}

EmbeddingSource parse_embedding_source(const std::string& text) {
  if (text == "braid") return EmbeddingSource::Braid;
  if (text == "pd") return EmbeddingSource::PD;
  throw InputError("unknown embedding source '" + text + "' (expected braid or pd)");
}

void validate(const EmbeddingOptions& o) {
  require_input(o.vertices >= 4, "embedding: need at least 4 vertices, got " + std::to_string(o.vertices));
  require_input(o.edge_length > 0.0 && std::isfinite(o.edge_length), "embedding: edge length must be positive");
  require_input(o.crossing_height > 0.0, "embedding: crossing height must be positive");
  require_input(!o.strand_spacing || (*o.strand_spacing > 0.0 && std::isfinite(*o.strand_spacing)),
                "embedding: the strand spacing must be positive");
  require_input(o.pd_crossing_height > 0.0, "embedding: PD crossing height must be positive");
  require_input(o.samples_per_letter >= 4 && o.samples_per_piece >= 2, "embedding: too few dense samples");
}

LinkEmbedding finish_link_embedding(const std::vector<Points>& dense, const EmbeddingOptions& o,
                                    const std::string& method) {
  double total = 0.0;
  for (const Points& D : dense) total += curve_length(D);
  LinkEmbedding e;
  double h = 0.0;
  std::vector<EquilateralResult> parts;
  for (const Points& D : dense) {
    const int m = std::max(4, static_cast<int>(std::lround(o.vertices * curve_length(D) / total)));
    try {
      parts.push_back(resample_equilateral(D, m));
    } catch (const std::invalid_argument&) {
      throw InputError(method + ": cannot place " + std::to_string(m) +
                       " equal edges along a component; use more vertices");
    }
    h += parts.back().edge_length / static_cast<double>(dense.size());
  }
  const double scale = o.edge_length / h;
  for (const EquilateralResult& p : parts) {
    e.components.push_back(p.points * scale);
    const VecX edges = edge_lengths(e.components.back());
    e.max_edge_deviation = std::max(e.max_edge_deviation, (edges.array() - o.edge_length).abs().maxCoeff());
  }
  e.edge_length = o.edge_length;
  validate_link(e.components, method);
  return e;
}

Embedding finish_embedding(const Points& dense, const EmbeddingOptions& o, EmbeddingMethod how,
                           const AlexanderPolynomial* expected) {
  const std::string method = to_string(how);
  EquilateralResult eq;
  try {
    eq = resample_equilateral(dense, o.vertices);
  } catch (const std::invalid_argument&) {
    throw InputError(method + " embedding: cannot place " + std::to_string(o.vertices) +
                     " equal edges along the curve; use more vertices");
  }
  const double scale = o.edge_length / eq.edge_length;
  Embedding e;
  e.points = eq.points * scale;
  e.edge_length = o.edge_length;
  e.max_edge_deviation = eq.max_deviation * scale;
  e.method = how;
  e.clearance = clearance(e.points).distance;
  if (o.verify && expected) {
    AlexanderPolynomial got;
    try {
      got = alexander(e.points);
    } catch (const InputError&) {
      throw InputError(method + " embedding with " + std::to_string(o.vertices) +
                       " vertices intersects itself; use more vertices");
    }
    if (got != *expected)
      throw InputError(method + " embedding with " + std::to_string(o.vertices) +
                       " vertices is too coarse to keep the knot type (Alexander " + got.to_string() +
                       " instead of " + expected->to_string() + "); use more vertices");
    e.alexander = got;
  }
  return e;
}

Embedding embed_knot(const KnotRecord& knot, EmbeddingSource source, const EmbeddingOptions& options) {
  validate(options);
  if (knot.crossing_number == 0) {
    Points dense(std::max(64, options.vertices), 3);
    for (int i = 0; i < dense.rows(); ++i) {
      const double s = 2.0 * M_PI * i / dense.rows();
      dense.row(i) << std::cos(s), std::sin(s), 0.0;
    }
    const AlexanderPolynomial one;
    return finish_embedding(dense, options, EmbeddingMethod::Circle, &one);
  }
  if (source == EmbeddingSource::Braid) {
    if (!knot.braid) throw InputError("knot " + knot.name + " has no braid word in the table");
    return embed_braid(*knot.braid, options);
  }
  if (!knot.pd) throw InputError("knot " + knot.name + " has no PD code in the table");
  return embed_pd(*knot.pd, options);
}

}  // namespace ek
