// The data-set reader's checks of what HDF5 hands it (dataset_file.cpp,
// h5.cpp), structure-aware: the input decides the type, rank, shape and
// presence of every attribute and dataset of a data-set file, which is
// written through the HDF5 library (so the library only ever reads a file it
// wrote itself) and sealed with a valid checksum. DatasetReader must read
// every knot or refuse the file with an InputError. Most choices default to
// what the writer writes, so that the reader's later checks are reached.
#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/metadata.hpp"
#include "fuzz_common.hpp"
#include "ek/dataset/h5.hpp"

namespace {

using ek::h5::Handle;

enum class Kind { Double, Int, String };

/// Variable-length UTF-8 strings, as the writer writes them.
Handle string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.id(), H5T_VARIABLE);
  H5Tset_cset(t.id(), H5T_CSET_UTF8);
  return t;
}

/// How a field deviates from what the writer writes.
enum class Deviation { None, Absent, WrongType, WrongRank, WrongSize };

Deviation deviation(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 15)) {
    case 12: return Deviation::Absent;
    case 13: return Deviation::WrongType;
    case 14: return Deviation::WrongRank;
    case 15: return Deviation::WrongSize;
    default: return Deviation::None;
  }
}

Kind other(Kind k, FuzzedDataProvider& in) {
  const Kind others[2][3] = {{Kind::Int, Kind::String, Kind::Double}, {Kind::String, Kind::Double, Kind::Int}};
  return others[in.ConsumeBool() ? 1 : 0][static_cast<int>(k)];
}

/// Writes `count` values of `kind` as an attribute (attr) or a dataset;
/// strings are `text` or, when the input says so, any text.
void write_values(FuzzedDataProvider& in, hid_t parent, const std::string& name, Kind kind,
                  const std::vector<hsize_t>& shape, bool attr, const std::string& text) {
  hsize_t count = 1;
  for (hsize_t d : shape) count *= d;
  Handle space(shape.empty() ? H5Screate(H5S_SCALAR)
                             : H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr),
               H5Sclose);
  Handle str = string_type();
  const hid_t type = kind == Kind::Double ? H5T_NATIVE_DOUBLE : kind == Kind::Int ? H5T_NATIVE_INT64 : str.id();
  std::vector<double> d;
  std::vector<std::int64_t> i;
  std::vector<std::string> s;
  std::vector<const char*> p;
  for (hsize_t k = 0; k < count; ++k) {
    if (kind == Kind::Double) d.push_back(in.ConsumeBool() ? in.ConsumeFloatingPoint<double>() : 0.5 * k);
    if (kind == Kind::Int) i.push_back(in.ConsumeBool() ? in.ConsumeIntegral<std::int64_t>() : 1);
    if (kind == Kind::String) s.push_back(in.ConsumeBool() ? in.ConsumeRandomLengthString(12) : text);
  }
  for (const auto& x : s) p.push_back(x.c_str());
  const void* data = kind == Kind::Double ? static_cast<const void*>(d.data())
                     : kind == Kind::Int  ? static_cast<const void*>(i.data())
                                          : static_cast<const void*>(p.data());
  if (attr) {
    Handle a(H5Acreate2(parent, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (a.valid() && count > 0) H5Awrite(a.id(), type, data);
  } else {
    Handle ds(H5Dcreate2(parent, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if (ds.valid() && count > 0) H5Dwrite(ds.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  }
}

/// A field of the writer's kind and shape, or a deviation from it.
void field(FuzzedDataProvider& in, hid_t parent, const std::string& name, Kind kind, std::vector<hsize_t> shape,
           bool attr, const std::string& text = "") {
  switch (deviation(in)) {
    case Deviation::Absent: return;
    case Deviation::WrongType: kind = other(kind, in); break;
    case Deviation::WrongRank:
      if (shape.empty() || in.ConsumeBool()) shape.push_back(in.ConsumeIntegralInRange<hsize_t>(0, 3));
      else shape.pop_back();
      break;
    case Deviation::WrongSize:
      if (shape.empty()) shape.push_back(in.ConsumeIntegralInRange<hsize_t>(0, 3));
      else shape[in.ConsumeIntegralInRange<size_t>(0, shape.size() - 1)] = in.ConsumeIntegralInRange<hsize_t>(0, 7);
      break;
    case Deviation::None: break;
  }
  write_values(in, parent, name, kind, shape, attr, text);
}

/// The root's attributes; returns the format version written (both the
/// current one and the oldest the reader reads, whose runs name a column otherwise).
std::int64_t root(FuzzedDataProvider& in, hid_t f) {
  // the format tag must be right for anything else to be read
  Handle str = string_type();
  if (in.ConsumeIntegralInRange<int>(0, 15) != 0) {
    const char* tag = "elastic-knots-dataset";
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(f, "format", str.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    H5Awrite(a.id(), str.id(), &tag);
  }
  const std::int64_t version = in.ConsumeBool() ? 2 : 1;
  if (in.ConsumeIntegralInRange<int>(0, 15) != 0) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(f, "format_version", H5T_NATIVE_INT64, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    H5Awrite(a.id(), H5T_NATIVE_INT64, &version);
  }
  // every parameter of the table (metadata.hpp), as the writer stores its kind
  for (const auto& p : ek::metadata_fields()) {
    const bool text = p.kind == ek::FieldKind::Text || p.kind == ek::FieldKind::List;
    field(in, f, p.name, p.kind == ek::FieldKind::Real ? Kind::Double : text ? Kind::String : Kind::Int, {}, true,
          p.kind == ek::FieldKind::List ? "0.001,0.1" : "");
  }
  return version;
}

void knot(FuzzedDataProvider& in, hid_t knots, const std::string& name, std::int64_t version) {
  Handle g(H5Gcreate2(knots, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  const hsize_t m = in.ConsumeIntegralInRange<hsize_t>(0, 3), n = in.ConsumeIntegralInRange<hsize_t>(0, 6),
                k = in.ConsumeIntegralInRange<hsize_t>(0, 3), r = in.ConsumeIntegralInRange<hsize_t>(0, 4);
  field(in, g.id(), "name", Kind::String, {}, true, name);
  for (const char* a : {"crossing_number", "bridge_index", "braid_index", "samples_used", "adaptive", "complete"})
    field(in, g.id(), a, Kind::Int, {}, true);
  field(in, g.id(), "alexander", Kind::Int, {3}, true);
  field(in, g.id(), "equilibria", Kind::Double, {m, n, 3}, false);
  field(in, g.id(), "attributes", Kind::Double, {m, k}, false);
  field(in, g.id(), "attribute_names", Kind::String, {k}, false);
  if (in.ConsumeIntegralInRange<int>(0, 15) != 0) {
    Handle runs(H5Gcreate2(g.id(), "runs", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    for (const char* c : {"sample", "seed", "equilibrium", "iterations", "contacts",
                          version < 2 ? "alexander_preserved" : "topology_preserved"})
      field(in, runs.id(), c, Kind::Int, {r}, false);
    for (const char* c : {"seconds", "energy", "gradient_norm"}) field(in, runs.id(), c, Kind::Double, {r}, false);
    for (const char* c : {"status", "message"}) field(in, runs.id(), c, Kind::String, {r}, false);
  }
  field(in, g.id(), "similarity", Kind::Double, {m, m}, false);
  field(in, g.id(), "linkage", Kind::Double, {m > 0 ? m - 1 : 0, 4}, false);
  field(in, g.id(), "score_history", Kind::Double, {in.ConsumeIntegralInRange<hsize_t>(0, 2)}, false);
}

std::string scratch_path() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/ek-fuzz-dataset-fields-" + std::to_string(::getpid()) + ".h5";
}

const std::string& path() {
  static const std::string p = scratch_path();
  return p;
}

void write_file(FuzzedDataProvider& in) {
  Handle f = ek::h5::create_file(path());
  const std::int64_t version = root(in, f.id());
  const std::vector<std::string> names{"3_1", "4_1"};
  std::vector<std::string> listed;
  for (const auto& name : names)
    if (in.ConsumeBool()) listed.push_back(name);
  if (in.ConsumeIntegralInRange<int>(0, 15) == 0) listed.push_back(in.ConsumeRandomLengthString(8));
  if (in.ConsumeIntegralInRange<int>(0, 15) != 0) ek::h5::write_strings(f.id(), "knot_names", listed);
  Handle knots(H5Gcreate2(f.id(), "knots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  for (const auto& name : names)
    if (in.ConsumeIntegralInRange<int>(0, 15) != 0) knot(in, knots.id(), name, version);
  knots.reset();
  if (!f.close()) ek::fuzz::check_failed("cannot write the scratch file", __FILE__, __LINE__);
  ek::h5::seal(path());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit([] { std::remove(path().c_str()); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  write_file(in);
  ek::fuzz::expect_result_or_input_error([&] {
    ek::DatasetReader reader(path());
    for (const auto& name : reader.knot_names()) {
      const ek::KnotEntry k = reader.read(name);
      const auto m = static_cast<Eigen::Index>(k.equilibria.size());
      EK_FUZZ_CHECK(k.name == name && k.attributes.rows() == m);
      EK_FUZZ_CHECK(k.attributes.cols() == static_cast<Eigen::Index>(k.attribute_names.size()));
      EK_FUZZ_CHECK(k.similarity.size() == 0 || (k.similarity.rows() == m && k.similarity.cols() == m));
      for (const auto& P : k.equilibria) EK_FUZZ_CHECK(P.allFinite());
      for (const auto& run : k.runs) EK_FUZZ_CHECK(run.equilibrium >= -1 && run.equilibrium < m);
    }
  });
  return 0;
}
