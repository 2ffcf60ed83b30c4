// `knots relax`: the command-line contract of the solver (docs/cli.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;

namespace {
std::string trefoil(const std::string& dir) {
  const std::string f = dir + "/coil.obj";
  const auto r = run("embed 3_1 --from braid -n 120 -o " + f);
  EXPECT_EQ(r.status, 0) << r.err;
  return f;
}
}  // namespace

TEST(RelaxCli, RelaxesKeepsTheKnotAndWritesTheEquilibrium) {
  const std::string dir = temp_dir("relax_cli_ok");
  const std::string in = trefoil(dir), out = dir + "/eq.obj";
  for (const char* method : {"default", "exact"}) {
    const auto r = run("relax " + in + " -o " + out + " --method " + std::string(method) + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = r.json();
    EXPECT_EQ(j.at("status"), "converged-stable") << method;
    EXPECT_TRUE(j.at("alexander_preserved").get<bool>()) << method;
    EXPECT_EQ(j.at("alexander"), (std::vector<int>{1, -1, 1})) << method;  // trefoil
    EXPECT_LE(j.at("gradient_norm").get<double>(), 1e-7) << method;
    EXPECT_NEAR(j.at("link").get<double>(), j.at("twist").get<double>() + j.at("writhe").get<double>(), 1e-9);
    std::ifstream f(out);
    EXPECT_TRUE(f.good()) << method;
  }
  // the relaxed curve is an equilibrium: relaxing it again at n takes (almost) no work
  const auto again = run("relax " + out + " --method hybrid --json");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_LE(again.json().at("iterations").get<int>(), 5);
}

// --continuation: the soft solves are reported, the iteration total counts
// every phase, and the result is an equilibrium of the model at ω (the
// final phase's gradient is below the tolerance).
TEST(RelaxCli, ContinuationReportsEveryPhase) {
  const std::string dir = temp_dir("relax_cli_cont");
  const std::string in = trefoil(dir);
  const auto r = run("relax " + in + " --continuation 0.001,0.1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("status"), "converged-stable");
  EXPECT_TRUE(j.at("alexander_preserved").get<bool>());
  ASSERT_EQ(j.at("continuation_reports").size(), 2u);
  int total = j.at("iterations").get<int>();
  for (const auto& c : j.at("continuation_reports")) total += c.at("iterations").get<int>();
  for (const auto& c : j.at("coarse_reports")) total += c.at("iterations").get<int>();  // multilevel: the coarse level
  EXPECT_EQ(j.at("coarse_vertices"), (std::vector<int>{60}));
  EXPECT_EQ(j.at("total_iterations").get<int>(), total);
  EXPECT_GT(total, j.at("iterations").get<int>());  // the soft phases did work
  EXPECT_LE(j.at("gradient_norm").get<double>(), 1e-7);
}

// --trace: one CSV row per Newton iteration of every phase (each phase ends
// with its convergence test), with the energy parts summing to the energy
// and the last row at the reported energy.
TEST(RelaxCli, TraceHasOneRowPerIterationOfEveryPhase) {
  const std::string dir = temp_dir("relax_cli_trace");
  const std::string in = trefoil(dir), trace = dir + "/trace.csv";
  const auto r = run("relax " + in + " --continuation 0.001 --trace " + trace + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("trace"), trace);
  std::ifstream f(trace);
  std::string header, line, last;
  ASSERT_TRUE(std::getline(f, header));
  EXPECT_EQ(header.rfind("phase,phase_name,iteration,kind,energy,energy_stretch,energy_bend,energy_twist,"
                         "energy_contact,gradient_norm,hessian,shift",
                         0),
            0u);
  int rows = 0, finals = 0;
  while (std::getline(f, line)) {
    ++rows;
    if (line.find(",final,") != std::string::npos && line.find(",final,", line.find(',') + 1) != std::string::npos)
      ++finals;
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::atof(cell.c_str()));
    ASSERT_GE(v.size(), 10u);
    EXPECT_NEAR(v[5] + v[6] + v[7] + v[8], v[4], 1e-9 * std::fabs(v[4])) << line;
    last = line;
  }
  const int phases = static_cast<int>(j.at("phases").size());  // coarse: continuation, final; continuation; final
  EXPECT_EQ(phases, 4);
  EXPECT_EQ(rows, j.at("total_iterations").get<int>() + phases);  // + one convergence test per phase
  EXPECT_EQ(last.rfind(std::to_string(phases - 1) + ",final,", 0), 0u) << last;
  std::stringstream ss(last);
  std::string cell;
  for (int k = 0; k < 5; ++k) std::getline(ss, cell, ',');
  EXPECT_NEAR(std::atof(cell.c_str()), j.at("energy").get<double>(), 1e-12);
}

TEST(RelaxCli, BadInputIsOneMessageAndStatusTwo) {
  const std::string dir = temp_dir("relax_cli_bad");
  const std::string in = trefoil(dir);
  const std::vector<std::string> cases = {in + " --method newton", in + " --release", dir + "/missing.obj",
                                          in + " -o /nonexistent-dir/x.obj", in + " --radius -1",
                                          in + " --continuation 2", in + " --continuation 0", in + " --continuation x",
                                          in + " --continuation 0.1,"};
  for (const auto& args : cases) {
    const auto r = run("relax " + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
}

// A link from the command line: the Borromean rings embedded from their
// braid word (σ1σ2⁻¹)³ as three components, relaxed (converged stable,
// every component still an unknot, every linking number still 0, the
// components brought into contact), the relaxed file's invariants the
// same; the knot-only options refused on a link; a knot's word embeds as
// the knot.
TEST(RelaxCli, BorromeanRingsFromTheirBraidWordRelaxAsALink) {
  const std::string dir = temp_dir("relax_link");
  auto e = run("embed --braid 1,-2,1,-2,1,-2 -n 240 -o " + dir + "/b.obj --json");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_EQ(e.json().at("components"), 3);
  EXPECT_EQ(e.json().at("linking_numbers"), nlohmann::json::parse("[[0,0,0],[0,0,0],[0,0,0]]"));
  const auto r = run("relax " + dir + "/b.obj -o " + dir + "/relaxed.obj --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("status"), "converged-stable");
  EXPECT_EQ(j.at("components"), 3);
  EXPECT_EQ(j.at("alexander"), nlohmann::json::parse("[[1],[1],[1]]"));
  EXPECT_TRUE(j.at("alexander_preserved").get<bool>() && j.at("linking_preserved").get<bool>());
  EXPECT_EQ(j.at("conway"), nlohmann::json::parse("[0,0,0,0,1]"));  // not the unlink's 0
  EXPECT_TRUE(j.at("conway_preserved").get<bool>());
  EXPECT_LT(j.at("min_distance").get<double>(), 0.4);  // d̂: the rings press on each other
  EXPECT_EQ(j.at("output"), dir + "/relaxed.obj");
  const auto inv = run("invariants " + dir + "/relaxed.obj --json");
  ASSERT_EQ(inv.status, 0) << inv.err;
  EXPECT_EQ(inv.json().at("linking_numbers"), nlohmann::json::parse("[[0,0,0],[0,0,0],[0,0,0]]"));
  EXPECT_EQ(inv.json().at("components"), 3);
  EXPECT_EQ(inv.json().at("conway"), nlohmann::json::parse("[0,0,0,0,1]"));
  EXPECT_EQ(inv.json().at("milnor_triple"), 1);  // |μ̄(123)|: the Borromean rings
  const auto bad = run("relax " + dir + "/b.obj --planar 1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("apply to a knot, not to a link of 3 components"), std::string::npos) << bad.err;
  const auto trefoil = run("embed --braid 1,1,1 -o " + dir + "/t.obj --json");
  ASSERT_EQ(trefoil.status, 0) << trefoil.err;
  EXPECT_EQ(trefoil.json().at("alexander"), nlohmann::json::parse("[1,-1,1]"));
  for (const std::string& args : {"embed 3_1 --braid 1,1,1 -o " + dir + "/x.obj", "embed --strands 3 3_1 -o " + dir + "/x.obj",
                                  "embed --braid 1,1 --from pd -o " + dir + "/x.obj", "embed -o " + dir + "/x.obj",
                                  "embed --braid 1,0,1 -o " + dir + "/x.obj"}) {
    const auto b = run(args);
    EXPECT_EQ(b.status, 2) << args;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << args << ": " << b.err;
  }
}

// Links from PD codes: a code given with --pd (LinkInfo's Hopf link) and the
// table's Borromean rings drawn from theirs (--from pd) are written as links
// of the code's type; a knot's code gives a curve; bad codes are one line
// and status 2.
TEST(RelaxCli, LinksFromPDCodes) {
  const std::string dir = temp_dir("embed_pd_link");
  const auto h = run("embed --pd '[[4;1;3;2];[2;3;1;4]]' -n 160 -o " + dir + "/h.obj --json");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_EQ(h.json().at("from"), "pd");
  EXPECT_EQ(h.json().at("components"), 2);
  EXPECT_EQ(h.json().at("conway"), nlohmann::json::parse("[0,1]"));
  const auto b = run("embed borromean --from pd -n 300 -o " + dir + "/b.obj --json");
  ASSERT_EQ(b.status, 0) << b.err;
  const auto inv = run("invariants " + dir + "/b.obj --json");
  ASSERT_EQ(inv.status, 0) << inv.err;
  EXPECT_EQ(inv.json().at("components"), 3);
  EXPECT_EQ(inv.json().at("milnor_triple"), 1);
  const auto info = run("info borromean --json");
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_EQ(info.json().at("pd").get<std::string>().substr(0, 2), "[[");
  const auto k = run("embed --pd '[[1;5;2;4];[3;1;4;6];[5;3;6;2]]' -n 120 -o " + dir + "/t.obj --json");
  ASSERT_EQ(k.status, 0) << k.err;
  EXPECT_EQ(k.json().at("alexander"), nlohmann::json::parse("[1,-1,1]"));
  for (const std::string& args : {"embed --pd '[[1;2;3;4];[3;4;1;2]]' -o " + dir + "/x.obj",
                                  "embed 3_1 --pd '[[4;1;3;2];[2;3;1;4]]' -o " + dir + "/x.obj",
                                  "embed --pd '[[4;1;3;2];[2;3;1;4]]' --from pd -o " + dir + "/x.obj"}) {
    const auto bad = run(args);
    EXPECT_EQ(bad.status, 2) << args;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << args << ": " << bad.err;
  }
}
