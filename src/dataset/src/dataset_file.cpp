#include "ek/dataset/dataset_file.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <ostream>
#include <sstream>
#include <thread>
#include <variant>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "child_read.hpp"
#include "parameters_h5.hpp"
#include "ek/dataset/h5.hpp"
#include "ek/dataset/h5_columns.hpp"

namespace ek {
namespace {

constexpr const char* kFormat = "elastic-knots-dataset";
/// Attributes added since the first files are optional: the table
/// (metadata.hpp) says what a file without them reads as, and older readers
/// ignore them. Version 2 renamed the runs' column alexander_preserved to
/// topology_preserved and made a link's attribute `energy` the total with
/// contact, as a knot's; version 1 files are read as version 2 (the file
/// comment of dataset_file.hpp).
constexpr std::int64_t kFormatVersion = 2;
constexpr std::int64_t kOldestFormatVersion = 1;

void write_value(hid_t f, const std::string& name, const FieldValue& v) {
  if (const auto* x = std::get_if<double>(&v)) h5::set_attr(f, name, *x);
  else if (const auto* i = std::get_if<std::int64_t>(&v)) h5::set_attr(f, name, *i);
  else if (const auto* u = std::get_if<std::uint64_t>(&v)) h5::set_attr(f, name, static_cast<std::int64_t>(*u));
  else if (const auto* t = std::get_if<std::string>(&v)) h5::set_attr(f, name, *t);
  else if (const auto* list = std::get_if<std::vector<double>>(&v)) h5::set_attr(f, name, continuation_text(*list));
}

/// A field's attribute, which must hold one value of the field's kind: the
/// h5::get_attr_* helpers refuse an attribute of another shape (several
/// values where one belongs) or type with an InputError naming it.
FieldValue read_present(hid_t f, const MetadataField& field, const std::string& path) {
  switch (field.kind) {
    case FieldKind::Real: return h5::get_attr_double(f, field.name);
    case FieldKind::Integer: {
      const std::int64_t v = h5::get_attr_int(f, field.name);
      // earlier versions wrote -1 for an iteration cap they did not know
      if (v < 0 && field.absent == WhenAbsent::NotRecorded) return std::monostate{};
      return v;
    }
    case FieldKind::Unsigned: return static_cast<std::uint64_t>(h5::get_attr_int(f, field.name));
    case FieldKind::Text: return h5::get_attr_string(f, field.name);
    case FieldKind::List: {
      const std::string text = h5::get_attr_string(f, field.name);
      if (auto list = parse_continuation(text)) return *list;
      throw InputError("'" + path + "' has a malformed " + field.name + " attribute '" + text + "'");
    }
  }
  return std::monostate{};
}

FieldValue read_value(hid_t f, const MetadataField& field, const std::string& path) {
  if (h5::has_attr(f, field.name)) return read_present(f, field, path);
  switch (field.absent) {
    case WhenAbsent::Required: throw InputError("'" + path + "' lacks the data-set attribute '" + field.name + "'");
    case WhenAbsent::Default: return field.absent_value;
    case WhenAbsent::NotRecorded: break;
  }
  return std::monostate{};
}

const std::pair<RunStatus, const char*> kRunStatusNames[] = {
    {RunStatus::ConvergedStable, "converged-stable"}, {RunStatus::ConvergedUnstable, "converged-unstable"},
    {RunStatus::MaxIterations, "max-iterations"},     {RunStatus::Stalled, "stalled"},
    {RunStatus::TopologyChanged, "topology-changed"}, {RunStatus::Error, "error"}};

}  // namespace

std::string to_string(RunStatus status) {
  for (const auto& [s, name] : kRunStatusNames)
    if (s == status) return name;
  return "?";
}

std::ostream& operator<<(std::ostream& out, RunStatus status) { return out << to_string(status); }

RunStatus parse_run_status(const std::string& text) {
  for (const auto& [s, name] : kRunStatusNames)
    if (text == name) return s;
  throw InputError("unknown run status '" + text + "'");
}

void detail::write_parameters(hid_t f, const DatasetMetadata& m) {
  for (const auto& field : metadata_fields()) {
    const FieldValue v = field.get(m);
    require(!std::holds_alternative<std::monostate>(v) || field.absent == WhenAbsent::NotRecorded,
            "DatasetWriter: the metadata field '" + field.name + "' is not set");
    write_value(f, field.name, v);
  }
}

DatasetMetadata detail::read_parameters(hid_t f, const std::string& path) {
  DatasetMetadata m;
  for (const auto& field : metadata_fields()) field.set(m, read_value(f, field, path));
  return m;
}

void detail::write_knot_header(hid_t id, const KnotHeader& k) {
  h5::set_attr(id, "name", k.name);
  h5::set_attr(id, "crossing_number", static_cast<std::int64_t>(k.crossing_number));
  h5::set_attr(id, "bridge_index", static_cast<std::int64_t>(k.bridge_index));
  h5::set_attr(id, "braid_index", static_cast<std::int64_t>(k.braid_index));
  h5::set_attr(id, "alexander", k.alexander);
  h5::set_attr(id, "samples_used", static_cast<std::int64_t>(k.samples_used));
  h5::set_attr(id, "adaptive", static_cast<std::int64_t>(k.adaptive ? 1 : 0));
  h5::set_attr(id, "complete", static_cast<std::int64_t>(k.complete ? 1 : 0));
  h5::write_doubles(id, "score_history", {k.score_history.size()}, k.score_history.data());
  if (!k.is_link()) return;
  h5::set_attr(id, "components", std::vector<std::int64_t>(k.components.begin(), k.components.end()));
  h5::set_attr(id, "conway", k.conway);
  h5::set_attr(id, "linking_numbers", k.linking_numbers);
}

KnotHeader detail::read_knot_header(hid_t id, const std::string& name,
                                    const std::function<void(const std::string&)>& damaged) {
  KnotHeader k;
  k.name = h5::get_attr_string(id, "name");
  if (k.name != name) damaged("its group is named " + name + " but its name attribute " + k.name);
  k.crossing_number = static_cast<int>(h5::get_attr_int(id, "crossing_number"));
  k.bridge_index = static_cast<int>(h5::get_attr_int(id, "bridge_index"));
  k.braid_index = static_cast<int>(h5::get_attr_int(id, "braid_index"));
  k.alexander = h5::get_attr_ints(id, "alexander");
  k.samples_used = static_cast<int>(h5::get_attr_int(id, "samples_used"));
  k.adaptive = h5::get_attr_int(id, "adaptive") != 0;
  k.complete = h5::get_attr_int(id, "complete") != 0;
  std::vector<hsize_t> shape;
  k.score_history = h5::read_doubles(id, "score_history", &shape);
  if (shape.size() != 1) damaged("score_history is not a list");
  if (!h5::has_attr(id, "components")) return k;
  const std::vector<std::int64_t> sizes = h5::get_attr_ints(id, "components");
  for (std::int64_t c : sizes) {
    if (c < 4 || c > (1 << 24)) damaged("a link component has " + std::to_string(c) + " vertices");
    k.components.push_back(static_cast<int>(c));
  }
  if (sizes.size() < 2) damaged("a link has fewer than 2 components");
  k.conway = h5::get_attr_ints(id, "conway");
  k.linking_numbers = h5::get_attr_ints(id, "linking_numbers");
  if (k.linking_numbers.size() != sizes.size() * sizes.size()) damaged("the linking numbers are not m by m");
  return k;
}

namespace {

/// Every field of the table; an empty field is left out (not recorded), which
/// only the fields that older files may lack allow.
void write_meta(hid_t f, const DatasetMetadata& m) {
  h5::set_attr(f, "format", std::string(kFormat));
  h5::set_attr(f, "format_version", kFormatVersion);
  detail::write_parameters(f, m);
}

/// The file's format version after checking it is one this reader reads.
std::int64_t read_version(hid_t f, const std::string& path) {
  if (!h5::has_attr(f, "format") || h5::get_attr_string(f, "format") != kFormat)
    throw InputError("'" + path + "' is an HDF5 file but not an elastic-knots data set");
  const auto version = h5::get_attr_int(f, "format_version");
  if (version < kOldestFormatVersion || version > kFormatVersion)
    throw InputError("'" + path + "' has data-set format version " + std::to_string(version) + ", expected " +
                     std::to_string(kOldestFormatVersion) + " to " + std::to_string(kFormatVersion));
  return version;
}

DatasetMetadata read_meta(hid_t f, const std::string& path) {
  read_version(f, path);
  return detail::read_parameters(f, path);
}


/// The columns of a knot's runs/ group (docs/dataset-format.md): one
/// dataset per column, one row per run, in the file's order (integers,
/// reals, texts). In files of format `version` 1 the column
/// topology_preserved was named alexander_preserved.
std::vector<h5::Column<RunRecord>> run_columns(std::int64_t version) {
  using h5::member_column;
  return {
      member_column<RunRecord>("sample", &RunRecord::sample),
      member_column<RunRecord>("seed", &RunRecord::seed),
      member_column<RunRecord>("equilibrium", &RunRecord::equilibrium),
      member_column<RunRecord>("iterations", &RunRecord::iterations),
      member_column<RunRecord>("contacts", &RunRecord::contacts),
      member_column<RunRecord>(version < 2 ? "alexander_preserved" : "topology_preserved",
                               &RunRecord::topology_preserved),
      member_column<RunRecord>("seconds", &RunRecord::seconds),
      member_column<RunRecord>("energy", &RunRecord::energy),
      member_column<RunRecord>("gradient_norm", &RunRecord::gradient_norm),
      {"status", h5::ColumnType::Text,
       [](const RunRecord& r, const h5::NoContext&) { return h5::Cell(to_string(r.status)); },
       [](RunRecord& r, h5::Cell&& c) { r.status = parse_run_status(std::get<std::string>(c)); }},
      member_column<RunRecord>("message", &RunRecord::message),
  };
}

void write_runs(hid_t knot, const std::vector<RunRecord>& runs) {
  h5::Handle g = h5::create_group(knot, "runs");
  h5::write_columns(g.id(), run_columns(kFormatVersion), runs, h5::NoContext{});
}

}  // namespace

int KnotEntry::attribute_column(const std::string& attribute) const {
  for (size_t k = 0; k < attribute_names.size(); ++k)
    if (attribute_names[k] == attribute) return static_cast<int>(k);
  std::string known;
  for (const auto& a : attribute_names) known += (known.empty() ? "" : ", ") + a;
  throw InputError("unknown attribute '" + attribute + "' (known: " + known + ")");
}

struct DatasetWriter::Impl {
  std::string path, tmp;
  h5::Handle file, knots;
  std::vector<std::string> names;
  bool committed = false;
};

DatasetWriter::DatasetWriter(const std::string& path, const DatasetMetadata& meta) : impl_(new Impl) {
  check_writable(path);
  impl_->path = path;
  impl_->tmp = temporary_path(path);
  impl_->file = h5::create_file(impl_->tmp);
  try {
    write_meta(impl_->file.id(), meta);
    impl_->knots = h5::create_group(impl_->file.id(), "knots");
  } catch (...) {
    impl_->file.reset();
    std::remove(impl_->tmp.c_str());
    throw;
  }
}

DatasetWriter::~DatasetWriter() {
  if (!impl_->committed) {
    impl_->knots.reset();
    impl_->file.reset();
    std::remove(impl_->tmp.c_str());
  }
}

Link KnotEntry::equilibrium_link(int i) const {
  require(i >= 0 && i < static_cast<int>(equilibria.size()), "equilibrium_link: no equilibrium " + std::to_string(i));
  const Points& all = equilibria[static_cast<size_t>(i)];
  if (!is_link()) return {all};
  Link out;
  Eigen::Index row = 0;
  for (int n : components) {
    out.push_back(all.middleRows(row, n));
    row += n;
  }
  return out;
}

void DatasetWriter::add(const KnotEntry& k) {
  require(!impl_->committed, "DatasetWriter::add after commit");
  h5::Handle g = h5::create_group(impl_->knots.id(), k.name);
  const hid_t id = g.id();
  detail::write_knot_header(id, k);
  const hsize_t m = k.equilibria.size();
  const hsize_t n = m > 0 ? static_cast<hsize_t>(k.equilibria.front().rows()) : 0;
  std::vector<double> eq(m * n * 3);
  for (hsize_t e = 0; e < m; ++e) {
    require(static_cast<hsize_t>(k.equilibria[e].rows()) == n, "DatasetWriter: equilibria of different sizes");
    std::copy(k.equilibria[e].data(), k.equilibria[e].data() + n * 3, eq.begin() + static_cast<long>(e * n * 3));
  }
  h5::write_doubles(id, "equilibria", {m, n, 3}, eq.data());
  const hsize_t kcols = k.attribute_names.size();
  require(static_cast<hsize_t>(k.attributes.rows()) == (kcols ? m : static_cast<hsize_t>(k.attributes.rows())) &&
              static_cast<hsize_t>(k.attributes.cols()) == kcols,
          "DatasetWriter: attribute table has the wrong shape");
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> attr = k.attributes;
  h5::write_doubles(id, "attributes", {m, kcols}, attr.data());
  h5::write_strings(id, "attribute_names", k.attribute_names);
  write_runs(id, k.runs);
  require(k.similarity.size() == 0 || (static_cast<hsize_t>(k.similarity.rows()) == m && k.similarity.cols() == k.similarity.rows()),
          "DatasetWriter: similarity matrix has the wrong shape");
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> sim = k.similarity;
  h5::write_doubles(id, "similarity", {static_cast<hsize_t>(sim.rows()), static_cast<hsize_t>(sim.cols())}, sim.data());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> link = k.linkage;
  h5::write_doubles(id, "linkage", {static_cast<hsize_t>(link.rows()), 4}, link.data());
  require(!k.is_link() || std::accumulate(k.components.begin(), k.components.end(), hsize_t{0}) == n || m == 0,
          "DatasetWriter: a link's components do not add up to its equilibria's vertices");
  impl_->names.push_back(k.name);
}

void DatasetWriter::commit() {
  require(!impl_->committed, "DatasetWriter::commit called twice");
  h5::write_strings(impl_->file.id(), "knot_names", impl_->names);
  impl_->knots.reset();
  if (H5Fflush(impl_->file.id(), H5F_SCOPE_GLOBAL) < 0 || !impl_->file.close())
    throw InputError("cannot write '" + impl_->path + "'");
  h5::seal(impl_->tmp);
  atomic_replace(impl_->tmp, impl_->path);
  impl_->committed = true;
}

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Reads one knot group, checking every shape the writer guarantees, so that
/// a damaged file is an InputError rather than a wrong or out-of-bounds read.
class KnotGroupReader {
 public:
  /// The group `group` of a file of format `version`.
  KnotGroupReader(hid_t group, std::string path, std::string name, std::int64_t version)
      : id_(group), path_(std::move(path)), name_(std::move(name)), version_(version) {}

  [[noreturn]] void damaged(const std::string& what) const {
    throw InputError("data set '" + path_ + "': knot " + name_ + " is damaged (" + what + ")");
  }

  /// A float64 [rows, cols] dataset.
  Eigen::MatrixXd matrix(const char* field) const {
    std::vector<hsize_t> shape;
    const auto v = h5::read_doubles(id_, field, &shape);
    if (shape.size() != 2) damaged(std::string(field) + " is not a table");
    return Eigen::Map<const RowMajor>(v.data(), static_cast<Eigen::Index>(shape[0]),
                                      static_cast<Eigen::Index>(shape[1]));
  }

  /// float64 [m, n, 3]: m curves of n finite vertices.
  std::vector<Points> equilibria() const {
    std::vector<hsize_t> shape;
    const auto eq = h5::read_doubles(id_, "equilibria", &shape);
    if (shape.size() != 3 || shape[2] != 3) damaged("equilibria are not an [m, n, 3] array");
    std::vector<Points> out;
    const auto n = static_cast<Eigen::Index>(shape[1]);
    for (hsize_t e = 0; e < shape[0]; ++e) {
      Points P = Eigen::Map<const Points>(eq.data() + e * shape[1] * 3, n, 3);
      if (!P.allFinite()) damaged("equilibrium " + std::to_string(e) + " has a coordinate that is not finite");
      out.push_back(std::move(P));
    }
    return out;
  }

  /// runs/: columns of one length; `equilibria` rows exist.
  std::vector<RunRecord> runs(size_t equilibria) const {
    std::vector<RunRecord> out;
    try {
      h5::Handle g = h5::open_group(id_, "runs");
      out = h5::read_columns(g.id(), run_columns(version_), "runs");
    } catch (const InputError& e) {
      damaged(e.what());
    }
    for (size_t k = 0; k < out.size(); ++k)
      if (out[k].equilibrium < -1 || out[k].equilibrium >= static_cast<int>(equilibria))
        damaged("run " + std::to_string(k) + " names equilibrium " + std::to_string(out[k].equilibrium) + " of " +
                std::to_string(equilibria));
    return out;
  }

  KnotEntry read() const {
    KnotEntry k;
    static_cast<KnotHeader&>(k) = detail::read_knot_header(id_, name_, [this](const std::string& what) { damaged(what); });
    k.equilibria = equilibria();
    const auto m = static_cast<Eigen::Index>(k.equilibria.size());
    k.attribute_names = h5::read_strings(id_, "attribute_names");
    k.attributes = matrix("attributes");
    if (k.attributes.rows() != m || k.attributes.cols() != static_cast<Eigen::Index>(k.attribute_names.size()))
      damaged("the attribute table is not one row per equilibrium and one column per name");
    if (version_ < 2 && k.is_link()) add_contact_to_energy(k);
    k.runs = runs(k.equilibria.size());
    k.similarity = matrix("similarity");
    if (k.similarity.size() != 0 && (k.similarity.rows() != m || k.similarity.cols() != m))
      damaged("the similarity matrix is not m by m");
    k.linkage = matrix("linkage");
    if (k.linkage.cols() != 4) damaged("the linkage table does not have 4 columns");
    if (k.is_link() && !k.equilibria.empty() &&
        std::accumulate(k.components.begin(), k.components.end(), 0) != k.equilibria.front().rows())
      damaged("the link's components do not add up to its equilibria's vertices");
    return k;
  }

 private:
  /// A version 1 link's `energy` column (without contact) made the total.
  static void add_contact_to_energy(KnotEntry& k) {
    const auto column = [&k](const char* name) {
      const auto it = std::find(k.attribute_names.begin(), k.attribute_names.end(), name);
      return it == k.attribute_names.end() ? -1 : static_cast<int>(it - k.attribute_names.begin());
    };
    const int energy = column("energy"), contact = column("energy_contact");
    if (energy >= 0 && contact >= 0) k.attributes.col(energy) += k.attributes.col(contact);
  }

  hid_t id_;
  std::string path_, name_;
  std::int64_t version_;
};

/// Runs `read`; an InputError that does not name the file (one of the HDF5
/// helpers') is given the context "data set 'PATH'[, knot NAME]: ".
template <class F>
auto naming_the_file(const std::string& path, const std::string& knot, F&& read) {
  try {
    return read();
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.find("'" + path + "'") != std::string::npos) throw;
    throw InputError("data set '" + path + "'" + (knot.empty() ? "" : ", knot " + knot) + ": " + message);
  }
}

/// Reads all of `path` (metadata and every knot) and exits the process: 0
/// when it reads, 2 on an InputError (its message, at most 4 kB, written to
/// `message_fd`), 3 on any other exception.
[[noreturn]] void read_all_and_exit(const std::string& path, int message_fd) {
  int status = 0;
  try {
    h5::Handle f = h5::open_file(path, false);
    std::int64_t version = 0;
    const auto names = naming_the_file(path, "", [&] {
      read_meta(f.id(), path);
      version = read_version(f.id(), path);
      return h5::read_strings(f.id(), "knot_names");
    });
    h5::Handle knots = naming_the_file(path, "", [&] { return h5::open_group(f.id(), "knots"); });
    for (const auto& name : names)
      naming_the_file(path, name, [&] {
        h5::Handle g = h5::open_group(knots.id(), name);
        return KnotGroupReader(g.id(), path, name, version).read();
      });
  } catch (const InputError& e) {
    const std::string message = std::string(e.what()).substr(0, 4096);  // fits the pipe: no blocking
    if (::write(message_fd, message.data(), message.size()) < 0) status = 3;
    status = 2;
  } catch (...) {
    status = 3;
  }
  ::_exit(status);
}

/// [s] time given to the child: base + per_10_mb per 10 MB (child_read.hpp)
std::atomic<double> child_limit_base{60.0}, child_limit_per_10_mb{1.0};

/// Waits for the child `pid` at most `seconds` and returns its exit status,
/// -1 when a signal ended it, -3 when it ran out of time (it is killed).
int wait_for_child(pid_t pid, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  for (auto wait = std::chrono::microseconds(200);; wait = std::min(2 * wait, std::chrono::microseconds(50000))) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (done < 0 && errno != EINTR) return 0;  // not waitable (SIGCHLD ignored by the program): unknown, read here
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -3;
    }
    std::this_thread::sleep_for(wait);
  }
}

/// A file without a checksum (written before data sets carried one) is read
/// completely in a child process first: the HDF5 library (1.10) can crash,
/// hang or exhaust memory on damaged HDF5 structures, which only another
/// process survives. The child is given 60 s plus 1 s per 10 MB; if it dies
/// or runs out of time the file is refused, and a file the child refuses is
/// refused with its message. Once the child has read it, the same reads in
/// this process are safe (the library is deterministic).
void read_in_child(const std::string& path) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  const double seconds = child_limit_base + child_limit_per_10_mb * (ec ? 0.0 : static_cast<double>(bytes) / 1e7);
  int fds[2];
  if (::pipe(fds) != 0) throw InputError("cannot check data set '" + path + "': no pipe");
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, SIG_DFL);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, 2);  // the library's and any sanitizer's reports
    ::close(fds[0]);
    read_all_and_exit(path, fds[1]);
  }
  ::close(fds[1]);
  const int status = pid < 0 ? -2 : wait_for_child(pid, seconds);
  std::string message(4096, '\0');
  const ssize_t got = ::read(fds[0], message.data(), message.size());
  ::close(fds[0]);
  message.resize(got > 0 ? static_cast<size_t>(got) : 0);
  const std::string no_checksum = " (the file has no checksum: written before data sets carried one)";
  if (status == 0) return;
  if (status == 2 && !message.empty()) throw InputError(message);
  if (status == -2) throw InputError("cannot check data set '" + path + "': fork failed");
  std::ostringstream limit;
  limit << seconds;
  throw InputError("data set '" + path + "' is damaged: HDF5 " +
                   (status == -3 ? "did not finish reading it in " + limit.str() + " s" : "failed on it") + no_checksum);
}

}  // namespace

void detail::set_child_read_limit(double base, double per_10_mb) {
  child_limit_base = base;
  child_limit_per_10_mb = per_10_mb;
}

struct DatasetReader::Impl {
  std::string path;
  h5::Handle file;
  std::int64_t version = 0;  ///< the file's format version
  DatasetMetadata meta;
  std::vector<std::string> names;
};

DatasetReader::DatasetReader(const std::string& path) : impl_(new Impl) {
  // impl_ is a unique_ptr member: a throw below releases it.
  impl_->path = path;
  if (!h5::verify(path)) read_in_child(path);
  impl_->file = h5::open_file(path, false);
  naming_the_file(path, "", [&] {
    impl_->meta = read_meta(impl_->file.id(), path);
    impl_->version = read_version(impl_->file.id(), path);
    impl_->names = h5::read_strings(impl_->file.id(), "knot_names");
    return 0;
  });
}

DatasetReader::~DatasetReader() = default;

const DatasetMetadata& DatasetReader::metadata() const { return impl_->meta; }
std::vector<std::string> DatasetReader::knot_names() const { return impl_->names; }
bool DatasetReader::has_knot(const std::string& name) const {
  return std::find(impl_->names.begin(), impl_->names.end(), name) != impl_->names.end();
}

KnotEntry DatasetReader::read(const std::string& name) const {
  if (!has_knot(name)) throw InputError("data set '" + impl_->path + "' has no knot '" + name + "'");
  return naming_the_file(impl_->path, name, [&] {
    h5::Handle knots = h5::open_group(impl_->file.id(), "knots");
    h5::Handle g = h5::open_group(knots.id(), name);
    return KnotGroupReader(g.id(), impl_->path, name, impl_->version).read();
  });
}

}  // namespace ek
