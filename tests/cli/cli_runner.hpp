#pragma once
// Runs the `knots` binary and captures exit status, stdout and stderr.
#include <nlohmann/json.hpp>
#include <string>

namespace ek::clitest {

struct Result {
  int status = -1;
  std::string out, err;
  nlohmann::json json() const { return nlohmann::json::parse(out); }
};

/// Runs `knots ARGS` (ARGS is passed to /bin/sh, quote accordingly). With
/// timeout_seconds > 0 the process is killed after that long (status 137).
Result run(const std::string& args, int timeout_seconds = 0);

/// A fresh temporary folder for one test.
std::string temp_dir(const std::string& name);

}  // namespace ek::clitest
