// The ledger file (ledger.hpp): round trip, merge, and the refusal of damaged,
// foreign and inconsistent files. Label parsers: also run with ASan/UBSan.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/ledger.hpp"
#include "metadata_testing.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// A knot of m equilibria in `states` states (equilibrium i in state i mod
/// states), its runs one per equilibrium plus a failed one.
LedgerEntry sample_entry(const std::string& name, int m, int states, int n) {
  LedgerEntry e;
  e.name = name;
  e.crossing_number = 5;
  e.bridge_index = 2;
  e.braid_index = 3;
  e.alexander = {2, -3, 2};
  e.samples_used = m + 1;
  e.adaptive = true;
  e.score_history = {0.8, 0.05};
  e.attribute_names = {"energy", "threedim", "total_curvature"};
  e.attributes.resize(m, 3);
  for (int i = 0; i < m; ++i) {
    e.attributes.row(i) << 1.0 + (i % states) + 1e-3 * i, 0.05 * i, 4.0 * M_PI + 0.1 * i;
    e.state.push_back(i % states);
  }
  e.linkage = Eigen::MatrixXd::Zero(std::max(m - 1, 0), 4);
  for (int i = 0; i + 1 < m; ++i) e.linkage.row(i) << i, i + 1, 0.01 * i, 2;
  for (int s = 0; s < states; ++s)
    e.states.push_back({s, (m - s + states - 1) / states, fixtures::random_fourier_curve(n, 3, 20 + s)});
  for (int r = 0; r <= m; ++r)
    e.runs.push_back({r, r < m ? RunStatus::ConvergedStable : RunStatus::MaxIterations, r < m ? r : -1, 100 + r, 0.25 * r, true});
  return e;
}

Ledger sample_ledger() {
  Ledger l;
  l.parameters = testing_metadata::complete_metadata();
  l.provenance.cut = 0.05;
  l.provenance.commit = "abc123";
  l.provenance.created = "2026-12-03T21:00:00Z";
  l.provenance.source = "test";
  l.provenance.cores = 2;
  l.provenance.jobs = 2;
  l.provenance.wall_seconds = 12.5;
  l.provenance.cpu_seconds = 24.0;
  l.entries = {sample_entry("5_2", 7, 3, 40), sample_entry("3_1", 1, 1, 40), sample_entry("4_1", 0, 0, 40)};
  l.entries[0].states[2].curve = Points(0, 3);  // beyond the curves kept
  l.entries[2].attribute_names.clear();          // a knot without equilibria nor attributes
  l.entries[2].attributes.resize(0, 0);
  return l;
}

}  // namespace

// Every field reads back: integers and attributes exactly, the kept curves
// within half the quantum (each coordinate rounded to the grid), a state
// without a kept curve without one.
TEST(LedgerFile, RoundTrip) {
  const std::string path = ::testing::TempDir() + "round.ledger.h5";
  const Ledger a = sample_ledger();
  write_ledger(path, a);
  EXPECT_TRUE(is_ledger_file(path));
  const Ledger b = read_ledger(path);
  EXPECT_EQ(b.parameters.difference(a.parameters), "");
  EXPECT_EQ(b.provenance.commit, "abc123");
  EXPECT_EQ(b.provenance.cut, 0.05);
  EXPECT_EQ(b.provenance.cores, 2);
  EXPECT_EQ(b.provenance.wall_seconds, 12.5);
  ASSERT_EQ(b.entries.size(), a.entries.size());
  for (size_t k = 0; k < a.entries.size(); ++k) {
    const LedgerEntry &x = a.entries[k], &y = b.entries[k];
    EXPECT_EQ(y.name, x.name);
    EXPECT_EQ(y.alexander, x.alexander);
    EXPECT_EQ(y.score_history, x.score_history);
    EXPECT_EQ(y.attribute_names, x.attribute_names);
    EXPECT_EQ(y.attributes, x.attributes);
    EXPECT_EQ(y.state, x.state);
    EXPECT_EQ(y.linkage, x.linkage);
    ASSERT_EQ(y.runs.size(), x.runs.size());
    for (size_t r = 0; r < x.runs.size(); ++r) {
      EXPECT_EQ(y.runs[r].status, x.runs[r].status);
      EXPECT_EQ(y.runs[r].equilibrium, x.runs[r].equilibrium);
      EXPECT_EQ(y.runs[r].seconds, x.runs[r].seconds);
    }
    ASSERT_EQ(y.states.size(), x.states.size());
    for (size_t s = 0; s < x.states.size(); ++s) {
      EXPECT_EQ(y.states[s].members, x.states[s].members);
      ASSERT_EQ(y.states[s].curve.rows(), x.states[s].curve.rows());
      if (x.states[s].curve.rows() > 0) {
        EXPECT_LE((y.states[s].curve - x.states[s].curve).cwiseAbs().maxCoeff(),
                  0.5 * a.provenance.curve_quantum * (1 + 1e-9));
      }
    }
  }
  EXPECT_EQ(b.entries[0].stable_runs(), 7);
  EXPECT_EQ(b.entries[0].representative_sample(1), 1);
  EXPECT_EQ(b.provenance.curves_per_knot, a.provenance.curves_per_knot);
  EXPECT_EQ(b.provenance.curve_quantum, a.provenance.curve_quantum);
  EXPECT_EQ(b.entries[0].status_counts().at(RunStatus::MaxIterations), 1);
}

// A state's spread over its members: state 0 of 5_2 holds rows 0, 3, 6.
TEST(LedgerFile, SpreadIsOverTheStatesMembers) {
  const LedgerEntry e = sample_entry("5_2", 7, 3, 10);
  EXPECT_EQ(e.members(0), (std::vector<int>{0, 3, 6}));
  const AttributeSpread a = e.spread(0, e.attribute_column("threedim"));
  EXPECT_DOUBLE_EQ(a.min, 0.0);
  EXPECT_DOUBLE_EQ(a.median, 0.15);
  EXPECT_DOUBLE_EQ(a.max, 0.3);
  const AttributeSpread b = e.spread(1, e.attribute_column("threedim"));  // rows 1, 4: an even count
  EXPECT_DOUBLE_EQ(b.median, 0.125);
  fixtures::expect_input_error([&] { e.attribute_column("nope"); }, "unknown attribute 'nope'");
}

// A changed byte, a truncated file, a data set and a file without the
// checksum header are each refused with one InputError naming the file.
TEST(LedgerFile, DamagedAndForeignFilesAreRefused) {
  const std::string path = ::testing::TempDir() + "good.ledger.h5", bad = ::testing::TempDir() + "bad.ledger.h5";
  write_ledger(path, sample_ledger());
  const std::string good = fixtures::read_bytes(path);
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  fixtures::write_bytes(bad, flipped);
  fixtures::expect_input_error([&] { read_ledger(bad); }, "ledger '" + bad + "' is damaged");
  fixtures::write_bytes(bad, good.substr(0, good.size() - 100));
  fixtures::expect_input_error([&] { read_ledger(bad); }, "truncated");
  fixtures::write_bytes(bad, good.substr(512));  // the HDF5 file without its checksum header
  fixtures::expect_input_error([&] { read_ledger(bad); }, "not a ledger");
  fixtures::write_bytes(bad, "knot,crossings\n3_1,3\n");
  fixtures::expect_input_error([&] { read_ledger(bad); }, "not a readable HDF5 ledger");
  const std::string dataset = ::testing::TempDir() + "a.h5";
  {
    DatasetWriter w(dataset, testing_metadata::complete_metadata());
    w.commit();
  }
  EXPECT_FALSE(is_ledger_file(dataset));
  fixtures::expect_input_error([&] { read_ledger(dataset); }, "not an elastic-knots ledger");
}

// An inconsistent ledger is not written: a state index beyond the states.
TEST(LedgerFile, InconsistentLedgerIsNotWritten) {
  Ledger l = sample_ledger();
  l.entries[0].state[2] = 9;
  const std::string path = ::testing::TempDir() + "never.ledger.h5";
  std::filesystem::remove(path);
  EXPECT_THROW(write_ledger(path, l), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
}

// Merging: entries in order, times summed, commits listed once; different
// parameters, different cuts and a knot in two ledgers are refused.
TEST(LedgerFile, MergeKeepsEntriesAndRefusesConflicts) {
  Ledger a = sample_ledger(), b = sample_ledger();
  b.entries = {sample_entry("6_1", 4, 2, 40)};
  b.provenance.commit = "def456";
  const Ledger m = merge_ledgers({a, b});
  ASSERT_EQ(m.entries.size(), 4u);
  EXPECT_EQ(m.entries.back().name, "6_1");
  EXPECT_EQ(m.provenance.commit, "abc123,def456");
  EXPECT_EQ(m.provenance.wall_seconds, 25.0);
  const std::string folder = ::testing::TempDir() + "ledgers";
  std::filesystem::create_directories(folder);
  write_ledger(folder + "/shard-01.ledger.h5", a);
  write_ledger(folder + "/shard-02.ledger.h5", b);
  EXPECT_EQ(read_ledger_folder(folder).entries.size(), 4u);
  fixtures::expect_input_error([&] { merge_ledgers({a, a}); }, "knot 5_2 is in two of the ledgers");
  Ledger c = b;
  c.provenance.cut = 0.1;
  fixtures::expect_input_error([&] { merge_ledgers({a, c}); }, "different cuts");
  Ledger d = b;
  d.parameters.radius = 0.3;
  fixtures::expect_input_error([&] { merge_ledgers({a, d}); }, "different parameters");
  fixtures::expect_input_error([&] { read_ledger_folder(::testing::TempDir() + "nowhere"); }, "ledger folder");
}
