// connect_states(): on a hand-made graph, the components follow inter-state
// edges only and two states already joined come back with their minimax
// chain and its barrier without a search; on relaxed BFACF samples of 4_1,
// the searches it runs stay within the budget, never repeat a pair, and a
// chain it returns joins a to b through saddles that pass the checks again
// on their own, its barrier the highest of them minus E_a.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/transitions/connect.hpp"
#include "testing.hpp"
#include "transitions_test_util.hpp"

using namespace ek;
using namespace ek::transitionstest;

namespace {

Points square(double shift) {
  Points P(4, 3);
  P << 0, 0, shift, 1, 0, shift, 1, 1, shift, 0, 1, shift;
  return P;
}

/// States 0..3 (energies 1.0, 1.1, 1.2, 1.3); edges 0-1 (saddle 5), 1-1
/// (two minima of state 1, saddle 2), 2-3 (saddle 4).
TransitionGraph small_graph() {
  TransitionGraph g;
  g.energy_scale = 0.5;
  for (int k = 0; k < 4; ++k) g.states.push_back({k, k, 1.0 + 0.1 * k, square(k)});
  const int ends[3][2] = {{0, 1}, {1, 1}, {2, 3}};
  const double energies[3] = {5.0, 2.0, 4.0};
  for (int k = 0; k < 3; ++k) {
    TransitionSaddle s;
    s.energy = energies[k];
    s.from = ends[k][0];
    s.to = ends[k][1];
    s.positions = square(10 + k);
    g.saddles.push_back(s);
    g.edges.push_back({s.from, s.to, k, s.energy, s.energy - g.states[s.from].energy, s.energy - g.states[s.to].energy});
  }
  return g;
}

/// A graph of three relaxed BFACF samples of 4_1 (seed 1, unit edges),
/// relaxed by the one-level method, with which these tests were designed
/// (from the default's states of these samples the searches below do not
/// find the saddles they look for), the
/// energies those of the relaxation, EI/L as the energy scale.
TransitionGraph samples41() {
  SampleOptions so;
  so.vertices = kVertices;
  so.count = 3;
  const SampleBatch batch = sample_knot(KnotTable::global().at("4_1"), so);
  TransitionGraph g;
  g.knot = "4_1";
  g.cut = 0.05;
  for (const auto& p : batch.samples) {
    const RelaxResult r = relax(to_points(p), with_method(RelaxOptions{}, "one-level"));
    EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
    g.states.push_back({-1, -1, r.energy.total, r.positions});
  }
  g.energy_scale = RelaxOptions{}.material.bending_stiffness() / kVertices;
  return g;
}

struct ConnectRun {
  TransitionGraph graph;
  ConnectResult result;
  int budget = 8;
};

/// connect_states(0, 2) on samples41(), run once for the tests below (the
/// search between 0 and 2 itself ends "other-minima").
const ConnectRun& run41() {
  static const ConnectRun r = [] {
    ConnectRun x;
    x.graph = samples41();
    ConnectOptions o;
    o.max_searches = x.budget;
    x.result = connect_states(x.graph, 0, 2, VecX::Ones(kVertices), o, sim, 0.95);
    std::cout << "[ measured ] 4_1 samples 0 -> 2: " << to_string(x.result.status) << " after " << x.result.attempts
              << " searches, " << x.graph.states.size() << " states, " << x.graph.edges.size() << " edges, "
              << x.result.seconds << " s" << std::endl;
    for (const ConnectAttempt& a : x.result.attempt_list)
      std::cout << "[ measured ]   " << a.u << " -> " << a.v << " (d = " << a.distance
                << "): " << to_string(a.status) << ", +"
                << a.edges_added << " inter-state edges, +" << a.states_added << " states, " << a.seconds << " s"
                << std::endl;
    if (x.result.connected)
      std::cout << "[ measured ]   chain of " << x.result.chain.size() << " saddles, barrier "
                << x.result.barrier_forward_scaled << " EI/L" << std::endl;
    return x;
  }();
  return r;
}

}  // namespace

TEST(ConnectStates, ComponentsFollowInterStateEdges) {
  const TransitionGraph g = small_graph();
  EXPECT_EQ(connected_states(g, 0), (std::vector<int>{0, 1}));
  EXPECT_EQ(connected_states(g, 1), (std::vector<int>{0, 1}));
  EXPECT_EQ(connected_states(g, 3), (std::vector<int>{2, 3}));
  EXPECT_THROW(connected_states(g, 4), std::invalid_argument);
}

// Joined already: no search runs; the chain is the edge 0-1, read from either end.
TEST(ConnectStates, JoinedStatesNeedNoSearch) {
  TransitionGraph g = small_graph();
  const ConnectResult r = connect_states(g, 1, 0, VecX::Ones(4), {}, sim, 0.95);
  EXPECT_TRUE(r.connected);
  EXPECT_EQ(r.status, ConnectStatus::Connected);
  EXPECT_EQ(r.attempts, 0);
  EXPECT_EQ(r.chain, (std::vector<int>{0}));
  EXPECT_DOUBLE_EQ(r.barrier_forward, 5.0 - 1.1);
  EXPECT_DOUBLE_EQ(r.barrier_backward, 5.0 - 1.0);
  EXPECT_DOUBLE_EQ(r.barrier_forward_scaled, (5.0 - 1.1) / 0.5);
  EXPECT_FALSE(r.upper_bound.has_value());
  EXPECT_EQ(g.pairs.size(), 0u);
}

// States that are no stable states of a knot (translated squares: every
// search ends "same-state" or refused, adding no edge): the loop tries each
// pair between the two sides once, never the pair the graph records as
// searched already (1-2), and ends "exhausted".
TEST(ConnectStates, EveryPairOnceThenExhausted) {
  TransitionGraph g = small_graph();
  PairSearch searched;
  searched.a = 2;
  searched.b = 1;
  searched.status = SearchOutcome::OtherMinima;
  g.pairs.push_back(searched);
  ConnectOptions o;
  o.max_searches = 10;
  const ConnectResult r = connect_states(g, 0, 3, VecX::Ones(4), o, sim, 0.95);
  EXPECT_FALSE(r.connected);
  EXPECT_EQ(r.status, ConnectStatus::Exhausted);
  ASSERT_EQ(r.attempts, 3);  // 0-2, 0-3, 1-3
  std::set<std::pair<int, int>> seen;
  for (const ConnectAttempt& a : r.attempt_list) {
    EXPECT_FALSE(a.status.verified());
    EXPECT_EQ(a.edges_added, 0);
    const std::pair<int, int> k{std::min(a.u, a.v), std::max(a.u, a.v)};
    EXPECT_TRUE(seen.insert(k).second);
    EXPECT_NE(k, std::make_pair(1, 2));
    EXPECT_TRUE(a.u <= 1 && a.v >= 2) << a.u << "-" << a.v;  // from a's side to b's
  }
  EXPECT_EQ(g.pairs.size(), 4u);
  EXPECT_FALSE(r.upper_bound.has_value());
}

TEST(ConnectStates, MisuseThrows) {
  TransitionGraph g = small_graph();
  EXPECT_THROW(connect_states(g, 2, 2, VecX::Ones(4), {}, sim, 0.95), std::invalid_argument);
  EXPECT_THROW(connect_states(g, 0, 4, VecX::Ones(4), {}, sim, 0.95), std::invalid_argument);
  EXPECT_THROW(connect_states(g, -1, 2, VecX::Ones(4), {}, sim, 0.95), std::invalid_argument);
  ConnectOptions o;
  o.max_searches = 0;
  fixtures::expect_input_error([&] { connect_states(g, 0, 2, VecX::Ones(4), o, sim, 0.95); }, "max_searches");
  o = {};
  o.search.seeds = 0;
  EXPECT_THROW(o.validate(), InputError);
}

// The budget holds, no pair (in either order) is searched twice, every
// search is in the graph's pair list, and the result agrees with the graph:
// joined exactly when a chain of edges exists, the loop ending at the first
// attempt that joined them.
TEST(ConnectStates, SearchesStayWithinTheBudgetAndNeverRepeatAPair) {
  const ConnectRun& x = run41();
  const ConnectResult& r = x.result;
  EXPECT_GE(r.attempts, 1);
  EXPECT_LE(r.attempts, x.budget);
  ASSERT_EQ(static_cast<int>(r.attempt_list.size()), r.attempts);
  ASSERT_EQ(x.graph.pairs.size(), r.attempt_list.size());
  std::set<std::pair<int, int>> seen;
  for (size_t k = 0; k < r.attempt_list.size(); ++k) {
    const ConnectAttempt& a = r.attempt_list[k];
    EXPECT_NE(a.u, a.v);
    EXPECT_TRUE(seen.insert({std::min(a.u, a.v), std::max(a.u, a.v)}).second) << a.u << "-" << a.v << " twice";
    EXPECT_EQ(x.graph.pairs[k].a, a.u);
    EXPECT_EQ(x.graph.pairs[k].b, a.v);
    EXPECT_EQ(x.graph.pairs[k].status, a.status);
    EXPECT_GE(a.distance, 0.0);
  }
  EXPECT_EQ(r.connected, minimax_path(x.graph, 0, 2).has_value());
  if (r.connected) {
    EXPECT_EQ(r.status, ConnectStatus::Connected);
  } else {
    EXPECT_TRUE(r.status == ConnectStatus::Budget ? r.attempts == x.budget : r.status == ConnectStatus::Exhausted)
        << to_string(r.status);
    EXPECT_TRUE(r.chain.empty());
  }
}

// A returned chain: consecutive inter-state edges of the graph from a to b;
// its barrier the highest saddle on it minus E_a (and minus E_b); every
// saddle on it recorded with index one and passing the checks again here:
// gradient within the tolerance, exactly one negative eigenvalue and none
// near zero, its energy the stored one (1e-8 relative), above both ends.
TEST(ConnectStates, AChainJoinsAToBThroughVerifiedSaddles) {
  const ConnectRun& x = run41();
  const ConnectResult& r = x.result;
  // measured: after 7 searches, a chain of 4 saddles through the 3 other states
  ASSERT_TRUE(r.connected) << to_string(r.status);
  const TransitionGraph& g = x.graph;
  ASSERT_FALSE(r.chain.empty());
  int at = 0;
  double top = -1e300;
  for (const int k : r.chain) {
    ASSERT_GE(k, 0);
    ASSERT_LT(k, static_cast<int>(g.edges.size()));
    const TransitionEdge& e = g.edges[static_cast<size_t>(k)];
    EXPECT_TRUE(inter_state(e));
    ASSERT_TRUE(e.from == at || e.to == at) << "edge " << k << " does not continue the chain at state " << at;
    at = e.from == at ? e.to : e.from;
    top = std::max(top, e.energy);
    const TransitionSaddle& s = g.saddles[static_cast<size_t>(e.saddle)];
    EXPECT_EQ(s.index, 1);
    EXPECT_GT(e.barrier_forward, 0.0);
    EXPECT_GT(e.barrier_backward, 0.0);
    const PointCheck c = check_point(s.positions, VecX::Ones(kVertices), RelaxOptions{});
    EXPECT_LE(c.gradient_norm, c.tolerance);
    ASSERT_TRUE(c.index.converged);
    EXPECT_EQ(c.index.negative, 1);
    EXPECT_EQ(c.index.near_zero, 0);
    EXPECT_NEAR(c.energy, s.energy, 1e-8 * s.energy);
  }
  EXPECT_EQ(at, 2);
  EXPECT_DOUBLE_EQ(r.barrier_forward, top - g.states[0].energy);
  EXPECT_DOUBLE_EQ(r.barrier_backward, top - g.states[2].energy);
  EXPECT_GT(r.barrier_forward, 0.0);
  EXPECT_DOUBLE_EQ(r.barrier_forward_scaled, r.barrier_forward / g.energy_scale);
}
