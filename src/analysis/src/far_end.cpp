// The far end of Fig. 9 at the full budget (far_end.hpp).
#include "ek/analysis/far_end.hpp"

#include <algorithm>
#include <stdexcept>

namespace ek {

FarEndCertificate far_end_certificate(const std::vector<KnotRatio>& knots, int k, int budget) {
  if (k < 1) throw std::invalid_argument("far_end_certificate: k must be at least 1");
  if (budget < 1) throw std::invalid_argument("far_end_certificate: budget must be at least 1");
  FarEndCertificate c;
  const KnotRatio* other = nullptr;  // the knot that is not 2-bridge with the largest ratio
  for (const KnotRatio& r : knots)
    if (!r.two_bridge && (!other || r.ratio > other->ratio)) other = &r;
  if (other) {
    c.other_max_ratio = other->ratio;
    c.other_max_knot = other->name;
  }
  std::vector<const KnotRatio*> below;  // 2-bridge, below the budget, above M
  int above = 0;                        // 2-bridge, above M (at the budget or not)
  for (const KnotRatio& r : knots) {
    if (!r.two_bridge || (other && !(r.ratio > other->ratio))) continue;
    ++above;
    if (r.samples >= budget)
      ++c.certified_two_bridge;
    else
      below.push_back(&r);
  }
  c.certified = c.certified_two_bridge >= k;
  if (c.certified) return c;
  if (other && other->samples < budget && above < k) c.to_sample.push_back(other->name);
  std::sort(below.begin(), below.end(), [](const KnotRatio* a, const KnotRatio* b) { return a->ratio > b->ratio; });
  const size_t missing = static_cast<size_t>(k - c.certified_two_bridge);
  for (size_t i = 0; i < below.size() && i < missing; ++i) c.to_sample.push_back(below[i]->name);
  return c;
}

}  // namespace ek
