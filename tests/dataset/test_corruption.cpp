// Damaged data sets: a small data set written by `knots explore`, truncated
// at 20 points of its length and with a random byte changed at 20 places, is
// read through the command line (`knots query`, `knots export` of every
// equilibrium) and in this process (DatasetReader, every stored value). Each
// read must give exactly the original values or be refused with one error
// line and exit status 2: a crash, a hang or a value that differs from the
// original is a failure. The same damage to a copy in the layout of files
// written before data sets carried a checksum is reported beside it (those
// can only be checked for crashes and hangs: nothing in them detects a
// changed value).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "cli_runner.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "testing.hpp"
#include "unsealed_copy.hpp"

using ek::clitest::run;
namespace fs = std::filesystem;

namespace {

enum class Outcome { Correct, Refused, Wrong, Crash };

bool same_runs(const std::vector<ek::RunRecord>& a, const std::vector<ek::RunRecord>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const auto &x = a[i], &y = b[i];
    if (x.sample != y.sample || x.seed != y.seed || x.status != y.status || x.equilibrium != y.equilibrium ||
        x.iterations != y.iterations || x.seconds != y.seconds || x.energy != y.energy ||
        x.gradient_norm != y.gradient_norm || x.contacts != y.contacts ||
        x.topology_preserved != y.topology_preserved || x.message != y.message)
      return false;
  }
  return true;
}

/// Every value DatasetReader returns, compared with the original's.
bool same_entry(const ek::KnotEntry& a, const ek::KnotEntry& b) {
  auto same = [](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
    // bitwise, NaN included (max_stress may be NaN)
    return x.rows() == y.rows() && x.cols() == y.cols() &&
           std::equal(x.data(), x.data() + x.size(), y.data(), [](double u, double v) {
             return std::memcmp(&u, &v, sizeof u) == 0;
           });
  };
  return a.name == b.name && a.crossing_number == b.crossing_number && a.bridge_index == b.bridge_index &&
         a.braid_index == b.braid_index && a.alexander == b.alexander && a.equilibria == b.equilibria &&
         a.attribute_names == b.attribute_names && same(a.attributes, b.attributes) && same_runs(a.runs, b.runs) &&
         same(a.similarity, b.similarity) && same(a.linkage, b.linkage) && a.adaptive == b.adaptive &&
         a.complete == b.complete && a.samples_used == b.samples_used && a.score_history == b.score_history;
}

/// What one reader of the file returned.
struct Reference {
  std::string query;                      ///< stdout of `knots query --json`
  std::vector<std::string> exports;       ///< the exported .obj files, one per equilibrium of 3_1
  ek::DatasetMetadata meta;
  std::vector<std::string> names;
  std::vector<ek::KnotEntry> entries;
};

Outcome in_process(const std::string& path, const Reference& ref) {
  try {
    ek::DatasetReader r(path);
    if (!r.metadata().difference(ref.meta).empty() || r.metadata().sampling != ref.meta.sampling ||
        r.metadata().seed != ref.meta.seed || r.metadata().created != ref.meta.created || r.knot_names() != ref.names)
      return Outcome::Wrong;
    for (size_t k = 0; k < ref.names.size(); ++k)
      if (!same_entry(r.read(ref.names[k]), ref.entries[k])) return Outcome::Wrong;
    return Outcome::Correct;
  } catch (const ek::InputError& e) {
    return std::string(e.what()).find('\n') == std::string::npos ? Outcome::Refused : Outcome::Crash;
  }
}

/// A command's outcome: exit 0 with `expected` output, or exit 2 with one
/// "knots CMD: error:" line; anything else (a signal, a timeout, another
/// status, more lines) is a crash.
Outcome cli(const std::string& args, const std::string& command,
            const std::function<bool(const ek::clitest::Result&)>& expected) {
  const auto r = run(args, 120);
  if (r.status == 0) return expected(r) ? Outcome::Correct : Outcome::Wrong;
  const bool one_line = std::count(r.err.begin(), r.err.end(), '\n') == 1 &&
                        r.err.rfind("knots " + command + ": error: ", 0) == 0;
  if (r.status == 2 && one_line) return Outcome::Refused;
  std::printf("  knots %s: exit status %d, stderr: %s\n", args.c_str(), r.status, r.err.substr(0, 300).c_str());
  return Outcome::Crash;
}

/// The worst of the reads of one damaged file.
Outcome read_all_ways(const std::string& file, const std::string& dir, const Reference& ref) {
  std::vector<Outcome> outcomes{in_process(file, ref)};
  outcomes.push_back(cli("query " + file + " --json", "query", [&](const auto& r) { return r.out == ref.query; }));
  for (size_t i = 0; i < ref.exports.size(); ++i) {
    const std::string obj = dir + "/case.obj";
    fs::remove(obj);
    outcomes.push_back(cli("export " + file + " 3_1 " + std::to_string(i) + " -o " + obj, "export",
                           [&](const auto&) { return ek::fixtures::read_bytes(obj) == ref.exports[i]; }));
  }
  Outcome worst = Outcome::Correct;
  for (Outcome o : outcomes)
    if (static_cast<int>(o) > static_cast<int>(worst)) worst = o;
  // a file some reads accept and others refuse counts as refused (both are allowed)
  return worst;
}

struct Table {
  int cases = 0, refused = 0, correct = 0, wrong = 0, crash = 0;
  void add(Outcome o) {
    ++cases;
    (o == Outcome::Correct ? correct : o == Outcome::Refused ? refused : o == Outcome::Wrong ? wrong : crash) += 1;
  }
};

Reference reference_of(const std::string& file, const std::string& dir) {
  Reference ref;
  const auto q = run("query " + file + " --json");
  EXPECT_EQ(q.status, 0) << q.err;
  ref.query = q.out;
  ek::DatasetReader r(file);
  ref.meta = r.metadata();
  ref.names = r.knot_names();
  for (const auto& name : ref.names) ref.entries.push_back(r.read(name));
  for (size_t i = 0; i < ref.entries.front().equilibria.size(); ++i) {
    const std::string obj = dir + "/ref" + std::to_string(i) + ".obj";
    EXPECT_EQ(run("export " + file + " 3_1 " + std::to_string(i) + " -o " + obj).status, 0);
    ref.exports.push_back(ek::fixtures::read_bytes(obj));
  }
  return ref;
}

/// 20 truncations (at k/20 of the length, k = 0..19) and 20 changed bytes
/// (seeded positions, each XORed with a nonzero byte); one table each.
std::pair<Table, Table> damage(const std::string& file, const std::string& dir, std::uint64_t seed) {
  const Reference ref = reference_of(file, dir);
  const std::string bytes = ek::fixtures::read_bytes(file);
  const std::string damaged = dir + "/damaged.h5";
  std::pair<Table, Table> tables;
  for (int k = 0; k < 20; ++k) {
    ek::fixtures::write_bytes(damaged, bytes.substr(0, bytes.size() * static_cast<size_t>(k) / 20));
    tables.first.add(read_all_ways(damaged, dir, ref));
  }
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 20; ++k) {
    std::string flipped = bytes;
    const size_t at = std::uniform_int_distribution<size_t>(0, bytes.size() - 1)(rng);
    flipped[at] = static_cast<char>(flipped[at] ^ std::uniform_int_distribution<int>(1, 255)(rng));
    ek::fixtures::write_bytes(damaged, flipped);
    const Outcome o = read_all_ways(damaged, dir, ref);
    tables.second.add(o);
    if (o == Outcome::Wrong) std::printf("  changed byte at %zu of %zu: a read returned other values\n", at, bytes.size());
  }
  return tables;
}

void print(const char* layout, const char* damage_kind, const Table& t) {
  std::printf("%-22s %-14s cases %2d  refused %2d  read correctly %2d  wrong values %2d  crash or hang %2d\n", layout,
              damage_kind, t.cases, t.refused, t.correct, t.wrong, t.crash);
}

}  // namespace

TEST(DatasetCorruption, DamagedFilesAreReadCorrectlyOrRefused) {
  const std::string dir = ek::clitest::temp_dir("ds_corrupt");
  const std::string file = dir + "/small.h5";
  const auto made = run("explore 3_1 --samples 3 -n 100 --no-stiffness --quiet -o " + file);
  ASSERT_EQ(made.status, 0) << made.err;
  ASSERT_GE(ek::DatasetReader(file).read("3_1").equilibria.size(), 1u);
  const auto [truncated, flipped] = damage(file, dir, 20261201);
  print("with checksum", "truncated", truncated);
  print("with checksum", "byte changed", flipped);
  for (const Table* t : {&truncated, &flipped}) {
    EXPECT_EQ(t->cases, 20);
    EXPECT_EQ(t->wrong, 0);
    EXPECT_EQ(t->crash, 0);
  }
  // the same damage to the layout before checksums: never a crash or a hang
  const std::string old = dir + "/old_layout.h5";
  ek::fixtures::write_unsealed_copy(file, old);
  const auto [old_truncated, old_flipped] = damage(old, dir, 20261201);
  print("without checksum (old)", "truncated", old_truncated);
  print("without checksum (old)", "byte changed", old_flipped);
  EXPECT_EQ(old_truncated.crash + old_flipped.crash, 0);
  fs::remove_all(dir);
}
