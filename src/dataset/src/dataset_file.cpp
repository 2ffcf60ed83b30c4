#include "ek/dataset/dataset_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <variant>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "h5.hpp"

namespace ek {
namespace {

constexpr const char* kFormat = "elastic-knots-dataset";
/// Attributes added since the first version-1 files are optional: the table
/// (metadata.hpp) says what a file without them reads as, and older readers
/// ignore them, so the version stays 1.
constexpr std::int64_t kFormatVersion = 1;

void write_value(hid_t f, const std::string& name, const FieldValue& v) {
  if (const auto* x = std::get_if<double>(&v)) h5::set_attr(f, name, *x);
  else if (const auto* i = std::get_if<std::int64_t>(&v)) h5::set_attr(f, name, *i);
  else if (const auto* u = std::get_if<std::uint64_t>(&v)) h5::set_attr(f, name, static_cast<std::int64_t>(*u));
  else if (const auto* t = std::get_if<std::string>(&v)) h5::set_attr(f, name, *t);
  else if (const auto* list = std::get_if<std::vector<double>>(&v)) h5::set_attr(f, name, continuation_text(*list));
}

/// Every field of the table; an empty field is left out (not recorded), which
/// only the fields that older files may lack allow.
void write_meta(hid_t f, const DatasetMetadata& m) {
  h5::set_attr(f, "format", std::string(kFormat));
  h5::set_attr(f, "format_version", kFormatVersion);
  for (const auto& field : metadata_fields()) {
    const FieldValue v = field.get(m);
    require(!std::holds_alternative<std::monostate>(v) || field.absent == WhenAbsent::NotRecorded,
            "DatasetWriter: the metadata field '" + field.name + "' is not set");
    write_value(f, field.name, v);
  }
}

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

DatasetMetadata read_meta(hid_t f, const std::string& path) {
  if (!h5::has_attr(f, "format") || h5::get_attr_string(f, "format") != kFormat)
    throw InputError("'" + path + "' is an HDF5 file but not an elastic-knots data set");
  const auto version = h5::get_attr_int(f, "format_version");
  if (version != kFormatVersion)
    throw InputError("'" + path + "' has data-set format version " + std::to_string(version) + ", expected " +
                     std::to_string(kFormatVersion));
  DatasetMetadata m;
  for (const auto& field : metadata_fields()) field.set(m, read_value(f, field, path));
  return m;
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
  static std::atomic<unsigned> counter{0};
  impl_->path = path;
  impl_->tmp = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
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

void DatasetWriter::add(const KnotEntry& k) {
  require(!impl_->committed, "DatasetWriter::add after commit");
  h5::Handle g = h5::create_group(impl_->knots.id(), k.name);
  const hid_t id = g.id();
  h5::set_attr(id, "name", k.name);
  h5::set_attr(id, "crossing_number", static_cast<std::int64_t>(k.crossing_number));
  h5::set_attr(id, "bridge_index", static_cast<std::int64_t>(k.bridge_index));
  h5::set_attr(id, "braid_index", static_cast<std::int64_t>(k.braid_index));
  h5::set_attr(id, "alexander", k.alexander);
  h5::set_attr(id, "samples_used", static_cast<std::int64_t>(k.samples_used));
  h5::set_attr(id, "adaptive", static_cast<std::int64_t>(k.adaptive ? 1 : 0));
  h5::set_attr(id, "complete", static_cast<std::int64_t>(k.complete ? 1 : 0));
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
  {
    h5::Handle runs = h5::create_group(id, "runs");
    const hsize_t r = k.runs.size();
    std::vector<std::int64_t> sample, seed, eqi, iters, contacts, alex;
    std::vector<double> seconds, energy, gnorm;
    std::vector<std::string> status, message;
    for (const auto& run : k.runs) {
      sample.push_back(run.sample);
      seed.push_back(static_cast<std::int64_t>(run.seed));
      eqi.push_back(run.equilibrium);
      iters.push_back(run.iterations);
      contacts.push_back(run.contacts);
      alex.push_back(run.alexander_preserved ? 1 : 0);
      seconds.push_back(run.seconds);
      energy.push_back(run.energy);
      gnorm.push_back(run.gradient_norm);
      status.push_back(run.status);
      message.push_back(run.message);
    }
    h5::write_int64(runs.id(), "sample", {r}, sample.data());
    h5::write_int64(runs.id(), "seed", {r}, seed.data());
    h5::write_int64(runs.id(), "equilibrium", {r}, eqi.data());
    h5::write_int64(runs.id(), "iterations", {r}, iters.data());
    h5::write_int64(runs.id(), "contacts", {r}, contacts.data());
    h5::write_int64(runs.id(), "alexander_preserved", {r}, alex.data());
    h5::write_doubles(runs.id(), "seconds", {r}, seconds.data());
    h5::write_doubles(runs.id(), "energy", {r}, energy.data());
    h5::write_doubles(runs.id(), "gradient_norm", {r}, gnorm.data());
    h5::write_strings(runs.id(), "status", status);
    h5::write_strings(runs.id(), "message", message);
  }
  require(k.similarity.size() == 0 || (static_cast<hsize_t>(k.similarity.rows()) == m && k.similarity.cols() == k.similarity.rows()),
          "DatasetWriter: similarity matrix has the wrong shape");
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> sim = k.similarity;
  h5::write_doubles(id, "similarity", {static_cast<hsize_t>(sim.rows()), static_cast<hsize_t>(sim.cols())}, sim.data());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> link = k.linkage;
  h5::write_doubles(id, "linkage", {static_cast<hsize_t>(link.rows()), 4}, link.data());
  h5::write_doubles(id, "score_history", {k.score_history.size()}, k.score_history.data());
  impl_->names.push_back(k.name);
}

void DatasetWriter::commit() {
  require(!impl_->committed, "DatasetWriter::commit called twice");
  h5::write_strings(impl_->file.id(), "knot_names", impl_->names);
  impl_->knots.reset();
  if (H5Fflush(impl_->file.id(), H5F_SCOPE_GLOBAL) < 0) throw InputError("cannot write '" + impl_->path + "'");
  impl_->file.reset();
  atomic_replace(impl_->tmp, impl_->path);
  impl_->committed = true;
}

struct DatasetReader::Impl {
  std::string path;
  h5::Handle file;
  DatasetMetadata meta;
  std::vector<std::string> names;
};

DatasetReader::DatasetReader(const std::string& path) : impl_(new Impl) {
  // impl_ is a unique_ptr member: a throw below releases it.
  impl_->path = path;
  impl_->file = h5::open_file(path, false);
  impl_->meta = read_meta(impl_->file.id(), path);
  impl_->names = h5::read_strings(impl_->file.id(), "knot_names");
}

DatasetReader::~DatasetReader() = default;

const DatasetMetadata& DatasetReader::metadata() const { return impl_->meta; }
std::vector<std::string> DatasetReader::knot_names() const { return impl_->names; }
bool DatasetReader::has_knot(const std::string& name) const {
  return std::find(impl_->names.begin(), impl_->names.end(), name) != impl_->names.end();
}

KnotEntry DatasetReader::read(const std::string& name) const {
  if (!has_knot(name)) throw InputError("data set '" + impl_->path + "' has no knot '" + name + "'");
  h5::Handle knots = h5::open_group(impl_->file.id(), "knots");
  h5::Handle g = h5::open_group(knots.id(), name);
  const hid_t id = g.id();
  KnotEntry k;
  k.name = h5::get_attr_string(id, "name");
  k.crossing_number = static_cast<int>(h5::get_attr_int(id, "crossing_number"));
  k.bridge_index = static_cast<int>(h5::get_attr_int(id, "bridge_index"));
  k.braid_index = static_cast<int>(h5::get_attr_int(id, "braid_index"));
  k.alexander = h5::get_attr_ints(id, "alexander");
  k.samples_used = static_cast<int>(h5::get_attr_int(id, "samples_used"));
  k.adaptive = h5::get_attr_int(id, "adaptive") != 0;
  k.complete = h5::get_attr_int(id, "complete") != 0;
  std::vector<hsize_t> shape;
  const auto eq = h5::read_doubles(id, "equilibria", &shape);
  if (shape.size() != 3 || (shape[0] > 0 && shape[2] != 3))
    throw InputError("data set '" + impl_->path + "': knot " + name + " has malformed equilibria");
  for (hsize_t e = 0; e < shape[0]; ++e) {
    Points P(static_cast<Eigen::Index>(shape[1]), 3);
    std::copy(eq.begin() + static_cast<long>(e * shape[1] * 3), eq.begin() + static_cast<long>((e + 1) * shape[1] * 3),
              P.data());
    k.equilibria.push_back(std::move(P));
  }
  k.attribute_names = h5::read_strings(id, "attribute_names");
  const auto attr = h5::read_doubles(id, "attributes", &shape);
  k.attributes = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      attr.data(), static_cast<Eigen::Index>(shape.at(0)), static_cast<Eigen::Index>(shape.at(1)));
  {
    h5::Handle runs = h5::open_group(id, "runs");
    const auto sample = h5::read_int64(runs.id(), "sample");
    const auto seed = h5::read_int64(runs.id(), "seed");
    const auto eqi = h5::read_int64(runs.id(), "equilibrium");
    const auto iters = h5::read_int64(runs.id(), "iterations");
    const auto contacts = h5::read_int64(runs.id(), "contacts");
    const auto alex = h5::read_int64(runs.id(), "alexander_preserved");
    const auto seconds = h5::read_doubles(runs.id(), "seconds");
    const auto energy = h5::read_doubles(runs.id(), "energy");
    const auto gnorm = h5::read_doubles(runs.id(), "gradient_norm");
    const auto status = h5::read_strings(runs.id(), "status");
    const auto message = h5::read_strings(runs.id(), "message");
    for (size_t r = 0; r < sample.size(); ++r) {
      RunRecord run;
      run.sample = static_cast<int>(sample[r]);
      run.seed = static_cast<std::uint64_t>(seed[r]);
      run.equilibrium = static_cast<int>(eqi[r]);
      run.iterations = static_cast<int>(iters[r]);
      run.contacts = static_cast<int>(contacts[r]);
      run.alexander_preserved = alex[r] != 0;
      run.seconds = seconds[r];
      run.energy = energy[r];
      run.gradient_norm = gnorm[r];
      run.status = status[r];
      run.message = message[r];
      k.runs.push_back(std::move(run));
    }
  }
  const auto sim = h5::read_doubles(id, "similarity", &shape);
  k.similarity = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      sim.data(), static_cast<Eigen::Index>(shape.at(0)), static_cast<Eigen::Index>(shape.at(1)));
  const auto link = h5::read_doubles(id, "linkage", &shape);
  k.linkage = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      link.data(), static_cast<Eigen::Index>(shape.at(0)), static_cast<Eigen::Index>(shape.at(1)));
  k.score_history = h5::read_doubles(id, "score_history");
  return k;
}

}  // namespace ek
