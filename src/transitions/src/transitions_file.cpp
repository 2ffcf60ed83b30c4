#include "ek/transitions/transitions_file.hpp"

#include <cstdio>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/h5.hpp"
#include "ek/dataset/h5_columns.hpp"

namespace ek {
namespace {

constexpr const char* kFormat = "elastic-knots-transitions";
/// The reader accepts this version only (the data set's policy, dataset_file.cpp).
constexpr std::int64_t kFormatVersion = 1;
constexpr const char* kPathFormat = "elastic-knots-path";
constexpr std::int64_t kPathFormatVersion = 1;
constexpr const char* kRefusedRow = "start-refused: ";  ///< the searches/ status of a refused start

// ---------------------------------------------------------------------------
// Columns and attributes: each is described once, in the tables below, and
// both write_transitions() and read_transitions() walk the tables in order
// (the order is the file's: datasets are created in it).

using Type = h5::ColumnType;
using h5::Cell;
using h5::from_cell;
using h5::read_columns;
using h5::to_cell;
using h5::write_columns;

/// One dataset of a group: one row per record of type Row, with the graph
/// for the columns derived from it (h5_columns.hpp).
template <class Row>
using Column = h5::Column<Row, TransitionGraph>;

/// A column that is the member `m` (of Row or of a base of it).
template <class Row, class Class, class T>
Column<Row> column(std::string name, T Class::*m) {
  return h5::member_column<Row, TransitionGraph>(std::move(name), m);
}

/// A column holding to_string() of the member `m`, read by from_string<T>().
template <class Row, class T>
Column<Row> text_of(std::string name, T Row::*m) {
  return {std::move(name), Type::Text, [m](const Row& r, const TransitionGraph&) { return Cell(to_string(r.*m)); },
          [m](Row& r, Cell&& c) { r.*m = from_string<T>(std::get<std::string>(c)); }};
}

/// A column derived from a record and the graph (written only).
template <class Row>
Column<Row> derived(std::string name, double (*get)(const Row&, const TransitionGraph&)) {
  return h5::derived_column<Row, TransitionGraph>(std::move(name), get);
}

/// A group of the file and its columns.
template <class Row>
struct Table {
  std::string group;
  std::vector<Column<Row>> columns;
};

/// One row of searches/: a search from a state, or a start that was refused
/// (one row with mode −1, direction 0, index −1, no iterations, energy and
/// gradient 0, the start's seconds, and status "start-refused: <error>").
struct SearchRow : SaddleRecord {
  int state = -1;
  bool refused = false;
  std::string error;  ///< of a refused start
};

/// One image of a saddle's path (saddles/path_<j>/) or of a path file.
struct PathRow {
  Points image;
  double energy = 0.0;
};

using State = TransitionState;
using Saddle = TransitionSaddle;
using Edge = TransitionEdge;

const Table<State> kStates{"states",
                           {
                               column<State>("energy", &State::energy),
                               column<State>("cluster", &State::cluster),
                               column<State>("equilibrium", &State::equilibrium),
                               column<State>("positions", &State::positions),
                           }};

/// Each saddle's path is a group path_<j> of kPath's columns besides these.
const Table<Saddle> kSaddles{"saddles",
                             {
                                 column<Saddle>("energy", &Saddle::energy),
                                 column<Saddle>("negative_eigenvalue", &Saddle::negative_eigenvalue),
                                 column<Saddle>("second_eigenvalue", &Saddle::second_eigenvalue),
                                 column<Saddle>("gradient_norm", &Saddle::gradient_norm),
                                 column<Saddle>("index", &Saddle::index),
                                 column<Saddle>("from", &Saddle::from),
                                 column<Saddle>("to", &Saddle::to),
                                 column<Saddle>("saddle_image", &Saddle::saddle_image),
                                 column<Saddle>("energy_from", &Saddle::energy_from),
                                 column<Saddle>("energy_to", &Saddle::energy_to),
                                 column<Saddle>("double_ended", &Saddle::double_ended),
                                 column<Saddle>("positions", &Saddle::positions),
                             }};

const std::vector<Column<PathRow>> kPath = {
    column<PathRow>("images", &PathRow::image),
    column<PathRow>("energies", &PathRow::energy),
};

const Table<Edge> kEdges{"edges",
                         {
                             column<Edge>("from", &Edge::from),
                             column<Edge>("to", &Edge::to),
                             column<Edge>("saddle", &Edge::saddle),
                             column<Edge>("energy", &Edge::energy),
                             column<Edge>("barrier_forward", &Edge::barrier_forward),
                             column<Edge>("barrier_backward", &Edge::barrier_backward),
                             // divided by EI/L
                             derived<Edge>("barrier_forward_scaled",
                                           [](const Edge& e, const TransitionGraph& g) {
                                             return e.barrier_forward / g.energy_scale;
                                           }),
                             derived<Edge>("barrier_backward_scaled",
                                           [](const Edge& e, const TransitionGraph& g) {
                                             return e.barrier_backward / g.energy_scale;
                                           }),
                         }};

const Table<SearchRow> kSearches{
    "searches",
    {
        column<SearchRow>("state", &SearchRow::state),
        column<SearchRow>("mode", &SearchRow::mode),
        column<SearchRow>("direction", &SearchRow::direction),
        column<SearchRow>("verified", &SearchRow::verified),
        column<SearchRow>("index", &SearchRow::index),
        column<SearchRow>("iterations", &SearchRow::iterations),
        {"status", Type::Text,
         [](const SearchRow& r, const TransitionGraph&) {
           return Cell(r.refused ? kRefusedRow + r.error : to_string(r.status));
         },
         [](SearchRow& r, Cell&& c) {
           const std::string& text = std::get<std::string>(c);
           r.refused = text.rfind(kRefusedRow, 0) == 0;
           if (r.refused) r.error = text.substr(std::string(kRefusedRow).size());
           else r.status = from_string<SearchStatus>(text);
         }},
        column<SearchRow>("energy", &SearchRow::energy),
        column<SearchRow>("gradient_norm", &SearchRow::gradient_norm),
        column<SearchRow>("seconds", &SearchRow::seconds),
    }};

const Table<PairSearch> kPairs{"pairs",
                               {
                                   column<PairSearch>("a", &PairSearch::a),
                                   column<PairSearch>("b", &PairSearch::b),
                                   text_of("status", &PairSearch::status),
                                   text_of("seed_statuses", &PairSearch::seed_statuses),
                                   column<PairSearch>("reached", &PairSearch::reached),
                                   column<PairSearch>("verified", &PairSearch::verified),
                                   column<PairSearch>("stages", &PairSearch::stages),
                                   column<PairSearch>("saddle", &PairSearch::saddle),
                                   column<PairSearch>("path_barrier", &PairSearch::path_barrier),
                                   column<PairSearch>("reached_similarity", &PairSearch::reached_similarity),
                                   column<PairSearch>("saddle_energy", &PairSearch::saddle_energy),
                                   column<PairSearch>("seconds", &PairSearch::seconds),
                               }};

/// An attribute of the root group (after format and format_version). An
/// optional one is left out when `get` gives std::monostate (not recorded),
/// and `set` receives std::monostate when the file lacks it; a required one
/// must be in the file.
struct Attribute {
  std::string name;
  Type type;
  std::function<Cell(const TransitionGraph&, const TransitionsFileInfo&)> get;
  std::function<void(TransitionGraph&, TransitionsFileInfo&, Cell&&)> set;
  bool optional = false;
};

template <class T>
Attribute attribute(std::string name, T TransitionGraph::*m) {
  return {std::move(name), h5::column_type_of<T>(),
          [m](const TransitionGraph& g, const TransitionsFileInfo&) { return to_cell(g.*m); },
          [m](TransitionGraph& g, TransitionsFileInfo&, Cell&& c) { from_cell(std::move(c), g.*m); }};
}
template <class T>
Attribute attribute(std::string name, T TransitionsFileInfo::*m) {
  return {std::move(name), h5::column_type_of<T>(),
          [m](const TransitionGraph&, const TransitionsFileInfo& i) { return to_cell(i.*m); },
          [m](TransitionGraph&, TransitionsFileInfo& i, Cell&& c) { from_cell(std::move(c), i.*m); }};
}

const std::vector<Attribute> kAttributes = {
    attribute("knot", &TransitionGraph::knot),
    attribute("dataset", &TransitionsFileInfo::dataset),
    attribute("cut", &TransitionGraph::cut),
    attribute("energy_scale", &TransitionGraph::energy_scale),
    attribute("options", &TransitionsFileInfo::options),
    attribute("complete", &TransitionsFileInfo::complete),
    // optional: the experiment's files do not record it (states_searched < 0)
    {"states_searched", Type::Int64,
     [](const TransitionGraph&, const TransitionsFileInfo& i) {
       return i.states_searched < 0 ? Cell() : Cell(std::int64_t{i.states_searched});
     },
     [](TransitionGraph&, TransitionsFileInfo& i, Cell&& c) {
       i.states_searched = std::holds_alternative<std::monostate>(c) ? -1 : static_cast<int>(std::get<std::int64_t>(c));
     },
     true},
};

// ---------------------------------------------------------------------------
// Walking the tables.

template <class Row>
h5::Handle write_table(hid_t file, const Table<Row>& table, const std::vector<Row>& rows,
                       const TransitionGraph& graph) {
  h5::Handle g = h5::create_group(file, table.group);
  write_columns(g.id(), table.columns, rows, graph);
  return g;
}

template <class Row>
std::vector<Row> read_table(hid_t file, const Table<Row>& table, h5::Handle* group = nullptr) {
  h5::Handle g = h5::open_group(file, table.group);
  std::vector<Row> rows = read_columns(g.id(), table.columns, table.group);
  if (group) *group = std::move(g);
  return rows;
}

std::vector<PathRow> path_rows(const std::vector<Points>& images, const std::vector<double>& energies) {
  require(images.size() == energies.size(), "transitions file: one energy per path image");
  std::vector<PathRow> rows;
  for (size_t k = 0; k < images.size(); ++k) rows.push_back({images[k], energies[k]});
  return rows;
}

std::string path_group(size_t saddle) { return "path_" + std::to_string(saddle); }

std::vector<SearchRow> search_rows(const TransitionGraph& graph) {
  std::vector<SearchRow> rows;
  for (const StateSearches& s : graph.searches) {
    if (!s.error.empty()) {
      SearchRow r;
      r.state = s.state;
      r.refused = true;
      r.error = s.error;
      r.mode = -1;
      r.direction = 0;
      r.verified = false;
      r.index = -1;
      r.iterations = 0;
      r.energy = r.gradient_norm = 0.0;
      r.seconds = s.seconds;
      rows.push_back(std::move(r));
    }
    for (const SaddleRecord& x : s.records) {
      SearchRow r;
      static_cast<SaddleRecord&>(r) = x;
      r.state = s.state;
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

/// The searches/ rows back as one StateSearches per state (in the order of
/// their first row); the record members the file does not keep stay default.
void add_search_rows(TransitionGraph& g, std::vector<SearchRow>&& rows) {
  for (size_t j = 0; j < rows.size(); ++j) {
    SearchRow& row = rows[j];
    if (row.state < 0 || row.state >= static_cast<int>(g.states.size()))
      throw InputError("searches: a state index out of range");
    if (g.searches.empty() || g.searches.back().state != row.state) {
      g.searches.emplace_back();
      g.searches.back().state = row.state;
      g.searches.back().energy = g.states[static_cast<size_t>(row.state)].energy;
    }
    StateSearches& out = g.searches.back();
    if (row.refused) {
      if (row.mode >= 0)
        throw InputError("searches: row " + std::to_string(j) + " is a refused start with mode " +
                         std::to_string(row.mode));
      out.error = row.error;
      out.seconds = row.seconds;
      continue;
    }
    out.seconds += row.seconds;
    out.records.push_back(std::move(static_cast<SaddleRecord&>(row)));
  }
}

/// Removes the temporary unless committed.
struct Temporary {
  std::string path;
  bool committed = false;
  ~Temporary() {
    if (!committed) std::remove(path.c_str());
  }
};

void set_cell_attr(hid_t obj, const std::string& name, const Cell& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) h5::set_attr(obj, name, *i);
  else if (const auto* x = std::get_if<double>(&v)) h5::set_attr(obj, name, *x);
  else if (const auto* t = std::get_if<std::string>(&v)) h5::set_attr(obj, name, *t);
}

Cell get_cell_attr(hid_t obj, const Attribute& a) {
  if (!h5::has_attr(obj, a.name)) {
    if (!a.optional) throw InputError("the attribute '" + a.name + "' is missing");
    return {};
  }
  switch (a.type) {
    case Type::Int64: return h5::get_attr_int(obj, a.name);
    case Type::Float64: return h5::get_attr_double(obj, a.name);
    case Type::Text: return h5::get_attr_string(obj, a.name);
    case Type::Curves: break;
  }
  return {};
}

}  // namespace

void write_transitions(const std::string& path, const TransitionGraph& graph, const std::string& dataset,
                       const std::string& options, bool complete, int states_searched) {
  h5::quiet();
  check_writable(path);
  const TransitionsFileInfo info{dataset, options, complete, states_searched};
  Temporary tmp{temporary_path(path)};
  {
    const h5::Handle f = h5::create_file(tmp.path);
    h5::set_attr(f.id(), "format", std::string(kFormat));
    h5::set_attr(f.id(), "format_version", kFormatVersion);
    for (const Attribute& a : kAttributes) {
      const Cell v = a.get(graph, info);
      require(!std::holds_alternative<std::monostate>(v) || a.optional,
              "transitions file: the attribute '" + a.name + "' is not set");
      set_cell_attr(f.id(), a.name, v);
    }
    write_table(f.id(), kStates, graph.states, graph);
    {
      const h5::Handle g = write_table(f.id(), kSaddles, graph.saddles, graph);
      for (size_t k = 0; k < graph.saddles.size(); ++k) {
        const h5::Handle p = h5::create_group(g.id(), path_group(k));
        write_columns(p.id(), kPath, path_rows(graph.saddles[k].path, graph.saddles[k].path_energies), graph);
      }
    }
    write_table(f.id(), kEdges, graph.edges, graph);
    write_table(f.id(), kSearches, search_rows(graph), graph);
    write_table(f.id(), kPairs, graph.pairs, graph);
  }
  atomic_replace(tmp.path, path);
  tmp.committed = true;
}

TransitionGraph read_transitions(const std::string& path, TransitionsFileInfo& info) {
  h5::quiet();
  const h5::Handle f = h5::open_file(path, false);
  try {
    if (!h5::has_attr(f.id(), "format") || h5::get_attr_string(f.id(), "format") != kFormat)
      throw InputError("not a transitions file");
    if (!h5::has_attr(f.id(), "format_version")) throw InputError("the attribute 'format_version' is missing");
    const std::int64_t version = h5::get_attr_int(f.id(), "format_version");
    if (version != kFormatVersion)
      throw InputError("transitions format version " + std::to_string(version) + ", expected " +
                       std::to_string(kFormatVersion));
    TransitionGraph g;
    info = TransitionsFileInfo{};
    for (const Attribute& a : kAttributes) a.set(g, info, get_cell_attr(f.id(), a));

    g.states = read_table(f.id(), kStates);

    h5::Handle saddles;
    g.saddles = read_table(f.id(), kSaddles, &saddles);
    for (size_t j = 0; j < g.saddles.size(); ++j) {
      TransitionSaddle& t = g.saddles[j];
      const std::string name = path_group(j);
      const h5::Handle p = h5::open_group(saddles.id(), name);
      for (PathRow& r : read_columns(p.id(), kPath, kSaddles.group + "/" + name)) {
        t.path.push_back(std::move(r.image));
        t.path_energies.push_back(r.energy);
      }
      if (t.saddle_image < 0 || t.saddle_image >= static_cast<int>(t.path.size()))
        throw InputError("saddles: path " + std::to_string(j) + " is inconsistent");
    }

    g.edges = read_table(f.id(), kEdges);
    const int states = static_cast<int>(g.states.size()), saddle_count = static_cast<int>(g.saddles.size());
    for (const TransitionEdge& e : g.edges)
      if (e.from < 0 || e.from >= states || e.to < 0 || e.to >= states || e.saddle < 0 || e.saddle >= saddle_count)
        throw InputError("edges: an index out of range");

    add_search_rows(g, read_table(f.id(), kSearches));

    g.pairs = read_table(f.id(), kPairs);
    for (const PairSearch& x : g.pairs)
      if (x.saddle >= saddle_count) throw InputError("pairs: a saddle index out of range");
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
    h5::set_attr(f.id(), "format", std::string(kPathFormat));
    h5::set_attr(f.id(), "format_version", kPathFormatVersion);
    h5::set_attr(f.id(), "knot", knot);
    write_columns(f.id(), kPath, path_rows(images, energies), TransitionGraph{});
    const std::vector<std::int64_t> at(saddle_images.begin(), saddle_images.end());
    h5::write_int64(f.id(), "saddle_images", {at.size()}, at.data());
  }
  atomic_replace(tmp.path, path);
  tmp.committed = true;
}

}  // namespace ek
