#pragma once
// JSON and text of a transition graph (`knots transitions`, `knots path`;
// the keys are listed in docs/cli.md and are a contract).
#include <iostream>
#include <map>

#include "args.hpp"
#include "ek/core/errors.hpp"
#include "ek/transitions/graph.hpp"
#include "output.hpp"

namespace ek::cli {

/// A state of the graph given on the command line (`what`: its argument's
/// name): an integer in 0..states−1, else InputError.
inline int parse_state(const std::string& text, const TransitionGraph& g, const std::string& what) {
  const long long k = parse_integer(text, what);
  require_input(k >= 0 && k < static_cast<long long>(g.states.size()),
                what + " must be a state of the graph, 0.." + std::to_string(g.states.size() - 1));
  return static_cast<int>(k);
}

inline Json graph_saddles_json(const TransitionGraph& g) {
  Json a = Json::array();
  for (const TransitionSaddle& s : g.saddles) {
    Json j;
    j["energy"] = number(s.energy);
    j["barrier_forward"] = number(s.energy - s.energy_from);
    j["barrier_backward"] = number(s.energy - s.energy_to);
    j["barrier_forward_scaled"] = number((s.energy - s.energy_from) / g.energy_scale);
    j["barrier_backward_scaled"] = number((s.energy - s.energy_to) / g.energy_scale);
    j["double_ended"] = s.double_ended;
    j["inter_state"] = s.from != s.to;
    j["negative_eigenvalue"] = number(s.negative_eigenvalue);
    j["second_eigenvalue"] = number(s.second_eigenvalue);
    j["index"] = s.index;
    j["gradient_norm"] = number(s.gradient_norm);
    j["minima"] = {s.from, s.to};
    j["images"] = s.path.size();
    a.push_back(j);
  }
  return a;
}

inline Json graph_json(const TransitionGraph& g) {
  Json j;
  j["knot"] = g.knot;
  j["cut"] = number(g.cut);
  j["energy_scale"] = number(g.energy_scale);
  j["saddles"] = graph_saddles_json(g);
  Json states = Json::array();
  std::map<int, const StateSearches*> by_state;
  for (const StateSearches& s : g.searches) by_state[s.state] = &s;
  int searches = 0, verified = 0;
  for (size_t k = 0; k < g.states.size(); ++k) {
    const TransitionState& s = g.states[k];
    Json sj;
    sj["state"] = k;
    sj["cluster"] = s.cluster;
    sj["equilibrium"] = s.equilibrium;
    sj["energy"] = number(s.energy);
    const auto it = by_state.find(static_cast<int>(k));
    int n = 0, v = 0;
    if (it != by_state.end()) {
      for (const SaddleRecord& r : it->second->records) {
        ++n;
        v += r.verified ? 1 : 0;
      }
      if (!it->second->error.empty()) sj["error"] = it->second->error;
    }
    sj["searches"] = n;
    sj["verified"] = v;
    searches += n;
    verified += v;
    states.push_back(sj);
  }
  j["states"] = states;
  Json edges = Json::array();
  for (const TransitionEdge& e : g.edges) {
    Json ej;
    ej["from"] = e.from;
    ej["to"] = e.to;
    ej["saddle"] = e.saddle;
    ej["inter_state"] = inter_state(e);
    ej["energy"] = number(e.energy);
    ej["barrier_forward"] = number(e.barrier_forward);
    ej["barrier_backward"] = number(e.barrier_backward);
    ej["barrier_forward_scaled"] = number(e.barrier_forward / g.energy_scale);
    ej["barrier_backward_scaled"] = number(e.barrier_backward / g.energy_scale);
    edges.push_back(ej);
  }
  j["edges"] = edges;
  Json pairs = Json::array();
  for (const PairSearch& p : g.pairs) {
    Json pj;
    pj["a"] = p.a;
    pj["b"] = p.b;
    pj["status"] = to_string(p.status);
    pj["seed_statuses"] = to_string(p.seed_statuses);
    pj["reached"] = p.reached;
    pj["verified"] = p.verified;
    pj["stages"] = p.stages;
    pj["path_barrier_scaled"] = p.reached ? number(p.path_barrier / g.energy_scale) : Json(nullptr);
    pj["reached_similarity"] = number(p.reached_similarity);
    pj["saddle"] = p.saddle;
    pj["seconds"] = number(p.seconds);
    pairs.push_back(pj);
  }
  j["pairs"] = pairs;
  j["searches"] = searches;
  j["verified_searches"] = verified;
  return j;
}

inline void print_graph(const TransitionGraph& g, double seconds) {
  std::cout << g.knot << ": " << g.states.size() << " states, " << g.saddles.size() << " saddles, " << g.edges.size()
            << " edges (EI/L = " << fmt(g.energy_scale, 6) << ")\n";
  for (size_t k = 0; k < g.states.size(); ++k)
    std::cout << "  state " << k << ": energy " << fmt(g.states[k].energy)
              << (g.states[k].cluster < 0 ? " (not in the data set)" : "") << "\n";
  for (const TransitionEdge& e : g.edges)
    std::cout << "  edge " << e.from << " -- " << e.to << ": saddle " << fmt(e.energy) << ", barriers "
              << fmt(e.barrier_forward, 6) << " / " << fmt(e.barrier_backward, 6) << " ("
              << fmt(e.barrier_forward / g.energy_scale, 5) << " / " << fmt(e.barrier_backward / g.energy_scale, 5)
              << " EI/L)" << (inter_state(e) ? "" : " (within the state)") << "\n";
  for (const PairSearch& p : g.pairs)
    std::cout << "  double-ended " << p.a << " -> " << p.b << ": " << to_string(p.status) << " (" << p.stages
              << " stages, "
              << (p.reached ? "reached" : "not reached") << ", " << fmt(p.seconds, 3) << " s)\n";
  std::cout << "seconds: " << fmt(seconds, 4) << "\n";
}

}  // namespace ek::cli
