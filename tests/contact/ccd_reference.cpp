#include "ccd_reference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>


namespace ek::ccdtest {

namespace {

Vec3 rvec(std::mt19937_64& rng, double s) {
  std::uniform_real_distribution<double> U(-s, s);
  return Vec3(U(rng), U(rng), U(rng));
}
Vec3 runit(std::mt19937_64& rng) {
  std::normal_distribution<double> N;
  return Vec3(N(rng), N(rng), N(rng)).normalized();
}
Vec3 ortho(const Vec3& u) {
  Vec3 v = std::abs(u.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (v - v.dot(u) * u).normalized();
}
double log_uniform(std::mt19937_64& rng, double lo_exp, double hi_exp) {
  return std::pow(10.0, std::uniform_real_distribution<double>(lo_exp, hi_exp)(rng));
}

// Start positions such that the pair is at (p0, p1, q0, q1) at time s*, with
// displacements V (random, magnitude ~speed).
Motion through(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, double s_star, const Vec3 V[4]) {
  Motion m;
  m.da0 = V[0];
  m.da1 = V[1];
  m.db0 = V[2];
  m.db1 = V[3];
  m.a0 = p0 - s_star * V[0];
  m.a1 = p1 - s_star * V[1];
  m.b0 = q0 - s_star * V[2];
  m.b1 = q1 - s_star * V[3];
  return m;
}

void random_velocities(std::mt19937_64& rng, Vec3 V[4], double speed, bool rigid_ish) {
  const Vec3 common = rvec(rng, speed);
  for (int k = 0; k < 4; ++k) V[k] = rigid_ish ? common + rvec(rng, 0.1 * speed) : rvec(rng, speed);
}

// coefficients of det[a1 − a0, b0 − a0, b1 − a0](s), lowest degree first
void coplanarity_cubic(const Motion& m, double c[4]) {
  const Vec3 u0 = m.a1 - m.a0, u1 = m.da1 - m.da0;
  const Vec3 v0 = m.b0 - m.a0, v1 = m.db0 - m.da0;
  const Vec3 w0 = m.b1 - m.a0, w1 = m.db1 - m.da0;
  c[0] = u0.dot(v0.cross(w0));
  c[1] = u1.dot(v0.cross(w0)) + u0.dot(v1.cross(w0)) + u0.dot(v0.cross(w1));
  c[2] = u1.dot(v1.cross(w0)) + u1.dot(v0.cross(w1)) + u0.dot(v1.cross(w1));
  c[3] = u1.dot(v1.cross(w1));
}

// Component k of (p − e0) × (e1 − e0) as a quadratic in s (c[3] = 0): zero
// whenever p lies on the line through e0, e1.
void point_line_quadratic(const Vec3& p, const Vec3& dp, const Vec3& e0, const Vec3& de0, const Vec3& e1,
                          const Vec3& de1, int k, double c[4]) {
  const Vec3 r0 = p - e0, r1 = dp - de0, f0 = e1 - e0, f1 = de1 - de0;
  const Vec3 q0 = r0.cross(f0), q1 = r1.cross(f0) + r0.cross(f1), q2 = r1.cross(f1);
  c[0] = q0(k);
  c[1] = q1(k);
  c[2] = q2(k);
  c[3] = 0.0;
}

double poly(const double c[4], double s) { return ((c[3] * s + c[2]) * s + c[1]) * s + c[0]; }

// Real roots in [0, t] of a polynomial of degree <= 3: split at the critical
// points (roots of the derivative), bisect every sign change, and keep
// critical points where it (nearly) vanishes (double roots: tangency).
std::vector<double> poly_roots(const double c[4], double t) {
  std::vector<double> knots = {0.0, t};
  const double A = 3 * c[3], B = 2 * c[2], C = c[1];
  if (A != 0.0) {
    const double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const double sq = std::sqrt(disc);
      for (double r : {(-B - sq) / (2 * A), (-B + sq) / (2 * A)})
        if (r > 0 && r < t) knots.push_back(r);
    }
  } else if (B != 0.0) {
    const double r = -C / B;
    if (r > 0 && r < t) knots.push_back(r);
  }
  std::sort(knots.begin(), knots.end());
  const double scale = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]);
  std::vector<double> roots;
  for (size_t k = 0; k < knots.size(); ++k) {
    if (std::abs(poly(c, knots[k])) <= 1e-12 * scale) roots.push_back(knots[k]);
    if (k + 1 == knots.size()) break;
    double lo = knots[k], hi = knots[k + 1];
    double flo = poly(c, lo);
    const double fhi = poly(c, hi);
    if ((flo < 0) == (fhi < 0) || flo == 0 || fhi == 0) continue;
    for (int it = 0; it < 200 && hi - lo > 1e-17 * (1 + hi); ++it) {
      const double mid = 0.5 * (lo + hi);
      const double fm = poly(c, mid);
      if ((fm < 0) == (flo < 0)) {
        lo = mid;
        flo = fm;
      } else {
        hi = mid;
      }
    }
    roots.push_back(lo);
    roots.push_back(hi);
  }
  return roots;
}

bool identically_zero(const double c[4], double scale) {
  return std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]) <= 1e-13 * scale;
}

}  // namespace

const char* category_name(int c) {
  static const char* names[kCategories] = {"crossing",           "grazing",      "parallel approach",
                                           "endpoint-endpoint",  "endpoint-interior", "nearly touching start",
                                           "rotating",           "random",       "parallel sliding",
                                           "tiny motion"};
  return names[c];
}

Motion random_motion(std::mt19937_64& rng, int c) {
  std::uniform_real_distribution<double> U01(0.0, 1.0);
  const double speed = log_uniform(rng, -2, 0.5);
  const double s_star = std::uniform_real_distribution<double>(0.02, 1.3)(rng);
  Vec3 V[4];
  random_velocities(rng, V, speed, U01(rng) < 0.5);
  switch (c) {
    case 0:
    case 1: {  // segments intersecting (0) or eps apart (1) at s*
      const Vec3 P = rvec(rng, 1.0), u = runit(rng), v = runit(rng);
      const double al = log_uniform(rng, -3, 0), be = log_uniform(rng, -3, 0);
      const double ga = log_uniform(rng, -3, 0), de = log_uniform(rng, -3, 0);
      Vec3 off = Vec3::Zero();
      if (c == 1) {
        Vec3 n = u.cross(v);
        n = n.norm() > 1e-12 ? n.normalized() : ortho(u);
        off = log_uniform(rng, -9, -2) * n;
      }
      return through(P - al * u, P + be * u, P - ga * v + off, P + de * v + off, s_star, V);
    }
    case 2: {  // parallel (or within 1e-12 .. 1e-2 rad), approaching to ±eps or 0
      const Vec3 u = runit(rng), n = ortho(u), w = u.cross(n);
      const double ang = U01(rng) < 0.3 ? 0.0 : log_uniform(rng, -12, -2);
      const Vec3 dir = std::cos(ang) * u + std::sin(ang) * w;
      const double la = log_uniform(rng, -2, 0.3), lb = log_uniform(rng, -2, 0.3);
      const double off = std::uniform_real_distribution<double>(-1.5, 1.5)(rng);
      const double h = U01(rng) < 0.3 ? 0.0 : (U01(rng) < 0.5 ? 1 : -1) * log_uniform(rng, -10, -2);
      const Vec3 P = rvec(rng, 1.0);
      Vec3 W[4];
      const Vec3 approach = -speed * n;  // b moves towards a along −n
      W[0] = W[1] = Vec3::Zero();
      W[2] = W[3] = approach;
      if (U01(rng) < 0.5)
        for (auto& w4 : W) w4 += rvec(rng, 0.05 * speed);
      return through(P, P + la * u, P + off * u + h * n, P + off * u + h * n + lb * dir, s_star, W);
    }
    case 3: {  // endpoint a1 meets endpoint b0 (or eps apart)
      const Vec3 P = rvec(rng, 1.0);
      const double eps = U01(rng) < 0.5 ? 0.0 : log_uniform(rng, -10, -3);
      return through(P - log_uniform(rng, -2, 0) * runit(rng), P, P + eps * runit(rng),
                     P + log_uniform(rng, -2, 0) * runit(rng), s_star, V);
    }
    case 4: {  // endpoint a0 meets the interior of b
      const Vec3 P = rvec(rng, 1.0), v = runit(rng);
      const double eps = U01(rng) < 0.5 ? 0.0 : log_uniform(rng, -10, -3);
      return through(P + eps * ortho(v), P + log_uniform(rng, -2, 0) * runit(rng), P - log_uniform(rng, -3, 0) * v,
                     P + log_uniform(rng, -3, 0) * v, s_star, V);
    }
    case 5: {  // nearly touching at s = 0
      const Vec3 P = rvec(rng, 1.0), u = runit(rng), v = runit(rng);
      Vec3 n = u.cross(v);
      n = n.norm() > 1e-12 ? n.normalized() : ortho(u);
      const double d0 = log_uniform(rng, -10, -3);
      return through(P - 0.5 * u, P + 0.5 * u, P - 0.4 * v + d0 * n, P + 0.6 * v + d0 * n, 0.0, V);
    }
    case 6: {  // rotating about the midpoints (endpoints move along chords) while approaching
      const Vec3 ca = rvec(rng, 0.5), cb = rvec(rng, 0.5);
      const Vec3 u0 = runit(rng), u1 = runit(rng), v0 = runit(rng), v1 = runit(rng);
      const double la = log_uniform(rng, -1, 0.3), lb = log_uniform(rng, -1, 0.3);
      const Vec3 dc = (cb - ca) * std::uniform_real_distribution<double>(0.0, 1.2)(rng);
      Motion m;
      m.a0 = ca - la * u0;
      m.a1 = ca + la * u0;
      m.b0 = cb - lb * v0;
      m.b1 = cb + lb * v0;
      m.da0 = dc + (-la * u1) - (-la * u0);
      m.da1 = dc + la * u1 - la * u0;
      m.db0 = -lb * v1 + lb * v0;
      m.db1 = lb * v1 - lb * v0;
      return m;
    }
    case 7: {
      Motion m{rvec(rng, 1), rvec(rng, 1), rvec(rng, 1), rvec(rng, 1),
               rvec(rng, 2), rvec(rng, 2), rvec(rng, 2), rvec(rng, 2)};
      return m;
    }
    case 8: {  // parallel at a small distance, sliding along each other
      const Vec3 u = runit(rng), n = ortho(u);
      const double h = log_uniform(rng, -8, -1);
      const double ang = U01(rng) < 0.5 ? 0.0 : log_uniform(rng, -10, -3);
      const Vec3 P = rvec(rng, 1.0);
      Motion m;
      m.a0 = P;
      m.a1 = P + u;
      m.b0 = P + h * n - 0.5 * u;
      m.b1 = m.b0 + (std::cos(ang) * u + std::sin(ang) * n);
      m.da0 = m.da1 = Vec3::Zero();
      m.db0 = m.db1 = std::uniform_real_distribution<double>(-2, 2)(rng) * u + 0.5 * h * rvec(rng, 1.0);
      return m;
    }
    default: {  // tiny or zero motion near contact
      const Vec3 P = rvec(rng, 1.0), u = runit(rng), v = runit(rng);
      const double d0 = log_uniform(rng, -6, -1);
      const double tiny = U01(rng) < 0.2 ? 0.0 : log_uniform(rng, -14, -4);
      Motion m{P - u, P + u, P - v + d0 * u.cross(v).normalized(), P + v + d0 * u.cross(v).normalized(),
               tiny * runit(rng), tiny * runit(rng), tiny * runit(rng), tiny * runit(rng)};
      return m;
    }
  }
}

namespace {

// Segment distance in long double (64-bit mantissa), its own implementation:
// the minimum of |r + u a − v b|² over the unit square, from the interior
// critical point or the four sides when sin²θ > 1e-6 (the interior solve is
// then accurate to ~(ε/sin²θ)² length², negligible), and for nearly parallel
// segments by golden-section search over u of the (convex) distance from
// a(u) to segment b, which has no conditioning problem.
using LD = long double;
struct L3 {
  LD x, y, z;
};
inline L3 operator-(const L3& p, const L3& q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
inline L3 operator+(const L3& p, const L3& q) { return {p.x + q.x, p.y + q.y, p.z + q.z}; }
inline L3 operator*(LD s, const L3& p) { return {s * p.x, s * p.y, s * p.z}; }
inline LD dot(const L3& p, const L3& q) { return p.x * q.x + p.y * q.y + p.z * q.z; }
// position at time s: x + s·dx, rounded once (as the solver computes it)
inline L3 at(const Vec3& x, const Vec3& dx, double s) {
  const Vec3 p = x + s * dx;
  return {p.x(), p.y(), p.z()};
}

LD point_segment2(const L3& p, const L3& e0, const L3& e1) {
  const L3 e = e1 - e0;
  const LD ee = dot(e, e);
  LD t = ee > 0 ? dot(p - e0, e) / ee : 0;
  t = std::min<LD>(1, std::max<LD>(0, t));
  const L3 w = p - (e0 + t * e);
  return dot(w, w);
}

LD segment_distance2(const L3& a0, const L3& a1, const L3& b0, const L3& b1) {
  const L3 a = a1 - a0, b = b1 - b0, r = a0 - b0;
  const LD A = dot(a, a), B = dot(b, b), C = dot(a, b), D = dot(a, r), F = dot(b, r);
  const LD det = A * B - C * C;
  if (A > 0 && B > 0 && det > 1e-6L * A * B) {
    const LD u = (C * F - D * B) / det, v = (A * F - C * D) / det;
    if (u >= 0 && u <= 1 && v >= 0 && v <= 1) {
      const L3 w = r + u * a - v * b;
      return dot(w, w);
    }
    return std::min(std::min(point_segment2(a0, b0, b1), point_segment2(a1, b0, b1)),
                    std::min(point_segment2(b0, a0, a1), point_segment2(b1, a0, a1)));
  }
  // nearly parallel: the distance from a(u) to segment b is convex in u;
  // golden-section search to the resolution of long double
  auto f = [&](LD u) { return point_segment2(a0 + u * a, b0, b1); };
  LD lo = 0, hi = 1;
  const LD g = 0.6180339887498948482L;
  LD m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo), f1 = f(m1), f2 = f(m2);
  for (int it = 0; it < 64; ++it) {  // bracket 0.618^64 ~ 4e-14: value error negligible (curvature <= 1e-6)
    if (f1 < f2) {
      hi = m2;
      m2 = m1;
      f2 = f1;
      m1 = hi - g * (hi - lo);
      f1 = f(m1);
    } else {
      lo = m1;
      m1 = m2;
      f1 = f2;
      m2 = lo + g * (hi - lo);
      f2 = f(m2);
    }
  }
  return std::min({f(lo), f(hi), f1, f2, f(0), f(1)});
}

}  // namespace

double distance_at(const Motion& m, double s) {
  return static_cast<double>(std::sqrt(segment_distance2(at(m.a0, m.da0, s), at(m.a1, m.da1, s),
                                                         at(m.b0, m.db0, s), at(m.b1, m.db1, s))));
}

Verdict check(const Motion& m, double t, double floor) {
  Verdict v;
  const double L = std::sqrt(std::max({(m.da0 - m.db0).squaredNorm(), (m.da0 - m.db1).squaredNorm(),
                                       (m.da1 - m.db0).squaredNorm(), (m.da1 - m.db1).squaredNorm()}));
  const double scale = 1.0 + m.a0.norm() + m.a1.norm() + m.b0.norm() + m.b1.norm() +
                       m.da0.norm() + m.da1.norm() + m.db0.norm() + m.db1.norm();
  const double tol = 1e-16 * scale;  // resolution of the long double distance of the rounded positions
  v.min_sampled = distance_at(m, 0.0);
  auto sample = [&](double s) {
    const double d = distance_at(m, s);
    v.min_sampled = std::min(v.min_sampled, d);
    if (d <= tol) v.touches = true;
    if (d < floor * (1 - 1e-9) - tol) v.below_floor = true;
    return d;
  };
  if (!(t > 0)) return v;
  // (1) Exact contact times. A touch at time s is (a) interior-interior of
  // non-parallel segments: the four points are coplanar (root of the cubic),
  // or (b) an endpoint on the other segment: (p − e0) × e = 0, so s is a root
  // of every non-vanishing component. In a motion that stays coplanar the
  // first contact always involves an endpoint (case b). Every candidate time
  // is checked with the exact distance.
  bool complete = true;
  double c[4];
  coplanarity_cubic(m, c);
  const bool planar = identically_zero(c, std::pow(scale, 3));
  if (!planar)
    for (double s : poly_roots(c, t)) {
      ++v.roots;
      sample(s);
    }
  const Vec3 P[4] = {m.a0, m.a1, m.b0, m.b1}, D[4] = {m.da0, m.da1, m.db0, m.db1};
  const int combos[4][3] = {{0, 2, 3}, {1, 2, 3}, {2, 0, 1}, {3, 0, 1}};
  for (const auto& cb : combos) {
    // the component with the largest coefficients
    double best[4] = {0, 0, 0, 0};
    double best_size = -1;
    for (int k = 0; k < 3; ++k) {
      double q[4];
      point_line_quadratic(P[cb[0]], D[cb[0]], P[cb[1]], D[cb[1]], P[cb[2]], D[cb[2]], k, q);
      const double size = std::abs(q[0]) + std::abs(q[1]) + std::abs(q[2]);
      if (size > best_size) {
        best_size = size;
        std::copy(q, q + 4, best);
      }
    }
    if (identically_zero(best, scale * scale)) {
      complete = false;  // the point stays on the line: no isolated contact times
      continue;
    }
    for (double s : poly_roots(best, t)) {
      ++v.roots;
      sample(s);
    }
  }
  // (2) The floor, at 128 uniform samples and around the sampled minimum.
  const int N = 128;
  double dmin = 1e300, smin = 0;
  for (int k = 0; k <= N; ++k) {
    const double s = t * k / N;
    const double d = sample(s);
    if (d < dmin) {
      dmin = d;
      smin = s;
    }
  }
  double lo = std::max(0.0, smin - t / N), hi = std::min(t, smin + t / N);
  for (int it = 0; it < 60; ++it) {  // golden-section refinement of the minimum
    const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
    if (sample(m1) < sample(m2)) hi = m2;
    else lo = m1;
  }
  // (3) Degenerate motions (a point stays on a line): certified sampling, with
  // d >= (d(s0) + d(s1) − L (s1 − s0))/2 between two samples.
  if (!complete) {
    struct Iv {
      double s0, s1, d0, d1;
      int depth;
    };
    std::vector<Iv> stack;
    for (int k = 0; k < 64; ++k) {
      const double s0 = t * k / 64, s1 = t * (k + 1) / 64;
      stack.push_back({s0, s1, distance_at(m, s0), distance_at(m, s1), 0});
    }
    long work = 0;
    while (!stack.empty()) {
      const Iv iv = stack.back();
      stack.pop_back();
      const double lb = 0.5 * (iv.d0 + iv.d1 - L * (iv.s1 - iv.s0));
      if (lb > tol) continue;
      if (iv.depth > 60 || ++work > 1000000) {
        v.uncertified = true;
        continue;
      }
      const double mid = 0.5 * (iv.s0 + iv.s1);
      const double dm = sample(mid);
      stack.push_back({iv.s0, mid, iv.d0, dm, iv.depth + 1});
      stack.push_back({mid, iv.s1, dm, iv.d1, iv.depth + 1});
    }
  }
  return v;
}

std::string Stats::summary() const {
  std::ostringstream o;
  o << motions << " motions: touches " << touches << ", below floor " << below_floor << ", uncertified "
    << uncertified << ", iteration cap " << capped << ", full step " << full_step << ", candidate contact times checked "
    << roots << ", mean t " << mean_t;
  return o.str();
}

Stats run_adversarial(std::uint64_t seed, long count, const CcdParams& params) {
  std::mt19937_64 rng(seed);
  Stats st;
  double sum_t = 0;
  for (long k = 0; k < count; ++k) {
    const int c = static_cast<int>(k % kCategories);
    const Motion m = random_motion(rng, c);
    const CcdResult r = edge_edge_ccd(m.a0, m.a1, m.b0, m.b1, m.da0, m.da1, m.db0, m.db1, 1.0, params);
    const Verdict v = check(m, r.t, r.floor);
    ++st.motions;
    ++st.per_category[c];
    st.touches += v.touches;
    st.below_floor += v.below_floor;
    st.uncertified += v.uncertified;
    st.capped += r.iterations >= params.max_iterations;
    st.full_step += r.t == 1.0;
    st.roots += v.roots;
    sum_t += r.t;
  }
  st.mean_t = count ? sum_t / count : 0;
  return st;
}

}  // namespace ek::ccdtest
