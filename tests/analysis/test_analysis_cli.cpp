// End-to-end tests of `knots similarity` and `knots attributes`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli_runner.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "testing.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;

TEST(AnalysisCli, SimilarityJson) {
  const std::string dir = temp_dir("similarity");
  const ek::Points P = ek::fixtures::torus_knot(200, 2, 3);
  ek::Points M = ek::fixtures::rigid_copy(P, ek::fixtures::random_rotation(4), ek::Vec3(1, 2, 3), 30);
  M.col(0) *= -1.0;  // mirror image of a chiral curve
  ek::write_curve(dir + "/a.obj", P);
  ek::write_curve(dir + "/m.txt", M);
  const auto self = run("similarity " + dir + "/a.obj " + dir + "/a.obj --json");
  ASSERT_EQ(self.status, 0) << self.err;
  EXPECT_EQ(self.json()["similarity"].get<double>(), 1.0);
  const auto plain = run("similarity " + dir + "/a.obj " + dir + "/m.txt --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_LT(plain.json()["similarity"].get<double>(), 0.75);
  EXPECT_FALSE(plain.json()["mirrored"].get<bool>());
  const auto mir = run("similarity " + dir + "/a.obj " + dir + "/m.txt --mirror --reverse --json");
  ASSERT_EQ(mir.status, 0) << mir.err;
  const auto j = mir.json();
  EXPECT_GE(j["similarity"].get<double>(), 0.999);
  EXPECT_TRUE(j["mirrored"].get<bool>());
  for (const char* key : {"curvature_correlation", "torsion_correlation", "best_shift", "reversed", "samples"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["samples"], 200);
  // human-readable output and bad input
  const auto text = run("similarity " + dir + "/a.obj " + dir + "/m.txt");
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("similarity:"), std::string::npos);
  const auto missing = run("similarity " + dir + "/a.obj " + dir + "/none.obj");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1);
  EXPECT_EQ(run("similarity " + dir + "/a.obj " + dir + "/a.obj --samples 2").status, 2);
  std::filesystem::remove_all(dir);
}

// Links: the Borromean rings embedded from the table against a renumbered
// copy (similarity 1, the pairing found, placement 0), against the Whitehead
// link (refused: 3 components against 2, one line, status 2).
TEST(AnalysisCli, SimilarityOfLinks) {
  const std::string dir = temp_dir("similarity_links");
  ASSERT_EQ(run("embed borromean -n 240 -o " + dir + "/b.obj").status, 0);
  ASSERT_EQ(run("embed whitehead -n 200 -o " + dir + "/w.obj").status, 0);
  ek::Link b = ek::read_link(dir + "/b.obj");
  ek::write_link(dir + "/renumbered.obj", ek::Link{b[2], b[0], b[1]});
  const auto r = run("similarity " + dir + "/b.obj " + dir + "/renumbered.obj --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_NEAR(j.at("similarity").get<double>(), 1.0, 1e-9);
  EXPECT_EQ(j.at("pairing"), nlohmann::json::parse("[1,2,0]"));
  EXPECT_NEAR(j.at("placement").get<double>(), 0.0, 1e-9);
  EXPECT_EQ(j.at("component_similarity").size(), 3u);
  const auto bad = run("similarity " + dir + "/b.obj " + dir + "/w.obj");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("A has 3 components, B 2"), std::string::npos) << bad.err;
  std::filesystem::remove_all(dir);
}

TEST(AnalysisCli, AttributesJson) {
  const std::string dir = temp_dir("attributes");
  const int n = 100;
  ek::write_curve(dir + "/circle.obj", ek::fixtures::circle(n, 2.0));
  const auto r = run("attributes " + dir + "/circle.obj --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  EXPECT_NEAR(j["total_curvature"].get<double>(), 2 * M_PI, 1e-12);
  EXPECT_NEAR(j["threedim"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["sphericity"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["diameter"].get<double>(), 4.0, 1e-12);
  EXPECT_NEAR(j["writhe"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["max_stress"].get<double>(), 0.2 * 2000 * 2 * std::tan(M_PI / n), 1e-9);  // defaults r, E
  for (const char* key : {"energy", "energy_stretch", "energy_bend", "energy_twist", "stiffness"})
    EXPECT_TRUE(j.contains(key)) << key;  // null until the rod and solver modules exist
  const auto m = run("attributes " + dir + "/circle.obj --radius 0.1 --young 1000 --json").json();
  EXPECT_NEAR(m["max_stress"].get<double>(), 0.25 * j["max_stress"].get<double>(), 1e-9);
  EXPECT_EQ(run("attributes " + dir + "/circle.obj --radius 0").status, 2);
  EXPECT_EQ(run("attributes " + dir + "/circle.obj --young abc").status, 2);
  EXPECT_EQ(run("attributes " + dir + "/none.obj").status, 2);
  const auto text = run("attributes " + dir + "/circle.obj");
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("threedim:"), std::string::npos);
  std::filesystem::remove_all(dir);
}
