// End-to-end test of `knots energy`: JSON keys and values on curves with
// known answers, text output, bad input (exit status 2, one stderr line).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/rod/material.hpp"
#include "testing.hpp"

namespace {

/// Runs `knots ARGS` (the shared runner of tests/cli).
ek::clitest::Result knots(const std::string& args) { return ek::clitest::run(args); }

/// A regular polygon with unit edges written to a temporary file.
std::string unit_polygon_file(int n) {
  const auto dir = std::filesystem::temp_directory_path() / ("ek_rod_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / ("polygon" + std::to_string(n) + ".txt")).string();
  ek::write_curve(path, ek::fixtures::circle(n, 1.0 / (2.0 * std::sin(M_PI / n))));
  return path;
}

}  // namespace

TEST(RodCli, EnergyJsonOfRegularPolygon) {
  const int n = 100;
  const std::string file = unit_polygon_file(n);
  const ek::RodMaterial m;  // defaults r = 0.2, E = 2000, ν = 0.3
  const ek::clitest::Result r = knots("energy " + file + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"energy", "energy_stretch", "energy_bend", "energy_twist", "gradient_norm", "twist",
                          "writhe", "link"})
    ASSERT_TRUE(j.contains(key)) << key;
  // Bending of a regular n-gon with unit edges: n EI/2 (2 tan(π/n))².
  const double bend = n * 0.5 * m.bending_stiffness() * std::pow(2 * std::tan(M_PI / n), 2);
  EXPECT_NEAR(j["energy_bend"].get<double>(), bend, 1e-10 * bend);
  EXPECT_NEAR(j["energy_stretch"].get<double>(), 0.0, 1e-20);
  EXPECT_EQ(j["energy_twist"].get<double>(), 0.0);
  EXPECT_NEAR(j["energy"].get<double>(), bend, 1e-10 * bend);
  EXPECT_LT(j["gradient_norm"].get<double>(), 1e-10);  // a regular polygon at rest is an equilibrium
  EXPECT_EQ(j["twist"].get<double>(), 0.0);
  EXPECT_NEAR(j["writhe"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["link"].get<double>(), 0.0, 1e-12);
  EXPECT_EQ(j["vertices"].get<int>(), n);
}

TEST(RodCli, EnergyWithLinkMaterialAndRestLength) {
  const int n = 80;
  const std::string file = unit_polygon_file(n);
  ek::RodMaterial m;
  m.radius = 0.3;
  m.young = 1000;
  m.poisson = 0.4;
  const ek::clitest::Result r = knots("energy " + file + " --radius 0.3 --young 1000 --poisson 0.4 --link 2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["link"].get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(j["twist"].get<double>(), 2.0, 1e-12);
  // Uniform twist: GJ/2 (2π Lk)² / L with L = n.
  const double tw = 0.5 * m.twisting_stiffness() * std::pow(4 * M_PI, 2) / n;
  EXPECT_NEAR(j["energy_twist"].get<double>(), tw, 1e-10 * tw);
  const double bend = n * 0.5 * m.bending_stiffness() * std::pow(2 * std::tan(M_PI / n), 2);
  EXPECT_NEAR(j["energy"].get<double>(), tw + bend, 1e-10 * (tw + bend));
  EXPECT_LT(j["gradient_norm"].get<double>(), 1e-9);  // the twisted ring is an equilibrium too
  // Rest length 1.1: every edge compressed by 1/1.1.
  const auto s = nlohmann::json::parse(knots("energy " + file + " --rest-length 1.1 --json").out);
  const ek::RodMaterial d;
  const double stretch = n * 0.5 * d.stretching_stiffness() * std::pow(1.0 / 1.1 - 1.0, 2) * 1.1;
  EXPECT_NEAR(s["energy_stretch"].get<double>(), stretch, 1e-10 * stretch);
  EXPECT_GT(s["gradient_norm"].get<double>(), 1.0);
}

TEST(RodCli, EnergyTextOutputAndBadInput) {
  const std::string file = unit_polygon_file(50);
  const ek::clitest::Result t = knots("energy " + file);
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("bending:"), std::string::npos);
  EXPECT_NE(t.out.find("link:"), std::string::npos);
  const std::vector<std::string> bad = {"energy " + file + " --poisson 0.7", "energy " + file + " --radius -1",
                                       "energy " + file + " --rest-length 0", "energy " + file + " --link abc",
                                       "energy /nonexistent/curve.txt", "energy"};
  for (const std::string& args : bad) {
    const ek::clitest::Result r = knots(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}
