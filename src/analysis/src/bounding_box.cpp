#include "ek/analysis/bounding_box.hpp"

#include "ek/geometry/convex_hull.hpp"
#include "ek/geometry/polyline.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "ek/core/errors.hpp"

namespace ek {

namespace {

/// Two unit vectors completing u to a right-handed orthonormal frame (u, p, q).
void complete_frame(const Vec3& u, Vec3& p, Vec3& q) {
  Eigen::Index k = 0;
  u.cwiseAbs().minCoeff(&k);
  Vec3 e = Vec3::Zero();
  e(k) = 1.0;
  p = u.cross(e).normalized();
  q = u.cross(p);
}

/// 2D convex hull (Andrew's monotone chain), counterclockwise, no collinear points.
std::vector<Vec2> convex_hull(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Vec2> h(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0.0) --k;
    h[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0.0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

/// Minimum-area enclosing rectangle of a CCW convex polygon by rotating calipers:
/// returns its area, side lengths (w along dir, hgt across), unit side direction and centre.
struct Rect {
  double area = 0.0, w = 0.0, hgt = 0.0;
  Vec2 dir = Vec2(1.0, 0.0);
  Vec2 center = Vec2::Zero();
};

Rect min_area_rectangle(const std::vector<Vec2>& H) {
  Rect best;
  const size_t h = H.size();
  if (h == 0) return best;
  if (h == 1) {
    best.center = H[0];
    return best;
  }
  if (h == 2) {
    const Vec2 d = H[1] - H[0];
    best.w = d.norm();
    best.dir = best.w > 0.0 ? Vec2(d / best.w) : Vec2(1.0, 0.0);
    best.center = 0.5 * (H[0] + H[1]);
    return best;
  }
  best.area = std::numeric_limits<double>::infinity();
  auto nxt = [h](size_t i) { return (i + 1) % h; };
  size_t right = 0, top = 0, left = 0;
  for (size_t i = 0; i < h; ++i) {
    const Vec2 d = (H[nxt(i)] - H[i]).normalized();
    const Vec2 nrm(-d.y(), d.x());  // inward for a CCW polygon
    if (i == 0) {
      // initial pointers: maxima along d and nrm, minimum along d
      for (size_t j = 0; j < h; ++j) {
        if (d.dot(H[j]) > d.dot(H[right])) right = j;
        if (nrm.dot(H[j]) > nrm.dot(H[top])) top = j;
      }
      left = top;
      for (size_t j = 0; j < h; ++j)
        if (d.dot(H[j]) < d.dot(H[left])) left = j;
    } else {
      for (size_t s = 0; s < h && d.dot(H[nxt(right)]) >= d.dot(H[right]); ++s) right = nxt(right);
      for (size_t s = 0; s < h && nrm.dot(H[nxt(top)]) >= nrm.dot(H[top]); ++s) top = nxt(top);
      for (size_t s = 0; s < h && d.dot(H[nxt(left)]) <= d.dot(H[left]); ++s) left = nxt(left);
    }
    // both are >= 0 exactly for a convex CCW polygon; clamp rounding (thin hulls)
    const double w = std::max(0.0, d.dot(H[right] - H[left]));
    const double hgt = std::max(0.0, nrm.dot(H[top] - H[i]));
    const double area = w * hgt;
    if (area < best.area) {
      best.area = area;
      best.w = w;
      best.hgt = hgt;
      best.dir = d;
      const double dmid = 0.5 * (d.dot(H[right]) + d.dot(H[left]));
      const double nmid = nrm.dot(H[i]) + 0.5 * hgt;
      best.center = dmid * d + nmid * nrm;
    }
  }
  return best;
}

/// The minimal box having u as one axis.
struct AxisBox {
  double volume = 0.0;
  OrientedBox box;
};

AxisBox box_for_axis(const Points& P, const Vec3& u) {
  Vec3 p, q;
  complete_frame(u, p, q);
  const auto n = P.rows();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<Vec2> proj(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 x = P.row(i).transpose();
    const double h = u.dot(x);
    lo = std::min(lo, h);
    hi = std::max(hi, h);
    proj[static_cast<size_t>(i)] = Vec2(p.dot(x), q.dot(x));
  }
  const Rect r = min_area_rectangle(convex_hull(std::move(proj)));
  AxisBox out;
  const double hu = hi - lo;
  out.volume = hu * r.area;
  const Vec3 a1 = r.dir.x() * p + r.dir.y() * q;
  const Vec3 a2 = -r.dir.y() * p + r.dir.x() * q;
  std::array<std::pair<double, Vec3>, 3> ax = {{{hu, u}, {r.w, a1}, {r.hgt, a2}}};
  out.box.center = 0.5 * (hi + lo) * u + r.center.x() * p + r.center.y() * q;
  std::stable_sort(ax.begin(), ax.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  for (int k = 0; k < 3; ++k) {
    out.box.extents(k) = ax[static_cast<size_t>(k)].first;
    out.box.axes.col(k) = ax[static_cast<size_t>(k)].second;
  }
  if (out.box.axes.determinant() < 0.0) out.box.axes.col(2) *= -1.0;
  return out;
}

// search parameters of min_volume_bounding_box (documented in the header)
constexpr int kBoxDirections = 200;
constexpr int kBoxStarts = 6;
constexpr double kBoxStartSeparation = 0.3;  // [rad]
constexpr double kBoxInitialStep = 0.1;      // [rad] initial simplex edge
constexpr double kBoxFinalStep = 1e-7;       // [rad] simplex size
constexpr int kBoxMaxEvaluations = 300;

void check_points(const Points& P, const char* who) {
  require(P.rows() >= 1, std::string(who) + ": no points");
  require(P.allFinite(), std::string(who) + ": non-finite coordinates");
}

/// The principal axes (geometry's principal_axes), made a proper rotation.
Mat3 proper_principal_axes(const Points& P) {
  Mat3 A = principal_axes(P);
  if (A.determinant() < 0.0) A.col(0) *= -1.0;
  return A;
}

}  // namespace

OrientedBox pca_bounding_box(const Points& P) {
  check_points(P, "pca_bounding_box");
  const Mat3 A = proper_principal_axes(P);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    const Vec3 y = A.transpose() * P.row(i).transpose();
    lo = lo.cwiseMin(y);
    hi = hi.cwiseMax(y);
  }
  std::array<std::pair<double, Vec3>, 3> ax;
  for (int k = 0; k < 3; ++k) ax[static_cast<size_t>(k)] = {hi(k) - lo(k), A.col(k)};
  OrientedBox box;
  box.center = A * (0.5 * (lo + hi));
  std::stable_sort(ax.begin(), ax.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  for (int k = 0; k < 3; ++k) {
    box.extents(k) = ax[static_cast<size_t>(k)].first;
    box.axes.col(k) = ax[static_cast<size_t>(k)].second;
  }
  if (box.axes.determinant() < 0.0) box.axes.col(2) *= -1.0;
  return box;
}

namespace {

/// The search of min_volume_bounding_box(), from the principal axes A of all
/// the points, with every box evaluated over the points P.
OrientedBox search_min_volume_box(const Mat3& A, const Points& P) {
  // 1. global sampling: the PCA axes and kBoxDirections Fibonacci directions on
  //    the upper hemisphere (u and -u give the same box)
  struct Sample {
    double volume;
    Vec3 u;
  };
  std::vector<Sample> samples;
  for (int k = 0; k < 3; ++k) samples.push_back({box_for_axis(P, A.col(k)).volume, A.col(k)});
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < kBoxDirections; ++k) {
    const double z = 1.0 - (k + 0.5) / kBoxDirections;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Vec3 u(r * std::cos(golden * k), r * std::sin(golden * k), z);
    samples.push_back({box_for_axis(P, u).volume, u});
  }
  std::stable_sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.volume < b.volume; });
  // 2. the best samples that are at least kBoxStartSeparation apart (distinct basins)
  std::vector<Vec3> starts;
  for (const Sample& smp : samples) {
    bool near = false;
    for (const Vec3& u : starts) near = near || std::abs(u.dot(smp.u)) > std::cos(kBoxStartSeparation);
    if (!near) starts.push_back(smp.u);
    if (static_cast<int>(starts.size()) == kBoxStarts) break;
  }
  // 3. Nelder-Mead in the gnomonic chart u(x, y) = normalize(u0 + x p + y q) around each start
  AxisBox best;
  best.volume = std::numeric_limits<double>::infinity();
  for (const Vec3& u0 : starts) {
    Vec3 p, q;
    complete_frame(u0, p, q);
    auto at = [&](const Vec2& x) { return box_for_axis(P, (u0 + x.x() * p + x.y() * q).normalized()); };
    std::array<Vec2, 3> xs = {Vec2(0.0, 0.0), Vec2(kBoxInitialStep, 0.0), Vec2(0.0, kBoxInitialStep)};
    std::array<AxisBox, 3> fs = {at(xs[0]), at(xs[1]), at(xs[2])};
    int evaluations = 3;
    while (evaluations < kBoxMaxEvaluations) {
      // order: 0 best, 2 worst
      std::array<int, 3> o = {0, 1, 2};
      std::sort(o.begin(), o.end(), [&](int a, int b) { return fs[static_cast<size_t>(a)].volume < fs[static_cast<size_t>(b)].volume; });
      const std::array<Vec2, 3> x = {xs[static_cast<size_t>(o[0])], xs[static_cast<size_t>(o[1])], xs[static_cast<size_t>(o[2])]};
      const std::array<AxisBox, 3> f = {fs[static_cast<size_t>(o[0])], fs[static_cast<size_t>(o[1])], fs[static_cast<size_t>(o[2])]};
      xs = x;
      fs = f;
      const double size = std::max((xs[1] - xs[0]).norm(), (xs[2] - xs[0]).norm());
      if (size < kBoxFinalStep) break;
      const Vec2 c = 0.5 * (xs[0] + xs[1]);
      const Vec2 xr = c + (c - xs[2]);
      const AxisBox fr = at(xr);
      ++evaluations;
      if (fr.volume < fs[0].volume) {
        const Vec2 xe = c + 2.0 * (c - xs[2]);
        const AxisBox fe = at(xe);
        ++evaluations;
        if (fe.volume < fr.volume) {
          xs[2] = xe;
          fs[2] = fe;
        } else {
          xs[2] = xr;
          fs[2] = fr;
        }
      } else if (fr.volume < fs[1].volume) {
        xs[2] = xr;
        fs[2] = fr;
      } else {
        const bool outside = fr.volume < fs[2].volume;
        const Vec2 xc = outside ? Vec2(c + 0.5 * (xr - c)) : Vec2(c + 0.5 * (xs[2] - c));
        const AxisBox fc = at(xc);
        ++evaluations;
        if (fc.volume < (outside ? fr.volume : fs[2].volume)) {
          xs[2] = xc;
          fs[2] = fc;
        } else {  // shrink towards the best
          for (size_t k = 1; k < 3; ++k) {
            xs[k] = xs[0] + 0.5 * (xs[k] - xs[0]);
            fs[k] = at(xs[k]);
            ++evaluations;
          }
        }
      }
    }
    for (const AxisBox& f : fs)
      if (f.volume < best.volume) best = f;
  }
  return best.box;
}

}  // namespace

OrientedBox min_volume_bounding_box(const Points& P) {
  check_points(P, "min_volume_bounding_box");
  const std::vector<Eigen::Index> boundary = convex_hull_boundary_points(P);
  Points E(static_cast<Eigen::Index>(boundary.size()), 3);
  for (size_t k = 0; k < boundary.size(); ++k) E.row(static_cast<Eigen::Index>(k)) = P.row(boundary[k]);
  return search_min_volume_box(proper_principal_axes(P), E);
}

OrientedBox min_volume_bounding_box_all_points(const Points& P) {
  check_points(P, "min_volume_bounding_box_all_points");
  return search_min_volume_box(proper_principal_axes(P), P);
}

}  // namespace ek
