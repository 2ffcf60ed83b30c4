// exp_transitions: the transition graph of 4_1's stable states (paper
// Section 8.5: the paper finds many stable states per knot but cannot yet
// find the transitions between them nor their barriers). The states are the
// clusters of ../multistability/multistability.h5 at kClusterCut (by
// energy); from the first few, the single-ended searches (saddles.hpp), and
// double-ended searches (double_ended.hpp) between states of neighbouring
// energy rank (knot_transitions(), run.hpp). Writes transitions_4_1.h5 (the
// graph, transitions_file.hpp), states.csv, edges.csv, searches.csv,
// pairs.csv, profile.csv (the energy along each edge's path) and
// summary.json (docs/results.md, "transitions").
#include <filesystem>
#include <iostream>

#include "ek/dataset/dataset_file.hpp"
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
  r.saddles.modes = by_scale(a, 1, 2, 4);
  r.max_states = by_scale(a, 3, 6, 0);
  r.pair_gap = by_scale(a, 1, 2, 2);
  r.max_pairs = by_scale(a, 2, 9, 40);
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
      csv.row({std::to_string(s.state), std::to_string(r.mode), std::to_string(r.direction), r.status,
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
    csv.row({std::to_string(p.a), std::to_string(p.b), p.status, p.seed_statuses, Csv::flag(p.reached), Csv::flag(p.verified),
             std::to_string(p.stages), p.reached ? Csv::num(barrier) : "", Csv::num(p.reached_similarity),
             std::to_string(p.saddle), Csv::num(p.seconds, 4)});
    sum.pair_list.push_back({p.a, p.b, p.status, p.seed_statuses, p.reached, p.verified, p.stages, barrier, p.seconds});
    ++sum.pairs;
    sum.pairs_reached += p.reached;
    sum.pairs_verified += p.verified;
    seconds += p.seconds;
  }
  csv.commit();
  sum.seconds_per_pair = sum.pairs > 0 ? seconds / sum.pairs : 0.0;
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
