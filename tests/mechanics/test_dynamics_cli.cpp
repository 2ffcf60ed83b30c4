// `knots dynamics`: the command-line contract (docs/cli.md): a trefoil
// thrown through itself keeps its type, its folder agrees with the JSON
// summary (trajectory.csv's rows and columns, one frame file per row, the
// start and the end); bad input is one line with exit status 2 and an
// existing output kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

TEST(DynamicsCli, ThrownTrefoilKeepsItsTypeAndTheFolderAgreesWithTheSummary) {
  const std::string dir = temp_dir("dynamics_cli_thrown");
  const std::string state = relaxed_trefoil(dir);
  const ek::Points x = ek::read_curve(state);
  ek::Points v(x.rows(), 3);  // every vertex towards the centroid and spinning
  const Eigen::RowVector3d c = x.colwise().mean();
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    v.row(i) = -0.5 * (x.row(i) - c) + 0.5 * Eigen::RowVector3d(-(x(i, 1) - c(1)), x(i, 0) - c(0), 0.0);
  ek::write_curve(dir + "/velocity.obj", v);
  const auto r = run("dynamics " + state + " --velocity " + dir + "/velocity.obj --time-step 0.05 --duration 2 "
                     "--friction 0.3 --frame-every 5 -o " + dir + "/out --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("model"), "twist-free");
  EXPECT_EQ(j.at("status"), "duration");
  EXPECT_EQ(j.at("steps"), 40);
  EXPECT_TRUE(j.at("alexander_preserved").get<bool>());
  EXPECT_TRUE(j.at("link").is_null());
  EXPECT_GT(j.at("dissipated").get<double>(), 0.0);  // friction and backward Euler dissipate
  const auto rows = lines_of(dir + "/out/trajectory.csv");
  ASSERT_EQ(rows.size(), j.at("frames").get<size_t>() + 1);  // 0, 5, ..., 40: 9 frames and the header
  EXPECT_EQ(j.at("frames"), 9);
  EXPECT_EQ(rows.front(), "frame,time,kinetic,elastic,gravity,total,max_speed,contacts,threedim,newton_iterations");
  size_t frames = 0;
  for (const auto& e : fs::directory_iterator(dir + "/out/frames")) frames += e.path().extension() == ".obj";
  EXPECT_EQ(frames, j.at("frames").get<size_t>());
  const ek::Points end = ek::read_curve(dir + "/out/end.obj");
  EXPECT_EQ(end, ek::read_curve(dir + "/out/frames/00008.obj"));
  EXPECT_EQ(ek::read_curve(dir + "/out/start.obj"), x);
  EXPECT_EQ(ek::alexander(end), ek::alexander(x));
}

TEST(DynamicsCli, BadInputIsOneLineAndExitTwo) {
  const std::string dir = temp_dir("dynamics_cli_bad");
  const std::string state = relaxed_trefoil(dir);
  fs::create_directories(dir + "/exists");
  ek::Points lifted(12, 3);  // a ring at z = 1
  for (int i = 0; i < 12; ++i) lifted.row(i) = Eigen::RowVector3d(2 * std::cos(M_PI * i / 6), 2 * std::sin(M_PI * i / 6), 1.0);
  ek::write_curve(dir + "/lifted.obj", lifted);
  for (const std::string& args :
       {"dynamics " + dir + "/missing.obj -o " + dir + "/o1",                   // no such file
        "dynamics " + state + " --time-step 0 -o " + dir + "/o2",                // no time step
        "dynamics " + state + " --friction -1 -o " + dir + "/o3",                // negative friction
        "dynamics " + state + " --gravity 0,1 -o " + dir + "/o4",                // not a vector
        "dynamics " + state + " --envelope 0.1 -o " + dir + "/o5",               // thinner than the wire
        "dynamics " + dir + "/lifted.obj --envelope 0.3 -o " + dir + "/o6",      // the curve is not inside
        "dynamics " + state + " --velocity " + state + ".none -o " + dir + "/o7",  // no velocity file
        "dynamics " + state + " -o " + dir + "/exists",                          // exists, no --overwrite
        "dynamics " + state}) {                                                  // no -o
    const auto r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir + "/exists"));
}
