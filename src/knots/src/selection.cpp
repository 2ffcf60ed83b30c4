#include "ek/knots/selection.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "ek/core/errors.hpp"

namespace ek {

void StratifiedSampleOptions::validate() const {
  require_input(min_crossings >= 0 && min_crossings <= max_crossings,
                "stratified sample: need 0 <= min crossings <= max crossings");
  require_input(fraction > 0.0 && fraction <= 1.0, "stratified sample: the fraction must be in (0, 1]");
}

bool is_bb_knot(const KnotRecord& k) { return k.bridge_index && k.braid_index && *k.bridge_index == *k.braid_index; }

std::vector<const KnotRecord*> stratified_sample(const KnotTable& table, const StratifiedSampleOptions& o) {
  o.validate();
  // stratum: crossing number, alternating (-1 unknown), bridge index (-1 unknown)
  using Stratum = std::tuple<int, int, int>;
  std::map<Stratum, std::vector<const KnotRecord*>> strata;
  for (const KnotRecord* k : table.up_to_crossings(o.max_crossings)) {
    if (k->crossing_number < o.min_crossings) continue;
    const int alternating = k->alternating ? static_cast<int>(*k->alternating) : -1;
    strata[{k->crossing_number, alternating, k->bridge_index.value_or(-1)}].push_back(k);
  }
  std::set<int> rows;
  for (const auto& [stratum, knots] : strata) {
    const auto s = static_cast<double>(knots.size());
    const int take = static_cast<int>(std::ceil(o.fraction * s - 1e-9));
    for (int j = 0; j < take; ++j) rows.insert(knots[static_cast<size_t>(std::floor((j + 0.5) * s / take))]->row);
    if (o.all_bb_knots)
      for (const KnotRecord* k : knots)
        if (is_bb_knot(*k)) rows.insert(k->row);
  }
  std::vector<const KnotRecord*> out;
  for (const KnotRecord* k : table.up_to_crossings(o.max_crossings))
    if (rows.count(k->row)) out.push_back(k);
  return out;
}

}  // namespace ek
