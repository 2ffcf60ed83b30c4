#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/diagram.hpp"

namespace ek {
namespace {

struct Crossing {
  int seg_a, seg_b;  // seg_a < seg_b
  double s, t;       // parameters along a and b
  bool a_over;
  int sign;
};

struct Projection {
  bool generic = true;
  std::vector<Crossing> crossings;
};

inline double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

/// The curve in the right-handed frame (u, v, d) of the view direction d:
/// plane coordinates (X, Y) and height H along d, per vertex.
struct ViewCoordinates {
  int n = 0;
  std::vector<double> X, Y, H;
  std::vector<int> succ;  ///< the vertex after each one on its closed polygon
  int next(int i) const { return succ[static_cast<size_t>(i)]; }
  /// Length of the projected edge i.
  double edge_length(int i) const {
    return std::hypot(X[static_cast<size_t>(next(i))] - X[static_cast<size_t>(i)],
                      Y[static_cast<size_t>(next(i))] - Y[static_cast<size_t>(i)]);
  }
};

/// succ[i]: the vertex after vertex i on its component (P holds the
/// components one after another).
std::vector<int> successors(const std::vector<int>& sizes) {
  std::vector<int> succ;
  int start = 0;
  for (const int size : sizes) {
    for (int k = 0; k < size; ++k) succ.push_back(start + (k + 1) % size);
    start += size;
  }
  return succ;
}

ViewCoordinates view_coordinates(const Points& P, const std::vector<int>& succ, const Vec3& dir) {
  ViewCoordinates c;
  c.n = static_cast<int>(P.rows());
  c.succ = succ;
  const Vec3 d = dir.normalized();
  Vec3 u = (std::fabs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(d).normalized();
  const Vec3 v = d.cross(u);
  u = v.cross(d);  // right-handed (u, v, d): u × v = d
  c.X.resize(static_cast<size_t>(c.n));
  c.Y.resize(static_cast<size_t>(c.n));
  c.H.resize(static_cast<size_t>(c.n));
  for (int i = 0; i < c.n; ++i) {
    const Vec3 p = P.row(i).transpose();
    c.X[static_cast<size_t>(i)] = p.dot(u);
    c.Y[static_cast<size_t>(i)] = p.dot(v);
    c.H[static_cast<size_t>(i)] = p.dot(d);
  }
  return c;
}

/// Projected edges must not vanish (length eps), and adjacent edges must not
/// fold back (sine of their angle below tol).
bool edges_generic(const ViewCoordinates& c, double eps, double tol) {
  const std::vector<double>& X = c.X;
  const std::vector<double>& Y = c.Y;
  for (int i = 0; i < c.n; ++i) {
    const double ex = X[static_cast<size_t>(c.next(i))] - X[static_cast<size_t>(i)];
    const double ey = Y[static_cast<size_t>(c.next(i))] - Y[static_cast<size_t>(i)];
    const double len = std::hypot(ex, ey);
    if (len < eps) return false;
    const int j = c.next(i);
    const double fx = X[static_cast<size_t>(c.next(j))] - X[static_cast<size_t>(j)];
    const double fy = Y[static_cast<size_t>(c.next(j))] - Y[static_cast<size_t>(j)];
    const double flen = std::hypot(fx, fy);
    if (std::fabs(cross2(ex, ey, fx, fy)) < tol * len * flen && ex * fx + ey * fy < 0.0) return false;
  }
  return true;
}

struct Box {
  double x0, x1, y0, y1;
};

/// The projected edges' boxes, inflated by eps.
std::vector<Box> edge_boxes(const ViewCoordinates& c, double eps) {
  const std::vector<double>& X = c.X;
  const std::vector<double>& Y = c.Y;
  std::vector<Box> box(static_cast<size_t>(c.n));
  for (int i = 0; i < c.n; ++i) {
    const size_t a = static_cast<size_t>(i), b = static_cast<size_t>(c.next(i));
    box[a] = {std::min(X[a], X[b]) - eps, std::max(X[a], X[b]) + eps, std::min(Y[a], Y[b]) - eps,
              std::max(Y[a], Y[b]) + eps};
  }
  return box;
}

enum class PairTest { Apart, Crossing, Degenerate };

/// Whether the projected edges a < b (not adjacent) cross; a crossing is
/// written to `out` (with its sign unless count_only). Degenerate: an endpoint
/// within eps of the other line near the other segment, nearly parallel
/// edges, or heights within eps at the crossing.
PairTest test_pair(const ViewCoordinates& c, int a, int b, double eps, double tol, bool count_only, Crossing& out) {
  const std::vector<double>& X = c.X;
  const std::vector<double>& Y = c.Y;
  const std::vector<double>& H = c.H;
  const size_t a0 = static_cast<size_t>(a), a1 = static_cast<size_t>(c.next(a));
  const size_t b0 = static_cast<size_t>(b), b1 = static_cast<size_t>(c.next(b));
  const double ax = X[a1] - X[a0], ay = Y[a1] - Y[a0];
  const double bx = X[b1] - X[b0], by = Y[b1] - Y[b0];
  const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
  // signed distances of b's endpoints to line a and of a's endpoints to line b
  const double o1 = cross2(ax, ay, X[b0] - X[a0], Y[b0] - Y[a0]) / la;
  const double o2 = cross2(ax, ay, X[b1] - X[a0], Y[b1] - Y[a0]) / la;
  const double o3 = cross2(bx, by, X[a0] - X[b0], Y[a0] - Y[b0]) / lb;
  const double o4 = cross2(bx, by, X[a1] - X[b0], Y[a1] - Y[b0]) / lb;
  const bool straddle_a = (o1 > 0) != (o2 > 0);
  const bool straddle_b = (o3 > 0) != (o4 > 0);
  // An endpoint within eps of the other line, near the other segment,
  // makes the crossing ambiguous.
  const bool near = std::fabs(o1) < eps || std::fabs(o2) < eps || std::fabs(o3) < eps || std::fabs(o4) < eps;
  if (near && (straddle_a || straddle_b)) return PairTest::Degenerate;
  if (!(straddle_a && straddle_b)) return PairTest::Apart;
  const double s = o3 / (o3 - o4);
  const double t = o1 / (o1 - o2);
  if (std::fabs(cross2(ax, ay, bx, by)) < tol * la * lb) return PairTest::Degenerate;
  const double ha = H[a0] + s * (H[a1] - H[a0]);
  const double hb = H[b0] + t * (H[b1] - H[b0]);
  if (std::fabs(ha - hb) < eps) return PairTest::Degenerate;
  out = Crossing{a, b, s, t, ha > hb, 0};
  if (!count_only) {
    // sign = sign of (over × under) · d in the right-handed (u, v, d) frame
    const double cr = out.a_over ? cross2(ax, ay, bx, by) : cross2(bx, by, ax, ay);
    out.sign = cr > 0 ? 1 : -1;
  }
  return PairTest::Crossing;
}

/// Two crossings at the same place of one edge (a triple point) are not
/// generic: false when two are within eps of each other along an edge.
bool crossings_apart(const ViewCoordinates& vc, const std::vector<Crossing>& crossings, double eps) {
  std::vector<std::pair<int, double>> at;  // (edge, arc position along it)
  for (const auto& c : crossings) {
    const auto la = vc.edge_length(c.seg_a);
    const auto lb = vc.edge_length(c.seg_b);
    at.emplace_back(c.seg_a, c.s * la);
    at.emplace_back(c.seg_b, c.t * lb);
  }
  std::sort(at.begin(), at.end());
  for (size_t k = 1; k < at.size(); ++k)
    if (at[k].first == at[k - 1].first && at[k].second - at[k - 1].second < eps) return false;
  return true;
}

/// Projects the closed polygons P (one after another, `succ` as
/// successors()) along d and finds all crossings; `generic` is false when the
/// projection is degenerate within tol (relative to the curves' size).
Projection project(const Points& P, const std::vector<int>& succ, const Vec3& dir, double tol, bool count_only) {
  Projection out;
  const int n = static_cast<int>(P.rows());
  const ViewCoordinates c = view_coordinates(P, succ, dir);
  const double scale = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
  const double eps = tol * scale;
  if (!edges_generic(c, eps, tol)) {
    out.generic = false;
    return out;
  }
  const std::vector<Box> box = edge_boxes(c, eps);
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return box[static_cast<size_t>(a)].x0 < box[static_cast<size_t>(b)].x0; });
  // sweep along x over the boxes' overlaps
  for (int oi = 0; oi < n; ++oi) {
    const int i = order[static_cast<size_t>(oi)];
    const Box& bi = box[static_cast<size_t>(i)];
    for (int oj = oi + 1; oj < n; ++oj) {
      const int j = order[static_cast<size_t>(oj)];
      const Box& bj = box[static_cast<size_t>(j)];
      if (bj.x0 > bi.x1) break;
      if (bj.y0 > bi.y1 || bi.y0 > bj.y1) continue;
      if (j == c.next(i) || i == c.next(j)) continue;  // adjacent edges meet only at their shared vertex
      Crossing x{};
      const PairTest t = test_pair(c, std::min(i, j), std::max(i, j), eps, tol, count_only, x);
      if (t == PairTest::Degenerate) {
        out.generic = false;
        return out;
      }
      if (t == PairTest::Crossing) out.crossings.push_back(x);
    }
  }
  if (!count_only && !crossings_apart(c, out.crossings, eps)) out.generic = false;
  return out;
}

Vec3 direction_from_seed(std::uint64_t& state) {
  auto next = [&state]() { return splitmix64_uniform(state); };
  const double zc = 2.0 * next() - 1.0, phi = 2.0 * M_PI * next();
  const double r = std::sqrt(std::max(0.0, 1.0 - zc * zc));
  return {r * std::cos(phi), r * std::sin(phi), zc};
}

}  // namespace

int projection_crossing_count(const Points& P, const Vec3& direction) {
  Projection p = project(P, successors({static_cast<int>(P.rows())}), direction, 1e-12, true);
  return static_cast<int>(p.crossings.size());
}

std::vector<ProjectedCrossing> projection_crossings(const Points& P, const Vec3& direction, bool* generic) {
  Projection p = project(P, successors({static_cast<int>(P.rows())}), direction, 1e-12, false);
  if (generic) *generic = p.generic;
  std::vector<ProjectedCrossing> out;
  if (!p.generic) return out;
  const int n = static_cast<int>(P.rows());
  for (const auto& c : p.crossings) {
    const Vec3 a = P.row(c.seg_a).transpose() + c.s * (P.row((c.seg_a + 1) % n) - P.row(c.seg_a)).transpose();
    const Vec3 b = P.row(c.seg_b).transpose() + c.t * (P.row((c.seg_b + 1) % n) - P.row(c.seg_b)).transpose();
    ProjectedCrossing x;
    x.over = c.a_over ? a : b;
    x.under = c.a_over ? b : a;
    x.over_edge = c.a_over ? c.seg_a : c.seg_b;
    x.under_edge = c.a_over ? c.seg_b : c.seg_a;
    x.sign = c.sign;
    out.push_back(x);
  }
  return out;
}

namespace {

/// A curve that (nearly) touches itself has no well-defined knot type.
void require_simple(const Points& P, double scale, const ProjectionOptions& options, const std::string& what) {
  const Clearance cl = clearance(P);
  if (cl.distance <= options.degeneracy * scale)
    throw InputError(what + " intersects itself (edges " + std::to_string(cl.edge_a + 1) + " and " +
                     std::to_string(cl.edge_b + 1) + " are " + std::to_string(cl.distance) + " apart)");
}

/// The generic projection with the fewest crossings among the first
/// `options.directions` generic ones of the direction sequence.
Projection best_projection(const Points& P, const std::vector<int>& succ, const ProjectionOptions& options,
                           const std::string& what) {
  require(options.directions >= 1, "diagram_from_curve: need at least one direction");
  std::uint64_t state = options.seed;
  Projection best;
  bool found = false;
  const int max_attempts = std::max(options.directions * 8, 64);
  int accepted = 0;
  for (int attempt = 0; attempt < max_attempts && accepted < options.directions; ++attempt) {
    const Vec3 d = direction_from_seed(state);
    Projection p = project(P, succ, d, options.degeneracy, false);
    if (!p.generic) continue;
    ++accepted;
    if (!found || p.crossings.size() < best.crossings.size()) {
      best = std::move(p);
      found = true;
    }
  }
  if (!found) throw InputError(what + " has no generic projection (it intersects itself or nearly so)");
  return best;
}

/// The crossings' visits in traversal order along each component; component
/// k owns the edges [start_k, start_k + sizes[k]) of the projected polygons.
std::vector<std::vector<GaussDiagram::Visit>> ordered_visits(const Projection& p, const std::vector<int>& sizes) {
  struct Visit {
    int seg;
    double param;
    int crossing;
    bool over;
  };
  std::vector<Visit> visits;
  visits.reserve(2 * p.crossings.size());
  for (size_t k = 0; k < p.crossings.size(); ++k) {
    const auto& c = p.crossings[k];
    visits.push_back({c.seg_a, c.s, static_cast<int>(k), c.a_over});
    visits.push_back({c.seg_b, c.t, static_cast<int>(k), !c.a_over});
  }
  std::sort(visits.begin(), visits.end(), [](const Visit& a, const Visit& b) {
    return a.seg != b.seg ? a.seg < b.seg : a.param < b.param;
  });
  std::vector<std::vector<GaussDiagram::Visit>> out(sizes.size());
  size_t component = 0;
  int end = sizes.empty() ? 0 : sizes[0];
  for (const auto& v : visits) {
    while (v.seg >= end) end += sizes[++component];
    out[component].push_back({v.crossing, v.over});
  }
  return out;
}

std::vector<int> signs_of(const Projection& p) {
  std::vector<int> signs;
  for (const auto& c : p.crossings) signs.push_back(c.sign);
  return signs;
}

}  // namespace

GaussDiagram diagram_from_curve(const Points& P, const ProjectionOptions& options) {
  require(P.rows() >= 3, "diagram_from_curve: need at least 3 vertices");
  const double scale = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
  require_simple(P, scale, options, "curve");
  const std::vector<int> sizes{static_cast<int>(P.rows())};
  const Projection best = best_projection(P, successors(sizes), options, "curve");
  GaussDiagram g;
  g.signs = signs_of(best);
  g.visits = ordered_visits(best, sizes)[0];
  return g;
}

LinkDiagram link_diagram_from_curves(const Link& link, const ProjectionOptions& options) {
  validate_link(link, "link");
  std::vector<int> sizes;
  for (const Points& P : link) sizes.push_back(static_cast<int>(P.rows()));
  const Points all = all_vertices(link);
  const double scale = (all.colwise().maxCoeff() - all.colwise().minCoeff()).norm();
  for (size_t k = 0; k < link.size(); ++k)
    require_simple(link[k], scale, options, "link component " + std::to_string(k + 1));
  const Projection best = best_projection(all, successors(sizes), options, "link");
  LinkDiagram d;
  d.signs = signs_of(best);
  d.components = ordered_visits(best, sizes);
  return d;
}

}  // namespace ek
