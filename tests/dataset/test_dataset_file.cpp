#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "ek/core/errors.hpp"
#include "child_read.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "metadata_testing.hpp"
#include "ek/dataset/h5.hpp"
#include "testing.hpp"
#include "unsealed_copy.hpp"

using namespace ek;
using ek::testing_metadata::changed;
using ek::testing_metadata::complete_metadata;

namespace {

KnotEntry sample_entry(const std::string& name, int m, int n) {
  KnotEntry k;
  k.name = name;
  k.crossing_number = 4;
  k.bridge_index = 2;
  k.braid_index = 3;
  k.alexander = {-1, 3, -1};
  for (int e = 0; e < m; ++e) k.equilibria.push_back(fixtures::random_fourier_curve(n, 3, 10 + e));
  k.attribute_names = {"energy", "writhe"};
  k.attributes.resize(m, 2);
  for (int e = 0; e < m; ++e) k.attributes.row(e) << 0.1 * e - 0.7, std::sqrt(2.0) * e;
  for (int r = 0; r < m + 1; ++r) {
    RunRecord run;
    run.sample = r;
    run.seed = 1000 + r;
    run.status = r < m ? RunStatus::ConvergedStable : RunStatus::Stalled;
    run.equilibrium = r < m ? r : -1;
    run.iterations = 10 + r;
    run.seconds = 0.5 * r;
    run.energy = 1.0 / (r + 1);
    run.gradient_norm = 1e-9;
    run.contacts = r;
    run.message = r < m ? "" : "line search cannot progress";
    k.runs.push_back(run);
  }
  k.similarity = Eigen::MatrixXd::Identity(m, m);
  k.linkage = Eigen::MatrixXd::Zero(std::max(m - 1, 0), 4);
  k.samples_used = m + 1;
  k.adaptive = true;
  k.score_history = {0.9, 0.5, 0.05};
  return k;
}

}  // namespace

TEST(DatasetFile, RoundTrip) {
  const std::string path = ::testing::TempDir() + "round.h5";
  const DatasetMetadata meta = complete_metadata();
  {
    DatasetWriter w(path, meta);
    w.add(sample_entry("4_1", 3, 40));
    w.add(sample_entry("3_1", 2, 40));
    w.commit();
  }
  DatasetReader r(path);
  // every field of the table, bit for bit
  for (const auto& f : metadata_fields()) {
    ASSERT_FALSE(std::holds_alternative<std::monostate>(f.get(meta))) << f.name << " is not set in the fixture";
    EXPECT_TRUE(f.get(r.metadata()) == f.get(meta)) << f.name;
  }
  EXPECT_EQ(r.metadata().difference(meta), "");
  EXPECT_EQ(r.metadata().seed, meta.seed);  // >= 2^63 through the int64 attribute
  EXPECT_EQ(r.metadata().contact_continuation, meta.contact_continuation);  // 17 digits: bit for bit
  EXPECT_EQ(r.knot_names(), (std::vector<std::string>{"4_1", "3_1"}));
  const KnotEntry a = r.read("4_1"), b = sample_entry("4_1", 3, 40);
  ASSERT_EQ(a.equilibria.size(), 3u);
  for (int e = 0; e < 3; ++e) EXPECT_EQ(a.equilibria[e], b.equilibria[e]);
  EXPECT_EQ(a.attributes, b.attributes);
  EXPECT_EQ(a.attribute_names, b.attribute_names);
  EXPECT_EQ(a.alexander, b.alexander);
  ASSERT_EQ(a.runs.size(), 4u);
  EXPECT_EQ(a.runs[3].status, RunStatus::Stalled);
  EXPECT_EQ(a.runs[3].equilibrium, -1);
  EXPECT_EQ(a.runs[3].message, "line search cannot progress");
  EXPECT_EQ(a.runs[2].seed, 1002u);
  EXPECT_EQ(a.score_history, b.score_history);
  EXPECT_EQ(a.similarity, b.similarity);
  EXPECT_TRUE(a.adaptive);
  EXPECT_EQ(a.attribute_column("writhe"), 1);
  EXPECT_THROW(a.attribute_column("colour"), InputError);
  EXPECT_THROW(r.read("5_1"), InputError);
  std::remove(path.c_str());
}

// Run statuses are text only in the file: every status reads back as itself,
// and a text no version wrote is an input error naming it.
TEST(DatasetFile, RunStatusTexts) {
  std::set<std::string> texts;
  for (RunStatus s : {RunStatus::ConvergedStable, RunStatus::ConvergedUnstable, RunStatus::MaxIterations,
                      RunStatus::Stalled, RunStatus::TopologyChanged, RunStatus::Error}) {
    EXPECT_EQ(parse_run_status(to_string(s)), s);
    texts.insert(to_string(s));
  }
  EXPECT_EQ(texts, (std::set<std::string>{"converged-stable", "converged-unstable", "max-iterations", "stalled",
                                          "topology-changed", "error"}));
  try {
    parse_run_status("converged");
    ADD_FAILURE() << "an unknown status was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'converged'"), std::string::npos) << e.what();
  }
}

TEST(DatasetFile, UncommittedWriterLeavesExistingFileAlone) {
  const std::string path = ::testing::TempDir() + "keep.h5";
  { std::ofstream(path) << "precious"; }
  {
    DatasetWriter w(path, complete_metadata());
    w.add(sample_entry("4_1", 2, 20));
    // destroyed without commit
  }
  std::ifstream in(path);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "precious");
  for (const auto& e : std::filesystem::directory_iterator(::testing::TempDir()))
    EXPECT_EQ(e.path().filename().string().find("keep.h5.tmp"), std::string::npos);
  std::remove(path.c_str());
}

TEST(DatasetFile, BadFilesAreInputErrors) {
  const std::string path = ::testing::TempDir() + "not.h5";
  { std::ofstream(path) << "not hdf5"; }
  EXPECT_THROW(DatasetReader{path}, InputError);
  EXPECT_THROW(DatasetReader{"/nonexistent/x.h5"}, InputError);
  EXPECT_THROW(DatasetWriter("/nonexistent-dir/x.h5", DatasetMetadata{}), InputError);
  std::remove(path.c_str());
}

namespace {

bool is_empty(const FieldValue& v) { return std::holds_alternative<std::monostate>(v); }

/// Runs f on the open file (read-write) and writes a new checksum, so that
/// the reader's own checks of what f changed are what is tested.
void edit_file(const std::string& path, const std::function<void(hid_t)>& f) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  f(file);
  ASSERT_GE(H5Fclose(file), 0);
  h5::seal(path);
}

void write_int_attribute(hid_t f, const char* name, long long value) {
  H5Adelete(f, name);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(f, name, H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(a, 0);
  H5Awrite(a, H5T_NATIVE_LLONG, &value);
  H5Aclose(a);
  H5Sclose(space);
}

void write_text_attribute(hid_t f, const char* name, const char* value) {
  H5Adelete(f, name);
  const hid_t type = H5Tcopy(H5T_C_S1);  // a variable-length string, as the writer stores text
  H5Tset_size(type, H5T_VARIABLE);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(f, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(a, 0);
  H5Awrite(a, type, &value);
  H5Aclose(a);
  H5Sclose(space);
  H5Tclose(type);
}

std::string write_one_knot_file(const std::string& name, const DatasetMetadata& meta) {
  const std::string path = ::testing::TempDir() + name;
  DatasetWriter w(path, meta);
  w.add(sample_entry("3_1", 1, 40));
  w.commit();
  return path;
}

}  // namespace

// Every compared field in turn: a changed value is reported by name with
// both values, in either order; a field that one side does not record
// matches; provenance is never compared.
TEST(DatasetMetadataTable, DifferenceNamesEachField) {
  const DatasetMetadata a = complete_metadata();
  for (const auto& f : metadata_fields()) {
    DatasetMetadata b = a;
    f.set(b, changed(f.get(a)));
    ASSERT_FALSE(f.get(b) == f.get(a)) << f.name;
    if (f.match == FieldMatch::Provenance) {
      EXPECT_EQ(a.difference(b), "") << f.name;
      continue;
    }
    EXPECT_EQ(a.difference(b).rfind(f.name + " ", 0), 0u) << f.name << ": " << a.difference(b);
    EXPECT_EQ(b.difference(a).rfind(f.name + " ", 0), 0u) << f.name << ": " << b.difference(a);
    f.set(b, std::monostate{});
    EXPECT_EQ(a.difference(b), "") << f.name << " not recorded matches";
    EXPECT_EQ(b.difference(a), "") << f.name << " not recorded matches";
  }
}

TEST(DatasetMetadataTable, DifferenceMessagesAndTolerance) {
  DatasetMetadata a = complete_metadata(), b = a;
  a.radius = 0.2;
  b.radius = 0.1;
  EXPECT_EQ(a.difference(b), "radius 0.2 vs 0.1");
  b = a;
  b.vertices = 200;
  EXPECT_EQ(a.difference(b), "vertices 120 vs 200");
  b = a;
  a.contact_continuation = std::vector<double>{};
  b.contact_continuation = std::vector<double>{1e-3};
  EXPECT_EQ(a.difference(b), "contact_continuation off vs 0.001");
  a.contact_continuation = std::vector<double>{1e-3, 0.1};
  EXPECT_EQ(a.difference(b), "contact_continuation 0.001,0.10000000000000001 vs 0.001");
  b = a;
  b.compute_stiffness = true;
  EXPECT_EQ(a.difference(b), "compute_stiffness 0 vs 1");
  // doubles are equal to a relative 1e-12 (values written and read back in binary)
  b = a;
  b.young = *a.young * (1.0 + 1e-13);
  EXPECT_EQ(a.difference(b), "");
  b.young = *a.young * (1.0 + 1e-9);
  EXPECT_EQ(a.difference(b), "young 2100.5 vs 2100.500002");
}

// A merged or extended file keeps only what every part records.
TEST(DatasetMetadataTable, ForgetUnrecorded) {
  DatasetMetadata a = complete_metadata(), old = a;
  old.max_iterations.reset();
  old.compute_stiffness.reset();
  a.forget_unrecorded(old);
  EXPECT_FALSE(a.max_iterations.has_value());
  EXPECT_FALSE(a.compute_stiffness.has_value());
  EXPECT_EQ(a.burn_in, 7);
  EXPECT_EQ(a.young, 2100.5);
}

// The writer needs every field that a file must have; the others may be "not
// recorded": left out of the file and read back as not recorded.
TEST(DatasetMetadataTable, WriterNeedsEveryRequiredField) {
  for (const auto& f : metadata_fields()) {
    DatasetMetadata m = complete_metadata();
    f.set(m, std::monostate{});
    if (f.absent != WhenAbsent::NotRecorded) {
      try {
        write_one_knot_file("unset.h5", m);
        ADD_FAILURE() << "an unset " << f.name << " was written";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'" + f.name + "' is not set"), std::string::npos) << e.what();
      }
      continue;
    }
    const std::string path = write_one_knot_file("unrecorded.h5", m);
    EXPECT_TRUE(is_empty(f.get(DatasetReader(path).metadata()))) << f.name;
    std::remove(path.c_str());
  }
  EXPECT_FALSE(std::filesystem::exists(::testing::TempDir() + "unset.h5"));
}

// Files written before an attribute existed: the required ones are in every
// version-1 file (missing: an input error naming the file and attribute); the
// others read as the documented value or as "not recorded"; earlier versions
// wrote -1 for an unknown iteration cap.
TEST(DatasetMetadataTable, OldFilesReadWithDocumentedValues) {
  const std::string path = write_one_knot_file("old.h5", complete_metadata());
  edit_file(path, [](hid_t f) {
    for (const auto& field : metadata_fields()) {
      if (field.absent != WhenAbsent::Required) {
        ASSERT_GE(H5Adelete(f, field.name.c_str()), 0) << field.name;
      }
    }
  });
  {
    const DatasetMetadata m = DatasetReader(path).metadata();
    for (const auto& f : metadata_fields()) {
      const FieldValue expected = f.absent == WhenAbsent::Default    ? f.absent_value
                                  : f.absent == WhenAbsent::Required ? f.get(complete_metadata())
                                                                     : FieldValue{};
      EXPECT_TRUE(f.get(m) == expected) << f.name;
    }
    EXPECT_EQ(m.grow_fugacity, 0.40);
    EXPECT_EQ(m.contact_continuation, std::vector<double>{});  // off
  }
  edit_file(path, [](hid_t f) { write_int_attribute(f, "max_iterations", -1); });
  EXPECT_FALSE(DatasetReader(path).metadata().max_iterations.has_value());
  edit_file(path, [](hid_t f) { write_text_attribute(f, "contact_continuation", "0.5,,2"); });
  try {
    DatasetReader r(path);
    ADD_FAILURE() << "a malformed contact_continuation attribute was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("malformed contact_continuation attribute '0.5,,2'"), std::string::npos)
        << e.what();
  }
  edit_file(path, [](hid_t f) {
    H5Adelete(f, "contact_continuation");
    ASSERT_GE(H5Adelete(f, "dhat"), 0);
  });
  try {
    DatasetReader r(path);
    ADD_FAILURE() << "a file without dhat was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lacks the data-set attribute 'dhat'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

// The journal key names every compared field that has a key (the burn-in is
// part of the sampling text), so a journal of a run with any other parameter
// is refused; fields added to the key later are left out at the values that
// older keys imply.
TEST(DatasetMetadataTable, JournalKeyCoversEveryComparedField) {
  const DatasetMetadata a = complete_metadata();
  const std::string key = journal_key(a);
  EXPECT_EQ(key,
            "young=2100.5 poisson=0.33333333333333331 radius=0.25 n=120 tol=3.3333333333333334e-09 omega=1234.5678 "
            "dhat=0.45000000000000001 model=free-theta method=multilevel levels=2 coarse=0.01 "
            "coarsening=either-parity,recheck-20x3 hessian=exact rigid=0 "
            "contact=gauss-newton damp=1 iterations=3000 "
            "sampling=fixed:3,burn-in=7 "
            "grow=0.40999999999999998 shrink=0.089999999999999997 growth=9.5 decorrelation=12345 "
            "seed=9223372036854775813 stiffness=0 continuation=0.001,0.033333333333333333");
  for (const auto& f : metadata_fields()) {
    if (f.match == FieldMatch::Provenance || f.key.empty()) {
      EXPECT_TRUE(f.match == FieldMatch::Provenance || f.name == "burn_in") << f.name << " has no journal key";
      continue;
    }
    DatasetMetadata b = a;
    f.set(b, changed(f.get(a)));
    EXPECT_NE(journal_key(b), key) << f.name;
    if (!(f.get(b) == f.key_omitted)) {  // rigid=0 changed to 1 is left out
      EXPECT_NE((" " + journal_key(b)).find(" " + f.key + "="), std::string::npos) << f.name;
    }
    if (!is_empty(f.key_omitted)) {  // edge=1 is left out of `key`
      f.set(b, f.key_omitted);
      EXPECT_EQ((" " + journal_key(b)).find(" " + f.key + "="), std::string::npos) << f.name;
    }
    f.set(b, std::monostate{});  // not recorded: left out
    EXPECT_EQ((" " + journal_key(b)).find(" " + f.key + "="), std::string::npos) << f.name;
  }
}

// text() and json() list every field in table order, with units and "not
// recorded" (null) for empty fields.
TEST(DatasetMetadataTable, TextAndJsonDescriptions) {
  DatasetMetadata m = complete_metadata();
  m.max_iterations.reset();
  const nlohmann::json j = nlohmann::json::parse(m.json());
  std::istringstream text(m.text());
  std::string line;
  for (const auto& f : metadata_fields()) {
    ASSERT_TRUE(std::getline(text, line)) << f.name;
    EXPECT_EQ(line.rfind(f.name + " ", 0), 0u) << line;
    if (!f.unit.empty()) {
      EXPECT_NE(line.find("[" + f.unit + "]"), std::string::npos) << line;
    }
    ASSERT_TRUE(j.contains(f.name)) << f.name;
  }
  EXPECT_FALSE(std::getline(text, line));
  EXPECT_EQ(j.size(), metadata_fields().size());
  EXPECT_TRUE(j["max_iterations"].is_null());
  EXPECT_EQ(j["vertices"], 120);
  EXPECT_EQ(j["twist_model"], "free-theta");
  EXPECT_EQ(j["compute_stiffness"], 0);
  EXPECT_EQ(j["contact_continuation"], nlohmann::json::parse("[0.001, 0.03333333333333333]"));
  EXPECT_NE(m.text().find("max_iterations        not recorded"), std::string::npos) << m.text();
  EXPECT_NE(m.text().find("radius                0.25 [length]"), std::string::npos) << m.text();
}

namespace {

/// A data set of two knots (2 and 0 equilibria of 20 vertices).
std::string small_dataset(const std::string& name) {
  const std::string path = ::testing::TempDir() + name;
  DatasetWriter w(path, complete_metadata());
  w.add(sample_entry("3_1", 2, 20));
  w.add(sample_entry("4_1", 0, 20));
  w.commit();
  return path;
}

/// Every stored value of the two data sets is equal.
void expect_same_content(const std::string& a, const std::string& b) {
  DatasetReader ra(a), rb(b);
  EXPECT_EQ(ra.metadata().difference(rb.metadata()), "");
  EXPECT_EQ(ra.metadata().sampling, rb.metadata().sampling);
  ASSERT_EQ(ra.knot_names(), rb.knot_names());
  for (const auto& name : ra.knot_names()) {
    const KnotEntry x = ra.read(name), y = rb.read(name);
    EXPECT_EQ(x.equilibria, y.equilibria) << name;
    EXPECT_EQ(x.attributes, y.attributes) << name;
    EXPECT_EQ(x.runs.size(), y.runs.size()) << name;
    EXPECT_EQ(x.similarity, y.similarity) << name;
  }
}

template <class F>
void expect_refused(F read, const std::string& needle) {
  try {
    read();
    ADD_FAILURE() << "expected an InputError containing '" << needle << "'";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(needle), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace

// A data set carries the CRC-32 and length of its bytes in the HDF5 user
// block: truncation, a flipped bit, an appended byte or a damaged header are
// refused before HDF5 parses anything.
TEST(DatasetFile, ChecksumDetectsDamage) {
  const std::string path = small_dataset("sealed.h5");
  const std::string good = fixtures::read_bytes(path);
  ASSERT_EQ(good.compare(0, 33, "elastic-knots-dataset checksum 1\n"), 0);
  EXPECT_EQ(good.compare(512, 4, "\x89HDF"), 0);
  const std::string damaged = path + ".damaged.h5";
  fixtures::write_bytes(damaged, good.substr(0, good.size() - 100));
  expect_refused([&] { DatasetReader r(damaged); }, "bytes, but it was written with " + std::to_string(good.size()));
  for (size_t at : {size_t{600}, good.size() / 2, good.size() - 1}) {
    std::string flipped = good;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    fixtures::write_bytes(damaged, flipped);
    expect_refused([&] { DatasetReader r(damaged); }, "its checksum does not match");
  }
  std::string header = good;
  header[40] = static_cast<char>(header[40] ^ 0x01);  // a digit of the CRC
  fixtures::write_bytes(damaged, header);
  expect_refused([&] { DatasetReader r(damaged); }, "damaged");
  header = good;
  header[300] = 'x';  // the zero padding
  fixtures::write_bytes(damaged, header);
  expect_refused([&] { DatasetReader r(damaged); }, "checksum header is unreadable");
  fixtures::write_bytes(damaged, good + "x");
  expect_refused([&] { DatasetReader r(damaged); }, "truncated or extended");
  fixtures::write_bytes(damaged, std::string(600, '\0'));
  expect_refused([&] { DatasetReader r(damaged); }, "is not a readable HDF5 data set");
  std::remove(damaged.c_str());
  std::remove(path.c_str());
}

// Files written before data sets carried a checksum (HDF5 signature at byte
// 0, no user block) are read as before.
TEST(DatasetFile, FilesWithoutChecksumAreStillRead) {
  const std::string path = small_dataset("with_checksum.h5");
  const std::string old = ::testing::TempDir() + "without_checksum.h5";
  fixtures::write_unsealed_copy(path, old);
  ASSERT_EQ(fixtures::read_bytes(old).compare(0, 4, "\x89HDF"), 0);
  expect_same_content(path, old);
  std::remove(old.c_str());
  std::remove(path.c_str());
}

// Damaged files without checksum on which the HDF5 library itself crashes,
// hangs or runs out of memory (found by fuzzing the reader under ASan): read
// in a child process first, they are refused with one line naming the file,
// and this process survives. (Without ASan some of them only make HDF5
// report an error.)
TEST(DatasetFile, DamagedFilesWithoutChecksumAreRefusedNotCrashed) {
  const std::string corpus = std::string(EK_FUZZ_CORPUS) + "/dataset_h5/";
  detail::set_child_read_limit(5.0, 0.0);  // the hang costs 5 s, not a minute
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("regression-hdf5-", 0) != 0) continue;
    ++files;
    SCOPED_TRACE(name);
    expect_refused(
        [&] {
          DatasetReader r(entry.path().string());
          for (const auto& k : r.knot_names()) r.read(k);
        },
        "'" + entry.path().string() + "'");
  }
  detail::set_child_read_limit(60.0, 1.0);
  EXPECT_GE(files, 5);
}

namespace {

void replace_dataset(hid_t parent, const char* name, hid_t type, std::vector<hsize_t> dims, const void* data,
                     hid_t dcpl = H5P_DEFAULT) {
  H5Ldelete(parent, name, H5P_DEFAULT);
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t ds = H5Dcreate2(parent, name, type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  if (data) H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(ds);
  H5Sclose(space);
}

}  // namespace

// What the reader used to do with files whose shapes or types differ from
// what the writer writes (found by the structure-aware fuzz target
// dataset_fields on the earlier reader): overflow a stack value (an array
// where one value belongs), read past a column (runs of different lengths),
// throw std::out_of_range (a one-dimensional table), accept a knot under
// another name. Each is now an InputError naming the problem.
TEST(DatasetFile, ShapesAndTypesAreChecked) {
  const std::string path = ::testing::TempDir() + "edited.h5";
  const std::string good = fixtures::read_bytes(small_dataset("shapes.h5"));
  auto check = [&](const std::function<void(hid_t)>& edit, const std::string& needle) {
    fixtures::write_bytes(path, good);
    edit_file(path, edit);
    expect_refused(
        [&] {
          DatasetReader r(path);
          for (const auto& k : r.knot_names()) r.read(k);
        },
        needle);
  };
  const std::int64_t three[3] = {1, 2, 3};
  check([&](hid_t f) {
    H5Adelete(f, "vertices");
    const hsize_t n = 3;
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t a = H5Acreate2(f, "vertices", H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT64, three);
    H5Aclose(a);
    H5Sclose(space);
  }, "attribute 'vertices' is not one value");
  check([&](hid_t f) {
    replace_dataset(f, "knots/3_1/runs/seed", H5T_NATIVE_INT64, {1}, three);
  }, "runs: column 'seed' has 1 rows, 'sample' 3");
  check([&](hid_t f) {
    const double v[2] = {1, 2};
    replace_dataset(f, "knots/3_1/attributes", H5T_NATIVE_DOUBLE, {2}, v);
  }, "attributes is not a table");
  check([&](hid_t f) {
    const std::int64_t eq[3] = {0, 7, -1};
    replace_dataset(f, "knots/3_1/runs/equilibrium", H5T_NATIVE_INT64, {3}, eq);
  }, "run 1 names equilibrium 7 of 2");
  check([&](hid_t f) {
    std::vector<double> nan(2 * 20 * 3, std::nan(""));
    replace_dataset(f, "knots/3_1/equilibria", H5T_NATIVE_DOUBLE, {2, 20, 3}, nan.data());
  }, "equilibrium 0 has a coordinate that is not finite");
  check([&](hid_t f) {
    H5Adelete(f, "format_version");
    const char* text = "1";
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(f, "format_version", type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, type, &text);
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
  }, "attribute 'format_version' is not an integer");
  check([&](hid_t f) {
    const char* names[2] = {"3_1", "4_1"};
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    replace_dataset(f, "knot_names", type, {1, 2}, names);
    H5Tclose(type);
  }, "'knot_names' has the wrong rank");
  check([&](hid_t f) {
    const hid_t g = H5Gopen2(f, "knots/4_1", H5P_DEFAULT);
    H5Adelete(g, "name");
    const char* text = "5_2";
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(g, "name", type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, type, &text);
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
    H5Gclose(g);
  }, "its group is named 4_1 but its name attribute 5_2");
  check([&](hid_t f) {
    // 2^40 values declared, none stored: refused before allocating for them
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    const hsize_t chunk[3] = {1, 1, 3};
    H5Pset_chunk(dcpl, 3, chunk);
    replace_dataset(f, "knots/3_1/equilibria", H5T_NATIVE_DOUBLE, {hsize_t{1} << 19, hsize_t{1} << 19, 3}, nullptr,
                    dcpl);
    H5Pclose(dcpl);
  }, "dataset 'equilibria' is damaged");
  std::remove(path.c_str());
}

// A file of format version 1 reads as version 2: its runs' column
// alexander_preserved is topology_preserved, and a link's `energy` (then the
// elastic energy without contact) gains energy_contact, a knot's unchanged.
// Versions outside 1..2 are refused.
TEST(DatasetFile, VersionOneFilesReadAsVersionTwo) {
  const std::string path = ::testing::TempDir() + "version1.h5";
  KnotEntry link = sample_entry("L2a1", 2, 20);
  link.components = {10, 10};
  link.conway = {0, 1};
  link.linking_numbers = {0, 1, 1, 0};
  link.alexander = {1};
  link.attribute_names = {"energy", "energy_contact", "writhe"};
  link.attributes.resize(2, 3);
  link.attributes << 1.0, 0.25, 0.5, 2.0, 0.125, -0.5;
  link.runs[1].topology_preserved = false;
  {
    DatasetWriter w(path, complete_metadata());
    w.add(sample_entry("3_1", 2, 20));
    w.add(link);
    w.commit();
  }
  const auto version = [&](long long v) {
    edit_file(path, [&](hid_t f) {
      H5Adelete(f, "format_version");
      write_int_attribute(f, "format_version", v);
    });
  };
  version(1);
  edit_file(path, [](hid_t f) {
    for (const char* knot : {"knots/3_1/runs/", "knots/L2a1/runs/"}) {
      const std::string from = std::string(knot) + "topology_preserved", to = std::string(knot) + "alexander_preserved";
      ASSERT_GE(H5Lmove(f, from.c_str(), f, to.c_str(), H5P_DEFAULT, H5P_DEFAULT), 0);
    }
  });
  {
    const DatasetReader r(path);
    const KnotEntry k = r.read("3_1"), l = r.read("L2a1");
    EXPECT_TRUE(k.attributes == sample_entry("3_1", 2, 20).attributes);
    EXPECT_EQ(l.attributes(0, 0), 1.25);
    EXPECT_EQ(l.attributes(1, 0), 2.125);
    EXPECT_EQ(l.attributes(1, 2), -0.5);
    ASSERT_EQ(l.runs.size(), 3u);
    EXPECT_TRUE(l.runs[0].topology_preserved);
    EXPECT_FALSE(l.runs[1].topology_preserved);
  }
  for (const long long v : {0LL, 3LL}) {
    version(v);
    expect_refused([&] { DatasetReader r(path); }, "format version " + std::to_string(v) + ", expected 1 to 2");
  }
  std::filesystem::remove(path);
}
