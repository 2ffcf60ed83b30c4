// `knots load`: the command-line contract (docs/cli.md): a trefoil pressed
// between plates until it snaps, its folder agreeing with the JSON summary
// (path.csv's rows and columns, the curves of the start, the end and the
// snap), the knot type of every written curve; a pull that goes on through
// its snaps with the work balanced; a start without equilibrium as one
// line with exit status 1 and nothing written; bad
// input as one line with exit status 2 and an existing output kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/alexander.hpp"

using ek::clitest::lines_of;
using ek::clitest::relaxed_trefoil;
using ek::clitest::run;
using ek::clitest::temp_dir;

namespace fs = std::filesystem;

TEST(LoadCli, PressedTrefoilSnapsAndTheFolderAgreesWithTheSummary) {
  const std::string dir = temp_dir("load_cli_plates");
  const std::string state = relaxed_trefoil(dir);
  const auto r = run("load " + state + " --plates --to 0.4 -o " + dir + "/out --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("load"), "plates");
  EXPECT_EQ(j.at("parameter"), "gap");
  EXPECT_EQ(j.at("status"), "stopped");
  EXPECT_TRUE(j.at("alexander_preserved").get<bool>());
  ASSERT_EQ(j.at("snaps").size(), 1u);
  const auto& s = j.at("snaps")[0];
  EXPECT_GT(s.at("reaction").get<double>(), 0.0);
  EXPECT_GT(s.at("energy_drop").get<double>(), 0.0);
  EXPECT_EQ(s.at("released_status"), "converged-stable");
  const auto rows = lines_of(dir + "/out/path.csv");
  ASSERT_EQ(rows.size(), j.at("points").get<size_t>() + 1);
  EXPECT_EQ(rows[0].rfind("point,parameter,displacement,reaction,stiffness,energy", 0), 0u);
  const int snap_row = s.at("point").get<int>() + 1;
  EXPECT_NE(rows[static_cast<size_t>(snap_row)].find(",snap,"), std::string::npos);
  const ek::AlexanderPolynomial expected = ek::alexander(ek::read_curve(state));
  for (const char* f : {"start.obj", "end.obj", "snap_0_before.obj", "snap_0_loaded.obj", "snap_0_released.obj"}) {
    ASSERT_TRUE(fs::exists(dir + "/out/" + f)) << f;
    EXPECT_EQ(ek::alexander(ek::read_curve(dir + "/out/" + f)), expected) << f;
  }
  EXPECT_TRUE(fs::exists(dir + "/out/summary.json"));
}

// Vertices 0 and 48 of the relaxed trefoil lie on two strands at a crossing:
// pulled apart to distance 30 with --go-on, the path goes on after each snap
// and reaches the target; the work equals the energy gained plus the energy
// the snaps dissipated (1%: the trapezoid rule), every released state is a
// converged stable trefoil.
TEST(LoadCli, PullGoesOnAfterEachSnapAndTheWorkBalances) {
  const std::string dir = temp_dir("load_cli_pull");
  const std::string state = relaxed_trefoil(dir);
  const auto r = run("load " + state + " --pull 0,48 --to 30 --go-on -o " + dir + "/out --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("status"), "reached");
  EXPECT_EQ(j.at("vertices"), nlohmann::json({0, 48}));
  EXPECT_NEAR(j.at("end_parameter").get<double>(), 30.0, 1e-9);
  const double gained = j.at("end_energy").get<double>() - j.at("start_energy").get<double>();
  const double balance = gained + j.at("dissipated").get<double>();
  EXPECT_GT(gained, 0.0);
  EXPECT_NEAR(j.at("work").get<double>(), balance, 0.01 * balance);
  for (const auto& s : j.at("snaps")) EXPECT_EQ(s.at("released_status"), "converged-stable");
  std::cout << "[ measured ] pull 0,48 to 30: " << j.at("points") << " points, " << j.at("snaps").size()
            << " snaps, work " << j.at("work") << ", gained " << gained << ", dissipated " << j.at("dissipated")
            << std::endl;
}

TEST(LoadCli, BadInputIsOneLineAndExitTwo) {
  const std::string dir = temp_dir("load_cli_bad");
  const std::string state = relaxed_trefoil(dir);
  fs::create_directories(dir + "/exists");
  for (const std::string& args :
       {"load " + dir + "/missing.obj --plates --to 0.5 -o " + dir + "/o1",  // no such file
        "load " + state + " --to 0.3 -o " + dir + "/o2",                       // no load
        "load " + state + " --plates --pull 0,1 --to 0.5 -o " + dir + "/o3",   // two loads
        "load " + state + " --pull 0 --to 30 -o " + dir + "/o4",               // one vertex
        "load " + state + " --pull 0,500 --to 30 -o " + dir + "/o5",           // beyond the curve
        "load " + state + " --pull 0,1 --normal 0,0,1 --to 30 -o " + dir + "/o6",
        "load " + state + " --plates --from 0.01 --to 0.005 -o " + dir + "/o7",  // the curve is not between
        "load " + state + " --plates --to 0 -o " + dir + "/o8",                 // thinner than the wire (2r = 0.4)
        "load " + state + " --pull 0,40 --to -5 -o " + dir + "/o9",             // a negative distance
        "load " + state + " --plates --to 0.5 -o " + dir + "/exists",            // exists, no --overwrite
        "load " + state + " --plates --to 0.5"}) {                              // no -o
    const auto r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir + "/exists"));
  const auto thin = run("load " + state + " --plates --to 0.399 -o " + dir + "/o10");
  EXPECT_NE(thin.err.find("at least the wire's thickness 2r = 0.4"), std::string::npos) << thin.err;
}

// Plates starting at a gap of 0.7, inside the relaxed trefoil's extent plus
// reach (0.80) yet with the curve between them: no equilibrium is found at
// the start, which is one line on stderr, exit status 1, nothing written.
TEST(LoadCli, AStartWithoutEquilibriumIsOneLineAndExitOne) {
  const std::string dir = temp_dir("load_cli_stalled");
  const std::string state = relaxed_trefoil(dir);
  const auto r = run("load " + state + " --plates --from 0.7 --to 0.4 -o " + dir + "/out");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("no equilibrium under the load at its start (gap 0.7"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}
