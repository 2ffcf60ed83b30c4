#include <cstdlib>

#include "ek/core/config.hpp"
#include "ek/core/paths.hpp"

namespace ek {

std::string knot_table_path() {
  const char* env = std::getenv("KNOT_TABLE");
  if (env != nullptr && env[0] != '\0') return env;
  return config::kDefaultKnotTable;
}

std::string project_version() { return config::kVersion; }

}  // namespace ek
