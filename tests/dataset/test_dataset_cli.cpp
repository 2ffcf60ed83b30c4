// The data-set commands end to end: explore/dataset/merge/cluster/query/export,
// crash safety (kill and resume), shards, and bad input.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <fstream>
#include <sstream>
#include <thread>

#include "cli_runner.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "metadata_testing.hpp"
#include "testing.hpp"
#include "journal.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;
namespace fs = std::filesystem;

namespace {

const std::string kSmall = " -n 100 --no-stiffness --quiet ";

/// Equilibria of every knot in the file (the deterministic part of a data set).
std::map<std::string, std::vector<ek::Points>> equilibria(const std::string& path) {
  ek::DatasetReader r(path);
  std::map<std::string, std::vector<ek::Points>> out;
  for (const auto& name : r.knot_names()) out[name] = r.read(name).equilibria;
  return out;
}

void expect_bad_input(const std::string& args, const std::string& needle) {
  const auto r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

}  // namespace

// `--continuation` reaches every relaxation of a data set and is recorded in
// it with the iteration cap; the relaxations still end converged-stable.
TEST(DatasetCli, ContinuationIsRecorded) {
  const std::string dir = temp_dir("ds_cont");
  const std::string file = dir + "/c.h5";
  const auto r = run("explore 3_1 --samples 2 --continuation 1e-3 --max-iter 4000" + kSmall + "-o " + file);
  ASSERT_EQ(r.status, 0) << r.err;
  ek::DatasetReader d(file);
  EXPECT_EQ(d.metadata().contact_continuation, std::vector<double>{1e-3});
  EXPECT_EQ(d.metadata().max_iterations, 4000);
  const ek::KnotEntry k = d.read("3_1");
  ASSERT_EQ(k.runs.size(), 2u);
  for (const auto& run : k.runs) EXPECT_EQ(run.status, ek::RunStatus::ConvergedStable) << run.message;
  fs::remove_all(dir);
}

// A small end-to-end run (3_1, 4_1, 5_1, 5_2; 20 samples each; 2 jobs)
// gives a valid data set that the query and cluster commands read.
TEST(DatasetCli, EndToEndQueryClusterExport) {
  const std::string dir = temp_dir("ds_e2e");
  const std::string file = dir + "/e2e.h5";
  const auto r = run("dataset --names 3_1,4_1,5_1,5_2 --samples 20 --jobs 2" + kSmall + "-o " + file + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j["knots"], 4);
  EXPECT_EQ(j["runs"], 80);
  EXPECT_GT(j["equilibria"].get<int>(), 60);  // most runs converge (measured: 80 of 80)
  ek::DatasetReader reader(file);
  EXPECT_EQ(reader.knot_names(), (std::vector<std::string>{"3_1", "4_1", "5_1", "5_2"}));
  EXPECT_EQ(reader.metadata().vertices, 100);
  EXPECT_EQ(reader.metadata().sampling, "fixed:20");
  for (const auto& name : reader.knot_names()) EXPECT_EQ(reader.read(name).runs.size(), 20u) << name;
  // query: sorted, filtered, limited
  const auto q = run("query " + file + " --sort energy --where 'total_curvature<20' --limit 5 --json");
  ASSERT_EQ(q.status, 0) << q.err;
  const auto rows = q.json()["rows"];
  ASSERT_GT(rows.size(), 0u);
  EXPECT_LE(rows.size(), 5u);
  for (size_t i = 1; i < rows.size(); ++i) EXPECT_LE(rows[i - 1]["energy"], rows[i]["energy"]);
  for (const auto& row : rows) EXPECT_LT(row["total_curvature"].get<double>(), 20.0);
  // cluster: every equilibrium in exactly one cluster
  const auto c = run("cluster " + file + " 4_1 --cut 0.1 --json");
  ASSERT_EQ(c.status, 0) << c.err;
  size_t members = 0;
  const auto clusters = c.json()["clusters"];  // keep the parsed object alive while iterating
  for (const auto& cl : clusters) members += cl["members"].size();
  EXPECT_EQ(members, reader.read("4_1").equilibria.size());
  // and what they leave unseen: the states found are the clusters, the samples the equilibria
  const auto unseen = c.json()["unseen"];
  EXPECT_EQ(unseen["found"].get<size_t>(), clusters.size());
  EXPECT_EQ(unseen["samples"].get<size_t>(), members);
  EXPECT_GE(unseen["estimated"].get<double>(), unseen["found"].get<double>());
  EXPECT_LE(unseen["lower"].get<double>(), unseen["upper"].get<double>());
  EXPECT_LE(c.json()["unseen_low_energy"]["found"].get<size_t>(), clusters.size());
  // export
  const auto x = run("export " + file + " 4_1 0 -o " + dir + "/eq.obj");
  ASSERT_EQ(x.status, 0) << x.err;
  const auto inv = run("invariants " + dir + "/eq.obj --json");
  EXPECT_EQ(inv.json()["alexander"], nlohmann::json::parse("[-1,3,-1]"));
  expect_bad_input("export " + file + " 4_1 999 -o " + dir + "/eq2.obj", "out of range");
  expect_bad_input("cluster " + file + " 6_1 --cut 0.1", "has no knot '6_1'");
  expect_bad_input("query " + file + " --sort colour", "unknown attribute 'colour'");
  expect_bad_input("query " + file + " --where 'energy~1'", "expected ATTR<VALUE");
  fs::remove_all(dir);
}

// Kill a run midway (SIGKILL), re-run, and get every equilibrium of
// an uninterrupted run with the same seeds; the output is never unreadable.
TEST(DatasetCli, KilledRunResumesWithoutLoss) {
  const std::string dir = temp_dir("ds_resume");
  const std::string args = "dataset --names 3_1,4_1 --samples 6 --jobs 1" + kSmall;
  ASSERT_EQ(run(args + "-o " + dir + "/full.h5").status, 0);
  const std::string out = dir + "/killed.h5";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // `exec` so that the pid is the knots process itself
    execl("/bin/sh", "sh", "-c",
          ("exec " + std::string(EK_KNOTS_BIN) + " " + args + "-o " + out + " >/dev/null 2>&1").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // wait until the first knot's journal holds a few runs, then kill
  const std::string journal = out + ".work/3_1.journal";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  bool killed = false;
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(journal) && fs::file_size(journal) > 10000) {  // header + at least one run with a curve
      kill(pid, SIGKILL);
      killed = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(killed) << "the run finished before it could be killed";
  EXPECT_FALSE(fs::exists(out));  // nothing committed yet, and certainly nothing half-written
  // the interrupted run is no data set to merge
  expect_bad_input("merge " + out + " -o " + dir + "/merged.h5", "'" + out + "' is unfinished");
  EXPECT_FALSE(fs::exists(dir + "/merged.h5"));
  // re-run the same command: resumes from the journal
  const auto resumed = run(args + "-o " + out + " --json");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_LT(resumed.json()["runs"].get<int>(), 12);  // the journaled runs were not repeated
  EXPECT_EQ(equilibria(out), equilibria(dir + "/full.h5"));
  EXPECT_FALSE(fs::exists(out + ".work"));
  fs::remove_all(dir);
}

namespace {

/// Runs of `knot` already finished in the work folder: all of them when its
/// part file is there (a finished knot), else the journal's intact records.
int finished_runs(const std::string& work, const std::string& knot, int samples) {
  const std::string part = work + "/" + knot + ".h5";
  if (fs::exists(part)) {
    ek::DatasetReader r(part);  // never half-written: it is renamed into place
    EXPECT_EQ(static_cast<int>(r.read(knot).runs.size()), samples);
    return samples;
  }
  const std::string data = ek::fixtures::read_bytes(work + "/" + knot + ".journal");
  const size_t line1 = data.find('\n'), line2 = line1 == std::string::npos ? line1 : data.find('\n', line1 + 1);
  if (line2 == std::string::npos) return 0;  // no journal, or killed while writing its header
  return static_cast<int>(ek::parse_journal(data, data.substr(0, line2 + 1), knot).runs.size());
}

/// Starts `knots ARGS` and kills it with SIGKILL after `seconds` (if it is
/// still running then). Returns true when it was killed.
bool run_and_kill(const std::string& args, double seconds) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + std::string(EK_KNOTS_BIN) + " " + args + " >/dev/null 2>&1").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status);
}

}  // namespace

// A data-set run killed (SIGKILL) at 20 random moments between its start and
// its end (trials whose run ends before the moment are repeated): after each
// kill the output is absent or complete, every part file reads, and resuming
// performs exactly the runs that had not finished (every finished run is
// kept, none repeated) and gives the equilibria of an uninterrupted run.
TEST(DatasetCli, KilledAtRandomMomentsKeepsEveryFinishedRun) {
  const std::string dir = temp_dir("ds_kills");
  const int samples = 6;
  const std::string args = "dataset --names 3_1,4_1 --samples " + std::to_string(samples) + " --jobs 1" + kSmall;
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(run(args + "-o " + dir + "/full.h5").status, 0);
  const double full_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto full = equilibria(dir + "/full.h5");
  std::mt19937_64 rng(8);
  int trials = 0, killed = 0, with_output = 0, finished_total = 0, resumed_total = 0;
  for (int trial = 0; killed < 20 && trial < 60; ++trial, ++trials) {
    const std::string out = dir + "/killed" + std::to_string(trial) + ".h5", work = out + ".work";
    const double moment = std::uniform_real_distribution<double>(0.0, full_seconds)(rng);
    if (!run_and_kill(args + "-o " + out, moment)) continue;  // finished before the moment
    ++killed;
    int finished = 2 * samples;
    if (fs::exists(out)) {
      ++with_output;
      EXPECT_EQ(equilibria(out), full) << "killed after " << moment << " s";
    } else {
      finished = finished_runs(work, "3_1", samples) + finished_runs(work, "4_1", samples);
    }
    finished_total += finished;
    const auto resumed = run(args + "-o " + out + " --json");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    resumed_total += resumed.json()["runs"].get<int>();
    EXPECT_EQ(resumed.json()["runs"].get<int>(), 2 * samples - finished) << "killed after " << moment << " s";
    EXPECT_EQ(equilibria(out), full) << "killed after " << moment << " s";
    EXPECT_FALSE(fs::exists(work));
  }
  std::printf("%d trials, %d kills (a run takes %.1f s): %d runs of %d finished before them and kept, %d runs "
              "performed by the resumed runs, %d kills after the output was written\n",
              trials, killed, full_seconds, finished_total, 2 * samples * killed, resumed_total, with_output);
  EXPECT_EQ(killed, 20);
  fs::remove_all(dir);
}

// A merge of two shards equals the unsharded run; overlapping, missing,
// repeated and unfinished shards are refused.
TEST(DatasetCli, MergedShardsEqualTheUnshardedRun) {
  const std::string dir = temp_dir("ds_shards");
  const std::string args = "dataset --names 3_1,4_1,5_2 --samples 4 --jobs 2" + kSmall;
  ASSERT_EQ(run(args + "-o " + dir + "/all.h5").status, 0);
  ASSERT_EQ(run(args + "--shard 1/2 -o " + dir + "/s1.h5").status, 0);
  ASSERT_EQ(run(args + "--shard 2/2 -o " + dir + "/s2.h5").status, 0);
  EXPECT_EQ(ek::DatasetReader(dir + "/s1.h5").knot_names(), (std::vector<std::string>{"3_1", "5_2"}));
  EXPECT_EQ(ek::DatasetReader(dir + "/s2.h5").knot_names(), (std::vector<std::string>{"4_1"}));
  const auto m = run("merge " + dir + "/s2.h5 " + dir + "/s1.h5 -o " + dir + "/merged.h5");
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(equilibria(dir + "/merged.h5"), equilibria(dir + "/all.h5"));
  ek::DatasetReader a(dir + "/all.h5"), b(dir + "/merged.h5");
  EXPECT_EQ(a.knot_names(), b.knot_names());
  for (const auto& name : a.knot_names()) {
    const auto ea = a.read(name), eb = b.read(name);
    EXPECT_EQ(ea.similarity, eb.similarity) << name;
    EXPECT_EQ(ea.linkage, eb.linkage) << name;
    const int t = ea.attribute_column("sample");
    EXPECT_EQ(ea.attributes.col(t), eb.attributes.col(t)) << name;
  }
  // merging a knot twice is an error and writes nothing
  expect_bad_input("merge " + dir + "/s1.h5 " + dir + "/all.h5 -o " + dir + "/bad.h5", "is in both");
  // a missing shard, a shard given twice, an unfinished shard (its work
  // folder exists: its run is still going or was interrupted)
  expect_bad_input("merge " + dir + "/s1.h5 " + dir + "/s3.h5 -o " + dir + "/bad.h5",
                   "'" + dir + "/s3.h5' does not exist");
  expect_bad_input("merge " + dir + "/s1.h5 " + dir + "/s2.h5 " + dir + "/s1.h5 -o " + dir + "/bad.h5",
                   "'" + dir + "/s1.h5' is given twice");
  fs::create_directory(dir + "/s2.h5.work");
  expect_bad_input("merge " + dir + "/s1.h5 " + dir + "/s2.h5 -o " + dir + "/bad.h5",
                   "'" + dir + "/s2.h5' is unfinished");
  EXPECT_FALSE(fs::exists(dir + "/bad.h5"));
  fs::remove_all(dir);
}

// An unknown knot, an unwritable output, an existing data set with a
// different material or n: a clear error, nothing overwritten.
TEST(DatasetCli, BadInputOverwritesNothing) {
  const std::string dir = temp_dir("ds_bad");
  const std::string file = dir + "/d.h5";
  ASSERT_EQ(run("explore 3_1 --samples 2" + kSmall + "-o " + file).status, 0);
  const std::string before = ek::fixtures::read_bytes(file);
  expect_bad_input("explore 13_7 --samples 2" + kSmall + "-o " + file, "unknown knot '13_7'");
  expect_bad_input("explore 4_1 --samples 2 -n 100 --radius 0.1 --quiet -o " + file, "radius 0.2 vs 0.1");
  expect_bad_input("explore 4_1 --samples 2 -n 120 --no-stiffness --quiet -o " + file, "vertices 100 vs 120");
  expect_bad_input("explore 4_1 --samples 2" + kSmall + "-o /nonexistent-folder/d.h5", "does not exist");
  expect_bad_input("explore 4_1 --samples 2 --adaptive" + kSmall + "-o " + file, "exclude each other");
  expect_bad_input("dataset --max-crossings 2" + kSmall + "-o " + file, "between 3 and 12");
  expect_bad_input("explore 4_1 --samples 2 --burn-in -1" + kSmall + "-o " + file,
                   "--burn-in must be between 0 and 100000");
  expect_bad_input("explore 4_1 --samples 2 --burn-in 3" + kSmall + "-o " + file, "burn_in 0 vs 3");
  expect_bad_input("dataset --names 3_1 --shard 3/2" + kSmall + "-o " + file, "1 <= I <= N");
  expect_bad_input("explore 4_1 --samples 2 --continuation 1e-3" + kSmall + "-o " + file,
                   "contact_continuation off vs 0.001");
  expect_bad_input("explore 4_1 --samples 2 --max-iter 300" + kSmall + "-o " + file, "max_iterations 5000 vs 300");
  expect_bad_input("explore 4_1 --samples 2 --continuation 1" + kSmall + "-o " + file,
                   "contact_continuation factors must be in (0, 1)");
  expect_bad_input("explore 4_1 --samples 2 --continuation 1e-3," + kSmall + "-o " + file,
                   "--continuation: '' is not a number");
  EXPECT_EQ(ek::fixtures::read_bytes(file), before);
  // a second explore of the same knot is a no-op; another knot extends the file
  const auto again = run("explore 3_1 --samples 2" + kSmall + "-o " + file + " --json");
  ASSERT_EQ(again.status, 0);
  EXPECT_EQ(again.json()["skipped"], true);
  ASSERT_EQ(run("explore 4_1 --samples 2" + kSmall + "-o " + file).status, 0);
  EXPECT_EQ(ek::DatasetReader(file).knot_names(), (std::vector<std::string>{"3_1", "4_1"}));
  fs::remove_all(dir);
}

// Each parameter changed in turn: `knots explore` into an existing data set
// and `knots merge` stop with one line naming the parameter (exit 2) and
// leave every file as it was; `knots describe` lists the parameters.
TEST(DatasetCli, EveryParameterMustMatchToExtendOrMerge) {
  const std::string dir = temp_dir("ds_params");
  const std::string file = dir + "/d.h5";
  const std::string same = " --samples 1 -n 100 --quiet -o " + file;
  ASSERT_EQ(run("explore 3_1 --no-stiffness" + same).status, 0);
  const std::string before = ek::fixtures::read_bytes(file);
  const std::vector<std::pair<std::string, std::string>> options = {
      {"--young 2500", "young"},       {"--poisson 0.35", "poisson"},        {"--radius 0.15", "radius"},
      {"--tol 1e-7", "tolerance"},     {"--max-iter 300", "max_iterations"}, {"--burn-in 2", "burn_in"},
      {"--seed 2", "seed"},            {"--continuation 1e-3", "contact_continuation"}};
  for (const auto& [option, field] : options)
    expect_bad_input("explore 4_1 --no-stiffness " + option + same, "different parameters (" + field + " ");
  expect_bad_input("explore 4_1" + same, "different parameters (compute_stiffness 0 vs 1)");
  expect_bad_input("explore 4_1 --no-stiffness --samples 2 -n 100 --quiet -o " + file, "(sampling fixed:1 vs fixed:2)");
  expect_bad_input("explore 4_1 --no-stiffness --adaptive -n 100 --quiet -o " + file, "(sampling fixed:1 vs adaptive:");
  expect_bad_input("explore 4_1 --no-stiffness --samples 1 -n 120 --quiet -o " + file, "(vertices 100 vs 120)");
  EXPECT_EQ(ek::fixtures::read_bytes(file), before);
  EXPECT_FALSE(fs::exists(file + ".work"));
  // merge: a second data set (knot 4_1) with one field of the table changed
  const ek::KnotEntry knot = ek::DatasetReader(file).read("3_1");
  const ek::DatasetMetadata meta = ek::DatasetReader(file).metadata();
  for (const auto& f : ek::metadata_fields()) {
    if (f.match == ek::FieldMatch::Provenance) continue;
    ek::DatasetMetadata other = meta;
    f.set(other, ek::testing_metadata::changed(f.get(meta)));
    ek::KnotEntry renamed = knot;
    renamed.name = "4_1";
    {
      ek::DatasetWriter w(dir + "/other.h5", other);
      w.add(renamed);
      w.commit();
    }
    const std::string other_before = ek::fixtures::read_bytes(dir + "/other.h5");
    expect_bad_input("merge " + file + " " + dir + "/other.h5 -o " + dir + "/merged.h5", "(" + f.name + " ");
    EXPECT_FALSE(fs::exists(dir + "/merged.h5")) << f.name;
    EXPECT_EQ(ek::fixtures::read_bytes(dir + "/other.h5"), other_before) << f.name;
  }
  EXPECT_EQ(ek::fixtures::read_bytes(file), before);
  // describe: every field of the table, with the values of the file
  const auto d = run("describe " + file + " --json");
  ASSERT_EQ(d.status, 0) << d.err;
  const auto params = d.json()["parameters"];
  ASSERT_EQ(params.size(), ek::metadata_fields().size());
  EXPECT_EQ(params["vertices"], 100);
  EXPECT_EQ(params["compute_stiffness"], 0);
  EXPECT_EQ(params["sampling"], "fixed:1");
  EXPECT_EQ(params["grow_fugacity"], 0.4);
  EXPECT_EQ(params["contact_continuation"], nlohmann::json::array());
  EXPECT_EQ(d.json()["knots"], nlohmann::json::parse("[\"3_1\"]"));
  const auto t = run("describe " + file);
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("radius                0.2 [length]"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("knots (1): 3_1"), std::string::npos) << t.out;
  expect_bad_input("describe " + dir + "/none.h5",
                   "cannot open data set '" + dir + "/none.h5': No such file or directory");
  fs::remove_all(dir);
}
