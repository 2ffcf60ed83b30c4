#pragma once
// The BFACF schedule's checks and helpers, shared by the knot and the link
// sampling (sampling.cpp, link_sampling.cpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "ek/core/errors.hpp"
#include "ek/lattice/sampling.hpp"

namespace ek::schedule {

/// InputError unless the options describe a possible schedule.
inline void validate(const SampleOptions& o) {
  require_input(o.vertices >= 4 && o.vertices % 2 == 0,
                "sampling: a lattice polygon has an even number >= 4 of vertices, got " + std::to_string(o.vertices));
  require_input(o.count >= 1, "sampling: the sample count must be >= 1, got " + std::to_string(o.count));
  require_input(std::isfinite(o.grow_fugacity) && o.grow_fugacity > kCriticalFugacity,
                "sampling: the growth fugacity must exceed the critical fugacity 0.2135");
  require_input(std::isfinite(o.shrink_fugacity) && o.shrink_fugacity > 0.0 && o.shrink_fugacity < kCriticalFugacity,
                "sampling: the shrink fugacity must be in (0, 0.2135)");
  require_input(std::isfinite(o.growth_factor) && o.growth_factor >= 1.0, "sampling: the growth factor must be >= 1");
  require_input(o.decorrelation_moves >= 0, "sampling: the decorrelation run must be >= 0 moves");
  require_input(std::isfinite(o.max_attempts_per_vertex) && o.max_attempts_per_vertex > 0.0,
                "sampling: the attempt budget must be positive");
  require_input(o.growth_factor * o.vertices < kMaxLatticeLength, "sampling: growth_factor · n is too large");
}

// Largest even number <= x, at least 4.
inline int even_floor(double x) { return std::max(4, 2 * static_cast<int>(std::floor(x / 2.0))); }

inline LatticePoints centered(LatticePoints L) {
  const Eigen::Vector3d c = L.cast<double>().colwise().mean();
  for (int k = 0; k < 3; ++k) L.col(k).array() -= static_cast<std::int32_t>(std::floor(c[k] + 0.5));
  return L;
}

inline long long budget(const SampleOptions& o, int target) {
  const double b = o.max_attempts_per_vertex * std::max(target, 4);
  return b > 9e18 ? static_cast<long long>(9e18) : static_cast<long long>(b);
}

}  // namespace ek::schedule
