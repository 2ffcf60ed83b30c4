#include "ek/dataset/ledger.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <set>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/h5.hpp"
#include "ek/dataset/h5_columns.hpp"
#include "parameters_h5.hpp"

namespace ek {
namespace {

constexpr const char* kLedgerFormat = "elastic-knots-ledger";
constexpr std::int64_t kLedgerFormatVersion = 1;

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// A knot's rows of the file's tables: [first, first + count).
struct Rows {
  std::int64_t runs_first = 0, runs = 0, equilibria_first = 0, equilibria = 0, linkage_first = 0, states_first = 0,
               states = 0;
  std::vector<std::int64_t> list() const {
    return {runs_first, runs, equilibria_first, equilibria, linkage_first, states_first, states};
  }
};

std::vector<std::string> attribute_union(const std::vector<LedgerEntry>& entries) {
  std::vector<std::string> names;
  for (const LedgerEntry& e : entries)
    for (const std::string& a : e.attribute_names)
      if (std::find(names.begin(), names.end(), a) == names.end()) names.push_back(a);
  return names;
}

int vertices_of(const std::vector<LedgerEntry>& entries) {
  int n = -1;
  for (const LedgerEntry& e : entries)
    for (const LedgerState& s : e.states) {
      if (s.curve.rows() == 0) continue;
      require(n < 0 || s.curve.rows() == n, "write_ledger: representative curves of different sizes");
      n = static_cast<int>(s.curve.rows());
    }
  return std::max(n, 0);
}

void check_entry(const LedgerEntry& e) {
  const auto m = e.attributes.rows();
  require(!e.alexander.empty(), "write_ledger: " + e.name + " has no Alexander polynomial");
  require(e.attributes.cols() == static_cast<Eigen::Index>(e.attribute_names.size()),
          "write_ledger: " + e.name + "'s attribute table does not match its names");
  require(static_cast<Eigen::Index>(e.state.size()) == m, "write_ledger: " + e.name + " needs one state per equilibrium");
  require(e.linkage.rows() == std::max<Eigen::Index>(m - 1, 0) && (e.linkage.rows() == 0 || e.linkage.cols() == 4),
          "write_ledger: " + e.name + "'s linkage is not (m-1) by 4");
  for (int s : e.state)
    require(s >= 0 && s < static_cast<int>(e.states.size()), "write_ledger: " + e.name + " names a missing state");
  for (const LedgerState& s : e.states)
    require(s.representative >= 0 && s.representative < m, "write_ledger: " + e.name + " has a bad representative");
  for (const LedgerRun& r : e.runs)
    require(r.equilibrium >= -1 && r.equilibrium < m, "write_ledger: " + e.name + " has a run naming a missing row");
}

void write_provenance(hid_t f, const LedgerProvenance& p) {
  h5::set_attr(f, "cut", p.cut);
  h5::set_attr(f, "curves_per_knot", static_cast<std::int64_t>(p.curves_per_knot));
  h5::set_attr(f, "curve_quantum", p.curve_quantum);
  h5::set_attr(f, "commit", p.commit);
  h5::set_attr(f, "ledger_created", p.created);
  h5::set_attr(f, "source", p.source);
  if (p.cores) h5::set_attr(f, "cores", static_cast<std::int64_t>(*p.cores));
  if (p.jobs) h5::set_attr(f, "jobs", static_cast<std::int64_t>(*p.jobs));
  if (p.wall_seconds) h5::set_attr(f, "wall_seconds", *p.wall_seconds);
  if (p.cpu_seconds) h5::set_attr(f, "cpu_seconds", *p.cpu_seconds);
}

LedgerProvenance read_provenance(hid_t f) {
  LedgerProvenance p;
  p.cut = h5::get_attr_double(f, "cut");
  p.curves_per_knot = static_cast<int>(h5::get_attr_int(f, "curves_per_knot"));
  p.curve_quantum = h5::get_attr_double(f, "curve_quantum");
  p.commit = h5::get_attr_string(f, "commit");
  p.created = h5::get_attr_string(f, "ledger_created");
  p.source = h5::get_attr_string(f, "source");
  if (h5::has_attr(f, "cores")) p.cores = static_cast<int>(h5::get_attr_int(f, "cores"));
  if (h5::has_attr(f, "jobs")) p.jobs = static_cast<int>(h5::get_attr_int(f, "jobs"));
  if (h5::has_attr(f, "wall_seconds")) p.wall_seconds = h5::get_attr_double(f, "wall_seconds");
  if (h5::has_attr(f, "cpu_seconds")) p.cpu_seconds = h5::get_attr_double(f, "cpu_seconds");
  return p;
}

/// The knots' scalar fields, one group each, with the knot's table rows and
/// its attribute columns (indices into the table's names).
void write_knot(hid_t knots, const LedgerEntry& e, const Rows& rows, const std::vector<std::string>& columns) {
  h5::Handle g = h5::create_group(knots, e.name);
  const hid_t id = g.id();
  detail::write_knot_header(id, e);
  h5::set_attr(id, "rows", rows.list());
  std::vector<std::int64_t> own;
  for (const std::string& a : e.attribute_names)
    own.push_back(std::find(columns.begin(), columns.end(), a) - columns.begin());
  h5::set_attr(id, "attribute_columns", own);
}

/// One row of the runs/ table: a LedgerRun with its status as the index
/// into status_names.
struct RunRow {
  int sample = 0;
  std::int64_t status = 0;
  int equilibrium = -1;
  int iterations = 0;
  bool topology_kept = true;
  double seconds = 0.0;
};

/// The columns of runs/, in the file's order (h5_columns.hpp).
const std::vector<h5::Column<RunRow>>& run_columns() {
  using h5::member_column;
  static const std::vector<h5::Column<RunRow>> columns = {
      member_column<RunRow>("sample", &RunRow::sample),
      member_column<RunRow>("status", &RunRow::status),
      member_column<RunRow>("equilibrium", &RunRow::equilibrium),
      member_column<RunRow>("iterations", &RunRow::iterations),
      member_column<RunRow>("topology_kept", &RunRow::topology_kept),
      member_column<RunRow>("seconds", &RunRow::seconds),
  };
  return columns;
}

/// Integer columns of one table, appended entry by entry.
struct IntColumns {
  std::vector<std::string> names;
  std::vector<std::vector<std::int64_t>> values;
  explicit IntColumns(std::vector<std::string> n) : names(std::move(n)), values(names.size()) {}
  void write(hid_t group) const {
    for (size_t c = 0; c < names.size(); ++c) h5::write_int64(group, names[c], {values[c].size()}, values[c].data());
  }
};

/// A curve on the grid of `quantum`: its first vertex and its n − 1 steps,
/// integers (coordinates over the quantum, rounded), so that summing the
/// steps gives every vertex back exactly on the grid.
void add_curve(const Points& P, double quantum, std::vector<std::int64_t>& origins, std::vector<std::int64_t>& steps) {
  std::array<std::int64_t, 3> previous{};
  for (Eigen::Index v = 0; v < P.rows(); ++v)
    for (int c = 0; c < 3; ++c) {
      const double q = std::round(P(v, c) / quantum);
      require(std::abs(q) < 9e15, "write_ledger: a coordinate is too large for the curve quantum");
      const auto g = static_cast<std::int64_t>(q);
      if (v == 0) origins.push_back(g);
      else steps.push_back(g - previous[static_cast<size_t>(c)]);
      previous[static_cast<size_t>(c)] = g;
    }
}

}  // namespace

int LedgerEntry::representative_sample(int s) const {
  require(s >= 0 && s < static_cast<int>(states.size()), "LedgerEntry::representative_sample: no state " + std::to_string(s));
  for (const LedgerRun& r : runs)
    if (r.equilibrium == states[static_cast<size_t>(s)].representative) return r.sample;
  return -1;
}

int LedgerEntry::attribute_column(const std::string& attribute) const {
  for (size_t k = 0; k < attribute_names.size(); ++k)
    if (attribute_names[k] == attribute) return static_cast<int>(k);
  std::string known;
  for (const auto& a : attribute_names) known += (known.empty() ? "" : ", ") + a;
  throw InputError("unknown attribute '" + attribute + "' (known: " + known + ")");
}

int LedgerEntry::stable_runs() const {
  return static_cast<int>(
      std::count_if(runs.begin(), runs.end(), [](const LedgerRun& r) { return r.status == RunStatus::ConvergedStable; }));
}

std::map<RunStatus, int> LedgerEntry::status_counts() const {
  std::map<RunStatus, int> out;
  for (const LedgerRun& r : runs) ++out[r.status];
  return out;
}

double LedgerEntry::run_seconds() const {
  double s = 0.0;
  for (const LedgerRun& r : runs) s += r.seconds;
  return s;
}

std::vector<int> LedgerEntry::members(int s) const {
  std::vector<int> out;
  for (size_t i = 0; i < state.size(); ++i)
    if (state[i] == s) out.push_back(static_cast<int>(i));
  return out;
}

AttributeSpread LedgerEntry::spread(int s, int column) const {
  require(s >= 0 && s < static_cast<int>(states.size()), "LedgerEntry::spread: no state " + std::to_string(s));
  require(column >= 0 && column < attributes.cols(), "LedgerEntry::spread: no column " + std::to_string(column));
  std::vector<double> v;
  for (int i : members(s)) v.push_back(attributes(i, column));
  require(!v.empty(), "LedgerEntry::spread: state " + std::to_string(s) + " has no member");
  std::sort(v.begin(), v.end());
  const size_t h = v.size() / 2;
  return {v.front(), v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]), v.back()};
}

void write_ledger(const std::string& path, const Ledger& ledger) {
  for (const LedgerEntry& e : ledger.entries) check_entry(e);
  require(ledger.provenance.curve_quantum > 0.0 && std::isfinite(ledger.provenance.curve_quantum),
          "write_ledger: the curve quantum must be positive");
  const std::vector<std::string> columns = attribute_union(ledger.entries);
  const int n = vertices_of(ledger.entries);
  check_writable(path);
  const std::string tmp = temporary_path(path);
  try {
    h5::Handle f = h5::create_file(tmp);
    h5::set_attr(f.id(), "format", std::string(kLedgerFormat));
    h5::set_attr(f.id(), "format_version", kLedgerFormatVersion);
    detail::write_parameters(f.id(), ledger.parameters);
    write_provenance(f.id(), ledger.provenance);
    // status names, in order of first appearance
    std::vector<RunStatus> statuses;
    for (const LedgerEntry& e : ledger.entries)
      for (const LedgerRun& r : e.runs)
        if (std::find(statuses.begin(), statuses.end(), r.status) == statuses.end()) statuses.push_back(r.status);
    std::vector<RunRow> runs;
    std::vector<double> attributes, linkage;
    std::vector<std::int64_t> origins, steps;  // the kept curves on the quantum's grid
    IntColumns eq({"state"});
    IntColumns st({"representative", "members", "curve"});
    std::vector<std::string> names;
    std::vector<Rows> rows;
    Rows at;
    for (const LedgerEntry& e : ledger.entries) {
      Rows r;
      r.runs_first = at.runs_first;
      r.runs = static_cast<std::int64_t>(e.runs.size());
      r.equilibria_first = at.equilibria_first;
      r.equilibria = e.attributes.rows();
      r.linkage_first = at.linkage_first;
      r.states_first = at.states_first;
      r.states = static_cast<std::int64_t>(e.states.size());
      for (const LedgerRun& x : e.runs) {
        const auto code = std::find(statuses.begin(), statuses.end(), x.status) - statuses.begin();
        runs.push_back({x.sample, code, x.equilibrium, x.iterations, x.topology_kept, x.seconds});
      }
      for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
        for (const std::string& name : columns) {
          const auto k = std::find(e.attribute_names.begin(), e.attribute_names.end(), name);
          attributes.push_back(k == e.attribute_names.end() ? std::nan("")
                                                            : e.attributes(i, k - e.attribute_names.begin()));
        }
        eq.values[0].push_back(e.state[static_cast<size_t>(i)]);
      }
      for (Eigen::Index i = 0; i < e.linkage.rows(); ++i)
        for (int c = 0; c < 4; ++c) linkage.push_back(e.linkage(i, c));
      for (const LedgerState& s : e.states) {
        st.values[0].push_back(s.representative);
        st.values[1].push_back(s.members);
        st.values[2].push_back(s.curve.rows() == 0 ? -1 : static_cast<std::int64_t>(origins.size() / 3));
        if (s.curve.rows() > 0) add_curve(s.curve, ledger.provenance.curve_quantum, origins, steps);
      }
      at.runs_first += r.runs;
      at.equilibria_first += r.equilibria;
      at.linkage_first += e.linkage.rows();
      at.states_first += r.states;
      names.push_back(e.name);
      rows.push_back(r);
    }
    h5::write_strings(f.id(), "knot_names", names);
    std::vector<std::string> status_names;
    for (RunStatus s : statuses) status_names.push_back(to_string(s));
    h5::write_strings(f.id(), "status_names", status_names);
    {
      h5::Handle g = h5::create_group(f.id(), "runs");
      h5::write_columns(g.id(), run_columns(), runs, h5::NoContext{});
    }
    {
      h5::Handle g = h5::create_group(f.id(), "equilibria");
      h5::write_strings(g.id(), "attribute_names", columns);
      h5::write_doubles(g.id(), "attributes", {static_cast<hsize_t>(at.equilibria_first), columns.size()},
                        attributes.data());
      eq.write(g.id());
      h5::write_doubles(g.id(), "linkage", {static_cast<hsize_t>(at.linkage_first), 4}, linkage.data());
    }
    {
      h5::Handle g = h5::create_group(f.id(), "states");
      st.write(g.id());
    }
    {
      h5::Handle g = h5::create_group(f.id(), "curves");
      const hsize_t c = origins.size() / 3;
      h5::write_int64(g.id(), "origin", {c, 3}, origins.data());
      h5::write_int64(g.id(), "steps", {c, static_cast<hsize_t>(std::max(n - 1, 0)), 3}, steps.data());
    }
    {
      h5::Handle knots = h5::create_group(f.id(), "knots");
      for (size_t k = 0; k < ledger.entries.size(); ++k) write_knot(knots.id(), ledger.entries[k], rows[k], columns);
    }
    if (H5Fflush(f.id(), H5F_SCOPE_GLOBAL) < 0 || !f.close()) throw InputError("cannot write ledger '" + path + "'");
    h5::seal(tmp);
    atomic_replace(tmp, path);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

namespace {

/// Reads a ledger file's tables back into entries, checking every length,
/// range and index the writer guarantees.
class LedgerFileReader {
 public:
  LedgerFileReader(hid_t file, std::string path) : f_(file), path_(std::move(path)) {}

  [[noreturn]] void damaged(const std::string& what) const {
    throw InputError("ledger '" + path_ + "' is damaged (" + what + ")");
  }

  Ledger read() {
    if (!h5::has_attr(f_, "format") || h5::get_attr_string(f_, "format") != kLedgerFormat)
      throw InputError("'" + path_ + "' is an HDF5 file but not an elastic-knots ledger");
    const auto version = h5::get_attr_int(f_, "format_version");
    if (version != kLedgerFormatVersion)
      throw InputError("'" + path_ + "' has ledger format version " + std::to_string(version) + ", expected " +
                       std::to_string(kLedgerFormatVersion));
    Ledger out;
    out.parameters = detail::read_parameters(f_, path_);
    out.provenance = read_provenance(f_);
    if (!(out.provenance.cut > 0.0 && out.provenance.cut < 1.0)) damaged("its cut is not in (0, 1)");
    quantum_ = out.provenance.curve_quantum;
    if (!(quantum_ > 0.0 && quantum_ < 1e6) || out.provenance.curves_per_knot < 0)
      damaged("its curve quantum or curves per knot are out of range");
    read_tables();
    const std::vector<std::string> names = h5::read_strings(f_, "knot_names");
    h5::Handle knots = h5::open_group(f_, "knots");
    for (const std::string& name : names) out.entries.push_back(entry(knots.id(), name));
    if (runs_next_ != runs_.size() || eq_next_ != state_.size() || linkage_next_ != linkage_rows_ ||
        states_next_ != representative_.size())
      damaged("its tables hold rows that no knot owns");
    return out;
  }

 private:
  std::vector<std::int64_t> ints(hid_t g, const char* name, size_t length, const std::string& table) const {
    std::vector<hsize_t> shape;
    auto v = h5::read_int64(g, name, &shape);
    if (shape.size() != 1 || v.size() != length) damaged(table + "/" + name + " is not one value per row");
    return v;
  }

  void read_tables() {
    for (const std::string& name : h5::read_strings(f_, "status_names")) {
      try {
        statuses_.push_back(parse_run_status(name));
      } catch (const InputError&) {
        damaged("its status names hold '" + name + "'");
      }
    }
    {
      h5::Handle g = h5::open_group(f_, "runs");
      try {
        runs_ = h5::read_columns(g.id(), run_columns(), "runs");
      } catch (const InputError& e) {
        damaged(e.what());
      }
    }
    {
      h5::Handle g = h5::open_group(f_, "equilibria");
      columns_ = h5::read_strings(g.id(), "attribute_names");
      std::vector<hsize_t> shape;
      attributes_ = h5::read_doubles(g.id(), "attributes", &shape);
      if (shape.size() != 2 || shape[1] != columns_.size()) damaged("the attribute table is not m by k");
      state_ = ints(g.id(), "state", shape[0], "equilibria");
      linkage_ = h5::read_doubles(g.id(), "linkage", &shape);
      if (shape.size() != 2 || shape[1] != 4) damaged("the linkage table does not have 4 columns");
      linkage_rows_ = shape[0];
    }
    {
      h5::Handle g = h5::open_group(f_, "curves");
      std::vector<hsize_t> shape;
      origins_ = h5::read_int64(g.id(), "origin", &shape);
      if (shape.size() != 2 || shape[1] != 3) damaged("the curves' origins are not a [c, 3] array");
      const hsize_t c = shape[0];
      steps_ = h5::read_int64(g.id(), "steps", &shape);
      if (shape.size() != 3 || shape[0] != c || shape[2] != 3) damaged("the curves' steps are not a [c, n-1, 3] array");
      n_ = shape[1] + 1;
    }
    {
      h5::Handle g = h5::open_group(f_, "states");
      std::vector<hsize_t> shape;
      representative_ = h5::read_int64(g.id(), "representative", &shape);
      if (shape.size() != 1) damaged("states/representative is not a list");
      members_ = ints(g.id(), "members", representative_.size(), "states");
      curve_ = ints(g.id(), "curve", representative_.size(), "states");
    }
  }

  /// One knot: its rows of every table, which follow the previous knot's.
  LedgerEntry entry(hid_t knots, const std::string& name) {
    h5::Handle g = h5::open_group(knots, name);
    const hid_t id = g.id();
    LedgerEntry e;
    static_cast<KnotHeader&>(e) =
        detail::read_knot_header(id, name, [&](const std::string& what) { damaged(name + ": " + what); });
    const std::vector<std::int64_t> r = h5::get_attr_ints(id, "rows");
    if (r.size() != 7) damaged(name + "'s rows are not 7 numbers");
    const auto m = r[3];
    if (r[0] != static_cast<std::int64_t>(runs_next_) || r[2] != static_cast<std::int64_t>(eq_next_) ||
        r[4] != static_cast<std::int64_t>(linkage_next_) || r[5] != static_cast<std::int64_t>(states_next_) ||
        r[1] < 0 || m < 0 || r[6] < 0 || runs_next_ + r[1] > runs_.size() || eq_next_ + m > state_.size() ||
        linkage_next_ + std::max<std::int64_t>(m - 1, 0) > linkage_rows_ ||
        states_next_ + r[6] > representative_.size() || (m > 0) != (r[6] > 0))
      damaged(name + "'s rows do not follow the previous knot's within the tables");
    read_runs(e, static_cast<size_t>(r[1]), m);
    read_equilibria(e, h5::get_attr_ints(id, "attribute_columns"), m, r[6]);
    read_states(e, static_cast<size_t>(r[6]), m);
    return e;
  }

  void read_runs(LedgerEntry& e, size_t count, std::int64_t m) {
    for (size_t k = runs_next_; k < runs_next_ + count; ++k) {
      const RunRow& x = runs_[k];
      if (x.status < 0 || x.status >= static_cast<std::int64_t>(statuses_.size()) || x.equilibrium < -1 ||
          x.equilibrium >= m)
        damaged(e.name + "'s run " + std::to_string(k - runs_next_) + " names a missing status or row");
      e.runs.push_back({x.sample, statuses_[static_cast<size_t>(x.status)], x.equilibrium, x.iterations, x.seconds,
                        x.topology_kept});
    }
    runs_next_ += count;
  }

  void read_equilibria(LedgerEntry& e, const std::vector<std::int64_t>& own, std::int64_t m, std::int64_t states) {
    const size_t k = columns_.size();
    for (std::int64_t c : own) {
      if (c < 0 || c >= static_cast<std::int64_t>(k)) damaged(e.name + " names a missing attribute column");
      e.attribute_names.push_back(columns_[static_cast<size_t>(c)]);
    }
    e.attributes.resize(m, static_cast<Eigen::Index>(own.size()));
    for (std::int64_t i = 0; i < m; ++i) {
      for (size_t c = 0; c < own.size(); ++c)
        e.attributes(i, static_cast<Eigen::Index>(c)) = attributes_[(eq_next_ + static_cast<size_t>(i)) * k + static_cast<size_t>(own[c])];
      const std::int64_t s = state_[eq_next_ + static_cast<size_t>(i)];
      if (s < 0 || s >= states) damaged(e.name + "'s equilibrium " + std::to_string(i) + " names a missing state");
      e.state.push_back(static_cast<int>(s));
    }
    const std::int64_t links = std::max<std::int64_t>(m - 1, 0);
    e.linkage = Eigen::Map<const RowMajor>(linkage_.data() + linkage_next_ * 4, links, 4);
    eq_next_ += static_cast<size_t>(m);
    linkage_next_ += static_cast<size_t>(links);
  }

  void read_states(LedgerEntry& e, size_t count, std::int64_t m) {
    for (size_t s = states_next_; s < states_next_ + count; ++s) {
      LedgerState x;
      x.representative = static_cast<int>(representative_[s]);
      x.members = static_cast<int>(members_[s]);
      if (representative_[s] < 0 || representative_[s] >= m || x.members < 1)
        damaged(e.name + "'s state " + std::to_string(s - states_next_) + " has a missing representative");
      if (curve_[s] < -1 || curve_[s] >= static_cast<std::int64_t>(origins_.size() / 3))
        damaged(e.name + "'s state " + std::to_string(s - states_next_) + " names a missing curve");
      if (curve_[s] >= 0) x.curve = curve(static_cast<size_t>(curve_[s]));
      e.states.push_back(std::move(x));
    }
    for (size_t s = 0; s < count; ++s)
      if (static_cast<int>(e.members(static_cast<int>(s)).size()) != e.states[s].members)
        damaged(e.name + "'s state " + std::to_string(s) + " does not have its member count");
    states_next_ += count;
  }

  /// Kept curve `c`: its origin plus its steps, times the quantum.
  Points curve(size_t c) const {
    Points P(static_cast<Eigen::Index>(n_), 3);
    std::array<std::int64_t, 3> g{origins_[3 * c], origins_[3 * c + 1], origins_[3 * c + 2]};
    for (size_t v = 0; v < n_; ++v)
      for (size_t d = 0; d < 3; ++d) {
        if (v > 0) g[d] += steps_[(c * (n_ - 1) + v - 1) * 3 + d];
        P(static_cast<Eigen::Index>(v), static_cast<Eigen::Index>(d)) = static_cast<double>(g[d]) * quantum_;
      }
    if (!P.allFinite()) damaged("a curve has a coordinate that is not finite");
    return P;
  }

  hid_t f_;
  std::string path_;
  double quantum_ = 1.0;
  std::vector<std::int64_t> origins_, steps_, curve_;
  std::vector<RunStatus> statuses_;
  std::vector<std::string> columns_;
  std::vector<RunRow> runs_;
  std::vector<double> attributes_, linkage_;
  std::vector<std::int64_t> state_, representative_, members_;
  size_t n_ = 0, linkage_rows_ = 0;
  size_t runs_next_ = 0, eq_next_ = 0, linkage_next_ = 0, states_next_ = 0;
};

}  // namespace

Ledger read_ledger(const std::string& path) {
  if (!h5::verify(path, "ledger")) throw InputError("'" + path + "' is not a ledger (it has no checksum header)");
  try {
    h5::Handle f = h5::open_file(path, false);
    return LedgerFileReader(f.id(), path).read();
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.find("'" + path + "'") != std::string::npos) throw;
    throw InputError("ledger '" + path + "': " + message);
  }
}

bool is_ledger_file(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return false;  // the data-set reader names what is missing
  if (!h5::verify(path, "data set or ledger")) return false;  // a data set written before checksums
  h5::Handle f = h5::open_file(path, false);
  return h5::has_attr(f.id(), "format") && h5::get_attr_string(f.id(), "format") == kLedgerFormat;
}

Ledger merge_ledgers(const std::vector<Ledger>& ledgers) {
  if (ledgers.empty()) throw InputError("merge_ledgers: no ledger");
  Ledger out;
  out.parameters = ledgers.front().parameters;
  out.provenance.cut = ledgers.front().provenance.cut;
  out.provenance.curve_quantum = ledgers.front().provenance.curve_quantum;
  out.provenance.curves_per_knot = 0;
  std::set<std::string> names, commits;
  bool wall = true, cpu = true;
  double wall_s = 0.0, cpu_s = 0.0;
  for (const Ledger& l : ledgers) {
    if (const std::string d = out.parameters.difference(l.parameters); !d.empty())
      throw InputError("ledgers with different parameters cannot be merged: " + d);
    if (l.provenance.cut != out.provenance.cut)
      throw InputError("ledgers with different cuts cannot be merged: " + std::to_string(out.provenance.cut) + " vs " +
                       std::to_string(l.provenance.cut));
    if (l.provenance.curve_quantum != out.provenance.curve_quantum)
      throw InputError("ledgers with different curve quanta cannot be merged");
    out.provenance.curves_per_knot = std::max(out.provenance.curves_per_knot, l.provenance.curves_per_knot);
    out.parameters.forget_unrecorded(l.parameters);
    for (const LedgerEntry& e : l.entries) {
      if (!names.insert(e.name).second) throw InputError("knot " + e.name + " is in two of the ledgers");
      out.entries.push_back(e);
    }
    if (!l.provenance.commit.empty() && commits.insert(l.provenance.commit).second)
      out.provenance.commit += (out.provenance.commit.empty() ? "" : ",") + l.provenance.commit;
    out.provenance.source += (out.provenance.source.empty() ? "" : "; ") + l.provenance.source;
    out.provenance.created = std::max(out.provenance.created, l.provenance.created);
    wall = wall && l.provenance.wall_seconds.has_value();
    cpu = cpu && l.provenance.cpu_seconds.has_value();
    wall_s += l.provenance.wall_seconds.value_or(0.0);
    cpu_s += l.provenance.cpu_seconds.value_or(0.0);
    if (l.provenance.cores && (!out.provenance.cores || *out.provenance.cores == *l.provenance.cores))
      out.provenance.cores = l.provenance.cores;
  }
  if (wall) out.provenance.wall_seconds = wall_s;
  if (cpu) out.provenance.cpu_seconds = cpu_s;
  return out;
}

std::vector<std::string> ledger_files(const std::string& folder) {
  std::vector<std::string> files;
  if (!std::filesystem::is_directory(folder)) return files;
  std::error_code ec;
  for (const auto& p : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = p.path().filename().string();
    if (name.size() > 10 && name.compare(name.size() - 10, 10, ".ledger.h5") == 0) files.push_back(p.path().string());
  }
  if (ec) throw InputError("cannot read the ledger folder '" + folder + "': " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

Ledger read_ledger_folder(const std::string& folder) {
  if (!std::filesystem::is_directory(folder)) throw InputError("no ledger folder '" + folder + "'");
  const std::vector<std::string> files = ledger_files(folder);
  if (files.empty()) throw InputError("no ledger (*.ledger.h5) in '" + folder + "'");
  std::vector<Ledger> ledgers;
  for (const std::string& f : files) ledgers.push_back(read_ledger(f));
  return merge_ledgers(ledgers);
}

bool is_ledger_source(const std::string& path) {
  return std::filesystem::is_directory(path) || is_ledger_file(path);
}

Ledger read_ledger_source(const std::string& path) {
  return std::filesystem::is_directory(path) ? read_ledger_folder(path) : read_ledger(path);
}

}  // namespace ek
