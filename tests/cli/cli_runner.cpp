#include "cli_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ek::clitest {

Result run(const std::string& args, int timeout_seconds) {
  static int counter = 0;
  const std::string base = std::filesystem::temp_directory_path().string() + "/ek_cli_" +
                           std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const std::string limit = timeout_seconds > 0 ? "timeout -s KILL " + std::to_string(timeout_seconds) + " " : "";
  const std::string cmd = limit + std::string(EK_KNOTS_BIN) + " " + args + " >" + base + ".out 2>" + base + ".err";
  Result r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  r.out = slurp(base + ".out");
  r.err = slurp(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("ek_cli_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::vector<std::string> lines_of(const std::string& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

size_t newline_count(const std::string& text) {
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::string relaxed_trefoil(const std::string& dir) {
  for (const std::string& args : {"embed 3_1 --from braid -n 96 -o " + dir + "/embedded.obj",
                                  "relax " + dir + "/embedded.obj -o " + dir + "/trefoil.obj"}) {
    const Result r = run(args);
    if (r.status != 0) throw std::runtime_error("knots " + args + ": " + r.err);
  }
  return dir + "/trefoil.obj";
}

}  // namespace ek::clitest
