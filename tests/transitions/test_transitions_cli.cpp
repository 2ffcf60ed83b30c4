// `knots transition`, `knots transitions`, `knots path`: the command-line
// contract (docs/cli.md): one-line errors with exit status 2 for bad input,
// an existing output kept without --overwrite, the double-ended search
// joining two relaxed samples of 4_1 (its folder agreeing with the JSON),
// and the graph of a small data set with a path through it or the statement
// that none joins the states; a killed `knots transitions` resumes from its
// checkpoint to the uninterrupted run's graph.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "cli_runner.hpp"
#include "ek/transitions/transitions_file.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;

namespace fs = std::filesystem;

namespace {

/// The small data sets of these tests: eight samples of 4_1 at n = 120,
/// relaxed by the one-level method (the default before two coarse levels),
/// with which these tests were designed.
const std::string kSmallDataSetMethod = " --method one-level";

/// Samples `first` and `first + 1` of 4_1 (BFACF, 120 unit edges, seed 1)
/// relaxed by the eigen-projected method (test_double_ended.cpp says why).
std::pair<std::string, std::string> states_41(const std::string& dir) {
  auto r = run("sample 4_1 -n 120 --count 3 -o " + dir + "/lattice");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* k : {"1", "2"}) {
    // the eigen-projected method: the inputs of test_double_ended.cpp (see there)
    r = run("relax " + dir + "/lattice/4_1-000" + k + ".obj --method eigen-projected -o " + dir + "/state" + k +
            ".obj");
    EXPECT_EQ(r.status, 0) << r.err;
  }
  return {dir + "/state1.obj", dir + "/state2.obj"};
}

}  // namespace

TEST(TransitionCli, BadInputIsOneLineAndExitTwo) {
  const std::string dir = temp_dir("transition_cli_bad");
  const auto [a, b] = states_41(dir);
  ASSERT_EQ(run("sample 4_1 -n 100 -o " + dir + "/small").status, 0);
  ASSERT_EQ(run("relax " + dir + "/small/4_1-0000.obj -o " + dir + "/small.obj").status, 0);
  fs::create_directories(dir + "/exists");
  for (const std::string& args :
       {"transition " + a + " " + dir + "/missing.obj -o " + dir + "/o1",  // no such file
        "transition " + a + " " + dir + "/small.obj -o " + dir + "/o2",    // vertex counts differ
        "transition " + a + " " + b + " --stages 0 -o " + dir + "/o3",
        "transition " + a + " " + b + " -o " + dir + "/exists",  // exists, no --overwrite
        "transition " + a + " " + b, "transitions " + dir + "/missing.h5 4_1 -o " + dir + "/t.h5",
        "path " + dir + "/missing.h5 4_1 0 1 -o " + dir + "/p.obj"}) {
    const auto r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(ek::clitest::newline_count(r.err), 1u) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
  for (const char* sub : {"o1", "o2", "o3", "t.h5", "p.obj"}) EXPECT_FALSE(fs::exists(dir + "/" + sub)) << sub;
  EXPECT_TRUE(fs::is_empty(dir + "/exists"));
}

// Two relaxed samples that one shallow saddle joins (test_double_ended.cpp):
// verified, and the folder holds A, the aligned B, the chain, the saddle and
// its path; the barriers agree with the minima's energies.
TEST(TransitionCli, JoinsTwoRelaxedSamplesOf41) {
  const std::string dir = temp_dir("transition_cli_ok");
  const auto [a, b] = states_41(dir);
  const std::string out = dir + "/out";
  const auto r = run("transition " + a + " " + b + " -o " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("status"), "verified");
  EXPECT_TRUE(j.at("reached").get<bool>());
  EXPECT_TRUE(j.at("alexander_preserved").get<bool>());
  const auto& s = j.at("saddle");
  EXPECT_EQ(s.at("index"), 1);
  ASSERT_EQ(s.at("minima").size(), 2u);
  EXPECT_NEAR(s.at("barrier_forward").get<double>(),
              s.at("energy").get<double>() - s.at("minima")[0].at("energy").get<double>(), 1e-15);
  EXPECT_GT(s.at("barrier_forward").get<double>(), 0.0);
  EXPECT_GT(s.at("barrier_backward").get<double>(), 0.0);
  for (const char* f : {"summary.json", "a.obj", "b.obj", "chain.obj", "saddle.obj", "path.obj"})
    EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
  const auto again = run("transition " + a + " " + b + " -o " + out);
  EXPECT_EQ(again.status, 2);  // the folder exists
}

// The graph of a small data set (4_1, 8 samples of 120 vertices): the JSON
// keys of the contract, and `knots path` between its two lowest states
// either a chain of edges (exit 0, its file written) or "no chain" (exit 1,
// nothing written), consistently with the graph's edges.
TEST(TransitionsCli, GraphAndPathOfASmallDataSet) {
  const std::string dir = temp_dir("transitions_cli");
  const std::string ds = dir + "/ds.h5", tr = dir + "/tr.h5";
  auto r = run("explore 4_1 --samples 8 -n 120 -o " + ds + kSmallDataSetMethod + " --jobs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  r = run("transitions " + ds + " 4_1 --modes 1 --states 2 --max-pairs 1 -o " + tr + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto g = r.json();
  for (const char* key : {"saddles", "states", "edges", "pairs", "seconds"}) EXPECT_TRUE(g.contains(key)) << key;
  for (const auto& s : g.at("saddles"))
    for (const char* key :
         {"energy", "barrier_forward", "barrier_backward", "negative_eigenvalue", "index", "gradient_norm", "minima"})
      EXPECT_TRUE(s.contains(key)) << key;
  ASSERT_GE(g.at("states").size(), 2u);
  EXPECT_LE(g.at("pairs").size(), 1u);
  EXPECT_EQ(run("transitions " + ds + " 4_1 -o " + tr).status, 2);  // exists, no --overwrite
  bool joined = false;
  for (const auto& e : g.at("edges"))
    joined = joined || (std::min(e.at("from").get<int>(), e.at("to").get<int>()) == 0 &&
                        std::max(e.at("from").get<int>(), e.at("to").get<int>()) == 1);
  const auto p = run("path " + tr + " 4_1 0 1 -o " + dir + "/p.obj --json");
  const auto pj = p.json();
  EXPECT_EQ(pj.at("connected").get<bool>(), p.status == 0);
  EXPECT_EQ(fs::exists(dir + "/p.obj"), p.status == 0);
  if (joined) {
    EXPECT_EQ(p.status, 0);
  }
  EXPECT_EQ(run("path " + tr + " 3_1 0 1 -o " + dir + "/q.obj").status, 2);   // another knot
  EXPECT_EQ(run("path " + tr + " 4_1 0 999 -o " + dir + "/q.obj").status, 2);  // no such state
}

namespace {

/// Starts `knots ARGS`, kills it (SIGKILL) once `file` exists; false when the
/// run ended first.
bool kill_when_written(const std::string& args, const std::string& file) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + std::string(EK_KNOTS_BIN) + " " + args + " >/dev/null 2>&1").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  bool killed = false;
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(600);
  while (!killed && std::chrono::steady_clock::now() < deadline && waitpid(pid, &status, WNOHANG) == 0) {
    if (fs::exists(file)) killed = kill(pid, SIGKILL) == 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!killed) kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return killed;
}

/// Equal graphs up to the timings.
void expect_same_graph_but_timings(const ek::TransitionGraph& a, const ek::TransitionGraph& b) {
  ASSERT_EQ(a.states.size(), b.states.size());
  for (size_t k = 0; k < a.states.size(); ++k) {
    EXPECT_EQ(a.states[k].energy, b.states[k].energy) << "state " << k;
    EXPECT_EQ(a.states[k].positions, b.states[k].positions) << "state " << k;
  }
  ASSERT_EQ(a.saddles.size(), b.saddles.size());
  for (size_t k = 0; k < a.saddles.size(); ++k) {
    EXPECT_EQ(a.saddles[k].energy, b.saddles[k].energy) << "saddle " << k;
    EXPECT_EQ(a.saddles[k].positions, b.saddles[k].positions) << "saddle " << k;
    EXPECT_EQ(a.saddles[k].path.size(), b.saddles[k].path.size()) << "saddle " << k;
  }
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (size_t k = 0; k < a.edges.size(); ++k) {
    EXPECT_EQ(a.edges[k].from, b.edges[k].from);
    EXPECT_EQ(a.edges[k].to, b.edges[k].to);
    EXPECT_EQ(a.edges[k].barrier_forward, b.edges[k].barrier_forward);
  }
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  for (size_t k = 0; k < a.pairs.size(); ++k) {
    EXPECT_EQ(a.pairs[k].status, b.pairs[k].status);
    EXPECT_EQ(a.pairs[k].path_barrier, b.pairs[k].path_barrier);
  }
  ASSERT_EQ(a.searches.size(), b.searches.size());
  for (size_t k = 0; k < a.searches.size(); ++k) {
    ASSERT_EQ(a.searches[k].records.size(), b.searches[k].records.size());
    for (size_t j = 0; j < a.searches[k].records.size(); ++j)
      EXPECT_EQ(a.searches[k].records[j].status, b.searches[k].records[j].status);
  }
}

}  // namespace

// Killed after its first unit of work (the checkpoint exists), the command
// run again resumes: its progress starts past the finished units, and the
// graph it writes equals an uninterrupted run's (energies and positions bit
// for bit). A checkpoint of other options is refused, one line, exit 2.
TEST(TransitionsCli, KilledRunResumesFromItsCheckpoint) {
  const std::string dir = temp_dir("transitions_resume");
  const std::string ds = dir + "/ds.h5";
  auto r = run("explore 4_1 --samples 8 -n 120 -o " + ds + kSmallDataSetMethod + " --jobs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string args = "transitions " + ds + " 4_1 --modes 1 --states 3 --max-pairs 2 --stages 20 -o ";
  const auto full = run(args + dir + "/full.h5 --quiet");
  ASSERT_EQ(full.status, 0) << full.err;
  EXPECT_FALSE(fs::exists(dir + "/full.h5.work"));
  const std::string out = dir + "/killed.h5", checkpoint = out + ".work/checkpoint.h5";
  ASSERT_TRUE(kill_when_written(args + out, checkpoint)) << "the run ended before its first checkpoint";
  EXPECT_FALSE(fs::exists(out));
  const auto other = run("transitions " + ds + " 4_1 --modes 2 --states 3 -o " + out);
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.err.find("checkpoint of a run with other options"), std::string::npos) << other.err;
  EXPECT_EQ(std::count(other.err.begin(), other.err.end(), '\n'), 1) << other.err;
  EXPECT_TRUE(fs::exists(checkpoint));  // the refused run kept it
  const auto resumed = run(args + out);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  const auto first = resumed.err.find("progress: ");
  ASSERT_NE(first, std::string::npos) << resumed.err;
  const auto units = resumed.err.find(" units done", first);
  const auto slash = resumed.err.rfind('/', units), comma = resumed.err.rfind(", ", slash);
  EXPECT_GE(std::stoi(resumed.err.substr(comma + 2, slash - comma - 2)), 1) << resumed.err;  // resumed past unit 1
  EXPECT_FALSE(fs::exists(out + ".work"));
  expect_same_graph_but_timings(ek::read_transitions(out), ek::read_transitions(dir + "/full.h5"));
  fs::remove_all(dir);
}

// `knots connect`: the searches stay within --searches, the grown graph is
// written (the input kept), and when it reports a connection the edges it
// names form a chain of inter-state edges from A to B in the written file;
// `knots path` on that file then finds a chain too. Bad input: one line,
// exit 2, nothing written.
TEST(TransitionsCli, ConnectGrowsTheGraphWithinItsBudget) {
  const std::string dir = temp_dir("transitions_connect");
  const std::string ds = dir + "/ds.h5", tr = dir + "/tr.h5", grown = dir + "/grown.h5";
  auto r = run("explore 4_1 --samples 8 -n 120 -o " + ds + kSmallDataSetMethod + " --jobs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  r = run("transitions " + ds + " 4_1 --modes 1 --states 1 --max-pairs 0 -o " + tr + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const ek::TransitionGraph before = ek::read_transitions(tr);
  ASSERT_GE(before.states.size(), 2u);
  r = run("connect " + tr + " 4_1 0 1 --searches 6 -o " + grown + " --json");
  ASSERT_TRUE(r.status == 0 || r.status == 1) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("connected").get<bool>(), r.status == 0);
  EXPECT_LE(j.at("attempts").get<int>(), 6);
  EXPECT_EQ(j.at("searches").size(), j.at("attempts").get<size_t>());
  const ek::TransitionGraph g = ek::read_transitions(grown);
  EXPECT_EQ(g.pairs.size(), before.pairs.size() + j.at("attempts").get<size_t>());
  EXPECT_GE(g.states.size(), before.states.size());
  EXPECT_EQ(ek::read_transitions(tr).pairs.size(), before.pairs.size());  // the input is unchanged
  if (j.at("connected").get<bool>()) {
    int at = 0;
    for (const auto& k : j.at("edges")) {
      const ek::TransitionEdge& e = g.edges.at(k.get<size_t>());
      ASSERT_TRUE(e.from == at || e.to == at) << "edge " << k << " does not leave state " << at;
      EXPECT_NE(e.from, e.to);
      at = e.from == at ? e.to : e.from;
    }
    EXPECT_EQ(at, 1);
    EXPECT_EQ(run("path " + grown + " 4_1 0 1 -o " + dir + "/p.obj").status, 0);
  }
  for (const std::string& bad : {"connect " + tr + " 4_1 0 0 -o " + dir + "/x.h5",       // the same state
                                "connect " + tr + " 4_1 0 999 -o " + dir + "/x.h5",     // no such state
                                "connect " + tr + " 3_1 0 1 -o " + dir + "/x.h5",       // another knot
                                "connect " + tr + " 4_1 0 1 --searches 0 -o " + dir + "/x.h5",
                                "connect " + tr + " 4_1 0 1 --dataset " + dir + "/none.h5 -o " + dir + "/x.h5",
                                "connect " + tr + " 4_1 0 1 -o " + grown}) {  // exists, no --overwrite
    const auto b = run(bad);
    EXPECT_EQ(b.status, 2) << bad;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << bad << ": " << b.err;
    EXPECT_FALSE(fs::exists(dir + "/x.h5")) << bad;
  }
  fs::remove_all(dir);
}
