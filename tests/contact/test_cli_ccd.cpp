// End-to-end test of `knots ccd` (exit status, JSON keys, a motion that
// collides and one that does not).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct CliRun {
  int status = -1;
  std::string out;
};

CliRun run(const std::string& args) {
  CliRun r;
  const std::string cmd = std::string(EK_KNOTS_BIN) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  size_t k;
  while ((k = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), k);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// A stadium: two long sides 1 apart (20 vertices each, spacing 0.5); `lift`
// moves the inner vertices of the first side towards (and past) the second.
void write_stadium(const std::string& path, double lift) {
  std::ofstream f(path);
  f.precision(17);
  const int m = 19;
  for (int i = 0; i <= m; ++i) f << i * 0.5 << " " << ((i >= 2 && i < m - 1) ? lift : 0.0) << " 0\n";
  for (int i = 0; i <= m; ++i) f << (m - i) * 0.5 << " 1 0\n";
}

}  // namespace

TEST(CliCcd, CollidingAndFreeMotions) {
  const auto dir = std::filesystem::temp_directory_path() / ("ek_cli_ccd_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string a = (dir / "a.txt").string(), through = (dir / "through.txt").string(),
                    small = (dir / "small.txt").string(), bad = (dir / "bad.txt").string();
  write_stadium(a, 0.0);
  write_stadium(through, 2.5);
  write_stadium(small, 0.3);
  {
    std::ofstream f(bad);
    f << "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  }
  const CliRun r = run("ccd " + a + " " + through + " --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"start", "end", "vertices", "t", "full_step", "separation", "dhat", "candidates",
                          "limiting_edges", "clearance_start", "clearance_at_t", "clearance_end",
                          "min_clearance_sampled"})
    EXPECT_TRUE(j.contains(key)) << key;
  // the sides start 1 apart and close at 2.5 per unit of t: contact at 0.4
  EXPECT_LT(j["t"].get<double>(), 0.4);
  EXPECT_GT(j["t"].get<double>(), 0.3);
  EXPECT_FALSE(j["full_step"].get<bool>());
  EXPECT_GT(j["clearance_at_t"].get<double>(), 0.0);
  EXPECT_EQ(j["clearance_end"].get<double>(), 0.0);
  const auto f = nlohmann::json::parse(run("ccd " + a + " " + small + " --json").out);
  EXPECT_EQ(f["t"].get<double>(), 1.0);
  EXPECT_TRUE(f["full_step"].get<bool>());
  EXPECT_TRUE(f["limiting_edges"].is_null());
  EXPECT_EQ(run("ccd " + a + " " + bad).status, 2);                        // vertex counts differ
  EXPECT_EQ(run("ccd " + a + " " + through + " --separation 1").status, 2);  // impossible parameter
  EXPECT_EQ(run("ccd " + a + " " + (dir / "missing.txt").string()).status, 2);
  std::filesystem::remove_all(dir);
}
