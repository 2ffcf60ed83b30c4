#include "ek/transitions/transitions_file.hpp"

#include <filesystem>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/h5.hpp"

namespace ek {
namespace {

constexpr const char* kFormat = "elastic-knots-transitions";
constexpr std::int64_t kFormatVersion = 1;
constexpr const char* kRefusedRow = "start-refused: ";  ///< the searches/ status of a refused start

void write_curves(hid_t g, const std::string& name, const std::vector<Points>& curves) {
  const hsize_t n = curves.empty() ? 0 : static_cast<hsize_t>(curves.front().rows());
  std::vector<double> data;
  data.reserve(curves.size() * n * 3);
  for (const Points& p : curves) {
    require(static_cast<hsize_t>(p.rows()) == n, "transitions file: curves of different vertex counts");
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      for (int a = 0; a < 3; ++a) data.push_back(p(i, a));
  }
  h5::write_doubles(g, name, {static_cast<hsize_t>(curves.size()), n, 3}, data.data());
}

std::vector<Points> read_curves(hid_t g, const std::string& name) {
  std::vector<hsize_t> shape;
  const std::vector<double> data = h5::read_doubles(g, name, &shape);
  if (shape.size() != 3 || shape[2] != 3) throw InputError("'" + name + "' is not an array of curves");
  std::vector<Points> out(shape[0], Points(shape[1], 3));
  size_t k = 0;
  for (Points& p : out)
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      for (int a = 0; a < 3; ++a) p(i, a) = data[k++];
  return out;
}

template <class T, class F>
std::vector<double> doubles(const std::vector<T>& v, F f) {
  std::vector<double> out;
  for (const T& x : v) out.push_back(f(x));
  return out;
}
template <class T, class F>
std::vector<std::int64_t> ints(const std::vector<T>& v, F f) {
  std::vector<std::int64_t> out;
  for (const T& x : v) out.push_back(f(x));
  return out;
}
void put(hid_t g, const std::string& name, const std::vector<double>& v) {
  h5::write_doubles(g, name, {v.size()}, v.data());
}
void put(hid_t g, const std::string& name, const std::vector<std::int64_t>& v) {
  h5::write_int64(g, name, {v.size()}, v.data());
}

std::vector<Points> state_curves(const std::vector<TransitionState>& s) {
  std::vector<Points> out;
  for (const TransitionState& x : s) out.push_back(x.positions);
  return out;
}

void write_states(hid_t file, const TransitionGraph& graph) {
  const h5::Handle g = h5::create_group(file, "states");
  const auto& s = graph.states;
  put(g.id(), "energy", doubles(s, [](const TransitionState& x) { return x.energy; }));
  put(g.id(), "cluster", ints(s, [](const TransitionState& x) { return x.cluster; }));
  put(g.id(), "equilibrium", ints(s, [](const TransitionState& x) { return x.equilibrium; }));
  write_curves(g.id(), "positions", state_curves(s));
}

void write_path(hid_t parent, const std::string& name, const std::vector<Points>& images,
                const std::vector<double>& energies) {
  const h5::Handle g = h5::create_group(parent, name);
  write_curves(g.id(), "images", images);
  put(g.id(), "energies", energies);
}

void write_saddles(hid_t file, const TransitionGraph& graph) {
  const h5::Handle g = h5::create_group(file, "saddles");
  const auto& s = graph.saddles;
  using S = TransitionSaddle;
  put(g.id(), "energy", doubles(s, [](const S& x) { return x.energy; }));
  put(g.id(), "negative_eigenvalue", doubles(s, [](const S& x) { return x.negative_eigenvalue; }));
  put(g.id(), "second_eigenvalue", doubles(s, [](const S& x) { return x.second_eigenvalue; }));
  put(g.id(), "gradient_norm", doubles(s, [](const S& x) { return x.gradient_norm; }));
  put(g.id(), "index", ints(s, [](const S& x) { return x.index; }));
  put(g.id(), "from", ints(s, [](const S& x) { return x.from; }));
  put(g.id(), "to", ints(s, [](const S& x) { return x.to; }));
  put(g.id(), "saddle_image", ints(s, [](const S& x) { return x.saddle_image; }));
  put(g.id(), "energy_from", doubles(s, [](const S& x) { return x.energy_from; }));
  put(g.id(), "energy_to", doubles(s, [](const S& x) { return x.energy_to; }));
  put(g.id(), "double_ended", ints(s, [](const S& x) { return x.double_ended ? 1 : 0; }));
  std::vector<Points> pos;
  for (const S& x : s) pos.push_back(x.positions);
  write_curves(g.id(), "positions", pos);
  for (size_t k = 0; k < s.size(); ++k) write_path(g.id(), "path_" + std::to_string(k), s[k].path, s[k].path_energies);
}

void write_edges(hid_t file, const TransitionGraph& graph) {
  const h5::Handle g = h5::create_group(file, "edges");
  const auto& e = graph.edges;
  using E = TransitionEdge;
  const double scale = graph.energy_scale;
  put(g.id(), "from", ints(e, [](const E& x) { return x.from; }));
  put(g.id(), "to", ints(e, [](const E& x) { return x.to; }));
  put(g.id(), "saddle", ints(e, [](const E& x) { return x.saddle; }));
  put(g.id(), "energy", doubles(e, [](const E& x) { return x.energy; }));
  put(g.id(), "barrier_forward", doubles(e, [](const E& x) { return x.barrier_forward; }));
  put(g.id(), "barrier_backward", doubles(e, [](const E& x) { return x.barrier_backward; }));
  put(g.id(), "barrier_forward_scaled", doubles(e, [scale](const E& x) { return x.barrier_forward / scale; }));
  put(g.id(), "barrier_backward_scaled", doubles(e, [scale](const E& x) { return x.barrier_backward / scale; }));
}

/// One row per search of every state.
void write_searches(hid_t file, const TransitionGraph& graph) {
  const h5::Handle g = h5::create_group(file, "searches");
  std::vector<std::int64_t> state, mode, direction, verified, index, iterations;
  std::vector<std::string> status;
  std::vector<double> energy, gradient, seconds;
  for (const StateSearches& s : graph.searches) {
    if (!s.error.empty()) {
      state.push_back(s.state);
      mode.push_back(-1);
      direction.push_back(0);
      verified.push_back(0);
      index.push_back(-1);
      iterations.push_back(0);
      status.push_back(kRefusedRow + s.error);
      energy.push_back(0.0);
      gradient.push_back(0.0);
      seconds.push_back(s.seconds);
    }
    for (const SaddleRecord& r : s.records) {
      state.push_back(s.state);
      mode.push_back(r.mode);
      direction.push_back(r.direction);
      verified.push_back(r.verified ? 1 : 0);
      index.push_back(r.index);
      iterations.push_back(r.iterations);
      status.push_back(to_string(r.status));
      energy.push_back(r.energy);
      gradient.push_back(r.gradient_norm);
      seconds.push_back(r.seconds);
    }
  }
  put(g.id(), "state", state);
  put(g.id(), "mode", mode);
  put(g.id(), "direction", direction);
  put(g.id(), "verified", verified);
  put(g.id(), "index", index);
  put(g.id(), "iterations", iterations);
  h5::write_strings(g.id(), "status", status);
  put(g.id(), "energy", energy);
  put(g.id(), "gradient_norm", gradient);
  put(g.id(), "seconds", seconds);
}

/// One row per double-ended search.
void write_pairs(hid_t file, const TransitionGraph& graph) {
  const h5::Handle g = h5::create_group(file, "pairs");
  const auto& p = graph.pairs;
  using P = PairSearch;
  put(g.id(), "a", ints(p, [](const P& x) { return x.a; }));
  put(g.id(), "b", ints(p, [](const P& x) { return x.b; }));
  std::vector<std::string> status;
  for (const P& x : p) status.push_back(to_string(x.status));
  h5::write_strings(g.id(), "status", status);
  std::vector<std::string> seeds;
  for (const P& x : p) seeds.push_back(to_string(x.seed_statuses));
  h5::write_strings(g.id(), "seed_statuses", seeds);
  put(g.id(), "reached", ints(p, [](const P& x) { return x.reached ? 1 : 0; }));
  put(g.id(), "verified", ints(p, [](const P& x) { return x.verified ? 1 : 0; }));
  put(g.id(), "stages", ints(p, [](const P& x) { return x.stages; }));
  put(g.id(), "saddle", ints(p, [](const P& x) { return x.saddle; }));
  put(g.id(), "path_barrier", doubles(p, [](const P& x) { return x.path_barrier; }));
  put(g.id(), "reached_similarity", doubles(p, [](const P& x) { return x.reached_similarity; }));
  put(g.id(), "saddle_energy", doubles(p, [](const P& x) { return x.saddle_energy; }));
  put(g.id(), "seconds", doubles(p, [](const P& x) { return x.seconds; }));
}

/// Removes the temporary unless committed.
struct Temporary {
  std::string path;
  bool committed = false;
  ~Temporary() {
    if (!committed) std::remove(path.c_str());
  }
};

}  // namespace

void write_transitions(const std::string& path, const TransitionGraph& graph, const std::string& dataset,
                       const std::string& options, bool complete, int states_searched) {
  h5::quiet();
  check_writable(path);
  Temporary tmp{temporary_path(path)};
  {
    const h5::Handle f = h5::create_file(tmp.path);
    h5::set_attr(f.id(), "format", std::string(kFormat));
    h5::set_attr(f.id(), "format_version", kFormatVersion);
    h5::set_attr(f.id(), "knot", graph.knot);
    h5::set_attr(f.id(), "dataset", dataset);
    h5::set_attr(f.id(), "cut", graph.cut);
    h5::set_attr(f.id(), "energy_scale", graph.energy_scale);
    h5::set_attr(f.id(), "options", options);
    h5::set_attr(f.id(), "complete", static_cast<std::int64_t>(complete ? 1 : 0));
    if (states_searched >= 0) h5::set_attr(f.id(), "states_searched", static_cast<std::int64_t>(states_searched));
    write_states(f.id(), graph);
    write_saddles(f.id(), graph);
    write_edges(f.id(), graph);
    write_searches(f.id(), graph);
    write_pairs(f.id(), graph);
  }
  atomic_replace(tmp.path, path);
  tmp.committed = true;
}

namespace {

void read_states(hid_t file, TransitionGraph& g) {
  const h5::Handle s = h5::open_group(file, "states");
  const std::vector<double> energy = h5::read_doubles(s.id(), "energy");
  const std::vector<std::int64_t> cluster = h5::read_int64(s.id(), "cluster");
  const std::vector<std::int64_t> eq = h5::read_int64(s.id(), "equilibrium");
  const std::vector<Points> pos = read_curves(s.id(), "positions");
  if (cluster.size() != energy.size() || eq.size() != energy.size() || pos.size() != energy.size())
    throw InputError("states: columns of different lengths");
  for (size_t k = 0; k < energy.size(); ++k)
    g.states.push_back({static_cast<int>(cluster[k]), static_cast<int>(eq[k]), energy[k], pos[k]});
}

void read_saddles(hid_t file, TransitionGraph& g) {
  const h5::Handle s = h5::open_group(file, "saddles");
  const std::vector<double> energy = h5::read_doubles(s.id(), "energy");
  const std::vector<double> neg = h5::read_doubles(s.id(), "negative_eigenvalue");
  const std::vector<double> second = h5::read_doubles(s.id(), "second_eigenvalue");
  const std::vector<double> grad = h5::read_doubles(s.id(), "gradient_norm");
  const std::vector<std::int64_t> index = h5::read_int64(s.id(), "index");
  const std::vector<std::int64_t> from = h5::read_int64(s.id(), "from"), to = h5::read_int64(s.id(), "to");
  const std::vector<std::int64_t> at = h5::read_int64(s.id(), "saddle_image");
  const std::vector<double> energy_from = h5::read_doubles(s.id(), "energy_from");
  const std::vector<double> energy_to = h5::read_doubles(s.id(), "energy_to");
  const std::vector<std::int64_t> two = h5::read_int64(s.id(), "double_ended");
  const std::vector<Points> pos = energy.empty() ? std::vector<Points>{} : read_curves(s.id(), "positions");
  const size_t k = energy.size();
  if (neg.size() != k || second.size() != k || grad.size() != k || index.size() != k || from.size() != k ||
      to.size() != k || at.size() != k || pos.size() != k || energy_to.size() != k || energy_from.size() != k || two.size() != k)
    throw InputError("saddles: columns of different lengths");
  for (size_t j = 0; j < k; ++j) {
    TransitionSaddle t;
    t.energy = energy[j];
    t.negative_eigenvalue = neg[j];
    t.second_eigenvalue = second[j];
    t.gradient_norm = grad[j];
    t.index = static_cast<int>(index[j]);
    t.from = static_cast<int>(from[j]);
    t.to = static_cast<int>(to[j]);
    t.saddle_image = static_cast<int>(at[j]);
    t.energy_from = energy_from[j];
    t.energy_to = energy_to[j];
    t.double_ended = two[j] != 0;
    t.positions = pos[j];
    const h5::Handle p = h5::open_group(s.id(), "path_" + std::to_string(j));
    t.path = read_curves(p.id(), "images");
    t.path_energies = h5::read_doubles(p.id(), "energies");
    if (t.path.size() != t.path_energies.size() || t.saddle_image < 0 ||
        t.saddle_image >= static_cast<int>(t.path.size()))
      throw InputError("saddles: path " + std::to_string(j) + " is inconsistent");
    g.saddles.push_back(std::move(t));
  }
}

void read_edges(hid_t file, TransitionGraph& g) {
  const h5::Handle e = h5::open_group(file, "edges");
  const std::vector<std::int64_t> from = h5::read_int64(e.id(), "from"), to = h5::read_int64(e.id(), "to");
  const std::vector<std::int64_t> saddle = h5::read_int64(e.id(), "saddle");
  const std::vector<double> energy = h5::read_doubles(e.id(), "energy");
  const std::vector<double> fw = h5::read_doubles(e.id(), "barrier_forward");
  const std::vector<double> bw = h5::read_doubles(e.id(), "barrier_backward");
  const size_t k = from.size();
  if (to.size() != k || saddle.size() != k || energy.size() != k || fw.size() != k || bw.size() != k)
    throw InputError("edges: columns of different lengths");
  const auto states = static_cast<std::int64_t>(g.states.size());
  const auto saddles = static_cast<std::int64_t>(g.saddles.size());
  for (size_t j = 0; j < k; ++j) {
    if (from[j] < 0 || from[j] >= states || to[j] < 0 || to[j] >= states || saddle[j] < 0 || saddle[j] >= saddles)
      throw InputError("edges: an index out of range");
    g.edges.push_back({static_cast<int>(from[j]), static_cast<int>(to[j]), static_cast<int>(saddle[j]), energy[j],
                       fw[j], bw[j]});
  }
}

void read_pairs(hid_t file, TransitionGraph& g) {
  const h5::Handle p = h5::open_group(file, "pairs");
  const std::vector<std::int64_t> a = h5::read_int64(p.id(), "a"), b = h5::read_int64(p.id(), "b");
  const std::vector<std::string> status = h5::read_strings(p.id(), "status");
  const std::vector<std::string> seeds = h5::read_strings(p.id(), "seed_statuses");
  const std::vector<std::int64_t> reached = h5::read_int64(p.id(), "reached");
  const std::vector<std::int64_t> verified = h5::read_int64(p.id(), "verified");
  const std::vector<std::int64_t> stages = h5::read_int64(p.id(), "stages");
  const std::vector<std::int64_t> saddle = h5::read_int64(p.id(), "saddle");
  const std::vector<double> barrier = h5::read_doubles(p.id(), "path_barrier");
  const std::vector<double> reach = h5::read_doubles(p.id(), "reached_similarity");
  const std::vector<double> energy = h5::read_doubles(p.id(), "saddle_energy");
  const std::vector<double> seconds = h5::read_doubles(p.id(), "seconds");
  const size_t k = a.size();
  for (const size_t m : {b.size(), status.size(), seeds.size(), reached.size(), verified.size(), stages.size(), saddle.size(),
                         barrier.size(), reach.size(), energy.size(), seconds.size()})
    if (m != k) throw InputError("pairs: columns of different lengths");
  for (size_t j = 0; j < k; ++j) {
    PairSearch x;
    x.a = static_cast<int>(a[j]);
    x.b = static_cast<int>(b[j]);
    x.status = from_string<SearchStatus>(status[j]);
    x.seed_statuses = from_string<std::vector<SearchStatus>>(seeds[j]);
    x.reached = reached[j] != 0;
    x.verified = verified[j] != 0;
    x.stages = static_cast<int>(stages[j]);
    x.saddle = static_cast<int>(saddle[j]);
    x.path_barrier = barrier[j];
    x.reached_similarity = reach[j];
    x.saddle_energy = energy[j];
    x.seconds = seconds[j];
    if (x.saddle >= static_cast<int>(g.saddles.size())) throw InputError("pairs: a saddle index out of range");
    g.pairs.push_back(x);
  }
}

/// The searches/ rows back as one StateSearches per state (in the order of
/// their first row); the columns the file does not keep stay default.
void read_searches(hid_t file, TransitionGraph& g) {
  const h5::Handle s = h5::open_group(file, "searches");
  const std::vector<std::int64_t> state = h5::read_int64(s.id(), "state"), mode = h5::read_int64(s.id(), "mode");
  const std::vector<std::int64_t> direction = h5::read_int64(s.id(), "direction");
  const std::vector<std::int64_t> verified = h5::read_int64(s.id(), "verified"), index = h5::read_int64(s.id(), "index");
  const std::vector<std::int64_t> iterations = h5::read_int64(s.id(), "iterations");
  const std::vector<std::string> status = h5::read_strings(s.id(), "status");
  const std::vector<double> energy = h5::read_doubles(s.id(), "energy"), gradient = h5::read_doubles(s.id(), "gradient_norm");
  const std::vector<double> seconds = h5::read_doubles(s.id(), "seconds");
  const size_t k = state.size();
  for (const size_t m : {mode.size(), direction.size(), verified.size(), index.size(), iterations.size(), status.size(),
                         energy.size(), gradient.size(), seconds.size()})
    if (m != k) throw InputError("searches: columns of different lengths");
  for (size_t j = 0; j < k; ++j) {
    if (state[j] < 0 || state[j] >= static_cast<std::int64_t>(g.states.size()))
      throw InputError("searches: a state index out of range");
    if (g.searches.empty() || g.searches.back().state != state[j]) {
      g.searches.emplace_back();
      g.searches.back().state = static_cast<int>(state[j]);
      g.searches.back().energy = g.states[static_cast<size_t>(state[j])].energy;
    }
    StateSearches& out = g.searches.back();
    if (mode[j] < 0 && status[j].rfind(kRefusedRow, 0) == 0) {
      out.error = status[j].substr(std::string(kRefusedRow).size());
      out.seconds = seconds[j];
      continue;
    }
    SaddleRecord r;
    r.mode = static_cast<int>(mode[j]);
    r.direction = static_cast<int>(direction[j]);
    r.verified = verified[j] != 0;
    r.index = static_cast<int>(index[j]);
    r.iterations = static_cast<int>(iterations[j]);
    r.status = from_string<SearchStatus>(status[j]);
    r.energy = energy[j];
    r.gradient_norm = gradient[j];
    r.seconds = seconds[j];
    out.seconds += seconds[j];
    out.records.push_back(std::move(r));
  }
}

}  // namespace

TransitionGraph read_transitions(const std::string& path, TransitionsFileInfo& info) {
  h5::quiet();
  const h5::Handle f = h5::open_file(path, false);
  try {
    if (!h5::has_attr(f.id(), "format") || h5::get_attr_string(f.id(), "format") != kFormat)
      throw InputError("not a transitions file");
    if (h5::get_attr_int(f.id(), "format_version") > kFormatVersion)
      throw InputError("written by a newer version (format_version " +
                       std::to_string(h5::get_attr_int(f.id(), "format_version")) + ")");
    TransitionGraph g;
    g.knot = h5::get_attr_string(f.id(), "knot");
    g.cut = h5::get_attr_double(f.id(), "cut");
    g.energy_scale = h5::get_attr_double(f.id(), "energy_scale");
    info.dataset = h5::get_attr_string(f.id(), "dataset");
    info.options = h5::get_attr_string(f.id(), "options");
    info.complete = h5::get_attr_int(f.id(), "complete") != 0;
    info.states_searched =
        h5::has_attr(f.id(), "states_searched") ? static_cast<int>(h5::get_attr_int(f.id(), "states_searched")) : -1;
    read_states(f.id(), g);
    read_saddles(f.id(), g);
    read_edges(f.id(), g);
    read_searches(f.id(), g);
    read_pairs(f.id(), g);
    return g;
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

TransitionGraph read_transitions(const std::string& path, std::string* options) {
  TransitionsFileInfo info;
  TransitionGraph g = read_transitions(path, info);
  if (options) *options = info.options;
  return g;
}

void write_path_h5(const std::string& path, const std::string& knot, const std::vector<Points>& images,
                   const std::vector<double>& energies, const std::vector<int>& saddle_images) {
  require(images.size() == energies.size(), "write_path_h5: one energy per image");
  h5::quiet();
  check_writable(path);
  Temporary tmp{temporary_path(path)};
  {
    const h5::Handle f = h5::create_file(tmp.path);
    h5::set_attr(f.id(), "format", std::string("elastic-knots-path"));
    h5::set_attr(f.id(), "format_version", kFormatVersion);
    h5::set_attr(f.id(), "knot", knot);
    write_curves(f.id(), "images", images);
    put(f.id(), "energies", energies);
    put(f.id(), "saddle_images", std::vector<std::int64_t>(saddle_images.begin(), saddle_images.end()));
  }
  atomic_replace(tmp.path, path);
  tmp.committed = true;
}

}  // namespace ek
