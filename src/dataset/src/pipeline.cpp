#include "ek/dataset/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/analysis/link_states.hpp"
#include "ek/analysis/unseen.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/core/parallel.hpp"
#include "ek/core/paths.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/lattice/link_sampling.hpp"
#include "ek/solver/relax_request.hpp"
#include "journal.hpp"

namespace ek {
namespace {

/// Rest edge length of the lattice samples (unit edges).
constexpr double kLatticeEdgeLength = 1.0;


/// The journal key: the knot and every parameter of the data set.
std::string options_text(const std::string& knot, const ExploreOptions& o) {
  return "knot=" + knot + " " + journal_key(dataset_metadata(o));
}

/// Relaxes one lattice sample of a knot (one component) or a link (the
/// components back to back in the stored positions); a change of the knot
/// or link type is a run with status "topology-changed" and the change as
/// its message, never an equilibrium.
JournalRun run_one(const Link& sample, int index, std::uint64_t seed, const ExploreOptions& o) {
  JournalRun out;
  out.record.sample = index;
  out.record.seed = seed;
  out.stiffness = std::numeric_limits<double>::quiet_NaN();
  try {
    RelaxOptions ro = o.relax;
    ro.smallest_eigenvalue = o.stiffness;
    const RelaxResult r = relax(sample, ro);
    out.record.status = run_status(r.status());
    const NewtonReport all = r.all_phases();
    out.record.iterations = all.iterations;
    out.record.seconds = all.seconds;
    out.record.energy = r.energy.total;
    out.record.gradient_norm = r.report.gradient_norm;
    out.record.contacts = r.contacts;
    out.record.topology_preserved = r.topology_preserved();
    out.energy = r.energy;
    out.link = sample.size() == 1 ? r.link : std::numeric_limits<double>::quiet_NaN();
    out.min_distance = r.min_distance;
    if (r.smallest_eigenvalue) out.stiffness = *r.smallest_eigenvalue;
    if (r.stable() && r.topology_preserved()) out.positions = r.positions;
    if (!r.topology_preserved()) out.record.message = topology_change(r);
  } catch (const std::exception& e) {
    out.record.status = RunStatus::Error;
    out.record.message = e.what();
  }
  return out;
}

}  // namespace

std::string to_string(StoppingRule rule) { return rule == StoppingRule::Score ? "score" : "unseen"; }

StoppingRule parse_stopping_rule(const std::string& name) {
  if (name == "score") return StoppingRule::Score;
  if (name == "unseen") return StoppingRule::Unseen;
  throw InputError("unknown stopping rule '" + name + "' (score or unseen)");
}

ExploreOptions::ExploreOptions() { similarity.reversal = true; }

void ExploreOptions::validate() const {
  relax.validate();
  require_input(samples >= 1, "explore: --samples must be at least 1");
  require_input(burn_in >= 0 && burn_in <= 100000, "explore: --burn-in must be between 0 and 100000 samples");
  require_input(initial_samples >= 1 && batch_samples >= 1, "explore: initial and batch sample counts must be positive");
  require_input(max_samples >= initial_samples, "explore: max samples must be >= the initial samples");
  require_input(score_threshold >= 0.0 && score_threshold < 1.0, "explore: score threshold must be in [0, 1)");
  require_input(new_state_threshold >= 0.0 && new_state_threshold < 1.0,
                "explore: the new-state threshold must be in [0, 1)");
  require_input(low_energy_factor >= 1.0, "explore: the low-energy factor must be at least 1");
  require_input(novelty_distance > 0.0 && novelty_distance <= 1.0, "explore: novelty distance must be in (0, 1]");
  require_input(jobs >= 1 && jobs <= 256, "explore: --jobs must be between 1 and 256");
  require_input(sampling.vertices >= 4 && sampling.vertices % 2 == 0,
                "explore: the vertex count n must be even and >= 4 (lattice polygons)");
}

std::string ExploreOptions::sampling_description() const {
  std::ostringstream s;
  if (adaptive) {
    s << "adaptive:" << initial_samples << "+" << batch_samples << ",max=" << max_samples;
    if (stopping == StoppingRule::Score)
      s << ",S>" << score_threshold;
    else
      s << ",unseen<" << new_state_threshold << ",low=" << low_energy_factor;
    s << ",delta=" << novelty_distance;
  } else
    s << "fixed:" << samples;
  if (burn_in > 0) s << ",burn-in=" << burn_in;
  return s.str();
}

RunStatus run_status(RelaxStatus status) {
  switch (status) {
    case RelaxStatus::ConvergedStable: return RunStatus::ConvergedStable;
    case RelaxStatus::ConvergedUnstable: return RunStatus::ConvergedUnstable;
    case RelaxStatus::MaxIterations: return RunStatus::MaxIterations;
    case RelaxStatus::Stalled: return RunStatus::Stalled;
    case RelaxStatus::TopologyChanged: return RunStatus::TopologyChanged;
  }
  return RunStatus::Error;
}

DatasetMetadata dataset_metadata(const ExploreOptions& o) {
  DatasetMetadata m;
  const RodMaterial& mat = o.relax.material;
  m.young = mat.young;
  m.poisson = mat.poisson;
  m.radius = mat.radius;
  m.vertices = o.sampling.vertices;
  m.edge_length = kLatticeEdgeLength;
  const ResolvedModel resolved = resolve_model(o.relax, kLatticeEdgeLength);
  m.tolerance = resolved.tolerance;
  m.contact_stiffness = resolved.contact_stiffness;
  m.dhat = resolved.dhat;
  m.twist_model = to_string(resolved.model);
  const bool multilevel = multilevel_applies(o.relax);
  m.relax_method = to_string(multilevel ? RelaxMethod::Multilevel : RelaxMethod::Direct);
  if (multilevel) {
    m.coarse_levels = o.relax.coarse_levels;
    m.coarse_continuation = o.relax.coarse_continuation;
    m.coarsening = to_string(o.relax.coarsening);
  } else {
    m.coarsening = "even";  // no coarse levels: the value of the files before the field
  }
  m.newton_hessian = to_string(o.relax.newton.hessian);
  m.remove_rigid_motions = o.relax.newton.remove_rigid_motions;
  m.contact_hessian = resolved.contact_gauss_newton ? "gauss-newton" : "eigen-projected";
  m.damp_short_steps = resolved.damp_short_steps;
  m.max_iterations = o.relax.max_iterations;
  m.burn_in = o.burn_in;
  m.sampling = o.sampling_description();
  m.grow_fugacity = o.sampling.grow_fugacity;
  m.shrink_fugacity = o.sampling.shrink_fugacity;
  m.growth_factor = o.sampling.growth_factor;
  m.decorrelation_moves = o.sampling.decorrelation_moves;
  m.seed = o.seed;
  m.compute_stiffness = o.stiffness;
  m.contact_continuation = o.relax.contact_continuation;
  m.project_version = project_version();
  m.knot_table = knot_table_path();
  return m;
}

std::uint64_t sample_seed(std::uint64_t knot_seed, int sample) {
  return splitmix64(knot_seed + 0x632BE59BD9B4E019ULL * static_cast<std::uint64_t>(sample + 1));
}

std::uint64_t knot_seed(std::uint64_t run_seed, const std::string& name) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return splitmix64(run_seed ^ splitmix64(h));
}

namespace {

/// What an attribute of a stored equilibrium is computed from.
struct AttributeSource {
  const JournalRun& run;
  const Attributes& attributes;
  int sample;
};

/// The attribute table's columns, in the stored order: names and values
/// from one list (dataset_attribute_names() and attribute_row()).
struct AttributeColumn {
  const char* name;
  double (*value)(const AttributeSource&);
};
const AttributeColumn kAttributeColumns[] = {
    {"energy", [](const AttributeSource& s) { return s.run.energy.total; }},
    {"energy_stretch", [](const AttributeSource& s) { return s.run.energy.stretch; }},
    {"energy_bend", [](const AttributeSource& s) { return s.run.energy.bend; }},
    {"energy_twist", [](const AttributeSource& s) { return s.run.energy.twist; }},
    {"energy_contact", [](const AttributeSource& s) { return s.run.energy.contact; }},
    {"stiffness", [](const AttributeSource& s) { return s.run.stiffness; }},
    {"max_stress", [](const AttributeSource& s) { return s.attributes.physical.max_stress.value_or(std::nan("")); }},
    {"total_curvature", [](const AttributeSource& s) { return s.attributes.geometric.total_curvature; }},
    {"threedim", [](const AttributeSource& s) { return s.attributes.geometric.threedim; }},
    {"sphericity", [](const AttributeSource& s) { return s.attributes.geometric.sphericity; }},
    {"diameter", [](const AttributeSource& s) { return s.attributes.geometric.diameter; }},
    {"writhe", [](const AttributeSource& s) { return s.attributes.geometric.writhe; }},
    {"link", [](const AttributeSource& s) { return s.run.link; }},
    {"contacts", [](const AttributeSource& s) { return static_cast<double>(s.run.record.contacts); }},
    {"sample", [](const AttributeSource& s) { return static_cast<double>(s.sample); }},
};

}  // namespace

const std::vector<std::string>& dataset_attribute_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const AttributeColumn& c : kAttributeColumns) v.push_back(c.name);
    return v;
  }();
  return names;
}

double importance_score(const Eigen::MatrixXd& sim, int earlier, const std::vector<double>& energies,
                        double minimum_energy, double novelty_distance) {
  const int m = static_cast<int>(energies.size());
  require(sim.rows() == m && sim.cols() == earlier + m, "importance_score: similarity matrix has the wrong shape");
  double score = 0.0;
  for (int j = 0; j < m; ++j) {
    double best = 0.0;
    for (int i = 0; i < earlier + j; ++i) best = std::max(best, sim(j, i));
    const double novelty = std::min(1.0, (1.0 - best) / novelty_distance);
    const double weight = energies[static_cast<size_t>(j)] > 0.0 ? minimum_energy / energies[static_cast<size_t>(j)] : 1.0;
    score = std::max(score, std::clamp(novelty * weight, 0.0, 1.0));
  }
  return score;
}

std::vector<StateCluster> clusters_at_cut(const KnotEntry& e, double cut, std::vector<int>* rank) {
  const int m = static_cast<int>(e.equilibria.size());
  if (rank) rank->assign(static_cast<size_t>(m), -1);
  if (m == 0) return {};
  std::vector<int> labels(static_cast<size_t>(m), 0);
  if (m > 1) labels = cut_dendrogram(Dendrogram::from_linkage(e.linkage), cut);
  const int ec = e.attribute_column("energy");
  std::vector<StateCluster> out(static_cast<size_t>(*std::max_element(labels.begin(), labels.end()) + 1));
  for (int i = 0; i < m; ++i) {
    StateCluster& c = out[static_cast<size_t>(labels[static_cast<size_t>(i)])];
    const double E = e.attributes(i, ec);
    if (c.members.empty() || E < c.energy_min) {
      c.energy_min = E;
      c.representative = i;
    }
    if (c.members.empty() || E > c.energy_max) c.energy_max = E;
    c.members.push_back(i);
  }
  std::sort(out.begin(), out.end(), [](const StateCluster& a, const StateCluster& b) {
    return a.energy_min < b.energy_min;
  });
  if (rank)
    for (size_t c = 0; c < out.size(); ++c)
      for (int i : out[c].members) (*rank)[static_cast<size_t>(i)] = static_cast<int>(c);
  return out;
}

void cluster_entry(KnotEntry& e, const SimilarityOptions& options) {
  const int m = static_cast<int>(e.equilibria.size());
  if (m == 0) {
    e.similarity.resize(0, 0);
    e.linkage.resize(0, 4);
    return;
  }
  if (e.is_link()) {
    std::vector<LinkShape> shapes;
    shapes.reserve(static_cast<size_t>(m));
    for (int i = 0; i < m; ++i) shapes.push_back(link_shape(e.equilibrium_link(i)));
    e.similarity = link_state_similarity_matrix(shapes);
  } else {
    SimilarityEngine engine(static_cast<int>(e.equilibria.front().rows()), options);
    std::vector<SignatureSpectrum> spectra;
    spectra.reserve(static_cast<size_t>(m));
    for (const auto& P : e.equilibria) spectra.push_back(engine.spectrum(P));
    e.similarity = engine.matrix(spectra);
  }
  e.linkage = complete_linkage_from_similarity(e.similarity).linkage_matrix();
}

StoppingScore::StoppingScore(const ExploreOptions& o)
    : rule_(o.stopping),
      novelty_distance_(o.novelty_distance),
      low_energy_factor_(o.low_energy_factor),
      batch_samples_(o.batch_samples) {}

double StoppingScore::add_batch(const Eigen::MatrixXd& sim, const std::vector<double>& energies) {
  const auto earlier = static_cast<Eigen::Index>(energies_.size());
  const auto m = static_cast<Eigen::Index>(energies.size());
  require(sim.rows() == m && sim.cols() == earlier + m, "StoppingScore: similarity matrix has the wrong shape");
  for (double E : energies) min_energy_ = std::min(min_energy_, E);
  double score = 0.0;
  if (rule_ == StoppingRule::Score) {
    if (m > 0) score = importance_score(sim, static_cast<int>(earlier), energies, min_energy_, novelty_distance_);
  } else {
    similarity_.conservativeResize(earlier + m, earlier + m);
    for (Eigen::Index j = 0; j < m; ++j)
      for (Eigen::Index i = 0; i <= earlier + j; ++i)
        similarity_(earlier + j, i) = similarity_(i, earlier + j) = i == earlier + j ? 1.0 : sim(j, i);
  }
  energies_.insert(energies_.end(), energies.begin(), energies.end());
  return rule_ == StoppingRule::Score ? score : unseen_score();
}

StateCounts state_counts(const Eigen::MatrixXd& similarity, const std::vector<double>& energies, double cut) {
  require(similarity.rows() == similarity.cols() && similarity.rows() == static_cast<Eigen::Index>(energies.size()),
          "state_counts: one energy per row of a square similarity matrix expected");
  StateCounts out;
  if (energies.empty()) return out;
  std::vector<int> labels(energies.size(), 0);
  if (energies.size() > 1) labels = cut_dendrogram(complete_linkage_from_similarity(similarity), cut);
  const size_t states = static_cast<size_t>(*std::max_element(labels.begin(), labels.end()) + 1);
  out.counts.assign(states, 0);
  out.lowest.assign(states, std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < labels.size(); ++i) {
    const auto c = static_cast<size_t>(labels[i]);
    ++out.counts[c];
    out.lowest[c] = std::min(out.lowest[c], energies[i]);
  }
  return out;
}

// P of the file comment.
double StoppingScore::unseen_score() const {
  const StateCounts s = state_counts(similarity_, energies_, novelty_distance_);
  std::vector<bool> low(s.counts.size());
  for (size_t c = 0; c < low.size(); ++c) low[c] = s.lowest[c] <= low_energy_factor_ * min_energy_;
  return new_state_probability_in_batch(new_state_probability_of_kind(s.counts, low), batch_samples_);
}

AdaptiveScorer::AdaptiveScorer(const ExploreOptions& o) : engine_(o.sampling.vertices, o.similarity), score_(o) {}

double AdaptiveScorer::add_batch(const std::vector<std::pair<const Points*, double>>& stable) {
  std::vector<SignatureSpectrum> batch;
  std::vector<double> energies;
  for (const auto& [P, E] : stable) {
    batch.push_back(engine_.spectrum(*P));
    energies.push_back(E);
  }
  std::vector<SignatureSpectrum> columns = spectra_;
  columns.insert(columns.end(), batch.begin(), batch.end());
  const double score = score_.add_batch(engine_.cross_matrix(batch, columns), energies);
  spectra_.insert(spectra_.end(), batch.begin(), batch.end());
  return score;
}

ExploreOptions options_for_knot(const ExploreOptions& options, const KnotRecord& knot) {
  ExploreOptions o = options;
  if (o.mirror_amphicheiral && knot.symmetry_type.find("amphicheiral") != std::string::npos) o.similarity.mirror = true;
  return o;
}

namespace {

/// The adaptive rule (paper Section 7.4): batches of samples while the last
/// batch's score (S or P, see the file comment) is above its threshold and fewer than
/// max_samples were taken. `batch(begin, end)` makes the samples
/// [begin, end) available and returns their score, or nothing when they
/// cannot be had (a replay's stored runs ended: `truncated`).
struct AdaptiveRule {
  int samples = 0;
  std::vector<double> scores;
  bool truncated = false;
};
AdaptiveRule run_adaptive_rule(const ExploreOptions& o, const std::function<std::optional<double>(int, int)>& batch) {
  AdaptiveRule out;
  out.samples = o.initial_samples;
  const std::optional<double> first = batch(0, out.samples);
  if (!first) {
    out.truncated = true;
    return out;
  }
  out.scores.push_back(*first);
  const double threshold = o.stopping == StoppingRule::Score ? o.score_threshold : o.new_state_threshold;
  while (out.scores.back() > threshold && out.samples < o.max_samples) {
    const int count = std::min(o.batch_samples, o.max_samples - out.samples);
    const std::optional<double> s = batch(out.samples, out.samples + count);
    if (!s) {
      out.truncated = true;
      break;
    }
    out.scores.push_back(*s);
    out.samples += count;
  }
  return out;
}

}  // namespace

AdaptiveReplay replay_adaptive(const KnotEntry& fixed, const ExploreOptions& options) {
  const KnotRecord* knot = KnotTable::global().find(fixed.name);
  ExploreOptions o = knot ? options_for_knot(options, *knot) : options;
  const int available = static_cast<int>(fixed.runs.size());
  o.initial_samples = std::min(o.initial_samples, available);
  const int energy_col = fixed.equilibria.empty() ? -1 : fixed.attribute_column("energy");
  require(fixed.similarity.rows() == static_cast<Eigen::Index>(fixed.equilibria.size()),
          "replay_adaptive: the entry has no similarity matrix of its equilibria");
  StoppingScore score(o);
  std::vector<int> seen;  // equilibrium indices in the order of the samples
  const AdaptiveRule rule = run_adaptive_rule(o, [&](int begin, int end) -> std::optional<double> {
    if (end > available) return std::nullopt;
    std::vector<int> batch;
    for (int k = begin; k < end; ++k) {
      const RunRecord& r = fixed.runs[static_cast<size_t>(k)];
      require(r.sample == k, "replay_adaptive: runs must be in sample order");
      if (r.equilibrium >= 0) batch.push_back(r.equilibrium);
    }
    seen.insert(seen.end(), batch.begin(), batch.end());
    Eigen::MatrixXd sim(static_cast<Eigen::Index>(batch.size()), static_cast<Eigen::Index>(seen.size()));
    std::vector<double> energies;
    for (size_t j = 0; j < batch.size(); ++j) {
      energies.push_back(fixed.attributes(batch[j], energy_col));
      for (size_t i = 0; i < seen.size(); ++i)
        sim(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = fixed.similarity(batch[j], seen[i]);
    }
    return score.add_batch(sim, energies);
  });
  AdaptiveReplay out;
  out.score_history = rule.scores;
  out.truncated = rule.truncated;
  out.samples_used = rule.samples;
  return out;
}

namespace {

// A knot's entry before any run: its name, indices and whether it is adaptive.
KnotEntry entry_header(const KnotRecord& knot, const ExploreOptions& o) {
  KnotEntry entry;
  entry.name = knot.name;
  entry.crossing_number = knot.crossing_number;
  entry.bridge_index = knot.bridge_index.value_or(-1);
  entry.braid_index = knot.braid_index.value_or(-1);
  entry.adaptive = o.adaptive;
  return entry;
}

// The BFACF walk of one knot or link (State: its lattice polygon, or one
// polygon per component). Sample k continues the walk from sample k - 1 with
// its own seed derived from (knot seed, k): the samples do not depend on how
// they are batched, so an adaptive run uses exactly the first samples of a
// fixed-budget run. With a burn-in the walk first makes o.burn_in samples
// (walk indices 0 .. burn_in - 1) and drops them; sample k is walk sample
// burn_in + k. step(state, options) makes the next state (options.count = 1,
// options.seed set).
template <class State>
class SampleWalk {
 public:
  using Step = std::function<State(const State&, const SampleOptions&)>;
  SampleWalk(State start, const ExploreOptions& o, std::uint64_t seed, Step step)
      : o_(o), seed_(seed), step_(std::move(step)), last_(std::move(start)) {}

  // Appends the next `count` samples to samples().
  void generate(int count) {
    while (walk_index_ < o_.burn_in) next_sample();
    for (int c = 0; c < count; ++c) {
      next_sample();
      samples_.push_back(last_);
    }
  }
  const std::vector<State>& samples() const { return samples_; }

 private:
  void next_sample() {
    SampleOptions so = o_.sampling;
    so.count = 1;
    so.seed = sample_seed(seed_, walk_index_++);
    last_ = step_(last_, so);
  }

  const ExploreOptions& o_;
  std::uint64_t seed_;
  Step step_;
  State last_;
  int walk_index_ = 0;
  std::vector<State> samples_;
};

// The runs of one knot, keyed by sample index: those of the journal, then the
// new ones, each appended to the journal as it finishes.
struct KnotRuns {
  /// Opens the journal at `journal_path` (none when empty) with the key of
  /// `name` and `o`, and takes the runs it already holds.
  KnotRuns(const std::string& journal_path, const std::string& name, const ExploreOptions& o,
           const RunCallback& callback)
      : on_run(&callback) {
    if (journal_path.empty()) return;
    journal = std::make_unique<Journal>(journal_path, options_text(name, o));
    done = journal->runs();
  }
  std::map<int, JournalRun> done;
  std::unique_ptr<Journal> journal;
  const RunCallback* on_run = nullptr;
  std::mutex mutex;
};

// Relaxes samples [begin, end) not yet done on o.jobs threads; run(k) relaxes sample k.
void relax_range(int begin, int end, const ExploreOptions& o, KnotRuns& runs,
                 const std::function<JournalRun(int)>& run) {
  std::vector<int> todo;
  for (int k = begin; k < end; ++k)
    if (!runs.done.count(k)) todo.push_back(k);
  parallel_for(todo.size(), o.jobs, [&](size_t t) {
    const int k = todo[t];
    JournalRun r = run(k);
    std::lock_guard<std::mutex> lock(runs.mutex);
    if (runs.journal) runs.journal->append(r);
    if (*runs.on_run) (*runs.on_run)(r.record);
    runs.done[k] = std::move(r);
  });
}

// The adaptive score of the stable equilibria of samples [begin, end).
double score_batch(AdaptiveScorer& scorer, const KnotRuns& runs, int begin, int end) {
  std::vector<std::pair<const Points*, double>> stable;
  for (int k = begin; k < end; ++k) {
    const JournalRun& r = runs.done.at(k);
    if (r.positions.rows() > 0) stable.emplace_back(&r.positions, r.energy.total);
  }
  return scorer.add_batch(stable);
}

// One row of the attribute table (kAttributeColumns' order).
std::vector<double> attribute_row(const JournalRun& r, int sample, const AttributeOptions& ao) {
  const Attributes a = compute_attributes(r.positions, ao);
  const AttributeSource source{r, a, sample};
  std::vector<double> row;
  for (const AttributeColumn& c : kAttributeColumns) row.push_back(c.value(source));
  return row;
}

using AttributeRow = std::function<std::vector<double>(const JournalRun&, int)>;

// Runs of samples [0, total) in sample order into the entry; the stable
// equilibria with their attributes (columns `names`, row(run, sample)).
void collect_runs(KnotEntry& entry, KnotRuns& runs, int total, const std::vector<std::string>& names,
                  const AttributeRow& row) {
  std::vector<std::vector<double>> rows;
  for (int k = 0; k < total; ++k) {
    JournalRun& r = runs.done.at(k);
    r.record.equilibrium = r.positions.rows() > 0 ? static_cast<int>(entry.equilibria.size()) : -1;
    if (r.positions.rows() > 0) {
      rows.push_back(row(r, k));
      entry.equilibria.push_back(r.positions);
    }
    entry.runs.push_back(r.record);
  }
  entry.attribute_names = names;
  entry.attributes.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(names.size()));
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t c = 0; c < names.size(); ++c)
      entry.attributes(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = rows[i][c];
}

AttributeOptions attribute_options(const ExploreOptions& o) {
  AttributeOptions ao;
  ao.radius = o.relax.material.radius;
  ao.young_modulus = o.relax.material.young;
  return ao;
}

}  // namespace

KnotEntry explore_knot(const KnotRecord& knot, const ExploreOptions& options, const std::string& journal_path,
                       const RunCallback& on_run) {
  const ExploreOptions o = options_for_knot(options, knot);
  o.validate();
  KnotEntry entry = entry_header(knot, o);
  const std::uint64_t seed = knot_seed(o.seed, knot.name);

  KnotRuns runs(journal_path, knot.name, o, on_run);

  const LatticeStart start = lattice_start(knot, o.start);
  entry.alexander = start.alexander.coefficients;
  SampleWalk<LatticePoints> walk(start.points, o, seed, [&](const LatticePoints& last, const SampleOptions& so) {
    return std::move(sample_lattice_polygons(last, so, start.alexander, knot.name).samples.front());
  });
  AdaptiveScorer scorer(o);

  const auto relax_samples = [&](int begin, int end) {
    walk.generate(end - begin);
    relax_range(begin, end, o, runs, [&](int k) {
      return run_one({to_points(walk.samples()[static_cast<size_t>(k)])}, k, sample_seed(seed, o.burn_in + k), o);
    });
  };
  int total = o.samples;
  if (o.adaptive) {
    const AdaptiveRule rule = run_adaptive_rule(o, [&](int begin, int end) -> std::optional<double> {
      relax_samples(begin, end);
      return score_batch(scorer, runs, begin, end);
    });
    entry.score_history = rule.scores;
    total = rule.samples;
  } else {
    relax_samples(0, total);
  }
  entry.samples_used = total;
  const AttributeOptions ao = attribute_options(o);
  collect_runs(entry, runs, total, dataset_attribute_names(),
               [&](const JournalRun& r, int k) { return attribute_row(r, k, ao); });
  cluster_entry(entry, o.similarity);
  entry.complete = true;
  return entry;
}

// ---------------------------------------------------------------- links

namespace {

/// The attribute columns of a link's equilibria (link_attribute_names()).
/// Per component and summed: total_curvature, writhe (the components' own,
/// without the linking terms); the largest over the components: max_stress;
/// of all vertices together: threedim, sphericity, diameter.
struct LinkAttributeSource {
  const JournalRun& run;
  const std::vector<Attributes>& components;
  const GeometricAttributes& whole;
  int sample;
};
struct LinkAttributeColumn {
  const char* name;
  double (*value)(const LinkAttributeSource&);
};
double sum_of(const LinkAttributeSource& s, double GeometricAttributes::*field) {
  double v = 0.0;
  for (const Attributes& a : s.components) v += a.geometric.*field;
  return v;
}
const LinkAttributeColumn kLinkAttributeColumns[] = {
    {"energy", [](const LinkAttributeSource& s) { return s.run.energy.total; }},
    {"energy_stretch", [](const LinkAttributeSource& s) { return s.run.energy.stretch; }},
    {"energy_bend", [](const LinkAttributeSource& s) { return s.run.energy.bend; }},
    {"energy_contact", [](const LinkAttributeSource& s) { return s.run.energy.contact; }},
    {"max_stress",
     [](const LinkAttributeSource& s) {
       double v = 0.0;
       for (const Attributes& a : s.components) v = std::max(v, a.physical.max_stress.value_or(std::nan("")));
       return v;
     }},
    {"total_curvature", [](const LinkAttributeSource& s) { return sum_of(s, &GeometricAttributes::total_curvature); }},
    {"threedim", [](const LinkAttributeSource& s) { return s.whole.threedim; }},
    {"sphericity", [](const LinkAttributeSource& s) { return s.whole.sphericity; }},
    {"diameter", [](const LinkAttributeSource& s) { return s.whole.diameter; }},
    {"writhe", [](const LinkAttributeSource& s) { return sum_of(s, &GeometricAttributes::writhe); }},
    {"min_distance", [](const LinkAttributeSource& s) { return s.run.min_distance; }},
    {"sample", [](const LinkAttributeSource& s) { return static_cast<double>(s.sample); }},
};

/// A link's run from a journal record of the first layout in today's
/// meaning: its one slot held the closest approach (min_distance; Lk is not
/// defined for a link), and its energy.total the elastic energy without the
/// contact part.
void upgrade_first_layout(JournalRun& r) {
  if (!r.first_layout) return;
  r.min_distance = r.link;
  r.link = std::numeric_limits<double>::quiet_NaN();
  r.energy.total = r.energy.stretch + r.energy.bend + r.energy.twist + r.energy.contact + r.energy.slab;
  r.first_layout = false;
}

std::vector<double> link_attribute_row(const JournalRun& r, int sample, const std::vector<int>& sizes,
                                       const AttributeOptions& ao) {
  std::vector<Attributes> components;
  Eigen::Index row = 0;
  for (int n : sizes) {
    components.push_back(compute_attributes(r.positions.middleRows(row, n), ao));
    row += n;
  }
  GeometricAttributes whole;  // of the vertex set: these three need no edges
  whole.threedim = threedim(r.positions);
  whole.sphericity = sphericity(r.positions);
  whole.diameter = diameter(r.positions).distance;
  const LinkAttributeSource source{r, components, whole, sample};
  std::vector<double> out;
  for (const LinkAttributeColumn& c : kLinkAttributeColumns) out.push_back(c.value(source));
  return out;
}

}  // namespace

const std::vector<std::string>& link_attribute_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const LinkAttributeColumn& c : kLinkAttributeColumns) v.push_back(c.name);
    return v;
  }();
  return names;
}

KnotEntry explore_link(const LinkRecord& link, const ExploreOptions& o, const std::string& journal_path,
                       const RunCallback& on_run) {
  o.validate();
  require_input(!o.adaptive, "explore: adaptive sampling is defined for knots only; give --samples K for a link");
  require_input(!multilevel_applies(o.relax), "explore: a link is relaxed by the direct method (--method direct)");
  require_input(!o.stiffness, "explore: the stiffness of a link is not computed (--no-stiffness)");
  KnotEntry entry;
  entry.name = link.name;
  entry.crossing_number = link.crossing_number;
  entry.conway = link.conway.coefficients;
  entry.linking_numbers.assign(link.linking_numbers.begin(), link.linking_numbers.end());
  entry.alexander = {1};
  const std::uint64_t seed = knot_seed(o.seed, link.name);

  KnotRuns runs(journal_path, link.name, o, on_run);
  for (auto& [k, r] : runs.done) upgrade_first_layout(r);

  const LatticeLinkStart start = lattice_link_start(link);
  using Polygons = std::vector<LatticePoints>;
  SampleWalk<Polygons> walk(start.components, o, seed, [&](const Polygons& last, const SampleOptions& so) {
    return std::move(sample_lattice_link(last, so, start.type, link.name).samples.front());
  });
  walk.generate(o.samples);  // o.samples >= 1: every sample has the components' target lengths
  for (const LatticePoints& polygon : walk.samples().front()) entry.components.push_back(static_cast<int>(polygon.rows()));
  relax_range(0, o.samples, o, runs, [&](int k) {
    return run_one(to_link(walk.samples()[static_cast<size_t>(k)]), k, sample_seed(seed, o.burn_in + k), o);
  });
  entry.samples_used = o.samples;
  const AttributeOptions ao = attribute_options(o);
  collect_runs(entry, runs, o.samples, link_attribute_names(),
               [&](const JournalRun& r, int k) { return link_attribute_row(r, k, entry.components, ao); });
  cluster_entry(entry, o.similarity);
  entry.complete = true;
  return entry;
}

}  // namespace ek
