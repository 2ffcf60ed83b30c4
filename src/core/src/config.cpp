#include <cstdlib>
#include <ctime>

#include "ek/core/config.hpp"
#include "ek/core/paths.hpp"

namespace ek {

std::string knot_table_path() {
  const char* env = std::getenv("KNOT_TABLE");
  if (env != nullptr && env[0] != '\0') return env;
  return config::kDefaultKnotTable;
}

std::string project_version() { return config::kVersion; }

std::string now_iso8601() {
  const std::time_t t = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

}  // namespace ek
