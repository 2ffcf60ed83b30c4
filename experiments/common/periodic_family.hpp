#pragma once
// The periodic braids of paper Fig. 16 (Section 8.4), shared by
// exp_periodic_braids and exp_periodic_links: (σ1σ2⁻¹)^p on 3 strands
// (p = 2..8) and (σ1σ2⁻¹σ3)^p on 4 strands (p = 2..7); the members whose
// closure is a knot (p = 2 is 4_1, 4 is 8_18, 5 is 10_123; (σ1σ2⁻¹σ3)^3 is
// 9_40), the others listed as skipped.
#include <string>
#include <vector>

#include "ek/knots/codes.hpp"

namespace ek::exp {

struct PeriodicBraid {
  std::string family;       ///< "s1s2i" or "s1s2is3"
  int strands = 0, p = 0;
  std::vector<int> period;  ///< one period of the word
  std::string table_name;   ///< "" when not tabulated
  BraidWord word() const {
    BraidWord w;
    w.strands = strands;
    for (int k = 0; k < p; ++k) w.letters.insert(w.letters.end(), period.begin(), period.end());
    return w;
  }
  /// [deg] the rotation between the two crossing p-gons of the family's
  /// p-fold symmetric 3D states: π/p for (σ1σ2⁻¹)^p, 0 for (σ1σ2⁻¹σ3)^p, as
  /// measured (docs/reproducing.md); the paper's sentence ties it to the
  /// parity of p instead, which (σ1σ2⁻¹)^5's 36° contradicts.
  double expected_rotation_deg() const { return family == "s1s2i" ? 180.0 / p : 0.0; }
  std::string label() const { return family + " p=" + std::to_string(p); }
};

/// Both families, p = 2..8 and 2..7.
inline std::vector<PeriodicBraid> periodic_braids() {
  std::vector<PeriodicBraid> all;
  for (int p = 2; p <= 8; ++p)
    all.push_back({"s1s2i", 3, p, {1, -2}, p == 2 ? "4_1" : p == 4 ? "8_18" : p == 5 ? "10_123" : ""});
  for (int p = 2; p <= 7; ++p) all.push_back({"s1s2is3", 4, p, {1, -2, 3}, p == 3 ? "9_40" : ""});
  return all;
}

/// The members of both families whose closure is a link (several components).
inline std::vector<PeriodicBraid> periodic_link_members() {
  std::vector<PeriodicBraid> links;
  for (const PeriodicBraid& m : periodic_braids())
    if (closure_components(m.word()) > 1) links.push_back(m);
  return links;
}

/// The knots of both families; `skipped` receives "family p=P: C components".
inline std::vector<PeriodicBraid> periodic_family(std::vector<std::string>& skipped) {
  std::vector<PeriodicBraid> knots;
  for (const PeriodicBraid& m : periodic_braids()) {
    const int c = closure_components(m.word());
    if (c == 1) knots.push_back(m);
    else skipped.push_back(m.label() + ": " + std::to_string(c) + " components");
  }
  return knots;
}

}  // namespace ek::exp
