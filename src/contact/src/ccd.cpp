#include "ek/contact/ccd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ek {

namespace {

struct State {
  double d;      // segment distance (for the stopping test)
  double lower;  // certified lower bound on it (for the steps)
  Vec3 n;        // unit vector from the closest point of B to that of A (zero if d = 0)
  double c[2][2];  // n·(a_i − b_j)
};

// Closest points, and the lower bound min over endpoint pairs of n·(a_i − b_j):
// for any unit n, |p − q| >= n·(p − q), which is bilinear in the segment
// parameters, hence >= its smallest corner value. This bound is rigorous
// whatever n is (each term is a dot product of endpoint differences, rounding
// ~1e-16 relative to the coordinates), unlike the distance formulas, which are
// ill-conditioned for nearly parallel segments; the steps below use it. Its
// tightness depends on n, taken along the closest pair and made exactly
// orthogonal to the segment(s) whose interior holds a closest point (for the
// interior case n = ±a×b/|a×b|), so that rounding in the closest points of
// nearly touching segments does not tilt it.
State closest(const Vec3* p) {
  using T = EdgeEdgeDistanceType;
  const EdgeEdgeClosest cl = edge_edge_closest(p[0], p[1], p[2], p[3]);
  double s = 0.0, t = 0.0;
  edge_edge_closest_parameters(p[0], p[1], p[2], p[3], cl.type, &s, &t);
  const Vec3 a = p[1] - p[0], b = p[3] - p[2];
  const Vec3 w = (p[0] + s * a) - (p[2] + t * b);
  Vec3 n = w;
  if (cl.type == T::EA_EB) {
    n = a.cross(b);
    if (n.dot(w) < 0.0) n = -n;
  } else if (cl.type == T::EA0_EB || cl.type == T::EA1_EB) {
    n = w - (w.dot(b) / b.squaredNorm()) * b;
  } else if (cl.type == T::EA_EB0 || cl.type == T::EA_EB1) {
    n = w - (w.dot(a) / a.squaredNorm()) * a;
  }
  if (!(n.squaredNorm() > 0.0) || !std::isfinite(n.squaredNorm())) n = w;
  State st;
  st.d = std::sqrt(cl.distance_squared);
  const double nn = n.norm();
  st.n = nn > 0.0 ? Vec3(n / nn) : Vec3::Zero();
  st.lower = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      st.c[i][j] = st.n.dot(p[i] - p[2 + j]);
      st.lower = std::min(st.lower, st.c[i][j]);
    }
  st.lower = std::max(0.0, std::min(st.lower, st.d));
  return st;
}

// Largest Δ such that the plane with normal n keeps every point of A at least
// δ above every point of B during [s, s + Δ]: n·(a_i(s') − b_j(s')) >= δ for
// the four endpoint pairs (i, j) and s' in the step. n·w is multilinear in
// the segment parameters and s', so the endpoint pairs at both ends of the
// step bound it; each condition is linear in Δ. 0 if it fails already at s.
double plane_step(const State& st, const Vec3* v, double delta) {
  double step = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double c = st.c[i][j];
      if (!(c >= delta)) return 0.0;
      const double r = st.n.dot(v[i] - v[2 + j]);
      if (r < 0.0) step = std::min(step, (c - delta) / -r);
    }
  return step;
}

}  // namespace

CcdResult edge_edge_ccd(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, const Vec3& da0,
                        const Vec3& da1, const Vec3& db0, const Vec3& db1, double t_max, const CcdParams& params) {
  CcdResult r;
  const Vec3 x0[4] = {a0, a1, b0, b1};
  const Vec3 v[4] = {da0, da1, db0, db1};
  State st = closest(x0);
  const double d0 = st.d;
  r.distance = d0;
  if (!(st.lower > 0.0) || !(t_max > 0.0)) return r;  // touching (or NaN): no step
  // the floor from the certified lower bound (equal to d0 up to rounding)
  const double delta = params.separation * std::min(st.lower, params.distance_cap);
  r.floor = delta;
  // Lipschitz constant of d(s): largest relative speed of two endpoints.
  const double L = std::sqrt(std::max({(da0 - db0).squaredNorm(), (da0 - db1).squaredNorm(),
                                       (da1 - db0).squaredNorm(), (da1 - db1).squaredNorm()}));
  if (L * t_max <= st.lower - delta) {  // cannot reach the floor before t_max
    r.t = t_max;
    return r;
  }
  const double stop = delta + params.tolerance * (d0 - delta);
  double t = 0.0;
  Vec3 x[4] = {a0, a1, b0, b1};
  for (int it = 0; it < params.max_iterations; ++it) {
    // Two certified steps, take the longer: the Lipschitz bound (d >= δ while
    // L·Δ <= d − δ) and the separating plane through the closest points.
    const double step = std::max((st.lower - delta) / L, plane_step(st, v, delta));
    if (!(step > 0.0)) break;  // at the floor (or rounding below it): keep t
    if (t + step >= t_max) {
      r.t = t_max;
      r.iterations = it;
      return r;
    }
    t += step;
    for (int k = 0; k < 4; ++k) x[k] = x0[k] + t * v[k];
    st = closest(x);
    r.iterations = it + 1;
    if (st.d <= stop) break;
  }
  r.t = t;
  return r;
}

}  // namespace ek
