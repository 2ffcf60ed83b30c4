#pragma once
// Runs the `knots` binary and captures exit status, stdout and stderr.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

/// The lines of a text file (none when it cannot be read).
std::vector<std::string> lines_of(const std::string& file);

/// The number of newline characters in `text` (a message's line count).
size_t newline_count(const std::string& text);

/// 3_1 embedded from its braid (96 vertices, DIR/embedded.obj) and relaxed
/// by the command (DIR/trefoil.obj); returns that path. Throws
/// std::runtime_error with the command's message when either fails.
std::string relaxed_trefoil(const std::string& dir);

}  // namespace ek::clitest
