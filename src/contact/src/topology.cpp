#include "ek/contact/topology.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "ek/core/errors.hpp"

namespace ek {

CurveTopology CurveTopology::single(int n) {
  require(n >= 3, "CurveTopology::single: a closed curve needs at least 3 vertices, got " + std::to_string(n));
  return CurveTopology{{0, n}};
}

CurveTopology CurveTopology::from_sizes(const std::vector<int>& sizes) {
  CurveTopology t;
  t.starts.push_back(0);
  for (int s : sizes) t.starts.push_back(t.starts.back() + s);
  t.validate();
  return t;
}

void CurveTopology::validate() const {
  require(starts.size() >= 2, "CurveTopology: starts needs at least 2 entries (k + 1 for k components)");
  require(starts.front() == 0, "CurveTopology: starts[0] must be 0");
  for (size_t c = 0; c + 1 < starts.size(); ++c)
    require(starts[c + 1] - starts[c] >= 3, "CurveTopology: component " + std::to_string(c) +
                                                " has fewer than 3 vertices (starts must increase by >= 3)");
}

int CurveTopology::component(int v) const {
  if (starts.size() == 2) return 0;
  const auto it = std::upper_bound(starts.begin(), starts.end(), v);
  return static_cast<int>(it - starts.begin()) - 1;
}

int CurveTopology::next(int v) const {
  const int c = component(v);
  return v + 1 == starts[c + 1] ? starts[c] : v + 1;
}

int CurveTopology::prev(int v) const {
  const int c = component(v);
  return v == starts[c] ? starts[c + 1] - 1 : v - 1;
}

bool CurveTopology::excluded(int i, int j, int neighbors) const {
  const int c = component(i);
  if (component(j) != c) return false;
  const int m = starts[c + 1] - starts[c];
  const int d = std::abs(i - j);
  return std::min(d, m - d) <= neighbors;
}

}  // namespace ek
