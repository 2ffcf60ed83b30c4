// End-to-end tests of `knots sample`: files written, names, JSON keys, the
// policy for existing files, one-line errors with exit status 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "testing.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;
namespace fs = std::filesystem;

namespace {

void expect_bad_input(const std::string& args, const std::string& needle) {
  const auto r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
}

void expect_lattice_sample(const std::string& file, int n, const ek::AlexanderPolynomial& alex) {
  const ek::Points P = ek::read_curve(file);
  ek::LatticePoints L;
  ASSERT_TRUE(ek::as_lattice_polygon(P, &L)) << file;
  EXPECT_EQ(L.rows(), n) << file;
  EXPECT_EQ(ek::alexander(P), alex) << file;
}

}  // namespace

TEST(SampleCli, TableKnotBatch) {
  const std::string dir = temp_dir("sample_table");
  const auto r = run("sample 5_2 --count 3 -n 120 --seed 4 -o " + dir + "/out --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  for (const char* key : {"name", "input", "start", "start_vertices", "rounding_scale", "vertices", "count", "seed",
                          "decorrelation", "alexander", "attempted_moves", "files"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["name"], "5_2");
  EXPECT_TRUE(j["input"].is_null());
  EXPECT_EQ(j["vertices"], 120);
  EXPECT_EQ(j["count"], 3);
  ASSERT_EQ(j["files"].size(), 3u);
  EXPECT_EQ(j["files"][2], dir + "/out/5_2-0002.obj");
  const auto alex = ek::alexander(*ek::KnotTable::global().at("5_2").pd);
  EXPECT_EQ(j["alexander"], nlohmann::json(alex.coefficients));
  for (int k = 0; k < 3; ++k) expect_lattice_sample(j["files"][k].get<std::string>(), 120, alex);
  // same seed, same files; an existing file is an error and stays untouched
  const std::string before = ek::fixtures::read_bytes(dir + "/out/5_2-0000.obj");
  expect_bad_input("sample 5_2 --count 3 -n 120 --seed 4 -o " + dir + "/out", "exists (use --overwrite");
  EXPECT_EQ(ek::fixtures::read_bytes(dir + "/out/5_2-0000.obj"), before);
  const auto again = run("sample 5_2 --count 1 -n 120 --seed 4 -o " + dir + "/out --overwrite");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(ek::fixtures::read_bytes(dir + "/out/5_2-0000.obj"), before);
  const auto other = run("sample 5_2 --count 1 -n 120 --seed 5 -o " + dir + "/out --overwrite");
  ASSERT_EQ(other.status, 0) << other.err;
  EXPECT_NE(ek::fixtures::read_bytes(dir + "/out/5_2-0000.obj"), before);
  fs::remove_all(dir);
}

TEST(SampleCli, StartFromCurveFiles) {
  const std::string dir = temp_dir("sample_file");
  const std::string peer = ek::fixtures::peer_dir();
  // a lattice polygon is used as it is
  const auto a = run("sample " + peer + "/9_47-cubiclattice.txt --count 2 -n 200 -o " + dir + " --format txt --json");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.json()["start"], "lattice");
  EXPECT_EQ(a.json()["name"], "9_47-cubiclattice");
  EXPECT_EQ(a.json()["files"][1], dir + "/9_47-cubiclattice-0001.txt");
  const auto alex947 = ek::alexander(*ek::KnotTable::global().at("9_47").pd);
  for (int k = 0; k < 2; ++k) expect_lattice_sample(a.json()["files"][k].get<std::string>(), 200, alex947);
  // any other closed curve is rounded onto the lattice first
  const auto b = run("sample " + peer + "/12n_838-braid.obj --count 1 -o " + dir + " --decorrelation 1000 --json");
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(b.json()["start"], "rounded");
  EXPECT_TRUE(b.json()["rounding_scale"].is_number());
  expect_lattice_sample(dir + "/12n_838-braid-0000.obj", 400, ek::alexander(*ek::KnotTable::global().at("12n_838").pd));
  fs::remove_all(dir);
}

// A link of the link table and a link file: K link files of lattice
// polygons, as many components as the link, the component lengths of the
// JSON, the table's Conway polynomial and linking numbers on every sample;
// a sample file fed back in starts from itself (on the lattice already).
TEST(SampleCli, TableLinkAndLinkFile) {
  const std::string dir = temp_dir("sample_link");
  const auto r = run("sample borromean --count 2 -n 240 --growth-factor 4 -o " + dir + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_EQ(j.at("components"), 3);
  EXPECT_EQ(j.at("conway"), nlohmann::json::parse("[0,0,0,0,1]"));
  ASSERT_EQ(j.at("files").size(), 2u);
  const std::vector<int> lengths = j.at("component_vertices");
  for (const auto& f : j.at("files")) {
    const ek::Link link = ek::read_link(f.get<std::string>());
    ASSERT_EQ(link.size(), 3u);
    for (size_t c = 0; c < 3; ++c) {
      ek::LatticePoints L;
      EXPECT_TRUE(ek::as_lattice_polygon(link[c], &L));
      EXPECT_EQ(L.rows(), lengths[c]);
    }
    const auto inv = run("invariants " + f.get<std::string>() + " --json");
    ASSERT_EQ(inv.status, 0) << inv.err;
    EXPECT_EQ(inv.json().at("conway"), nlohmann::json::parse("[0,0,0,0,1]"));
    EXPECT_EQ(inv.json().at("milnor_triple"), 1);
  }
  const std::string first = j.at("files")[0];
  const auto again = run("sample " + first + " --count 1 -n 240 --growth-factor 4 -o " + dir + "/again --json");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(again.json().at("start"), "lattice");
  EXPECT_EQ(again.json().at("conway"), nlohmann::json::parse("[0,0,0,0,1]"));
  fs::remove_all(dir);
}

TEST(SampleCli, BadInput) {
  const std::string dir = temp_dir("sample_bad");
  expect_bad_input("sample 13_1 -o " + dir, "unknown knot '13_1'");
  expect_bad_input("sample 3_1 -n 41 -o " + dir, "even number");
  expect_bad_input("sample 12a_1019 -n 20 -o " + dir, "at least 24");
  expect_bad_input("sample 3_1 --count 0 -o " + dir, "--count");
  expect_bad_input("sample 3_1 --seed -3 -o " + dir, "--seed");
  expect_bad_input("sample 3_1 --count 2", "missing -o");
  expect_bad_input("sample 3_1 --format ply -o " + dir, "--format");
  expect_bad_input("sample " + dir + "/missing.obj -o " + dir, "missing.obj");
  std::ofstream(dir + "/three.txt") << "0 0 0\n1 0 0\n0 1 0\n";
  expect_bad_input("sample " + dir + "/three.txt -o " + dir, "three.txt");
  std::ofstream(dir + "/file") << "x";
  expect_bad_input("sample 3_1 -o " + dir + "/file", "output folder");
  EXPECT_FALSE(fs::exists(dir + "/3_1-0000.obj"));  // nothing written by the failed runs
  fs::remove_all(dir);
}
