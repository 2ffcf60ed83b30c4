// Transitions between stable states (paper Section 8.5, an open direction):
// the transition graph exp_transitions writes for 4_1 is verified again from
// its stored curves, independently of the searches that found it. Edges
// between two different states are reported, not required (the searches may
// find none: that is a result). The puzzle barriers (connect_states()
// between the two states of a puzzle, paper Fig. 14): every chain reported
// connected is verified again from its stored graph; whether a puzzle
// connects is a measurement, not a claim.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "ek/dataset/dataset_file.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/transitions/run.hpp"
#include "ek/transitions/saddles.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "results.hpp"
#include "transitions_summary.hpp"

namespace {

/// [1] relative agreement of a stored energy with the one computed again
/// (the saddle is converged to the model's gradient tolerance).
constexpr double kGraphEnergyTolerance = 1e-8;

ek::TransitionGraph graph() {
  return ek::read_transitions(ek::paper::results("transitions") + "/transitions_4_1.h5");
}

/// The graph after connect_states() joined its double-ended pairs: the
/// experiment's final graph (the first graph's edges and the joining
/// searches' verified saddles).
ek::TransitionGraph connected_graph() {
  return ek::read_transitions(ek::paper::results("transitions") + "/transitions_4_1_connected.h5");
}

/// Both stored graphs with their file names, for the checks of every saddle.
std::vector<std::pair<std::string, ek::TransitionGraph>> both_graphs() {
  return {{"transitions_4_1.h5", graph()}, {"transitions_4_1_connected.h5", connected_graph()}};
}

ek::VecX rest_of(const ek::Points& x) {
  const ek::DatasetReader reader(ek::paper::results("multistability") + "/multistability.h5");
  return ek::VecX::Constant(x.rows(), reader.metadata().edge_length.value_or(1.0));
}

/// EverySaddleIsVerified's checks on one graph.
void expect_saddles_verified(const ek::TransitionGraph& g) {
  ASSERT_FALSE(g.states.empty());
  const ek::AlexanderPolynomial expected = ek::alexander(g.states.front().positions);
  for (const ek::TransitionState& s : g.states) EXPECT_EQ(ek::alexander(s.positions), expected);
  for (size_t k = 0; k < g.saddles.size(); ++k) {
    const ek::TransitionSaddle& s = g.saddles[k];
    const std::string at = "saddle " + std::to_string(k) + ": ";
    const ek::VecX rest = rest_of(s.positions);
    const ek::PointCheck c = ek::check_point(s.positions, rest, ek::RelaxOptions{});
    EXPECT_LE(c.gradient_norm, c.tolerance) << at;
    ASSERT_TRUE(c.index.converged) << at;
    EXPECT_EQ(c.index.negative, 1) << at << "eigenvalues " << c.index.values.transpose();
    EXPECT_EQ(c.index.near_zero, 0) << at;
    EXPECT_NEAR(c.energy, s.energy, kGraphEnergyTolerance * std::abs(s.energy)) << at;
    ASSERT_FALSE(s.path.empty()) << at;
    for (const ek::Points* end : {&s.path.front(), &s.path.back()}) {
      const ek::PointCheck m = ek::check_point(*end, rest, ek::RelaxOptions{});
      EXPECT_LE(m.gradient_norm, m.tolerance) << at << "an end is no equilibrium";
      ASSERT_TRUE(m.index.converged) << at;
      EXPECT_GT(m.index.values(0), m.threshold) << at << "an end is not stable";
    }
    for (size_t j = 0; j < s.path.size(); ++j) {
      EXPECT_LE(s.path_energies[j], s.energy + 1e-12 * std::abs(s.energy)) << at << "image " << j;
      EXPECT_EQ(ek::alexander(s.path[j]), expected) << at << "image " << j;
    }
  }
}

}  // namespace

// Each saddle of the graph: ||∇E|| <= the solver's tolerance; exactly one
// eigenvalue of H without rigid modes below −ε·λ_min and none within
// ±ε·λ_min; its energy the stored one (1e-8 relative); both ends of its path
// stable equilibria (||∇E|| <= tolerance, lowest eigenvalue above ε·λ_min);
// the saddle the highest image of its path; 4_1's Alexander polynomial on
// every stored image (states, saddles, paths).
TEST(PaperTransitions, EverySaddleIsVerified) {
  for (const auto& [file, g] : both_graphs()) {
    SCOPED_TRACE(file);
    expect_saddles_verified(g);
  }
}

// Every barrier is positive from both sides (E_saddle above the state it was
// searched from and above the minimum reached on the other side), in both
// stored graphs.
TEST(PaperTransitions, EveryBarrierIsPositive) {
  for (const auto& [file, g] : both_graphs())
    for (const ek::TransitionEdge& e : g.edges) {
      EXPECT_GT(e.barrier_forward, 0.0) << file << " edge " << e.from << "-" << e.to;
      EXPECT_GT(e.barrier_backward, 0.0) << file << " edge " << e.from << "-" << e.to;
      EXPECT_EQ(e.energy, g.saddles[static_cast<size_t>(e.saddle)].energy);
    }
}

// The summary agrees with the graph and the tables; the edges between two
// different states and the double-ended searches are reported (measured
// values in docs/reproducing.md).
TEST(PaperTransitions, SummaryAgreesAndInterStateEdgesAreReported) {
  const auto s = ek::paper::summary<ek::results::TransitionsSummary>("transitions");
  const ek::TransitionGraph g = graph();
  EXPECT_EQ(static_cast<int>(g.edges.size()), s.edges);
  EXPECT_EQ(static_cast<int>(g.saddles.size()), s.saddles);
  EXPECT_EQ(static_cast<int>(g.pairs.size()), s.pairs);
  EXPECT_EQ(s.states_refused, 0);
  const auto searches = ek::paper::csv(ek::paper::results("transitions") + "/searches.csv");
  EXPECT_EQ(static_cast<int>(searches.size()), s.searches);
  EXPECT_EQ(s.searches, 2 * s.modes * s.states_searched);
  int inter = 0;
  for (const ek::TransitionEdge& e : g.edges) inter += ek::inter_state(e);
  EXPECT_EQ(inter, s.inter_state_edges);
  for (const ek::PairSearch& p : g.pairs) {
    EXPECT_EQ(p.verified, p.saddle >= 0 && p.status.verified());
    if (p.verified) {
      EXPECT_TRUE(p.reached);
    }
    std::cout << "[ measured ] double-ended " << p.a << " -> " << p.b << ": " << ek::to_string(p.status) << ", "
              << (p.reached ? "reached" : "not reached") << ", " << p.stages << " stages, " << p.seconds << " s"
              << std::endl;
  }
  for (const ek::TransitionEdge& e : g.edges)
    if (ek::inter_state(e))
      std::cout << "[ measured ] inter-state edge " << e.from << " - " << e.to << ": barriers "
                << e.barrier_forward / g.energy_scale << " / " << e.barrier_backward / g.energy_scale << " EI/L"
                << std::endl;
  std::cout << "[ measured ] " << s.edges << " edges, " << s.inter_state_edges << " between states; "
            << s.pairs_reached << " of " << s.pairs << " double-ended searches reached B, " << s.pairs_verified
            << " verified" << std::endl;
}

// At least one verified saddle leaves every state of 4_1 the data set has
// (cluster >= 0): an edge of the experiment's final graph (after
// connect_states()) at the state, single-ended (often to another minimum of
// the same cluster) or from a double-ended or joining search (the edges'
// saddles are verified again by EverySaddleIsVerified). No tolerance: a
// count. The searches from the ground state along its softest modes find
// only near-zero "sliding" saddles whose descents both return to it
// (returns-to-start, not counted); its saddle comes from a double-ended seed
// or from the joining searches, whichever finds one first: which one does
// depends on rounding (the seeds' outcomes differ between BLAS builds).
TEST(PaperTransitions, EveryStateOfTheDataSetHasAVerifiedSaddle) {
  const ek::TransitionGraph g = connected_graph();
  for (size_t k = 0; k < g.states.size(); ++k) {
    if (g.states[k].cluster < 0) continue;
    int edges = 0, inter = 0;
    for (const ek::TransitionEdge& e : g.edges)
      if (e.from == static_cast<int>(k) || e.to == static_cast<int>(k)) {
        ++edges;
        inter += ek::inter_state(e);
      }
    std::cout << "[ measured ] state " << k << " (cluster " << g.states[k].cluster << "): " << edges
              << " verified saddles, " << inter << " to other states" << std::endl;
    EXPECT_GE(edges, 1) << "state " << k;
  }
}

namespace {

/// The chain from state a to b of g (minimax_path()) checked again: `count`
/// inter-state edges, each saddle passing the checks in `model` with rest
/// lengths `rest` (||∇E|| <= the tolerance, exactly one negative eigenvalue
/// and none near zero, the stored energy to 1e-8 relative) with positive
/// barriers from both sides (from the minima its descents reached); the
/// reported barriers (highest saddle − E_a) / (EI/L) and (highest saddle −
/// E_b) / (EI/L), to 1e-9 relative (the CSV keeps 12 digits of the same
/// numbers). Those are not asserted positive: the chain may enter a's or
/// b's state at a minimum of the state lower than its stored energy
/// (connect.hpp).
void expect_verified_chain(const ek::TransitionGraph& g, int a, int b, const ek::RelaxOptions& model,
                           const ek::VecX& rest, const std::map<std::string, std::string>& row, const std::string& at) {
  const auto chain = ek::minimax_path(g, a, b);
  ASSERT_TRUE(chain.has_value()) << at << "no chain in the stored graph";
  EXPECT_EQ(static_cast<int>(chain->size()), std::stoi(row.at("saddles_on_chain"))) << at;
  double top = -1e300;
  for (const int k : *chain) {
    const ek::TransitionEdge& e = g.edges[static_cast<size_t>(k)];
    const ek::TransitionSaddle& x = g.saddles[static_cast<size_t>(e.saddle)];
    EXPECT_TRUE(ek::inter_state(e)) << at;
    EXPECT_GT(e.barrier_forward, 0.0) << at;
    EXPECT_GT(e.barrier_backward, 0.0) << at;
    const ek::PointCheck c = ek::check_point(x.positions, rest, model);
    EXPECT_LE(c.gradient_norm, c.tolerance) << at << "edge " << k;
    ASSERT_TRUE(c.index.converged) << at;
    EXPECT_EQ(c.index.negative, 1) << at << "edge " << k << ": eigenvalues " << c.index.values.transpose();
    EXPECT_EQ(c.index.near_zero, 0) << at << "edge " << k;
    EXPECT_NEAR(c.energy, x.energy, kGraphEnergyTolerance * std::abs(x.energy)) << at << "edge " << k;
    top = std::max(top, e.energy);
  }
  const double forward = (top - g.states[static_cast<size_t>(a)].energy) / g.energy_scale;
  const double backward = (top - g.states[static_cast<size_t>(b)].energy) / g.energy_scale;
  EXPECT_NEAR(std::stod(row.at("barrier_forward_scaled")), forward, 1e-9 * std::abs(forward)) << at;
  EXPECT_NEAR(std::stod(row.at("barrier_backward_scaled")), backward, 1e-9 * std::abs(backward)) << at;
}

}  // namespace

// Each puzzle row reported connected: its stored graph (puzzle_graphs/)
// joins state 0 (the puzzle's state_a) to state 1 by a chain of verified
// saddles (expect_verified_chain(), in the model of the data set the puzzle
// came from). The summary counts the rows.
TEST(PaperTransitions, ConnectedPuzzleChainsAreVerifiedSaddles) {
  const auto s = ek::paper::summary<ek::results::TransitionsSummary>("transitions");
  const std::string path = ek::paper::results("transitions") + "/puzzle_barriers.csv";
  const auto rows = ek::paper::csv(path);
  EXPECT_EQ(s.puzzle_pairs, static_cast<int>(rows.size()));
  int connected = 0;
  for (const auto& row : rows) {
    const std::string at = row.at("knot") + " " + row.at("state_a") + "-" + row.at("state_b") + ": ";
    std::cout << "[ measured ] puzzle " << at << row.at("status") << " after " << row.at("attempts")
              << " searches, barrier " << row.at("barrier_forward_scaled") << " / " << row.at("barrier_backward_scaled")
              << " EI/L, upper bound " << row.at("upper_bound_scaled") << ", " << row.at("seconds") << " s ("
              << row.at("attempt_statuses") << ")" << std::endl;
    EXPECT_LE(std::stoi(row.at("attempts")), 12) << at;  // the largest budget (paper scale)
    if (!ek::paper::flag(row.at("connected"))) continue;
    ++connected;
    const ek::TransitionGraph g = ek::read_transitions(ek::paper::results("transitions") + "/" + row.at("graph"));
    const ek::DatasetReader reader(ek::paper::results(row.at("dataset")));
    ASSERT_GE(g.states.size(), 2u) << at;
    const ek::VecX rest = ek::VecX::Constant(g.states[0].positions.rows(), reader.metadata().edge_length.value_or(1.0));
    expect_verified_chain(g, 0, 1, ek::dataset_model(reader.metadata()), rest, row, at);
  }
  EXPECT_EQ(s.puzzles_connected, connected);
}

// The double-ended pairs of 4_1's graph joined after connect_states()
// (graph_pairs.csv): each chain verified again in transitions_4_1_connected.h5
// (expect_verified_chain()); a pair joined before stays joined.
TEST(PaperTransitions, ConnectedGraphPairsAreVerifiedChains) {
  const auto s = ek::paper::summary<ek::results::TransitionsSummary>("transitions");
  const std::string path = ek::paper::results("transitions") + "/graph_pairs.csv";
  const auto rows = ek::paper::csv(path);
  EXPECT_EQ(static_cast<int>(rows.size()), s.pairs);
  const ek::TransitionGraph g = ek::read_transitions(ek::paper::results("transitions") + "/transitions_4_1_connected.h5");
  const ek::DatasetReader reader(ek::paper::results("multistability") + "/multistability.h5");
  const ek::RelaxOptions model = ek::dataset_model(reader.metadata());
  int before = 0, after = 0;
  for (const auto& row : rows) {
    const int a = std::stoi(row.at("a")), b = std::stoi(row.at("b"));
    const std::string at = "pair " + row.at("a") + "-" + row.at("b") + ": ";
    std::cout << "[ measured ] 4_1 " << at << (ek::paper::flag(row.at("connected_before")) ? "joined" : "apart")
              << " before, " << (ek::paper::flag(row.at("connected_after")) ? "joined" : "apart") << " after "
              << row.at("attempts") << " searches, barrier " << row.at("barrier_forward_scaled") << " EI/L ("
              << row.at("attempt_statuses") << ")" << std::endl;
    before += ek::paper::flag(row.at("connected_before"));
    if (ek::paper::flag(row.at("connected_before"))) {
      EXPECT_TRUE(ek::paper::flag(row.at("connected_after"))) << at;
    }
    if (!ek::paper::flag(row.at("connected_after"))) continue;
    ++after;
    const ek::VecX rest = ek::VecX::Constant(g.states[0].positions.rows(), reader.metadata().edge_length.value_or(1.0));
    expect_verified_chain(g, a, b, model, rest, row, at);
  }
  EXPECT_EQ(s.graph_pairs_connected_before, before);
  EXPECT_EQ(s.graph_pairs_connected_after, after);
}
