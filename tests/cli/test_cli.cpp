#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "ek/core/config.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "output.hpp"
#include "testing.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;

namespace {

// Bad input: exactly one line on stderr and exit status 2.
void expect_bad_input(const std::string& args, const std::string& needle) {
  const auto r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
}

}  // namespace

TEST(Cli, InfoJson) {
  const auto r = run("info 4_1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j["name"], "4_1");
  EXPECT_EQ(j["crossing_number"], 4);
  EXPECT_EQ(j["bridge_index"], 2);
  EXPECT_EQ(j["braid_index"], 3);
  EXPECT_EQ(j["alexander"], nlohmann::json::parse("[-1,3,-1]"));
  EXPECT_EQ(j["determinant"], 5);
  const auto u = run("info unknot --json").json();
  EXPECT_EQ(u["alexander"], nlohmann::json::parse("[1]"));
  EXPECT_EQ(u["determinant"], 1);
  const auto h = run("info 12n_838");
  EXPECT_EQ(h.status, 0);
  EXPECT_NE(h.out.find("crossing number:   12"), std::string::npos);
}

TEST(Cli, EmbedAndInvariants) {
  const std::string dir = temp_dir("embed");
  for (const char* from : {"braid", "pd"}) {
    const std::string file = dir + "/8_19-" + from + ".obj";
    const auto e = run(std::string("embed 8_19 --from ") + from + " -n 300 -o " + file);
    ASSERT_EQ(e.status, 0) << e.err;
    const auto r = run("invariants " + file + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = r.json();
    EXPECT_EQ(j["vertices"], 300);
    EXPECT_NEAR(j["length"].get<double>(), 300.0, 1e-6);
    EXPECT_EQ(j["alexander"], nlohmann::json::parse("[1,-1,0,1,0,-1,1]"));
    EXPECT_EQ(j["determinant"], 3);
    for (const char* key : {"writhe", "total_curvature", "clearance"}) EXPECT_TRUE(j[key].is_number()) << key;
    // Milnor: total curvature above 2π · bridge index (8_19: bridge index 3)
    EXPECT_GT(j["total_curvature"].get<double>(), 2 * M_PI * 3);
  }
  // the braid's strands stacked along the axis (--tilt 90): same knot type, a
  // 3D start (z extent above a third of the x extent; the flat coil's is ~0.1)
  const std::string tall = dir + "/8_19-tall.txt";
  const auto e = run("embed 8_19 --tilt 90 --strand-spacing 0.5 -n 300 -o " + tall);
  ASSERT_EQ(e.status, 0) << e.err;
  const auto r = run("invariants " + tall + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.json()["alexander"], nlohmann::json::parse("[1,-1,0,1,0,-1,1]"));
  const ek::Points P = ek::read_curve(tall);
  const double zext = P.col(2).maxCoeff() - P.col(2).minCoeff(), xext = P.col(0).maxCoeff() - P.col(0).minCoeff();
  EXPECT_GT(zext, xext / 3) << zext << " vs " << xext;
  // the paper's cylinder: strands one letter slot's arc apart along the axis,
  // 3 strands of 8 letters (8_19's braid word): height 2·2πR/8 = 1.57 R
  const std::string cyl = dir + "/8_19-cylinder.obj";
  const auto c = run("embed 8_19 --style cylinder -n 300 -o " + cyl + " --json");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.json()["alexander"], nlohmann::json::parse("[1,-1,0,1,0,-1,1]"));
  const ek::Points C = ek::read_curve(cyl);
  const double R = C.leftCols(2).rowwise().norm().mean(), height = C.col(2).maxCoeff() - C.col(2).minCoeff();
  EXPECT_NEAR(height / R, 2.0 * 2.0 * M_PI / 8.0, 0.02);
  for (const char* bad : {"--style helix", "--style cylinder --crossing-offset 0", "--style cylinder --tilt 10"}) {
    const auto b = run(std::string("embed 8_19 ") + bad + " -o " + dir + "/bad.obj");
    EXPECT_EQ(b.status, 2) << bad;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/bad.obj")) << bad;
  }
  std::filesystem::remove_all(dir);
}

TEST(Cli, PeerFilesReadAsTheyAre) {
  const std::string dir = ek::fixtures::peer_dir();
  auto a = run("invariants " + dir + "/4_1-smooth.obj --json");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.json()["alexander"], nlohmann::json::parse("[-1,3,-1]"));
  EXPECT_EQ(a.json()["vertices"], 272);
  auto b = run("invariants " + dir + "/9_47-cubiclattice.txt --json");
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(b.json()["vertices"], 208);
  auto c = run("invariants " + dir + "/12n_838-braid.obj --json");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.json()["vertices"], 360);
  EXPECT_EQ(c.json()["alexander"], run("info 12n_838 --json").json()["alexander"]);
  EXPECT_EQ(b.json()["alexander"], run("info 9_47 --json").json()["alexander"]);
}

TEST(Cli, BadInputExitsWithStatus2AndOneLine) {
  const std::string dir = temp_dir("bad");
  expect_bad_input("info 13_1", "unknown knot '13_1'");
  expect_bad_input("info", "missing argument NAME");
  expect_bad_input("info 3_1 --bogus", "unknown option '--bogus'");
  expect_bad_input("frobnicate", "unknown command 'frobnicate'");
  expect_bad_input("invariants /nonexistent.obj", "cannot open");
  {
    std::ofstream(dir + "/nan.txt") << "0 0 0\n1 0 0\n1 nan 0\n0 1 0\n";
    std::ofstream(dir + "/three.txt") << "0 0 0\n1 0 0\n1 1 0\n";
    std::ofstream(dir + "/repeat.txt") << "0 0 0\n1 0 0\n1 0 0\n1 1 0\n0 1 0\n";
    std::ofstream(dir + "/garbage.obj") << "v 1 2\n";
  }
  expect_bad_input("invariants " + dir + "/nan.txt", "not finite");
  expect_bad_input("invariants " + dir + "/three.txt", "at least 4 vertices");
  expect_bad_input("invariants " + dir + "/repeat.txt", "coincide");
  expect_bad_input("invariants " + dir + "/garbage.obj", "3 coordinates");
  expect_bad_input("embed 3_1 --from dt -o " + dir + "/x.obj", "unknown embedding source 'dt'");
  expect_bad_input("embed 3_1 -n 2 -o " + dir + "/x.obj", "at least 4 vertices");
  expect_bad_input("embed 3_1 -n abc -o " + dir + "/x.obj", "'abc' is not an integer");
  expect_bad_input("embed 3_1 -o /nonexistent-folder/x.obj", "does not exist");
  expect_bad_input("embed 3_1", "missing -o FILE");
  expect_bad_input("embed 3_1 --tilt nan -o " + dir + "/x.obj", "--tilt: 'nan' is not a finite number");
  expect_bad_input("embed 3_1 --tilt 90 --strand-spacing 1.5 -o " + dir + "/x.obj", "too large for a tilted coil");
  expect_bad_input("embed 3_1 -o " + dir + "/x.ply", "unknown curve format");
  expect_bad_input("explore 3_1 --stopping unseen -o " + dir + "/x.h5", "--stopping needs --adaptive");
  expect_bad_input("explore 3_1 --adaptive --stopping chao -o " + dir + "/x.h5", "unknown stopping rule 'chao'");
  expect_bad_input("explore 3_1 --adaptive --stopping unseen --new-state-threshold 1 -o " + dir + "/x.h5",
                   "new-state threshold must be in [0, 1)");
  std::filesystem::remove_all(dir);
}

// A link file (the (2, 4) torus link: two (1, 2) curves on a torus, one l
// loop each): each component's invariants, the linking numbers ±2 as
// integers, the clearance between components; a link whose components cross
// is bad input.
TEST(Cli, InvariantsOfALink) {
  const std::string dir = temp_dir("link_invariants");
  ek::Link link(2, ek::Points(120, 3));
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 120; ++i) {
      const double t = 2.0 * M_PI * i / 120, theta = 2.0 * t + c * M_PI;
      link[static_cast<size_t>(c)].row(i) << (2.0 + std::cos(theta)) * std::cos(t),
          (2.0 + std::cos(theta)) * std::sin(t), std::sin(theta);
    }
  ek::write_link(dir + "/t24.obj", link);
  const auto r = run("invariants " + dir + "/t24.obj --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("components"), 2);
  EXPECT_EQ(j.at("vertices"), 240);
  ASSERT_EQ(j.at("component").size(), 2u);
  for (const auto& c : j.at("component")) EXPECT_EQ(c.at("alexander"), std::vector<int>{1});
  const int lk = j.at("linking_numbers")[0][1];
  EXPECT_EQ(std::abs(lk), 2);
  EXPECT_EQ(j.at("linking_numbers")[1][0], lk);
  EXPECT_EQ(j.at("linking_numbers")[0][0], 0);
  EXPECT_LT(j.at("linking_error").get<double>(), 1e-9);
  // at each angle φ the components are opposite on the tube's circle of radius 1: 2 apart at most
  EXPECT_GT(j.at("component_clearance").get<double>(), 0.5);
  EXPECT_LE(j.at("component_clearance").get<double>(), 2.0);
  EXPECT_EQ(j.at("conway"), nlohmann::json::parse("[0,2,0,1]"));  // T(2,4): 2z + z³
  EXPECT_TRUE(j.at("milnor_triple").is_null());                    // two components
  const auto text = run("invariants " + dir + "/t24.obj");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("components:      2"), std::string::npos) << text.out;
  std::ofstream(dir + "/cross.txt") << "0 0 0\n2 0 0\n2 2 0\n0 2 0\n\n1 0 -1\n1 0 1\n1 -2 1\n1 -2 -1\n";
  expect_bad_input("invariants " + dir + "/cross.txt", "components 1 and 2 touch or cross");
  std::filesystem::remove_all(dir);
}

// The link table from the command line: `knots info` of a link by name and
// by alias (text and JSON: components, their types, linking numbers, ∇,
// |μ̄(123)|); `knots embed NAME` of a link writes its components, whose
// invariants are the table's, also drawn from its PD code (--from pd).
TEST(Cli, InfoAndEmbedOfATableLink) {
  const auto j = run("info L6a4 --json");
  ASSERT_EQ(j.status, 0) << j.err;
  EXPECT_EQ(j.json().at("name"), "borromean");
  EXPECT_EQ(j.json().at("components"), 3);
  EXPECT_EQ(j.json().at("component_types"), nlohmann::json::parse(R"(["0_1","0_1","0_1"])"));
  EXPECT_EQ(j.json().at("conway"), nlohmann::json::parse("[0,0,0,0,1]"));
  EXPECT_EQ(j.json().at("milnor_triple"), 1);
  const auto text = run("info trefoil_hopf");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("components:        2 (3_1, 0_1)"), std::string::npos) << text.out;
  const std::string dir = temp_dir("link_table");
  const auto e = run("embed whitehead -n 200 -o " + dir + "/w.obj --json");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_EQ(e.json().at("name"), "whitehead");
  EXPECT_EQ(e.json().at("components"), 2);
  const auto inv = run("invariants " + dir + "/w.obj --json");
  ASSERT_EQ(inv.status, 0) << inv.err;
  EXPECT_EQ(inv.json().at("conway"), nlohmann::json::parse("[0,0,0,1]"));  // not the unlink's []
  EXPECT_EQ(inv.json().at("linking_numbers"), nlohmann::json::parse("[[0,0],[0,0]]"));
  const auto pd = run("embed hopf --from pd -n 160 -o " + dir + "/h.obj --json");  // the drawing of its PD code
  ASSERT_EQ(pd.status, 0) << pd.err;
  EXPECT_EQ(pd.json().at("from"), "pd");
  EXPECT_EQ(pd.json().at("conway"), nlohmann::json::parse("[0,1]"));
  expect_bad_input("embed hopf --from dt -o " + dir + "/h.obj", "unknown embedding source 'dt'");
  std::filesystem::remove_all(dir);
}

TEST(Cli, FailedRunKeepsExistingOutput) {
  const std::string dir = temp_dir("keep");
  const std::string file = dir + "/keep.obj";
  std::ofstream(file) << "precious";
  const auto r = run("embed 12n_838 --from pd -n 10 -o " + file);  // too coarse: fails
  EXPECT_EQ(r.status, 2) << r.err;
  std::ifstream in(file);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "precious");
  std::filesystem::remove_all(dir);
}

TEST(Cli, MissingKnotTableIsOneLineError) {
  const auto r = run("info 3_1 2>&1; KNOT_TABLE=/nonexistent.csv " EK_KNOTS_BIN " info 3_1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent.csv"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// Text read from a damaged file may not be UTF-8 (found by the corruption
// test: a changed byte in an attribute name of a file without checksum made
// `knots query --json` fail with an internal error): it prints as U+FFFD.
TEST(Cli, JsonOutputReplacesBytesThatAreNotUtf8) {
  std::ostringstream captured;
  auto* old = std::cout.rdbuf(captured.rdbuf());
  ek::cli::Json j;
  j["name\xc1x"] = "ok";
  EXPECT_NO_THROW(ek::cli::print_json(j));
  std::cout.rdbuf(old);
  EXPECT_EQ(captured.str(), "{\"name\xef\xbf\xbdx\":\"ok\"}\n");
}

// The front door and the reference list every command: each command that
// `knots --help` prints appears in README.md's command table as `knots NAME`
// and in docs/cli.md's table as [`NAME`](#knots-NAME) with its own section.
TEST(Cli, ReadmeAndCliReferenceListEveryCommand) {
  const auto h = run("--help");
  ASSERT_EQ(h.status, 0) << h.err;
  std::vector<std::string> commands;
  std::istringstream lines(h.out);
  bool in_list = false;
  for (std::string line; std::getline(lines, line);) {
    if (line == "commands:") {
      in_list = true;
      continue;
    }
    if (!in_list || line.size() < 3 || line.compare(0, 2, "  ") != 0) continue;
    commands.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  ASSERT_GE(commands.size(), 24u);
  const std::string readme = ek::fixtures::read_bytes(std::string(ek::config::kSourceDir) + "/README.md");
  const std::string cli = ek::fixtures::read_bytes(std::string(ek::config::kSourceDir) + "/docs/cli.md");
  ASSERT_FALSE(readme.empty());
  ASSERT_FALSE(cli.empty());
  for (const std::string& c : commands) {
    EXPECT_NE(readme.find("| `knots " + c), std::string::npos) << "README.md's command table lacks knots " << c;
    EXPECT_NE(cli.find("| [`" + c + "`](#knots-" + c + ")"), std::string::npos) << "docs/cli.md's table lacks " << c;
    EXPECT_NE(cli.find("### `knots " + c + "`"), std::string::npos) << "docs/cli.md has no section for " << c;
  }
}

// `knots --version`: the project version of CMakeLists.txt (config.hpp) and the source commit.
TEST(Cli, VersionNamesTheProjectVersionAndCommit) {
  const auto v = run("--version");
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_EQ(v.out.rfind(std::string("knots ") + ek::config::kVersion + " (commit ", 0), 0u) << v.out;
  EXPECT_EQ(run("--version extra").status, 2);  // an unknown command, as before
}
