// Distance kernels: values on known configurations, agreement with the
// geometry module's independent segment distance, and finite differences of
// the gradient and Hessian of every closest-feature case, including nearly
// parallel and nearly degenerate configurations.
#include <gtest/gtest.h>

#include <map>

#include "contact_test_util.hpp"
#include "ek/contact/distance.hpp"
#include "ek/geometry/segment_distance.hpp"

using namespace ek;
using namespace ek::contacttest;
using T = EdgeEdgeDistanceType;

namespace {

constexpr T kAllTypes[] = {T::EA_EB,   T::EA0_EB,  T::EA1_EB,  T::EA_EB0, T::EA_EB1,
                           T::EA0_EB0, T::EA0_EB1, T::EA1_EB0, T::EA1_EB1};

// FD check of the segment-pair trio for a fixed case at x; returns the best
// relative errors of gradient and Hessian.
std::pair<double, double> fd_errors(const X12& x, T type, std::initializer_list<double> steps) {
  auto f = [type](const X12& y) {
    const auto p = split(y);
    return edge_edge_distance_squared(p[0], p[1], p[2], p[3], type);
  };
  auto g = [type](const X12& y) -> X12 {
    const auto p = split(y);
    return edge_edge_distance_squared_gradient(p[0], p[1], p[2], p[3], type);
  };
  const auto p = split(x);
  const X12 G = g(x);
  const Mat12 H = edge_edge_distance_squared_hessian(p[0], p[1], p[2], p[3], type);
  const double eg = best_relative_error([&](double h) { return fd_grad<12>(f, x, h); }, G, steps);
  const double eh = best_relative_error([&](double h) { return fd_hess<12>(g, x, h); }, H, steps);
  return {eg, eh};
}

X12 random_pair(std::mt19937_64& rng) {
  return join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
}

}  // namespace

TEST(Distance, KnownValues) {
  // point-point, point-line
  EXPECT_DOUBLE_EQ(point_point_distance_squared({1, 2, 3}, {1, 2, 5}), 4.0);
  EXPECT_NEAR(point_line_distance_squared({0.3, 2, 0}, {0, 0, 0}, {1, 0, 0}), 4.0, 1e-15);
  EXPECT_NEAR(point_line_distance_squared({7, 1, 1}, {0, 0, 0}, {1, 0, 0}), 2.0, 1e-14);  // beyond the end: line
  // line-line: perpendicular lines 0.3 apart
  EXPECT_NEAR(line_line_distance_squared({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.3}, {0, 1, 0.3}), 0.09, 1e-15);
  // segments: each case
  const struct {
    Vec3 a0, a1, b0, b1;
    T type;
    double d2;
  } cases[] = {
      {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0.3}, {0, 1, 0.3}, T::EA_EB, 0.09},
      {{0, 0.5, 0.1}, {0, 2, 0.5}, {-1, 0, 0}, {1, 0, 0}, T::EA0_EB, 0.26},
      {{0, 2, 0.5}, {0, 0.5, 0.1}, {-1, 0, 0}, {1, 0, 0}, T::EA1_EB, 0.26},
      {{-1, 0, 0}, {1, 0, 0}, {0, 0.5, 0.1}, {0, 2, 0.5}, T::EA_EB0, 0.26},
      {{-1, 0, 0}, {1, 0, 0}, {0, 2, 0.5}, {0, 0.5, 0.1}, T::EA_EB1, 0.26},
      {{0, 0, 0}, {-1, -0.5, 0}, {0.3, 0.4, 0}, {1, 1, 0}, T::EA0_EB0, 0.25},
      {{0, 0, 0}, {-1, -0.5, 0}, {1, 1, 0}, {0.3, 0.4, 0}, T::EA0_EB1, 0.25},
      {{-1, -0.5, 0}, {0, 0, 0}, {0.3, 0.4, 0}, {1, 1, 0}, T::EA1_EB0, 0.25},
      {{-1, -0.5, 0}, {0, 0, 0}, {1, 1, 0}, {0.3, 0.4, 0}, T::EA1_EB1, 0.25},
  };
  for (const auto& c : cases) {
    const EdgeEdgeClosest cl = edge_edge_closest(c.a0, c.a1, c.b0, c.b1);
    EXPECT_EQ(cl.type, c.type) << to_string(c.type);
    EXPECT_NEAR(cl.distance_squared, c.d2, 1e-14) << to_string(c.type);
    EXPECT_NEAR(edge_edge_distance_squared(c.a0, c.a1, c.b0, c.b1, c.type), c.d2, 1e-14);
  }
  // exactly parallel, overlapping: an endpoint case with the right value
  const EdgeEdgeClosest par = edge_edge_closest({0, 0, 0}, {2, 0, 0}, {1, 0.3, 0}, {3, 0.3, 0});
  EXPECT_NE(par.type, T::EA_EB);
  EXPECT_NEAR(par.distance_squared, 0.09, 1e-15);
}

TEST(Distance, MatchesGeometryModuleOnRandomPairs) {
  // The geometry module's value-only routine is an independent implementation.
  std::mt19937_64 rng(11);
  std::map<T, int> seen;
  for (int k = 0; k < 20000; ++k) {
    X12 x = random_pair(rng);
    if (k % 4 == 1) {  // nearly parallel
      const Vec3 u = rand_unit(rng);
      const double eps = std::pow(10.0, -1.0 - 9.0 * (k % 97) / 96.0);
      x.segment<3>(3) = x.segment<3>(0) + 1.3 * u;
      x.segment<3>(9) = x.segment<3>(6) + 0.9 * (u + eps * rand_unit(rng)).normalized();
    }
    const auto p = split(x);
    const EdgeEdgeClosest cl = edge_edge_closest(p[0], p[1], p[2], p[3]);
    ++seen[cl.type];
    const double ref = segment_segment_distance_squared(p[0], p[1], p[2], p[3]);
    ASSERT_NEAR(cl.distance_squared, ref, 1e-12 * (1 + ref)) << k;
    // the chosen case's formula gives the same value
    ASSERT_NEAR(edge_edge_distance_squared(p[0], p[1], p[2], p[3], cl.type), cl.distance_squared, 1e-14);
  }
  for (T t : kAllTypes) EXPECT_GT(seen[t], 100) << to_string(t);
}

TEST(Distance, KernelTriosFiniteDifferences) {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 50; ++k) {
    const Vec3 p = rand_vec(rng), q = rand_vec(rng), e0 = rand_vec(rng), e1 = rand_vec(rng);
    // point-point
    using X6 = Eigen::Matrix<double, 6, 1>;
    X6 y6;
    y6 << p, q;
    auto f6 = [](const X6& y) { return point_point_distance_squared(y.segment<3>(0), y.segment<3>(3)); };
    auto g6 = [](const X6& y) -> X6 { return point_point_distance_squared_gradient(y.segment<3>(0), y.segment<3>(3)); };
    EXPECT_LT(best_relative_error([&](double h) { return fd_grad<6>(f6, y6, h); }, g6(y6)), 1e-8);
    EXPECT_LT(best_relative_error([&](double h) { return fd_hess<6>(g6, y6, h); },
                                  point_point_distance_squared_hessian(p, q)),
              1e-8);
    // point-line
    using X9 = Eigen::Matrix<double, 9, 1>;
    X9 y9;
    y9 << p, e0, e1;
    auto f9 = [](const X9& y) {
      return point_line_distance_squared(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6));
    };
    auto g9 = [](const X9& y) -> X9 {
      return point_line_distance_squared_gradient(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6));
    };
    const Mat9 H9 = point_line_distance_squared_hessian(p, e0, e1);
    ASSERT_GT(H9.norm(), 0.0);
    // relative errors: FD truncation ~h², rounding ~1e-16/h; 1e-7 leaves margin
    EXPECT_LT(best_relative_error([&](double h) { return fd_grad<9>(f9, y9, h); }, g9(y9)), 1e-7);
    EXPECT_LT(best_relative_error([&](double h) { return fd_hess<9>(g9, y9, h); }, H9), 1e-7);
    // point-line equals the cross-product formula |(p − e0) × e|² / |e|²
    const Vec3 e = e1 - e0;
    EXPECT_NEAR(point_line_distance_squared(p, e0, e1), (p - e0).cross(e).squaredNorm() / e.squaredNorm(), 1e-13);
    // line-line equals ((ea0 − eb0)·n)²/|n|²
    const Vec3 n = (e1 - e0).cross(q - p);
    const double ll = std::pow((e0 - p).dot(n), 2) / n.squaredNorm();
    EXPECT_NEAR(line_line_distance_squared(e0, e1, p, q), ll, 1e-12 * (1 + ll));
  }
}

TEST(Distance, EveryCaseFiniteDifferences) {
  // Random pairs, grouped by case; each case's formula is smooth, so its
  // derivatives are compared with central differences of the same case.
  std::mt19937_64 rng(7);
  std::map<T, int> tested;
  double worst_g = 0, worst_h = 0;
  for (int k = 0; k < 20000; ++k) {
    const X12 x = random_pair(rng);
    const auto p = split(x);
    const T type = edge_edge_distance_type(p[0], p[1], p[2], p[3]);
    if (tested[type] >= 25) continue;
    ++tested[type];
    const Vec12 G = edge_edge_distance_squared_gradient(p[0], p[1], p[2], p[3], type);
    const Mat12 H = edge_edge_distance_squared_hessian(p[0], p[1], p[2], p[3], type);
    ASSERT_GT(G.norm(), 0.0);
    ASSERT_GT(H.norm(), 0.0);
    const auto [eg, eh] = fd_errors(x, type, {1e-3, 1e-4, 1e-5, 1e-6});
    worst_g = std::max(worst_g, eg);
    worst_h = std::max(worst_h, eh);
    EXPECT_LT(eg, 1e-7) << to_string(type);  // relative error of the gradient
    EXPECT_LT(eh, 1e-6) << to_string(type);  // relative error of the Hessian
  }
  for (T t : kAllTypes) EXPECT_EQ(tested[t], 25) << to_string(t);
  RecordProperty("worst_gradient_error", std::to_string(worst_g));
  RecordProperty("worst_hessian_error", std::to_string(worst_h));
}

TEST(Distance, NearlyParallelAndNearlyDegenerateFiniteDifferences) {
  std::mt19937_64 rng(9);
  // Edge-edge interior for nearly parallel lines (sin² down to 1e-8): the
  // Hessian grows like 1/sin², the formula must stay exact.
  for (double sin_angle : {1e-1, 1e-2, 1e-3, 1e-4}) {
    for (int k = 0; k < 5; ++k) {
      const Vec3 u = rand_unit(rng), v = orthogonal(u), w = u.cross(v);
      const Vec3 c = rand_vec(rng);
      const Vec3 ea0 = c - 0.5 * u, ea1 = c + 0.5 * u;
      const Vec3 dir = (u + sin_angle * v).normalized();
      const Vec3 mid = c + 0.2 * w + 0.05 * k * u;
      const Vec3 eb0 = mid - 0.6 * dir, eb1 = mid + 0.6 * dir;
      const X12 x = join(ea0, ea1, eb0, eb1);
      ASSERT_EQ(edge_edge_distance_type(ea0, ea1, eb0, eb1), T::EA_EB);
      // steps must be small against the scale sin_angle on which the closest points move
      const double h0 = sin_angle * 1e-2;
      const auto [eg, eh] = fd_errors(x, T::EA_EB, {h0, h0 * 1e-1, h0 * 1e-2, h0 * 1e-3});
      EXPECT_LT(eg, 1e-6) << sin_angle;   // relative gradient error (steps down to 1e-9: rounding)
      EXPECT_LT(eh, 1e-5) << sin_angle;   // relative Hessian error (entries ~1/sin²)
    }
  }
  // Exactly parallel and nearly parallel segments (sin² below kParallelSin2)
  // use endpoint cases; those stay exact and smooth.
  for (double sin_angle : {0.0, 1e-9, 1e-7}) {
    const Vec3 u = rand_unit(rng), v = orthogonal(u);
    const Vec3 ea0 = Vec3::Zero(), ea1 = u;
    const Vec3 eb0 = 0.3 * v + 0.4 * u, eb1 = eb0 + (u + sin_angle * v).normalized() * 1.1;
    const T type = edge_edge_distance_type(ea0, ea1, eb0, eb1);
    EXPECT_NE(type, T::EA_EB) << sin_angle;
    EXPECT_NEAR(edge_edge_closest(ea0, ea1, eb0, eb1).distance_squared,
                segment_segment_distance_squared(ea0, ea1, eb0, eb1), 1e-14);
    const auto [eg, eh] = fd_errors(join(ea0, ea1, eb0, eb1), type, {1e-3, 1e-4, 1e-5, 1e-6});
    EXPECT_LT(eg, 1e-7);
    EXPECT_LT(eh, 1e-6);
  }
  // Closest points next to a case boundary (projection 1e-6 inside an end),
  // tiny distances and very short segments.
  for (double eps : {1e-3, 1e-6}) {
    const X12 x = join({-1, 0, 0}, {1, 0, 0}, {1 - eps, 0.2, 0.1}, {1 - eps + 0.3, 1.5, -0.4});
    const auto p = split(x);
    const T type = edge_edge_distance_type(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(type, T::EA_EB0);
    const auto [eg, eh] = fd_errors(x, type, {1e-4, 1e-5, 1e-6, 1e-7});
    EXPECT_LT(eg, 1e-7);
    EXPECT_LT(eh, 1e-6);
  }
  for (double d : {1e-2, 1e-4, 1e-6}) {
    const X12 x = join({-1, 0, 0}, {1, 0, 0}, {0.1, -1, d}, {-0.2, 1, d});
    const auto p = split(x);
    ASSERT_EQ(edge_edge_distance_type(p[0], p[1], p[2], p[3]), T::EA_EB);
    EXPECT_NEAR(edge_edge_closest(p[0], p[1], p[2], p[3]).distance_squared, d * d, 1e-15);
    const double h0 = d * 1e-2;
    const auto [eg, eh] = fd_errors(x, T::EA_EB, {h0, h0 * 0.1, h0 * 0.01});
    EXPECT_LT(eg, 1e-6);
    EXPECT_LT(eh, 1e-6);
  }
  {  // short segments (1e-3 long)
    const X12 x = join({0, 0, 0}, {1e-3, 2e-4, 0}, {5e-4, 1e-3, -3e-4}, {4e-4, -1e-3, 5e-4});
    const auto p = split(x);
    const T type = edge_edge_distance_type(p[0], p[1], p[2], p[3]);
    const auto [eg, eh] = fd_errors(x, type, {1e-6, 1e-7, 1e-8});
    EXPECT_LT(eg, 1e-6);
    EXPECT_LT(eh, 1e-5);
  }
}

TEST(Distance, PointEdgeCases) {
  std::mt19937_64 rng(5);
  std::map<PointEdgeDistanceType, int> seen;
  for (int k = 0; k < 300; ++k) {
    const Vec3 p = rand_vec(rng), e0 = rand_vec(rng), e1 = rand_vec(rng);
    const PointEdgeDistanceType type = point_edge_distance_type(p, e0, e1);
    ++seen[type];
    double t = 0;
    const double ref = point_segment_distance_squared(p, e0, e1, &t);
    EXPECT_NEAR(point_edge_distance_squared(p, e0, e1, type), ref, 1e-14);
    using X9 = Eigen::Matrix<double, 9, 1>;
    X9 y;
    y << p, e0, e1;
    auto f = [type](const X9& z) {
      return point_edge_distance_squared(z.segment<3>(0), z.segment<3>(3), z.segment<3>(6), type);
    };
    auto g = [type](const X9& z) -> X9 {
      return point_edge_distance_squared_gradient(z.segment<3>(0), z.segment<3>(3), z.segment<3>(6), type);
    };
    EXPECT_LT(best_relative_error([&](double h) { return fd_grad<9>(f, y, h); }, g(y)), 1e-7);
    EXPECT_LT(best_relative_error([&](double h) { return fd_hess<9>(g, y, h); },
                                  point_edge_distance_squared_hessian(p, e0, e1, type)),
              1e-6);
  }
  EXPECT_GT(seen[PointEdgeDistanceType::P_E], 30);
  EXPECT_GT(seen[PointEdgeDistanceType::P_E0], 30);
  EXPECT_GT(seen[PointEdgeDistanceType::P_E1], 30);
}

TEST(Distance, SegmentDistanceIsC1AcrossCaseBoundaries) {
  // Moving b's endpoint across the end of a (EA_EB0 -> EA1_EB0 ... ) and the
  // interior/endpoint boundary: the gradient of the true segment distance is
  // continuous (unique closest pair).
  std::mt19937_64 rng(21);
  int checked = 0;
  for (int k = 0; k < 60; ++k) {
    const X12 x0 = random_pair(rng);
    const X12 dir = random_pair(rng);
    // scan along a line in configuration space for a case change
    auto type_at = [&](double s) {
      const auto p = split(x0 + s * dir);
      return edge_edge_distance_type(p[0], p[1], p[2], p[3]);
    };
    double lo = 0, hi = 0;
    bool found = false;
    for (int i = 0; i < 200 && !found; ++i) {
      if (type_at(i * 0.01) != type_at((i + 1) * 0.01)) {
        lo = i * 0.01;
        hi = (i + 1) * 0.01;
        found = true;
      }
    }
    if (!found) continue;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (type_at(mid) == type_at(lo) ? lo : hi) = mid;
    }
    const auto pl = split(x0 + lo * dir), ph = split(x0 + hi * dir);
    const T tl = type_at(lo), th = type_at(hi);
    const Vec12 gl = edge_edge_distance_squared_gradient(pl[0], pl[1], pl[2], pl[3], tl);
    const Vec12 gh = edge_edge_distance_squared_gradient(ph[0], ph[1], ph[2], ph[3], th);
    // parallel segments are the only place where the gradient may jump
    const Vec3 a = pl[1] - pl[0], b = pl[3] - pl[2];
    if (a.cross(b).squaredNorm() < 1e-6 * a.squaredNorm() * b.squaredNorm()) continue;
    EXPECT_LT((gl - gh).norm(), 1e-6 * (1 + gl.norm())) << to_string(tl) << " -> " << to_string(th);
    ++checked;
  }
  EXPECT_GE(checked, 20);
}
