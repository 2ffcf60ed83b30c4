#include "ek/transitions/graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "ek/core/errors.hpp"

namespace ek {

int match_state(const std::vector<TransitionState>& states, const Points& x, const CurveSimilarity& similarity,
                double threshold) {
  int best = -1;
  double best_sim = threshold;
  for (size_t k = 0; k < states.size(); ++k) {
    if (states[k].positions.rows() != x.rows()) continue;
    const double s = similarity(states[k].positions, x);
    if (s >= best_sim) {
      best_sim = s;
      best = static_cast<int>(k);
    }
  }
  return best;
}

namespace {

/// The index of a saddle of the graph equal to r's, or -1.
int known_saddle(const TransitionGraph& g, const SaddleRecord& r, const CurveSimilarity& similarity) {
  for (size_t k = 0; k < g.saddles.size(); ++k) {
    const TransitionSaddle& s = g.saddles[k];
    if (std::abs(s.energy - r.energy) <= 1e-8 * std::abs(s.energy) && similarity(s.positions, r.saddle) >= 0.99)
      return static_cast<int>(k);
  }
  return -1;
}

/// The images from minima[0] over the saddle to minima[1] (saddle_path()
/// without its requirement of a verified record).
std::vector<Points> descent_path(const SaddleRecord& r, std::vector<double>& energies, int& saddle_image) {
  std::vector<Points> path;
  energies.clear();
  const SaddleMinimum& a = r.minima[0];
  for (size_t k = a.images.size(); k-- > 0;) {
    path.push_back(a.images[k]);
    energies.push_back(a.energies[k]);
  }
  saddle_image = static_cast<int>(path.size()) - 1;
  const SaddleMinimum& b = r.minima[1];
  for (size_t k = 1; k < b.images.size(); ++k) {
    path.push_back(b.images[k]);
    energies.push_back(b.energies[k]);
  }
  return path;
}

TransitionSaddle make_saddle(const SaddleRecord& r, int from, int to) {
  TransitionSaddle s;
  s.energy = r.energy;
  s.negative_eigenvalue = r.negative_eigenvalue;
  s.second_eigenvalue = r.second_eigenvalue;
  s.index = r.index;
  s.gradient_norm = r.gradient_norm;
  s.from = from;
  s.to = to;
  s.energy_from = r.minima[0].energy;
  s.energy_to = r.minima[1].energy;
  s.positions = r.saddle;
  s.path = descent_path(r, s.path_energies, s.saddle_image);
  return s;
}

void add_edge(TransitionGraph& g, TransitionSaddle s) {
  TransitionEdge e;
  e.from = s.from;
  e.to = s.to;
  e.saddle = static_cast<int>(g.saddles.size());
  e.energy = s.energy;
  e.barrier_forward = s.energy - s.energy_from;
  e.barrier_backward = s.energy - s.energy_to;
  g.saddles.push_back(std::move(s));
  g.edges.push_back(e);
}

/// The state of a minimum reached by a descent: the most similar at
/// `threshold`, or a new state appended.
int state_of(TransitionGraph& g, const SaddleMinimum& m, const CurveSimilarity& similarity, double threshold) {
  const int k = match_state(g.states, m.positions, similarity, threshold);
  if (k >= 0) return k;
  TransitionState s;
  s.energy = m.energy;
  s.positions = m.positions;
  g.states.push_back(s);
  return static_cast<int>(g.states.size()) - 1;
}

}  // namespace

void add_searches(TransitionGraph& g, StateSearches searches, const CurveSimilarity& similarity, double threshold) {
  require(searches.state >= 0 && searches.state < static_cast<int>(g.states.size()),
          "add_searches: the searched state is not in the graph");
  for (const SaddleRecord& r : searches.records) {
    if (!r.verified || r.duplicate_of >= 0 || known_saddle(g, r, similarity) >= 0) continue;
    add_edge(g, make_saddle(r, searches.state, state_of(g, r.minima[1], similarity, threshold)));
  }
  for (SaddleRecord& r : searches.records)
    for (SaddleMinimum& m : r.minima) m.images.clear();  // kept once, in the saddles' paths
  g.searches.push_back(std::move(searches));
}

void add_pair(TransitionGraph& g, int a, int b, const TransitionSearch& t, const CurveSimilarity& similarity,
              double threshold) {
  const int n = static_cast<int>(g.states.size());
  require(a >= 0 && a < n && b >= 0 && b < n && a != b, "add_pair: the states must be two states of the graph");
  PairSearch p;
  p.a = a;
  p.b = b;
  p.status = t.status;
  p.seed_statuses = t.seed_statuses;
  p.reached = t.reached;
  p.verified = t.verified;
  p.stages = t.stages;
  p.path_barrier = t.path_barrier;
  p.reached_similarity = t.reached_similarity;
  p.saddle_energy = t.seeds_tried > 0 ? t.saddle.energy : 0.0;
  p.seconds = t.seconds;
  if (t.verified) {
    p.saddle = known_saddle(g, t.saddle, similarity);
    if (p.saddle < 0) {
      TransitionSaddle s = make_saddle(t.saddle, a, b);
      s.double_ended = true;
      p.saddle = static_cast<int>(g.saddles.size());
      add_edge(g, std::move(s));
    }
  }
  for (const SaddleRecord& r : t.other_saddles) {
    if (known_saddle(g, r, similarity) >= 0) continue;
    const int from = state_of(g, r.minima[0], similarity, threshold);
    TransitionSaddle s = make_saddle(r, from, state_of(g, r.minima[1], similarity, threshold));
    s.double_ended = true;
    add_edge(g, std::move(s));
  }
  g.pairs.push_back(p);
}

TransitionSearch search_pair(TransitionGraph& g, int a, int b, const VecX& rest, const TransitionSearchOptions& o,
                             const CurveSimilarity& sim, double threshold) {
  TransitionSearch t;
  try {
    t = transition_search(g.states[static_cast<size_t>(a)].positions, g.states[static_cast<size_t>(b)].positions,
                          rest, o, sim);
  } catch (const InputError& e) {
    t = TransitionSearch{};
    t.status = SearchStatus::refused(e.what());
  }
  add_pair(g, a, b, t, sim, threshold);
  return t;
}

std::optional<std::vector<int>> minimax_path(const TransitionGraph& g, int a, int b) {
  const int n = static_cast<int>(g.states.size());
  require(a >= 0 && a < n && b >= 0 && b < n, "minimax_path: state out of range");
  if (a == b) return std::vector<int>{};
  // Dijkstra on the bottleneck: cost(path) = the highest saddle energy on it
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(n, inf);
  std::vector<int> via(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  cost[a] = -inf;
  queue.push({-inf, a});
  while (!queue.empty()) {
    const auto [c, u] = queue.top();
    queue.pop();
    if (c > cost[u]) continue;
    for (size_t k = 0; k < g.edges.size(); ++k) {
      const TransitionEdge& e = g.edges[k];
      if (e.from != u && e.to != u) continue;
      const int w = e.from == u ? e.to : e.from;
      const double cw = std::max(c, e.energy);
      if (cw < cost[w]) {
        cost[w] = cw;
        via[w] = static_cast<int>(k);
        queue.push({cw, w});
      }
    }
  }
  if (via[b] < 0) return std::nullopt;
  std::vector<int> edges;
  for (int w = b; w != a;) {
    const TransitionEdge& e = g.edges[via[w]];
    edges.push_back(via[w]);
    w = e.from == w ? e.to : e.from;
  }
  std::reverse(edges.begin(), edges.end());
  return edges;
}

void chain_profile(const TransitionGraph& g, int a, const std::vector<int>& edges, std::vector<Points>& images,
                   std::vector<double>& energies, std::vector<int>& saddle_images) {
  images.clear();
  energies.clear();
  saddle_images.clear();
  int at = a;
  for (const int k : edges) {
    const TransitionEdge& e = g.edges[k];
    const TransitionSaddle& s = g.saddles[e.saddle];
    const bool forward = e.from == at;
    require(forward || e.to == at, "chain_profile: the edges do not form a chain from the state");
    const size_t m = s.path.size();
    for (size_t j = 0; j < m; ++j) {
      const size_t i = forward ? j : m - 1 - j;
      images.push_back(s.path[i]);
      energies.push_back(s.path_energies[i]);
    }
    const int saddle = forward ? s.saddle_image : static_cast<int>(m) - 1 - s.saddle_image;
    saddle_images.push_back(static_cast<int>(images.size() - m) + saddle);
    at = forward ? e.to : e.from;
  }
}

}  // namespace ek
