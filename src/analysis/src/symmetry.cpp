#include "ek/analysis/symmetry.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/nearest_segment.hpp"
#include "ek/knots/diagram.hpp"

namespace ek {

namespace {

double wrap(double a, double period) {  // to [-period/2, period/2)
  a = std::fmod(a, period);
  if (a < -period / 2) a += period;
  if (a >= period / 2) a -= period;
  return a;
}

}  // namespace

namespace {

/// r_g of the link's vertices about c, and their count.
double radius_of_gyration(const Link& link, const Vec3& c, Eigen::Index& vertices) {
  double rg = 0.0;
  vertices = 0;
  for (const Points& P : link)
    for (Eigen::Index i = 0; i < P.rows(); ++i, ++vertices) rg += (P.row(i).transpose() - c).squaredNorm();
  return std::sqrt(rg / static_cast<double>(vertices));
}

/// rotational_symmetry_error() with the link's segments, r_g (> 0) and vertex
/// count given; +∞ as soon as the error of the vertices seen so far exceeds
/// `bound`. The partial sums of the distances only grow (so do their
/// rounded values), so the whole error would exceed the bound too: a search
/// for the smallest error that passes its best so far gets the same answer.
double bounded_symmetry_error(const Link& link, const NearestSegment& segments, const Vec3& c, const Vec3& axis, int p,
                              double rg, Eigen::Index vertices, double bound) {
  const Eigen::AngleAxisd R(2.0 * M_PI / p, axis.normalized());
  const double n = static_cast<double>(vertices);
  double sum = 0.0;
  for (const Points& P : link)
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      const Vec3 q = c + R * (P.row(i).transpose() - c);
      sum += std::sqrt(std::min(1e300, segments.nearest(q).distance_squared));
      if (sum / n / rg > bound) return std::numeric_limits<double>::infinity();
    }
  return sum / n / rg;
}

}  // namespace

double rotational_symmetry_error(const Points& P, const Vec3& c, const Vec3& axis, int p) {
  require(P.rows() >= 3, "rotational_symmetry_error: a curve needs at least 3 vertices");
  return rotational_symmetry_error(Link{P}, c, axis, p);
}

double rotational_symmetry_error(const Link& link, const Vec3& c, const Vec3& axis, int p) {
  require(p >= 2, "rotational_symmetry_error: p must be at least 2");
  require(!link.empty(), "rotational_symmetry_error: a link needs a component");
  Eigen::Index vertices = 0;
  const double rg = radius_of_gyration(link, c, vertices);
  if (rg == 0.0) return 0.0;
  return bounded_symmetry_error(link, NearestSegment(link), c, axis, p, rg, vertices,
                                std::numeric_limits<double>::infinity());
}

SymmetryAxis find_symmetry_axis(const Points& P, int p, const SymmetryAxisOptions& o) {
  require(o.step > 0.0 && o.max_tilt >= 0.0, "find_symmetry_axis: step must be > 0 and max_tilt >= 0");
  require(P.rows() >= 3, "find_symmetry_axis: a curve needs at least 3 vertices");
  require(p >= 2, "find_symmetry_axis: p must be at least 2");
  SymmetryAxis out;
  out.center = centroid(P);
  const Mat3 axes = principal_axes(P);
  const int k = static_cast<int>(std::lround(o.max_tilt / o.step));
  const int side = 2 * k + 1;
  const Link link{P};
  Eigen::Index vertices = 0;
  const double rg = radius_of_gyration(link, out.center, vertices);
  const NearestSegment segments(link);
  // The grid in its order (principal axis, then i, then q); the answer is the
  // smallest error, the first in that order among equals. The three untilted
  // axes are tried first: their small errors let the others stop early.
  auto axis_at = [&](int g) {
    const int axis = g / (side * side), i = (g / side) % side - k, q = g % side - k;
    const Vec3 e0 = axes.col(axis), e1 = e0.unitOrthogonal(), e2 = e0.cross(e1);
    return Vec3((e0 + o.step * i * e1 + o.step * q * e2).normalized());
  };
  const int untilted = k * side + k;
  std::vector<int> order = {untilted, side * side + untilted, 2 * side * side + untilted};
  for (int g = 0; g < 3 * side * side; ++g)
    if (g % (side * side) != untilted) order.push_back(g);
  out.error = 1e300;
  int best = -1;
  for (const int g : order) {
    const Vec3 ax = axis_at(g);
    const double err = rg == 0.0 ? 0.0 : bounded_symmetry_error(link, segments, out.center, ax, p, rg, vertices, out.error);
    if (err < out.error || (err == out.error && g < best)) {
      out.error = err;
      out.axis = ax;
      best = g;
    }
  }
  return out;
}

Points symmetrize(const Points& P, const Vec3& c, const Vec3& axis, int p, int strands) {
  const Eigen::Index n = P.rows();
  require(p >= 1 && n % p == 0, "symmetrize: n must be divisible by p");
  const Vec3 a = axis.normalized();
  Points best;
  double best_move = 1e300;
  for (const double sense : {1.0, -1.0}) {
    Points Q = Points::Zero(n, 3);
    for (int k = 0; k < p; ++k) {
      const Eigen::AngleAxisd R(-sense * 2.0 * M_PI * k * strands / p, a);
      for (Eigen::Index i = 0; i < n; ++i)
        Q.row(i) += (c + R * (P.row((i + k * n / p) % n).transpose() - c)).transpose() / p;
    }
    const double move = (Q - P).rowwise().norm().maxCoeff();
    if (move < best_move) {
      best_move = move;
      best = Q;
    }
  }
  return best;
}

RegularPolygonFit fit_regular_polygon(const std::vector<double>& angles, int p) {
  require(p >= 1, "fit_regular_polygon: p must be at least 1");
  RegularPolygonFit g;
  g.count = static_cast<int>(angles.size());
  if (angles.empty()) return g;
  double cs = 0.0, sn = 0.0;
  for (double a : angles) {
    cs += std::cos(p * a);
    sn += std::sin(p * a);
  }
  g.phase = std::atan2(sn, cs) / p;
  for (double a : angles)
    g.max_error = std::max(g.max_error, std::fabs(wrap(a - g.phase, 2.0 * M_PI / p)) * 180.0 / M_PI);
  return g;
}

namespace {

/// Crossings of a generic projection within ~1e-4 rad of `axis`.
std::vector<ProjectedCrossing> crossings_along(const Points& P, const Vec3& axis) {
  Vec3 view = (axis + 1e-7 * Vec3(0.3, 0.7, 0.1)).normalized();
  bool generic = false;
  auto crossings = projection_crossings(P, view, &generic);
  for (int attempt = 1; !generic && attempt < 10; ++attempt) {
    view = (axis + 1e-5 * attempt * Vec3(0.3, -0.7, 0.2)).normalized();
    crossings = projection_crossings(P, view, &generic);
  }
  return crossings;
}

/// The two halves' p-gons of the crossing midpoints `mids` (relative to the
/// centre), split at the median height along `a` or distance from it.
std::pair<RegularPolygonFit, RegularPolygonFit> split_fit(const std::vector<Vec3>& mids, const Vec3& a, int p,
                                                          bool by_height) {
  const Vec3 u = a.unitOrthogonal(), v = a.cross(u);
  std::vector<double> key;
  for (const Vec3& mid : mids) key.push_back(by_height ? mid.dot(a) : (mid - mid.dot(a) * a).norm());
  std::vector<double> sorted = key;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  std::vector<double> hi, lo;
  for (size_t q = 0; q < mids.size(); ++q)
    (key[q] >= median ? hi : lo).push_back(std::atan2(mids[q].dot(v), mids[q].dot(u)));
  return {fit_regular_polygon(hi, p), fit_regular_polygon(lo, p)};
}

}  // namespace

CrossingPolygons crossing_polygons(const Points& P, const Vec3& c, const Vec3& axis, int p, double max_gap) {
  require(p >= 1, "crossing_polygons: p must be at least 1");
  const Vec3 a = axis.normalized();
  CrossingPolygons out;
  auto crossings = crossings_along(P, a);
  out.projected = static_cast<int>(crossings.size());
  crossings.erase(std::remove_if(crossings.begin(), crossings.end(),
                                 [&](const auto& x) { return std::fabs((x.over - x.under).dot(a)) > max_gap; }),
                  crossings.end());
  out.crossings = static_cast<int>(crossings.size());
  std::vector<Vec3> mids;
  for (const auto& x : crossings) mids.push_back(0.5 * (x.over + x.under) - c);
  std::tie(out.top, out.bottom) = split_fit(mids, a, p, true);
  const auto [rt, rb] = split_fit(mids, a, p, false);
  out.by_radius = std::max(rt.max_error, rb.max_error) < out.error();
  if (out.by_radius) {
    out.top = rt;
    out.bottom = rb;
  }
  out.rotation = std::fabs(wrap(out.top.phase - out.bottom.phase, 2.0 * M_PI / p)) * 180.0 / M_PI;
  return out;
}

}  // namespace ek
