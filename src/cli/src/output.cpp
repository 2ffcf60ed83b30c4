#include "output.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace ek::cli {

void print_json(const Json& j) { std::cout << j.dump() << std::endl; }

Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

std::string fmt(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

}  // namespace ek::cli
