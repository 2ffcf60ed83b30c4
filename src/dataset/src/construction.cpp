#include "ek/dataset/construction.hpp"

#include <map>
#include <mutex>

#include "ek/analysis/search.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/knots/table.hpp"

namespace ek {

std::vector<std::string> table_knots_with_polynomial(const AlexanderPolynomial& p) {
  // the table's polynomials, computed once (thread-safe)
  static std::once_flag once;
  static std::map<std::vector<std::int64_t>, std::vector<std::string>> by_polynomial;
  std::call_once(once, [] {
    for (const KnotRecord& k : KnotTable::global().records())
      if (k.pd) by_polynomial[alexander(*k.pd).coefficients].push_back(k.name);
  });
  const auto it = by_polynomial.find(p.coefficients);
  return it == by_polynomial.end() ? std::vector<std::string>{} : it->second;
}

ConstructedKnot relax_construction(const PDCode& pd, const Points& pattern, const ConstructionOptions& options) {
  require(pattern.rows() == options.drawing.vertices,
          "relax_construction: the pattern must have the drawing's number of vertices");
  ConstructedKnot k;
  k.alexander = alexander(pd);
  k.table_knots = table_knots_with_polynomial(k.alexander);
  k.relaxed = relax(embed_pd(pd, options.drawing).points, options.relax);
  const Points& P = k.relaxed.positions;
  k.alexander_preserved = k.relaxed.alexander_preserved && alexander(P) == k.alexander;
  k.attributes = geometric_attributes(P);
  k.circles = fit_circles(P, options.circles);
  SimilarityOptions so;
  so.reversal = true;
  k.similarity = compare_curves(pattern, P, so).similarity;
  k.alignment_distance = align_curves(pattern, P).distance;
  return k;
}

}  // namespace ek
