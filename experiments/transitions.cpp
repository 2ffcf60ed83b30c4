// exp_transitions: the transition graph of 4_1's stable states (paper
// Section 8.5: the paper finds many stable states per knot but cannot yet
// find the transitions between them nor their barriers). The states are the
// clusters of ../multistability/multistability.h5 at kClusterCut (by
// energy); from every one, the single-ended searches (saddles.hpp), and
// double-ended searches (double_ended.hpp) between states of neighbouring
// energy rank (knot_transitions(), run.hpp). Writes transitions_4_1.h5 (the
// graph, transitions_file.hpp), states.csv, edges.csv, searches.csv,
// pairs.csv, profile.csv (the energy along each edge's path) and
// summary.json (docs/results.md, "transitions"). Puzzle barriers (paper
// Fig. 14): for the first pairs of ../puzzles/puzzles.csv, connect_states()
// (connect.hpp) between the two states; puzzle_barriers.csv and each pair's
// graph as puzzle_graphs/puzzle_<k>.h5. And for each double-ended pair of
// the 4_1 graph not joined by its edges, connect_states() on a copy of the
// graph (transitions_4_1_connected.h5, graph_pairs.csv).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

#include "ek/core/parse.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/transitions/connect.hpp"
#include "ek/transitions/run.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "experiment.hpp"
#include "scales.hpp"
#include "transitions_summary.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

TransitionRunOptions run_options(const Args& a) {
  TransitionRunOptions r;
  r.cut = kClusterCut;
  r.saddles.modes = by_scale(a, 2, 2, 4);
  r.max_states = 0;  // every state: each must have a verified saddle (check_transitions)
  r.pair_gap = by_scale(a, 1, 2, 2);
  r.max_pairs = by_scale(a, 5, 9, 40);
  r.progress = [](const std::string& what, int, int) { std::cout << "  " << what << std::endl; };
  return r;
}

void write_states(const Args& a, const TransitionGraph& g, results::TransitionsSummary& sum) {
  Csv csv(a.out + "/states.csv",
          {"state", "cluster", "equilibrium", "energy", "energy_scaled", "searches", "verified", "error"});
  for (size_t k = 0; k < g.states.size(); ++k) {
    int n = 0, v = 0;
    std::string error;
    for (const StateSearches& s : g.searches) {
      if (s.state != static_cast<int>(k)) continue;
      error = s.error;
      for (const SaddleRecord& r : s.records) {
        ++n;
        v += r.verified;
      }
    }
    const TransitionState& s = g.states[k];
    sum.states += s.cluster >= 0;
    sum.new_states += s.cluster < 0;
    csv.row({std::to_string(k), std::to_string(s.cluster), std::to_string(s.equilibrium), Csv::num(s.energy),
             Csv::num(s.energy / g.energy_scale), std::to_string(n), std::to_string(v), error});
  }
  csv.commit();
}

void write_edges(const Args& a, const TransitionGraph& g, results::TransitionsSummary& sum) {
  Csv csv(a.out + "/edges.csv", {"edge", "from", "to", "saddle", "inter_state", "double_ended", "saddle_energy",
                                 "barrier_forward", "barrier_backward", "barrier_forward_scaled",
                                 "barrier_backward_scaled", "negative_eigenvalue"});
  Csv profile(a.out + "/profile.csv", {"edge", "image", "energy", "energy_scaled", "saddle"});
  const double s = g.energy_scale;
  for (size_t k = 0; k < g.edges.size(); ++k) {
    const TransitionEdge& e = g.edges[k];
    const TransitionSaddle& x = g.saddles[static_cast<size_t>(e.saddle)];
    csv.row({std::to_string(k), std::to_string(e.from), std::to_string(e.to), std::to_string(e.saddle),
             Csv::flag(inter_state(e)), Csv::flag(x.double_ended), Csv::num(e.energy), Csv::num(e.barrier_forward),
             Csv::num(e.barrier_backward), Csv::num(e.barrier_forward / s), Csv::num(e.barrier_backward / s),
             Csv::num(x.negative_eigenvalue)});
    sum.edge_list.push_back({e.from, e.to, inter_state(e), x.double_ended, e.energy, e.barrier_forward,
                             e.barrier_backward, e.barrier_forward / s, e.barrier_backward / s});
    sum.inter_state_edges += inter_state(e);
    for (size_t j = 0; j < x.path.size(); ++j)
      profile.row({std::to_string(k), std::to_string(j), Csv::num(x.path_energies[j]),
                   Csv::num(x.path_energies[j] / s), Csv::flag(static_cast<int>(j) == x.saddle_image)});
  }
  sum.edges = static_cast<int>(g.edges.size());
  csv.commit();
  profile.commit();
}

void write_searches(const Args& a, const TransitionGraph& g, results::TransitionsSummary& sum) {
  Csv csv(a.out + "/searches.csv", {"state", "mode", "direction", "status", "verified", "energy", "gradient_norm",
                                    "index", "iterations", "seconds"});
  double seconds = 0.0;
  for (const StateSearches& s : g.searches) {
    ++sum.states_searched;
    sum.states_refused += !s.error.empty();
    for (const SaddleRecord& r : s.records) {
      csv.row({std::to_string(s.state), std::to_string(r.mode), std::to_string(r.direction), to_string(r.status),
               Csv::flag(r.verified), Csv::num(r.energy), Csv::num(r.gradient_norm), std::to_string(r.index),
               std::to_string(r.iterations), Csv::num(r.seconds, 4)});
      ++sum.searches;
      sum.verified += r.verified;
      seconds += r.seconds;
    }
  }
  csv.commit();
  sum.seconds_per_search = sum.searches > 0 ? seconds / sum.searches : 0.0;
}

void write_pairs(const Args& a, const TransitionGraph& g, results::TransitionsSummary& sum) {
  Csv csv(a.out + "/pairs.csv", {"a", "b", "status", "seed_statuses", "reached", "verified", "stages", "path_barrier_scaled",
                                 "reached_similarity", "saddle", "seconds"});
  double seconds = 0.0;
  for (const PairSearch& p : g.pairs) {
    const double barrier = p.reached ? p.path_barrier / g.energy_scale : 0.0;
    const std::string status = to_string(p.status), seeds = to_string(p.seed_statuses);
    csv.row({std::to_string(p.a), std::to_string(p.b), status, seeds, Csv::flag(p.reached), Csv::flag(p.verified),
             std::to_string(p.stages), p.reached ? Csv::num(barrier) : "", Csv::num(p.reached_similarity),
             std::to_string(p.saddle), Csv::num(p.seconds, 4)});
    sum.pair_list.push_back({p.a, p.b, status, seeds, p.reached, p.verified, p.stages, barrier, p.seconds});
    ++sum.pairs;
    sum.pairs_reached += p.reached;
    sum.pairs_verified += p.verified;
    seconds += p.seconds;
  }
  csv.commit();
  sum.seconds_per_pair = sum.pairs > 0 ? seconds / sum.pairs : 0.0;
}

/// One row of ../puzzles/puzzles.csv.
struct PuzzleRow {
  std::string knot, curve_a, curve_b;
  int state_a = -1, state_b = -1;
  double link = 0.0;
};

/// The rows of puzzles.csv (InputError when a needed column is missing or a cell is no number).
std::vector<PuzzleRow> read_puzzles(const std::string& path) {
  const std::string at = "exp_transitions: " + path;
  std::vector<PuzzleRow> rows;
  for (const CsvRow& c : read_csv_rows(path, "exp_transitions", {"knot", "state_a", "state_b", "link", "curve_a",
                                                                 "curve_b"}))
    rows.push_back({c.at("knot"), c.at("curve_a"), c.at("curve_b"),
                    static_cast<int>(parse_integer(c.at("state_a"), at + ": state_a")),
                    static_cast<int>(parse_integer(c.at("state_b"), at + ": state_b")),
                    parse_number(c.at("link"), at + ": link")});
  return rows;
}

/// The first `count` rows, one per knot first (in file order), then the rest in order.
std::vector<PuzzleRow> pick_puzzles(const std::vector<PuzzleRow>& rows, int count) {
  std::vector<PuzzleRow> out;
  std::set<std::string> knots;
  std::vector<char> taken(rows.size(), 0);
  for (size_t k = 0; k < rows.size() && static_cast<int>(out.size()) < count; ++k)
    if (knots.insert(rows[k].knot).second) {
      out.push_back(rows[k]);
      taken[k] = 1;
    }
  for (size_t k = 0; k < rows.size() && static_cast<int>(out.size()) < count; ++k)
    if (!taken[k]) out.push_back(rows[k]);
  return out;
}

/// The graph of one puzzle's two states, polished (prepare_start()), in the
/// model of the data set holding the knot (exp_puzzles reads
/// multistability.h5, then dataset.h5); energy scale EI/L as
/// knot_transitions(). `rest` receives the data set's edge lengths,
/// `source` the data set (relative to the results root).
TransitionGraph puzzle_graph(const Args& a, const PuzzleRow& z, KnotSaddleOptions& model, VecX& rest,
                             std::string& source) {
  for (const std::string f : {"multistability/multistability.h5", "dataset/dataset.h5"}) {
    const std::string path = a.results + "/" + f;
    if (source.empty() && std::filesystem::exists(path) && DatasetReader(path).has_knot(z.knot)) source = f;
  }
  require_input(!source.empty(), "exp_transitions: no data set holds the puzzle knot " + z.knot);
  const DatasetMetadata m = DatasetReader(a.results + "/" + source).metadata();
  model.relax = dataset_model(m);
  TransitionGraph g;
  g.knot = z.knot;
  g.cut = kClusterCut;
  const std::string dir = a.results + "/puzzles/";
  const Points xa = read_curve(dir + z.curve_a), xb = read_curve(dir + z.curve_b);
  rest = VecX::Constant(xa.rows(), m.edge_length.value_or(1.0));
  const SaddleStart sa = prepare_start(xa, rest, model), sb = prepare_start(xb, rest, model);
  g.states.push_back({-1, z.state_a, sa.energy, sa.positions});
  g.states.push_back({-1, z.state_b, sb.energy, sb.positions});
  g.energy_scale = model.relax.material.bending_stiffness() / (rest(0) * static_cast<double>(xa.rows()));
  return g;
}

/// The attempt_statuses cell: "u-v:<status>" of every search, ";" between them.
std::string attempt_statuses(const ConnectResult& c) {
  std::string out;
  for (const ConnectAttempt& t : c.attempt_list)
    out += (out.empty() ? "" : ";") + std::to_string(t.u) + "-" + std::to_string(t.v) + ":" + to_string(t.status);
  return out;
}

/// Puzzle barriers: connect_states() between the two states of the first
/// puzzles (ci 1, default 4, paper 12; distinct knots first), budget ci 2,
/// default 6, paper 12 searches. Writes puzzle_barriers.csv and
/// puzzle_graphs/puzzle_<k>.h5 (the graph of row k).
void puzzle_barriers(const Args& a, const TransitionRunOptions& r, results::TransitionsSummary& sum) {
  Csv csv(a.out + "/puzzle_barriers.csv",
          {"knot", "state_a", "state_b", "link", "status", "connected", "attempts", "saddles_on_chain",
           "barrier_forward_scaled", "barrier_backward_scaled", "upper_bound_scaled", "seconds", "attempt_statuses",
           "graph", "dataset"});
  const std::string input = a.results + "/puzzles/puzzles.csv";
  std::vector<PuzzleRow> rows;
  if (std::filesystem::exists(input)) rows = pick_puzzles(read_puzzles(input), by_scale(a, 1, 4, 12));
  std::filesystem::create_directories(a.out + "/puzzle_graphs");
  sum.puzzle_pairs = 0;
  sum.puzzles_connected = 0;
  for (size_t k = 0; k < rows.size(); ++k) {
    const PuzzleRow& z = rows[k];
    std::cout << "  puzzle " << k + 1 << "/" << rows.size() << ": " << z.knot << " " << z.state_a << " - "
              << z.state_b << std::endl;
    ConnectOptions o;
    o.max_searches = by_scale(a, 2, 6, 12);
    o.search = r.pair;
    o.search.saddle = r.saddles;
    VecX rest;
    std::string status, source;
    TransitionGraph g;
    ConnectResult c;
    try {
      g = puzzle_graph(a, z, o.search.saddle, rest, source);
      c = connect_states(g, 0, 1, rest, o, knot_similarity(z.knot), 1.0 - kClusterCut);
      status = to_string(c.status);
    } catch (const InputError& e) {
      status = to_string(SearchStatus::refused(e.what()));
    }
    const std::string statuses = attempt_statuses(c);
    const std::string graph = "puzzle_graphs/puzzle_" + std::to_string(k) + ".h5";
    if (!g.states.empty())
      write_transitions(a.out + "/" + graph, g, a.results + "/" + source,
                        "puzzle " + z.knot + " " + std::to_string(z.state_a) + "-" + std::to_string(z.state_b) +
                            " max_searches=" + std::to_string(o.max_searches),
                        true);
    csv.row({z.knot, std::to_string(z.state_a), std::to_string(z.state_b), Csv::num(z.link), status,
             Csv::flag(c.connected), std::to_string(c.attempts), std::to_string(c.chain.size()),
             c.connected ? Csv::num(c.barrier_forward_scaled) : "", c.connected ? Csv::num(c.barrier_backward_scaled) : "",
             c.upper_bound_scaled ? Csv::num(*c.upper_bound_scaled) : "", Csv::num(c.seconds, 4), statuses,
             g.states.empty() ? "" : graph, source});
    ++sum.puzzle_pairs;
    sum.puzzles_connected += c.connected;
  }
  csv.commit();
}

/// For each double-ended pair (a, b) of g in order: joined by g's edges
/// (before), and after connect_states() on a copy of g that grows over the
/// pairs (budget ci 1, default 3, paper 6 searches per pair not joined yet).
/// Writes graph_pairs.csv and the grown graph as transitions_4_1_connected.h5.
void connect_graph_pairs(const Args& a, const TransitionRunOptions& r, const TransitionGraph& g,
                         results::TransitionsSummary& sum) {
  Csv csv(a.out + "/graph_pairs.csv", {"a", "b", "connected_before", "connected_after", "attempts", "saddles_on_chain",
                                       "barrier_forward_scaled", "barrier_backward_scaled", "seconds",
                                       "attempt_statuses"});
  TransitionGraph c = g;
  ConnectOptions o;
  o.max_searches = by_scale(a, 1, 3, 6);
  o.search = r.pair;
  o.search.saddle = r.saddles;
  const std::string input = a.results + "/multistability/multistability.h5";
  const DatasetMetadata m = DatasetReader(input).metadata();
  o.search.saddle.relax = dataset_model(m);
  const VecX rest = VecX::Constant(g.states.front().positions.rows(), m.edge_length.value_or(1.0));
  const CurveSimilarity sim = knot_similarity("4_1");
  sum.graph_pairs_connected_before = 0;
  sum.graph_pairs_connected_after = 0;
  for (const PairSearch& p : g.pairs) {
    const bool before = minimax_path(g, p.a, p.b).has_value();
    std::cout << "  connecting " << p.a << " - " << p.b << std::endl;
    const ConnectResult x = connect_states(c, p.a, p.b, rest, o, sim, 1.0 - kClusterCut);
    const std::string statuses = attempt_statuses(x);
    csv.row({std::to_string(p.a), std::to_string(p.b), Csv::flag(before), Csv::flag(x.connected),
             std::to_string(x.attempts), std::to_string(x.chain.size()),
             x.connected ? Csv::num(x.barrier_forward_scaled) : "", x.connected ? Csv::num(x.barrier_backward_scaled) : "",
             Csv::num(x.seconds, 4), statuses});
    sum.graph_pairs_connected_before += before;
    sum.graph_pairs_connected_after += x.connected;
  }
  write_transitions(a.out + "/transitions_4_1_connected.h5", c, input, "connected " + std::to_string(o.max_searches),
                    true);
  csv.commit();
}

void run(const Args& a) {
  const std::string input = a.results + "/multistability/multistability.h5";
  require_input(std::filesystem::exists(input),
                "exp_transitions: run the multistability experiment first (" + input + ")");
  const TransitionRunOptions r = run_options(a);
  announce(a, "exp_transitions", "the transition graph of 4_1's states", by_scale(a, 120.0, 900.0, 7200.0));
  const DatasetReader reader(input);
  const KnotEntry e = reader.read("4_1");
  const TransitionGraph g = knot_transitions(e, reader.metadata(), r);
  write_transitions(a.out + "/transitions_4_1.h5", g, input,
                    transition_run_key("4_1", r, reader.metadata().edge_length.value_or(1.0)), true);
  results::TransitionsSummary sum;
  sum.scale = a.scale_name;
  sum.knot = "4_1";
  sum.cut = kClusterCut;
  sum.modes = r.saddles.modes;
  sum.energy_scale = g.energy_scale;
  sum.saddles = static_cast<int>(g.saddles.size());
  write_states(a, g, sum);
  write_edges(a, g, sum);
  write_searches(a, g, sum);
  write_pairs(a, g, sum);
  connect_graph_pairs(a, r, g, sum);
  puzzle_barriers(a, r, sum);
  sum.seconds = elapsed_seconds();
  write_summary(a, sum);
  std::cout << "exp_transitions: 4_1, " << sum.states_searched << " of " << sum.states << " states searched, "
            << sum.verified << " of " << sum.searches << " single-ended searches verified, " << sum.pairs_reached
            << " of " << sum.pairs << " double-ended searches reached B, " << sum.pairs_verified << " verified; "
            << sum.edges << " edges (" << sum.inter_state_edges << " between states)" << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_transitions",
                        "Transitions: the transition graph of 4_1's states (saddles, edges, barriers).", run);
}
