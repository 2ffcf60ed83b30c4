#include "ek/analysis/symmetry.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

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

double rotational_symmetry_error(const Points& P, const Vec3& c, const Vec3& axis, int p) {
  require(P.rows() >= 3, "rotational_symmetry_error: a curve needs at least 3 vertices");
  return rotational_symmetry_error(Link{P}, c, axis, p);
}

double rotational_symmetry_error(const Link& link, const Vec3& c, const Vec3& axis, int p) {
  require(p >= 2, "rotational_symmetry_error: p must be at least 2");
  require(!link.empty(), "rotational_symmetry_error: a link needs a component");
  const Eigen::AngleAxisd R(2.0 * M_PI / p, axis.normalized());
  double rg = 0.0, sum = 0.0;
  Eigen::Index vertices = 0;
  for (const Points& P : link)
    for (Eigen::Index i = 0; i < P.rows(); ++i, ++vertices) rg += (P.row(i).transpose() - c).squaredNorm();
  rg = std::sqrt(rg / static_cast<double>(vertices));
  if (rg == 0.0) return 0.0;
  const NearestSegment segments(link);
  for (const Points& P : link)
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      const Vec3 q = c + R * (P.row(i).transpose() - c);
      sum += std::sqrt(std::min(1e300, segments.nearest(q).distance_squared));
    }
  return sum / static_cast<double>(vertices) / rg;
}

SymmetryAxis find_symmetry_axis(const Points& P, int p, const SymmetryAxisOptions& o) {
  require(o.step > 0.0 && o.max_tilt >= 0.0, "find_symmetry_axis: step must be > 0 and max_tilt >= 0");
  SymmetryAxis out;
  out.center = centroid(P);
  const Mat3 axes = principal_axes(P);
  const int k = static_cast<int>(std::lround(o.max_tilt / o.step));
  out.error = 1e300;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 e0 = axes.col(axis), e1 = e0.unitOrthogonal(), e2 = e0.cross(e1);
    for (int i = -k; i <= k; ++i)
      for (int q = -k; q <= k; ++q) {
        const Vec3 ax = (e0 + o.step * i * e1 + o.step * q * e2).normalized();
        const double err = rotational_symmetry_error(P, out.center, ax, p);
        if (err < out.error) {
          out.error = err;
          out.axis = ax;
        }
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
