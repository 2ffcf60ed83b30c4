#include "ek/knots/diagram.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "ek/core/errors.hpp"

namespace ek {

int GaussDiagram::writhe() const { return std::accumulate(signs.begin(), signs.end(), 0); }

GaussDiagram diagram_from_pd(const PDCode& pd) {
  const int c = pd.size(), m = 2 * c;
  GaussDiagram g;
  g.signs.resize(static_cast<size_t>(c));
  // enters[label] = (crossing, over?) where edge `label` ends.
  std::vector<GaussDiagram::Visit> enters(static_cast<size_t>(m + 1), {-1, false});
  auto succ = [m](int x) { return x % m + 1; };
  for (int i = 0; i < c; ++i) {
    const auto& e = pd.crossings[static_cast<size_t>(i)].e;
    g.signs[static_cast<size_t>(i)] = pd.crossings[static_cast<size_t>(i)].sign(m);
    enters[static_cast<size_t>(e[0])] = {i, false};
    const int over_in = (g.signs[static_cast<size_t>(i)] > 0) ? e[3] : e[1];
    enters[static_cast<size_t>(over_in)] = {i, true};
    (void)succ;
  }
  for (int label = 1; label <= m; ++label) {
    require(enters[static_cast<size_t>(label)].crossing >= 0, "diagram_from_pd: PD code was not validated");
    g.visits.push_back(enters[static_cast<size_t>(label)]);
  }
  return g;
}

GaussDiagram diagram_from_braid(const BraidWord& word) {
  LinkDiagram d = link_diagram_from_braid(word);
  require(d.components.size() == 1, "diagram_from_braid: the closure is not a knot");
  return GaussDiagram{std::move(d.components[0]), std::move(d.signs)};
}

LinkDiagram link_diagram_from_braid(const BraidWord& word) {
  // Follow one strand of the closure through the word, repeatedly: position
  // p meets letter ±i when p is i or i+1 (1-based), then moves to the other.
  // σ_i: the strand from position i passes over (sign +1); σ_i^{-1}: the
  // strand from position i+1 passes over (sign -1). Both are right-handed for
  // σ_i when the strands run in the same direction. A strand leaving the word
  // at position p re-enters it at p, so a component's traversal ends when its
  // strand is back at its cycle's first position.
  LinkDiagram d;
  for (int letter : word.letters) d.signs.push_back(letter > 0 ? 1 : -1);
  for (const std::vector<int>& cycle : closure_cycles(word)) {
    std::vector<GaussDiagram::Visit> visits;
    int pos = cycle.front();
    do {
      for (int k = 0; k < word.length(); ++k) {
        const int letter = word.letters[static_cast<size_t>(k)];
        const int i = std::abs(letter);
        if (pos != i && pos != i + 1) continue;
        const bool from_left = (pos == i);
        visits.push_back({k, letter > 0 ? from_left : !from_left});
        pos = from_left ? i + 1 : i;
      }
    } while (pos != cycle.front());
    d.components.push_back(std::move(visits));
  }
  return d;
}

LinkDiagram link_diagram_from_pd(const PDLinkCode& pd) {
  const int c = pd.code.size(), m = 2 * c;
  LinkDiagram d;
  std::vector<GaussDiagram::Visit> enters(static_cast<size_t>(m + 1), {-1, false});  // where edge `label` ends
  for (int i = 0; i < c; ++i) {
    d.signs.push_back(pd.sign(i));
    enters[static_cast<size_t>(pd.code.crossings[static_cast<size_t>(i)].e[0])] = {i, false};
    enters[static_cast<size_t>(pd.over_in[static_cast<size_t>(i)])] = {i, true};
  }
  for (const auto& r : pd.components) {
    std::vector<GaussDiagram::Visit> visits;
    for (int label = r[0]; label <= r[1]; ++label) {
      require(enters[static_cast<size_t>(label)].crossing >= 0, "link_diagram_from_pd: PD code was not validated");
      visits.push_back(enters[static_cast<size_t>(label)]);
    }
    d.components.push_back(std::move(visits));
  }
  return d;
}

PDLinkCode pd_from_braid(const BraidWord& word) {
  const LinkDiagram d = link_diagram_from_braid(word);
  PDLinkCode out;
  out.code.crossings.resize(d.signs.size());
  out.over_in.resize(d.signs.size());
  // edge base + p enters the component's visit p and leaves visit p - 1
  int base = 1;
  for (const auto& visits : d.components) {
    const int n = static_cast<int>(visits.size());
    require_input(n > 0, "a braid closure with a component that meets no letter (a split circle) has no PD code");
    out.components.push_back({base, base + n - 1});
    for (int p = 0; p < n; ++p) {
      const auto& v = visits[static_cast<size_t>(p)];
      const int in = base + p, out_label = base + (p + 1) % n;
      auto& e = out.code.crossings[static_cast<size_t>(v.crossing)].e;
      const bool positive = d.signs[static_cast<size_t>(v.crossing)] > 0;
      if (!v.over) {
        e[0] = in;
        e[2] = out_label;
      } else {  // a positive crossing's over strand runs d -> b
        e[positive ? 3 : 1] = in;
        e[positive ? 1 : 3] = out_label;
        out.over_in[static_cast<size_t>(v.crossing)] = in;
      }
    }
    base += n;
  }
  return out;
}

GaussDiagram component_diagram(const LinkDiagram& d, int k) {
  require(k >= 0 && k < static_cast<int>(d.components.size()), "component_diagram: no component " + std::to_string(k));
  std::vector<int> count(d.signs.size(), 0);
  for (const auto& v : d.components[static_cast<size_t>(k)]) ++count[static_cast<size_t>(v.crossing)];
  std::vector<int> renumber(d.signs.size(), -1);
  GaussDiagram g;
  for (size_t x = 0; x < d.signs.size(); ++x)
    if (count[x] == 2) {
      renumber[x] = g.crossings();
      g.signs.push_back(d.signs[x]);
    }
  for (const auto& v : d.components[static_cast<size_t>(k)])
    if (renumber[static_cast<size_t>(v.crossing)] >= 0)
      g.visits.push_back({renumber[static_cast<size_t>(v.crossing)], v.over});
  return g;
}

Eigen::MatrixXi linking_numbers(const LinkDiagram& d) {
  const Eigen::Index m = static_cast<Eigen::Index>(d.components.size());
  std::vector<int> owner(d.signs.size(), -1);  // the component of the crossing's over visit
  std::vector<int> under(d.signs.size(), -1);
  for (Eigen::Index k = 0; k < m; ++k)
    for (const auto& v : d.components[static_cast<size_t>(k)])
      (v.over ? owner : under)[static_cast<size_t>(v.crossing)] = static_cast<int>(k);
  Eigen::MatrixXi twice = Eigen::MatrixXi::Zero(m, m);
  for (size_t x = 0; x < d.signs.size(); ++x)
    if (owner[x] != under[x]) {
      twice(owner[x], under[x]) += d.signs[x];
      twice(under[x], owner[x]) += d.signs[x];
    }
  require(((twice.array() / 2) * 2 == twice.array()).all(), "linking_numbers: a pair of components crosses an odd number of times");
  return twice / 2;
}

namespace {

/// Arc index of every position: arcs start right after each under visit.
/// arc[p] for p = position; an under visit at p ends arc arc[p-1] and starts arc[p].
std::vector<int> arc_ids(const GaussDiagram& g, int* count) {
  const int n = static_cast<int>(g.visits.size());
  std::vector<int> arc(static_cast<size_t>(n), 0);
  int first_under = -1;
  for (int p = 0; p < n; ++p)
    if (!g.visits[static_cast<size_t>(p)].over) {
      first_under = p;
      break;
    }
  if (first_under < 0) {
    *count = 1;
    return arc;
  }
  int id = -1;
  for (int k = 0; k < n; ++k) {
    const int p = (first_under + k) % n;
    if (!g.visits[static_cast<size_t>(p)].over) ++id;
    arc[static_cast<size_t>(p)] = id;
  }
  *count = id + 1;
  return arc;
}

void erase_crossings(GaussDiagram& g, int a, int b) {
  std::vector<GaussDiagram::Visit> kept;
  kept.reserve(g.visits.size());
  for (const auto& v : g.visits)
    if (v.crossing != a && v.crossing != b) kept.push_back(v);
  // renumber crossings to stay dense
  std::vector<int> map(g.signs.size(), -1);
  std::vector<int> signs;
  for (size_t c = 0; c < g.signs.size(); ++c)
    if (static_cast<int>(c) != a && static_cast<int>(c) != b) {
      map[c] = static_cast<int>(signs.size());
      signs.push_back(g.signs[c]);
    }
  for (auto& v : kept) v.crossing = map[static_cast<size_t>(v.crossing)];
  g.visits = std::move(kept);
  g.signs = std::move(signs);
}

}  // namespace

int simplify(GaussDiagram& g) {
  const int before = g.crossings();
  bool changed = true;
  while (changed && !g.signs.empty()) {
    changed = false;
    const int n = static_cast<int>(g.visits.size());
    int arcs = 0;
    const auto arc = arc_ids(g, &arcs);
    std::vector<int> under_pos(g.signs.size()), over_pos(g.signs.size());
    for (int p = 0; p < n; ++p) {
      const auto& v = g.visits[static_cast<size_t>(p)];
      (v.over ? over_pos : under_pos)[static_cast<size_t>(v.crossing)] = p;
    }
    // Generalised Reidemeister I: over-arc = incoming or outgoing under-arc.
    for (int c = 0; c < g.crossings() && !changed; ++c) {
      const int pu = under_pos[static_cast<size_t>(c)];
      const int over_arc = arc[static_cast<size_t>(over_pos[static_cast<size_t>(c)])];
      const int out_arc = arc[static_cast<size_t>(pu)];
      const int in_arc = arc[static_cast<size_t>((pu + n - 1) % n)];
      if (over_arc == out_arc || over_arc == in_arc) {
        erase_crossings(g, c, c);
        changed = true;
      }
    }
    if (changed) continue;
    // Generalised Reidemeister II: consecutive under visits, same over-arc, opposite signs.
    for (int p = 0; p < n && !changed; ++p) {
      const auto& v1 = g.visits[static_cast<size_t>(p)];
      const auto& v2 = g.visits[static_cast<size_t>((p + 1) % n)];
      if (v1.over || v2.over || v1.crossing == v2.crossing) continue;
      if (g.signs[static_cast<size_t>(v1.crossing)] == g.signs[static_cast<size_t>(v2.crossing)]) continue;
      if (arc[static_cast<size_t>(over_pos[static_cast<size_t>(v1.crossing)])] !=
          arc[static_cast<size_t>(over_pos[static_cast<size_t>(v2.crossing)])])
        continue;
      erase_crossings(g, v1.crossing, v2.crossing);
      changed = true;
    }
  }
  return before - g.crossings();
}

}  // namespace ek
