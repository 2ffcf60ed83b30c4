#pragma once
// Shared checks of the numerical stress tests: every run ends with
// a status, nothing is NaN or infinite, the knot type is preserved.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>

#include "ek/solver/relax.hpp"

namespace ek::stress {

struct Tally {
  int runs = 0, topology_changes = 0, non_finite = 0;
  std::map<std::string, int> statuses;

  void add(const RelaxResult& r, const std::string& what) {
    const bool finite = r.positions.allFinite() && std::isfinite(r.energy.total) &&
                        std::isfinite(r.report.gradient_norm) && std::isfinite(r.link);
    add_logged(to_string(r.status()), finite, r.alexander_preserved, what);
  }

  /// One run given by its status, whether its results were finite and
  /// whether the knot type was kept (also a run read back from a log).
  void add_logged(const std::string& status, bool finite, bool preserved, const std::string& what) {
    ++runs;
    ++statuses[status];
    if (!finite) ++non_finite;
    if (!preserved) ++topology_changes;
    EXPECT_TRUE(finite) << what << ": non-finite result";
    EXPECT_TRUE(preserved) << what << ": Alexander polynomial changed";
    EXPECT_FALSE(status.empty()) << what;
  }

  void print(const std::string& title) const {
    std::cout << "[ stress   ] " << title << ": " << runs << " runs, topology changes " << topology_changes
              << ", non-finite " << non_finite;
    for (const auto& [s, c] : statuses) std::cout << ", " << s << " " << c;
    std::cout << std::endl;
  }
};

}  // namespace ek::stress
