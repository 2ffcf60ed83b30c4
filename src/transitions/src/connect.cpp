#include "ek/transitions/connect.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"

namespace ek {

void ConnectOptions::validate() const {
  require_input(max_searches >= 1, "connect: max_searches must be >= 1");
  search.validate();
}

std::vector<int> connected_states(const TransitionGraph& g, int state) {
  const int n = static_cast<int>(g.states.size());
  require(state >= 0 && state < n, "connected_states: state out of range");
  std::vector<char> seen(static_cast<size_t>(n), 0);
  std::vector<int> stack{state};
  seen[static_cast<size_t>(state)] = 1;
  while (!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    for (const TransitionEdge& e : g.edges) {
      if (!inter_state(e) || (e.from != u && e.to != u)) continue;
      const int w = e.from == u ? e.to : e.from;
      if (!seen[static_cast<size_t>(w)]) {
        seen[static_cast<size_t>(w)] = 1;
        stack.push_back(w);
      }
    }
  }
  std::vector<int> out;
  for (int k = 0; k < n; ++k)
    if (seen[static_cast<size_t>(k)]) out.push_back(k);
  return out;
}

namespace {

using Pair = std::pair<int, int>;

Pair key(int u, int v) { return {std::min(u, v), std::max(u, v)}; }

/// The aligned RMS vertex distance of states u and v (cached; infinite for
/// different vertex counts).
double distance_of(const TransitionGraph& g, int u, int v, std::map<Pair, double>& cache) {
  const auto it = cache.find(key(u, v));
  if (it != cache.end()) return it->second;
  const Points& x = g.states[static_cast<size_t>(u)].positions;
  const Points& y = g.states[static_cast<size_t>(v)].positions;
  double d = std::numeric_limits<double>::infinity();
  if (x.rows() == y.rows()) align_vertices(x, y, d);
  cache.emplace(key(u, v), d);
  return d;
}

/// The next pair to search (see the file comment of connect.hpp): the first
/// missing hop, from a's side, of the path from a to b of least total
/// weight (0 along inter-state edges, d² across an untried pair);
/// {-1, -1} when no such path is left. Dijkstra on the complete graph of
/// the states, O(N²).
Pair next_pair(const TransitionGraph& g, int a, int b, const std::set<Pair>& tried,
               std::map<Pair, double>& distances, double& distance) {
  const int n = static_cast<int>(g.states.size());
  std::set<Pair> joined;
  for (const TransitionEdge& e : g.edges)
    if (inter_state(e)) joined.insert(key(e.from, e.to));
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(static_cast<size_t>(n), inf);
  std::vector<int> via(static_cast<size_t>(n), -1);
  std::vector<char> done(static_cast<size_t>(n), 0);
  cost[static_cast<size_t>(a)] = 0.0;
  for (int round = 0; round < n; ++round) {
    int u = -1;
    for (int k = 0; k < n; ++k)
      if (!done[static_cast<size_t>(k)] && cost[static_cast<size_t>(k)] < inf &&
          (u < 0 || cost[static_cast<size_t>(k)] < cost[static_cast<size_t>(u)]))
        u = k;
    if (u < 0 || u == b) break;
    done[static_cast<size_t>(u)] = 1;
    for (int v = 0; v < n; ++v) {
      if (v == u || done[static_cast<size_t>(v)]) continue;
      double w = 0.0;
      if (!joined.count(key(u, v))) {
        if (tried.count(key(u, v))) continue;
        const double d = distance_of(g, u, v, distances);
        w = d * d;
      }
      if (cost[static_cast<size_t>(u)] + w < cost[static_cast<size_t>(v)]) {
        cost[static_cast<size_t>(v)] = cost[static_cast<size_t>(u)] + w;
        via[static_cast<size_t>(v)] = u;
      }
    }
  }
  if (via[static_cast<size_t>(b)] < 0) return {-1, -1};
  Pair hop{-1, -1};
  for (int v = b; v != a; v = via[static_cast<size_t>(v)]) {
    const int u = via[static_cast<size_t>(v)];
    if (!joined.count(key(u, v))) hop = {u, v};  // the last one seen is the first from a's side
  }
  distance = distance_of(g, hop.first, hop.second, distances);
  return hop;
}

/// One double-ended search from u to v added to g (a refused start as its status).
ConnectAttempt attempt(TransitionGraph& g, int u, int v, const VecX& rest, const ConnectOptions& o,
                       const CurveSimilarity& sim, double threshold) {
  ConnectAttempt at;
  at.u = u;
  at.v = v;
  const Stopwatch t0;
  const size_t states = g.states.size();
  const auto inter_edges = [&g] {
    return static_cast<int>(std::count_if(g.edges.begin(), g.edges.end(), inter_state));
  };
  const int edges = inter_edges();
  const TransitionSearch t = search_pair(g, u, v, rest, o.search, sim, threshold);
  at.status = t.status;
  at.reached = t.reached;
  at.path_barrier = t.reached ? t.path_barrier : 0.0;
  at.edges_added = inter_edges() - edges;
  at.states_added = static_cast<int>(g.states.size() - states);
  at.seconds = t0.seconds();
  return at;
}

void fill_chain(const TransitionGraph& g, int a, int b, const std::vector<int>& chain, ConnectResult& r) {
  r.connected = true;
  r.status = ConnectStatus::Connected;
  r.chain = chain;
  double top = -std::numeric_limits<double>::infinity();
  for (const int e : chain) top = std::max(top, g.edges[static_cast<size_t>(e)].energy);
  r.barrier_forward = top - g.states[static_cast<size_t>(a)].energy;
  r.barrier_backward = top - g.states[static_cast<size_t>(b)].energy;
  r.barrier_forward_scaled = r.barrier_forward / g.energy_scale;
  r.barrier_backward_scaled = r.barrier_backward / g.energy_scale;
}

}  // namespace

ConnectResult connect_states(TransitionGraph& g, int a, int b, const VecX& rest, const ConnectOptions& o,
                             const CurveSimilarity& sim, double threshold) {
  const int n = static_cast<int>(g.states.size());
  require(a >= 0 && a < n && b >= 0 && b < n, "connect_states: a and b must be states of the graph");
  require(a != b, "connect_states: a and b must be two different states");
  o.validate();
  const Stopwatch t0;
  ConnectResult r;  // status Budget unless joined or exhausted
  std::set<Pair> tried;
  for (const PairSearch& p : g.pairs) tried.insert(key(p.a, p.b));  // searched before this call
  std::map<Pair, double> distances;
  std::optional<std::vector<int>> chain = minimax_path(g, a, b);
  while (!chain && r.attempts < o.max_searches) {
    double d = 0.0;
    const Pair p = next_pair(g, a, b, tried, distances, d);
    if (p.first < 0) {
      r.status = ConnectStatus::Exhausted;
      break;
    }
    tried.insert(key(p.first, p.second));
    ConnectAttempt at = attempt(g, p.first, p.second, rest, o, sim, threshold);
    at.distance = d;
    ++r.attempts;
    if (at.reached && key(at.u, at.v) == key(a, b) && (!r.upper_bound || at.path_barrier < *r.upper_bound))
      r.upper_bound = at.path_barrier;
    r.attempt_list.push_back(at);
    chain = minimax_path(g, a, b);
  }
  if (chain) {
    fill_chain(g, a, b, *chain, r);
    r.upper_bound.reset();
  } else if (r.upper_bound) {
    r.upper_bound_scaled = *r.upper_bound / g.energy_scale;
  }
  r.seconds = t0.seconds();
  return r;
}

}  // namespace ek
