#include "ek/geometry/convex_hull.hpp"

#include <cstdio>
#include <memory>
#include <numeric>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace ek {

namespace {

std::vector<Eigen::Index> every_index(Eigen::Index n) {
  std::vector<Eigen::Index> all(static_cast<size_t>(n));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  return all;
}

}  // namespace

std::vector<Eigen::Index> convex_hull_boundary_points(const Points& P) {
  const Eigen::Index n = P.rows();
  if (n < 5 || !P.allFinite()) return every_index(n);
  std::vector<coordT> coords(static_cast<size_t>(3 * n));
  for (Eigen::Index i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) coords[static_cast<size_t>(3 * i + k)] = P(i, k);
  // Qhull's error and trace messages go here: none of them is ours to print
  // (a flat input is an expected case, answered with every index)
  const std::unique_ptr<FILE, int (*)(FILE*)> null(std::fopen("/dev/null", "w"), &std::fclose);
  if (!null) return every_index(n);
  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, null.get());
  char options[] = "qhull Qc";  // Qc: keep the points within the tolerance of a facet (coplanar points)
  const int status = qh_new_qhull(qh, 3, static_cast<int>(n), coords.data(), False, options, nullptr, null.get());
  std::vector<char> on_boundary(static_cast<size_t>(n), 0);
  bool ok = status == 0;
  auto mark = [&](pointT* point) {
    const int id = qh_pointid(qh, point);
    if (id < 0 || id >= n) ok = false;
    else on_boundary[static_cast<size_t>(id)] = 1;
  };
  if (ok) {
    vertexT* vertex;
    FORALLvertices mark(vertex->point);
    facetT* facet;
    FORALLfacets {
      if (!facet->coplanarset) continue;
      pointT *point, **pointp;
      FOREACHpoint_(facet->coplanarset) mark(point);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (!ok) return every_index(n);
  std::vector<Eigen::Index> out;
  for (Eigen::Index i = 0; i < n; ++i)
    if (on_boundary[static_cast<size_t>(i)]) out.push_back(i);
  return out;
}

}  // namespace ek
