// Ledgers of real data sets (ledger.hpp): `knots dataset --ledger`, the
// states they keep, and a knot rerun from its ledger entry reproducing them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli_runner.hpp"
#include "ek/core/commit.hpp"
#include "ek/core/paths.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/dataset/run.hpp"
#include "testing.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;
using namespace ek;

namespace {

/// Equal, NaN where NaN (the stiffness column of a run without it).
bool same_table(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.array() == b.array() || (a.array().isNaN() && b.array().isNaN())).all();
}

const std::string kRun = " --samples 6 -n 100 --no-stiffness --novelty-distance 0.05 --quiet --jobs 2 ";

}  // namespace

// `knots dataset --ledger` writes, beside the data set, a ledger whose states
// are the data set's clusters at the novelty distance: the same members, the
// representatives' curves (within half the quantum; the lowest-energy
// states', --ledger-curves 2 of them), every attribute row and run, and the
// provenance of the run (commit, cores, wall and CPU time, the command);
// `knots query` gives the same rows from the ledger as from the data set.
TEST(Ledger, DatasetRunWritesTheLedgerOfItsStates) {
  const std::string dir = temp_dir("ledger_run");
  const std::string data = dir + "/d.h5", ledger = dir + "/d.ledger.h5";
  const auto r = run("dataset --names 3_1,5_2" + kRun + "-o " + data + " --ledger " + ledger + " --ledger-curves 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const Ledger l = read_ledger(ledger);
  const DatasetReader d(data);
  EXPECT_EQ(l.parameters.difference(d.metadata()), "");
  EXPECT_EQ(l.provenance.cut, 0.05);
  EXPECT_EQ(l.provenance.commit, source_commit());
  EXPECT_EQ(l.provenance.jobs, 2);
  EXPECT_GT(*l.provenance.wall_seconds, 0.0);
  EXPECT_GT(*l.provenance.cpu_seconds, 0.0);
  EXPECT_NE(l.provenance.source.find("dataset --names 3_1,5_2"), std::string::npos) << l.provenance.source;
  ASSERT_EQ(l.entries.size(), 2u);
  for (const LedgerEntry& e : l.entries) {
    const KnotEntry k = d.read(e.name);
    std::vector<int> rank;
    const std::vector<StateCluster> clusters = clusters_at_cut(k, 0.05, &rank);
    EXPECT_EQ(e.state, rank);
    EXPECT_TRUE(same_table(e.attributes, k.attributes));
    EXPECT_EQ(e.runs.size(), k.runs.size());
    ASSERT_EQ(e.states.size(), clusters.size());
    for (size_t s = 0; s < clusters.size(); ++s) {
      EXPECT_EQ(e.states[s].members, static_cast<int>(clusters[s].members.size()));
      EXPECT_EQ(e.states[s].representative, clusters[s].representative);
      const Points& x = k.equilibria[static_cast<size_t>(clusters[s].representative)];
      if (s >= 2) {
        EXPECT_EQ(e.states[s].curve.rows(), 0);
      } else {
        ASSERT_EQ(e.states[s].curve.rows(), x.rows());
        EXPECT_LE((e.states[s].curve - x).cwiseAbs().maxCoeff(), 0.5 * l.provenance.curve_quantum * (1 + 1e-9));
      }
      const int sample = e.representative_sample(static_cast<int>(s));
      for (const RunRecord& run : k.runs) {
        if (run.sample == sample) {
          EXPECT_EQ(run.equilibrium, clusters[s].representative);
        }
      }
    }
  }
  // describe reads it; merge of ledgers works; a ledger from the data set alone has no wall time
  const auto desc = run("describe " + ledger + " --states");
  ASSERT_EQ(desc.status, 0) << desc.err;
  EXPECT_NE(desc.out.find("5_2: 6 samples"), std::string::npos) << desc.out;
  // query reads the ledger as it reads the data set: the same rows, in the same order
  for (const std::string q : {" --sort energy:desc --limit 5", " --where 'threedim<0.2' --knot 5_2 --sort writhe"}) {
    const auto a = run("query " + data + q + " --json"), b = run("query " + ledger + q + " --json");
    ASSERT_EQ(a.status, 0) << a.err;
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(b.out, a.out) << q;
  }
  EXPECT_EQ(run("query " + dir + " --limit 1").status, 0);  // the folder of ledgers
  const auto missing = run("query " + ledger + " --knot 4_1");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("knot '4_1' is not in the ledger"), std::string::npos) << missing.err;
  const auto again = run("ledger " + data + " -o " + dir + "/again.ledger.h5");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_FALSE(read_ledger(dir + "/again.ledger.h5").provenance.wall_seconds.has_value());
  const auto merged = run("merge " + ledger + " " + dir + "/again.ledger.h5 -o " + dir + "/m.ledger.h5");
  EXPECT_EQ(merged.status, 2) << merged.err;  // the same knots twice
  EXPECT_NE(merged.err.find("in two of the ledgers"), std::string::npos) << merged.err;
  // a damaged ledger: one line naming it, exit status 2
  std::string bytes = fixtures::read_bytes(ledger);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 1);
  std::ofstream(dir + "/bad.ledger.h5", std::ios::binary) << bytes;
  const auto bad = run("describe " + dir + "/bad.ledger.h5");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_NE(bad.err.find("bad.ledger.h5' is damaged"), std::string::npos) << bad.err;
}

// Rerunning a knot from its ledger entry (the ledger's parameters, the
// knot's name, its samples) gives the same distinct states: the same number,
// member counts and representatives' energies (bit for bit: relaxations are
// deterministic), and curves within half the ledger's quantum.
TEST(Ledger, RerunFromTheLedgerReproducesTheStates) {
  const std::string dir = temp_dir("ledger_rerun");
  const std::string data = dir + "/d.h5", ledger = dir + "/d.ledger.h5";
  ASSERT_EQ(run("dataset --names 4_1" + kRun + "-o " + data + " --ledger " + ledger).status, 0);
  const Ledger l = read_ledger(ledger);
  const LedgerEntry& e = l.entries.at(0);
  // the rerun: a fresh data set of the same knot with the options the ledger records
  const std::string again = dir + "/again.h5";
  const auto r = run("explore " + e.name + " --samples " + std::to_string(e.samples_used) +
                     " -n " + std::to_string(*l.parameters.vertices) + " --seed " + std::to_string(*l.parameters.seed) +
                     " --no-stiffness --novelty-distance " + std::to_string(l.provenance.cut) + " --quiet -o " + again);
  ASSERT_EQ(r.status, 0) << r.err;
  const DatasetReader d(again);
  EXPECT_EQ(d.metadata().difference(l.parameters), "");
  const LedgerEntry f = ledger_entry(d.read(e.name), l.provenance.cut, l.provenance.curves_per_knot);
  ASSERT_EQ(f.states.size(), e.states.size());
  const int energy = e.attribute_column("energy");
  for (size_t s = 0; s < e.states.size(); ++s) {
    EXPECT_EQ(f.states[s].members, e.states[s].members);
    EXPECT_EQ(f.attributes(f.states[s].representative, energy), e.attributes(e.states[s].representative, energy));
    EXPECT_LE((f.states[s].curve - e.states[s].curve).cwiseAbs().maxCoeff(), 0.5 * l.provenance.curve_quantum * (1 + 1e-9));
  }
}

TEST(Ledger, SamplingBudgetIsTheFixedCountOrTheAdaptiveMaximum) {
  DatasetMetadata m;
  EXPECT_EQ(sampling_budget(m), 0);  // not recorded
  m.sampling = "fixed:50";
  EXPECT_EQ(sampling_budget(m), 50);
  m.sampling = "fixed:12,burn-in=100";
  EXPECT_EQ(sampling_budget(m), 12);
  m.sampling = "adaptive:50+10,max=500,S>0.1,delta=0.05";
  EXPECT_EQ(sampling_budget(m), 500);
  m.sampling = "adaptive:50+10,max=80,unseen<0.1,low=1.1,delta=0.1,burn-in=5";
  EXPECT_EQ(sampling_budget(m), 80);
  m.sampling = "mystery:3";
  EXPECT_THROW(sampling_budget(m), InputError);
}

// A knot of an adaptive scale sampled again at the full budget
// (scripts/ledger_far_end.sh): read_results_knots puts that entry in place
// of the adaptive one, whose runs are its first ones (the same walk and the
// same relaxations: equal attributes), and refuses full-budget ledgers of
// other parameters, of another sampling or of a knot the scale lacks.
TEST(Ledger, FullBudgetEntriesReplaceTheAdaptiveOnes) {
  const std::string dir = temp_dir("ledger_full_budget");
  std::filesystem::create_directories(dir + "/ledgers");
  std::filesystem::create_directories(dir + "/full_budget");
  const std::string common = " -n 100 --no-stiffness --novelty-distance 0.05 --quiet --jobs 2 ";
  ASSERT_EQ(run("dataset --names 3_1,5_2 --adaptive --max-samples 70" + common + "-o " + dir + "/a.h5 --ledger " +
                dir + "/ledgers/a.ledger.h5").status, 0);
  const std::string full = dir + "/full_budget/piece-01.ledger.h5";
  ASSERT_EQ(run("dataset --names 3_1 --samples 70" + common + "-o " + dir + "/f.h5 --ledger " + full).status, 0);

  EXPECT_TRUE(read_results_knots(dir, 0.05, false).replaced.empty());
  const ResultsKnots r = read_results_knots(dir, 0.05, true);
  EXPECT_EQ(r.budget, 70);
  EXPECT_EQ(r.source, dir + "/ledgers");
  ASSERT_EQ(r.entries.size(), 2u);
  ASSERT_EQ(r.replaced.size(), 1u);
  const LedgerEntry &own = r.replaced[0], &at_budget = r.entries[0];
  EXPECT_EQ(own.name, "3_1");
  EXPECT_EQ(at_budget.name, "3_1");
  EXPECT_EQ(at_budget.runs.size(), 70u);
  ASSERT_LE(own.runs.size(), at_budget.runs.size());
  for (size_t i = 0; i < own.runs.size(); ++i) {
    ASSERT_EQ(own.runs[i].sample, at_budget.runs[i].sample);
    const int a = own.runs[i].equilibrium, b = at_budget.runs[i].equilibrium;
    ASSERT_EQ(a < 0, b < 0) << "sample " << i;
    if (a >= 0) {
      EXPECT_TRUE(same_table(own.attributes.row(a), at_budget.attributes.row(b))) << "sample " << i;
    }
  }
  EXPECT_EQ(r.entries[1].name, "5_2");
  EXPECT_LT(r.entries[1].runs.size(), 71u);

  const Ledger l = read_ledger(full);
  const std::string& other = full;  // in its place: two full-budget ledgers must merge first
  Ledger radius = l;
  radius.parameters.radius = 0.3;
  write_ledger(other, radius);
  fixtures::expect_input_error([&] { read_results_knots(dir, 0.05, true); }, "differ from the scale's");
  Ledger adaptive = l;
  adaptive.parameters.sampling = "adaptive:50+10,max=70,S>0.1,delta=0.05";
  write_ledger(other, adaptive);
  fixtures::expect_input_error([&] { read_results_knots(dir, 0.05, true); }, "not fixed:70");
  Ledger stranger = l;
  stranger.entries[0].name = "4_1";
  write_ledger(other, stranger);
  fixtures::expect_input_error([&] { read_results_knots(dir, 0.05, true); }, "knot 4_1 of the full-budget ledgers");
}
