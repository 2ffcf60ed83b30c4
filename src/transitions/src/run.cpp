#include "ek/transitions/run.hpp"

#include <sstream>

#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/knots/table.hpp"

namespace ek {

void TransitionRunOptions::validate() const {
  require_input(cut > 0.0 && cut < 1.0, "transitions: the cut must be in (0, 1)");
  require_input(max_states >= 0, "transitions: max_states must be >= 0");
  require_input(pair_gap >= 0, "transitions: pair_gap must be >= 0");
  require_input(max_pairs >= 0, "transitions: max_pairs must be >= 0");
  saddles.validate();
  pair.validate();
}

RelaxOptions dataset_model(const DatasetMetadata& m) {
  RelaxOptions o;
  if (m.young) o.material.young = *m.young;
  if (m.poisson) o.material.poisson = *m.poisson;
  if (m.radius) o.material.radius = *m.radius;
  if (m.tolerance) o.tolerance = *m.tolerance;
  if (m.contact_stiffness) o.contact_stiffness = *m.contact_stiffness;
  if (m.dhat) o.dhat = *m.dhat;
  if (m.max_iterations) o.max_iterations = *m.max_iterations;
  require_input(!m.twist_model || *m.twist_model == "twist-free",
                "transitions: only data sets of the twist-free model are supported");
  return o;
}

CurveSimilarity knot_similarity(const std::string& knot) {
  SimilarityOptions so;
  so.reversal = true;
  const KnotRecord* record = KnotTable::global().find(knot);
  so.mirror = record && record->symmetry_type.find("amphicheiral") != std::string::npos;
  return [so](const Points& a, const Points& b) { return similarity(a, b, so); };
}

std::string transition_run_key(const std::string& knot, const TransitionRunOptions& r, double rest) {
  const KnotSaddleOptions& o = r.saddles;
  const TransitionSearchOptions& p = r.pair;
  std::ostringstream s;
  s.precision(17);
  s << "transitions 1 knot=" << knot << " cut=" << r.cut << " modes=" << o.modes << " states=" << r.max_states
    << " max_iter=" << o.search.max_iterations << " trust=" << o.search.trust_radius << " images=" << o.max_images
    << " displacement=" << o.displacement << " rise=" << o.max_rise_factor << " pair_gap=" << r.pair_gap
    << " max_pairs=" << r.max_pairs << " k0=" << p.initial_stiffness << " growth=" << p.growth
    << " stages=" << p.max_stages << " seeds=" << p.seeds << " reach=" << p.reach
    << " search_iter=" << p.search_iterations << " bisections=" << p.bisections << " tracking=" << p.tracking_rounds
    << "x" << p.tracking_steps << "/" << p.tracking_bisections << " E=" << o.relax.material.young
    << " nu=" << o.relax.material.poisson << " r=" << o.relax.material.radius << " tol=" << o.relax.tolerance.value_or(0.0)
    << " omega=" << o.relax.contact_stiffness.value_or(0.0) << " dhat=" << o.relax.dhat.value_or(0.0)
    << " rest=" << rest;
  return s.str();
}

std::vector<std::pair<int, int>> transition_pairs(int states, const TransitionRunOptions& r) {
  std::vector<std::pair<int, int>> out;
  for (int a = 0; a < states; ++a)
    for (int b = a + 1; b < states && b - a <= r.pair_gap; ++b)
      if (static_cast<int>(out.size()) < r.max_pairs) out.emplace_back(a, b);
  return out;
}

namespace {


/// The single-ended searches from state k (an InputError of the start is kept as its error).
StateSearches searches_of(const KnotSaddleOptions& o, int k, const Points& x, const VecX& rest,
                          const CurveSimilarity& sim) {
  StateSearches s;
  s.state = k;
  const Stopwatch t0;
  try {
    const SaddleStart start = prepare_start(x, rest, o);
    s.energy = start.energy;
    s.records = find_knot_saddles(start, rest, o, sim);
  } catch (const InputError& e) {
    s.error = e.what();
  }
  s.seconds = t0.seconds();
  return s;
}

/// The graph's states before any search: the clusters' representatives.
TransitionGraph initial_graph(const KnotEntry& entry, const TransitionRunOptions& o, double rest_length) {
  const std::vector<StateCluster> clusters = clusters_at_cut(entry, o.cut);
  require_input(!clusters.empty(), "transitions: " + entry.name + " has no stored equilibria");
  TransitionGraph g;
  g.knot = entry.name;
  g.cut = o.cut;
  const int energy = entry.attribute_column("energy");
  for (size_t k = 0; k < clusters.size(); ++k) {
    const int rep = clusters[k].representative;
    g.states.push_back({static_cast<int>(k), rep, entry.attributes(rep, energy), entry.equilibria[rep]});
  }
  g.energy_scale = o.saddles.relax.material.bending_stiffness() /
                   (rest_length * static_cast<double>(entry.equilibria.front().rows()));
  return g;
}

/// InputError unless `r` is a checkpoint of the run that starts from `g`.
void check_resume(const TransitionGraph& g, const TransitionResume& r, int searched,
                  const std::vector<std::pair<int, int>>& pairs) {
  const TransitionGraph& c = r.graph;
  bool ok = c.knot == g.knot && c.cut == g.cut && c.states.size() >= g.states.size() && r.states_searched >= 0 &&
            r.states_searched <= searched && c.pairs.size() <= pairs.size() &&
            (c.pairs.empty() || r.states_searched == searched);
  for (size_t k = 0; ok && k < g.states.size(); ++k)
    ok = c.states[k].cluster == g.states[k].cluster && c.states[k].equilibrium == g.states[k].equilibrium &&
         c.states[k].positions == g.states[k].positions;
  for (size_t k = 0; ok && k < c.pairs.size(); ++k)
    ok = c.pairs[k].a == pairs[k].first && c.pairs[k].b == pairs[k].second;
  require_input(ok, "transitions: the checkpoint is not of this run's states of " + g.knot);
}

}  // namespace

TransitionGraph knot_transitions(const KnotEntry& entry, const DatasetMetadata& metadata,
                                 const TransitionRunOptions& r, const TransitionResume* resume) {
  TransitionRunOptions o = r;
  o.saddles.relax = dataset_model(metadata);
  o.pair.saddle = o.saddles;
  o.validate();
  const double rest_length = metadata.edge_length.value_or(1.0);
  const CurveSimilarity sim = knot_similarity(entry.name);
  TransitionGraph g = initial_graph(entry, o, rest_length);
  const int states = static_cast<int>(g.states.size());
  const int searched = o.max_states > 0 ? std::min(o.max_states, states) : states;
  const std::vector<std::pair<int, int>> pairs = transition_pairs(searched, o);
  int first = 0;
  if (resume) {
    check_resume(g, *resume, searched, pairs);
    g = resume->graph;
    first = resume->states_searched;
  }
  const int total = searched + static_cast<int>(pairs.size());
  for (int k = first; k < searched; ++k) {
    if (o.progress) o.progress("state " + std::to_string(k + 1) + "/" + std::to_string(searched), k, total);
    const VecX rest = VecX::Constant(g.states[k].positions.rows(), rest_length);
    StateSearches s = searches_of(o.saddles, k, g.states[k].positions, rest, sim);
    if (s.error.empty()) g.states[k].energy = s.energy;
    add_searches(g, std::move(s), sim, 1.0 - o.cut);
    if (o.checkpoint) o.checkpoint(g, k + 1);
  }
  for (size_t k = g.pairs.size(); k < pairs.size(); ++k) {
    if (o.progress)
      o.progress("pair " + std::to_string(k + 1) + "/" + std::to_string(pairs.size()), searched + static_cast<int>(k),
                 total);
    const VecX rest = VecX::Constant(g.states[pairs[k].first].positions.rows(), rest_length);
    search_pair(g, pairs[k].first, pairs[k].second, rest, o.pair, sim, 1.0 - o.cut);
    if (o.checkpoint) o.checkpoint(g, searched);
  }
  return g;
}

}  // namespace ek
