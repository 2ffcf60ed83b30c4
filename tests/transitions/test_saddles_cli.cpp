// `knots saddles`: the command-line contract (docs/cli.md): one-line errors
// with exit status 2 for bad input, an existing folder kept without
// --overwrite, and the folder's files (summary.json, start, saddle, minimum
// and path per verified saddle) agreeing with the JSON.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;

namespace fs = std::filesystem;

namespace {

/// A stable state of 4_1: a BFACF sample (120 unit edges, seed 1, the second
/// of three) relaxed by the default method.
std::string state_41(const std::string& dir) {
  auto r = run("sample 4_1 -n 120 --count 3 -o " + dir + "/lattice");
  EXPECT_EQ(r.status, 0) << r.err;
  r = run("relax " + dir + "/lattice/4_1-0001.obj -o " + dir + "/state.obj");
  EXPECT_EQ(r.status, 0) << r.err;
  return dir + "/state.obj";
}

}  // namespace

TEST(SaddlesCli, BadInputIsOneLineAndExitTwo) {
  const std::string dir = temp_dir("saddles_cli_bad");
  const std::string lattice = dir + "/lattice/4_1-0000.obj";
  ASSERT_EQ(run("sample 4_1 -n 120 -o " + dir + "/lattice").status, 0);
  for (const std::string& args :
       {"saddles " + dir + "/missing.obj -o " + dir + "/a",  // no such file
        "saddles " + lattice + " -o " + dir + "/b",           // not an equilibrium
        "saddles " + lattice + " --modes 0 -o " + dir + "/c", "saddles " + lattice + " --displacement -1 -o " + dir + "/d",
        "saddles " + lattice + " --rest-length 0 -o " + dir + "/e", "saddles " + lattice}) {
    const auto r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(ek::clitest::newline_count(r.err), 1u) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
  for (const char* sub : {"a", "b", "c", "d", "e"}) EXPECT_FALSE(fs::exists(dir + "/" + sub)) << sub;
}

TEST(SaddlesCli, WritesVerifiedSaddlesAndKeepsAnExistingFolder) {
  const std::string dir = temp_dir("saddles_cli_ok");
  const std::string state = state_41(dir), out = dir + "/out";
  auto r = run("saddles " + state + " --modes 2 -o " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  ASSERT_EQ(j.at("searches").size(), 4u);
  int verified = 0;
  for (const auto& s : j.at("searches")) verified += s.at("verified").get<bool>();
  EXPECT_GE(verified, 1);
  std::ifstream f(out + "/summary.json");
  ASSERT_TRUE(f.good());
  EXPECT_EQ(nlohmann::json::parse(f), j);
  EXPECT_TRUE(fs::exists(out + "/start.obj"));
  ASSERT_GE(j.at("saddles").size(), 1u);
  for (const auto& s : j.at("saddles")) {
    const std::string k = std::to_string(s.at("search").get<int>());
    for (const std::string name : {"saddle_", "minimum_", "path_"}) EXPECT_TRUE(fs::exists(out + "/" + name + k + ".obj")) << name << k;
    EXPECT_EQ(s.at("index"), 1);
    EXPECT_GT(s.at("barrier").get<double>(), 0.0);
    EXPECT_NEAR(s.at("barrier").get<double>(), s.at("energy").get<double>() - j.at("start_energy").get<double>(), 1e-12);
    EXPECT_GE(s.at("start_similarity").get<double>(), 0.99);
    EXPECT_EQ(s.at("minima")[0].at("status"), "converged-stable");
    EXPECT_EQ(s.at("minima")[1].at("status"), "converged-stable");
    // the path file: relax accepts no multi-object file, but its first image is the start's basin
    std::ifstream p(out + "/path_" + k + ".obj");
    std::string first;
    std::getline(p, first);
    EXPECT_EQ(first.rfind("o image_0 E=", 0), 0u) << first;
  }
  // an existing folder is kept without --overwrite (before any search) ...
  std::ofstream(out + "/mine.txt") << "keep";
  r = run("saddles " + state + " --modes 1 -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(ek::clitest::newline_count(r.err), 1u) << r.err;
  EXPECT_TRUE(fs::exists(out + "/mine.txt"));
  // ... and replaced as a whole with it
  r = run("saddles " + state + " --modes 1 -o " + out + " --overwrite --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(out + "/mine.txt"));
  EXPECT_EQ(r.json().at("searches").size(), 2u);
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
    EXPECT_EQ(e.path().filename().string().find(".old."), std::string::npos) << e.path();
  }
}
