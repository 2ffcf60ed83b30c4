// Barrier, mollifier and pair energy: finite differences in every closest-
// feature case and in the nearly parallel band, C1 continuity where the
// plain barrier of the segment distance has a kink, growth at contact.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <map>

#include "contact_test_util.hpp"
#include "ek/contact/barrier.hpp"
#include "ek/geometry/segment_distance.hpp"

using namespace ek;
using namespace ek::contacttest;
using T = EdgeEdgeDistanceType;

namespace {

double pair_energy(const X12& x, const PairBarrierParams& p) {
  const auto v = split(x);
  return edge_edge_barrier(v[0], v[1], v[2], v[3], p);
}
X12 pair_gradient(const X12& x, const PairBarrierParams& p) {
  const auto v = split(x);
  return edge_edge_barrier_gradient(v[0], v[1], v[2], v[3], p);
}
Mat12 pair_hessian(const X12& x, const PairBarrierParams& p) {
  const auto v = split(x);
  return edge_edge_barrier_hessian(v[0], v[1], v[2], v[3], p);
}

// Case and band at x.
std::pair<T, bool> state(const X12& x, const PairBarrierParams& p) {
  const auto v = split(x);
  return {edge_edge_distance_type(v[0], v[1], v[2], v[3]),
          edge_edge_sin2(v[0], v[1], v[2], v[3]) < p.parallel_threshold};
}

// The case (and band membership) is the same at every point of the FD stencil.
bool stable(const X12& x, const PairBarrierParams& p, double h) {
  const auto s = state(x, p);
  for (int i = 0; i < 12; ++i)
    for (double sg : {-1.0, 1.0}) {
      X12 y = x;
      y(i) += sg * h;
      if (state(y, p) != s) return false;
    }
  return true;
}

struct FdErr {
  double g, h;
};
FdErr pair_fd(const X12& x, const PairBarrierParams& p, std::initializer_list<double> steps) {
  auto f = [&p](const X12& y) { return pair_energy(y, p); };
  auto g = [&p](const X12& y) -> X12 { return pair_gradient(y, p); };
  return {best_relative_error([&](double h) { return fd_grad<12>(f, x, h); }, g(x), steps),
          best_relative_error([&](double h) { return fd_hess<12>(g, x, h); }, pair_hessian(x, p), steps)};
}

// Nearly parallel pair: a = [0, u], b at offset `off` along u, height `hgt`
// along v, tilted by angle `ang` (rotated about its own midpoint), length lb.
X12 parallel_pair(const Vec3& u, const Vec3& v, double off, double hgt, double ang, double lb = 1.0) {
  const Vec3 dir = std::cos(ang) * u + std::sin(ang) * v;
  const Vec3 mid = (off + 0.5 * lb) * u + hgt * v;
  return join(Vec3::Zero(), u, mid - 0.5 * lb * dir, mid + 0.5 * lb * dir);
}

// A random nearly parallel pair (in the mollified band): b is a = [a0, a1]
// shifted by up to 0.1 and tilted by about 1e-3.
X12 random_nearly_parallel(std::mt19937_64& rng, const Vec3& a0, const Vec3& a1) {
  const Vec3 off = 0.1 * rand_vec(rng);
  return join(a0, a1, a0 + off, a1 + off + 1e-3 * rand_vec(rng));
}

}  // namespace

TEST(Barrier, ScalarBarrierAndDerivatives) {
  const double dhat = 0.4;
  EXPECT_EQ(barrier(dhat, dhat), 0.0);
  EXPECT_EQ(barrier(0.5, dhat), 0.0);
  EXPECT_EQ(barrier(0.0, dhat), std::numeric_limits<double>::infinity());
  for (double d : {1e-6, 1e-3, 0.05, 0.2, 0.39, 0.399999}) {
    EXPECT_GT(barrier(d, dhat), 0.0);
    EXPECT_LT(barrier_first_derivative(d, dhat), 0.0);   // decreasing
    EXPECT_GT(barrier_second_derivative(d, dhat), 0.0);  // convex
    // central differences, relative errors (truncation ~h²)
    const double h = 1e-6 * d;
    const double fd1 = (barrier(d + h, dhat) - barrier(d - h, dhat)) / (2 * h);
    const double fd2 = (barrier_first_derivative(d + h, dhat) - barrier_first_derivative(d - h, dhat)) / (2 * h);
    EXPECT_NEAR(fd1, barrier_first_derivative(d, dhat), 1e-6 * std::abs(fd1) + 1e-12);
    EXPECT_NEAR(fd2, barrier_second_derivative(d, dhat), 1e-5 * std::abs(fd2) + 1e-9);
  }
  // C2 at dhat: b, b', b'' tend to 0
  EXPECT_LT(barrier(dhat * (1 - 1e-5), dhat), 1e-15);
  EXPECT_LT(std::abs(barrier_first_derivative(dhat * (1 - 1e-5), dhat)), 1e-9);
  EXPECT_LT(std::abs(barrier_second_derivative(dhat * (1 - 1e-5), dhat)), 1e-4);
  // b grows without bound at contact (like d̂² ln(d̂/d))
  EXPECT_GT(barrier(1e-100, dhat), 0.15 * std::log(0.4e100));
}

TEST(Barrier, MollifierAndSin2FiniteDifferences) {
  const double eps = 1e-3;
  for (double c : {0.0, 1e-5, 3e-4, 9.99e-4}) {
    const double h = 1e-7 * eps;
    EXPECT_NEAR((parallel_mollifier(c + h, eps) - parallel_mollifier(c - h, eps)) / (2 * h),
                parallel_mollifier_first_derivative(c, eps), 1e-6 * 2 / eps);
    EXPECT_NEAR((parallel_mollifier_first_derivative(c + h, eps) - parallel_mollifier_first_derivative(c - h, eps)) /
                    (2 * h),
                parallel_mollifier_second_derivative(c, eps), 1e-6 * 2 / (eps * eps));
  }
  EXPECT_EQ(parallel_mollifier(0, eps), 0.0);
  EXPECT_EQ(parallel_mollifier(eps, eps), 1.0);
  EXPECT_NEAR(parallel_mollifier(eps * (1 - 1e-9), eps), 1.0, 1e-15);
  EXPECT_NEAR(parallel_mollifier_first_derivative(eps * (1 - 1e-9), eps), 0.0, 1e-5);

  std::mt19937_64 rng(2);
  for (int k = 0; k < 30; ++k) {
    X12 x = join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
    if (k % 3 == 0) x.segment<3>(9) = x.segment<3>(6) + (x.segment<3>(3) - x.segment<3>(0)) + 1e-3 * rand_vec(rng);
    auto f = [](const X12& y) {
      const auto v = split(y);
      return edge_edge_sin2(v[0], v[1], v[2], v[3]);
    };
    auto g = [](const X12& y) -> X12 {
      const auto v = split(y);
      Vec12 out;
      edge_edge_sin2(v[0], v[1], v[2], v[3], &out, nullptr);
      return out;
    };
    const auto v = split(x);
    Mat12 H;
    edge_edge_sin2(v[0], v[1], v[2], v[3], nullptr, &H);
    const Vec3 a = v[1] - v[0], b = v[3] - v[2];
    EXPECT_NEAR(f(x), 1.0 - std::pow(a.dot(b), 2) / (a.squaredNorm() * b.squaredNorm()), 1e-14);
    EXPECT_LT(best_relative_error([&](double h) { return fd_grad<12>(f, x, h); }, g(x)), 1e-6);
    EXPECT_LT(best_relative_error([&](double h) { return fd_hess<12>(g, x, h); }, H), 1e-6);
  }
}

TEST(Barrier, PairEnergyFiniteDifferencesInEveryCase) {
  // Random pairs with d̂ set between 1.2 and 3 times their distance, grouped
  // by closest-feature case; the FD stencil must stay in one case.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(1.2, 3.0);
  std::map<T, int> tested;
  double worst_g = 0, worst_h = 0;
  for (int k = 0; k < 50000; ++k) {
    const X12 x = join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
    const auto v = split(x);
    const EdgeEdgeClosest cl = edge_edge_closest(v[0], v[1], v[2], v[3]);
    if (tested[cl.type] >= 20) continue;
    PairBarrierParams p;
    p.dhat = std::sqrt(cl.distance_squared) * U(rng);
    if (state(x, p).second || !stable(x, p, 1e-4)) continue;  // the band is tested separately
    ++tested[cl.type];
    const Vec12 g = pair_gradient(x, p);
    ASSERT_GT(g.norm(), 0.0);
    const FdErr e = pair_fd(x, p, {1e-4, 1e-5, 1e-6});
    worst_g = std::max(worst_g, e.g);
    worst_h = std::max(worst_h, e.h);
    EXPECT_LT(e.g, 1e-6) << to_string(cl.type);  // relative gradient error
    EXPECT_LT(e.h, 1e-5) << to_string(cl.type);  // relative Hessian error
  }
  for (T t : {T::EA_EB, T::EA0_EB, T::EA1_EB, T::EA_EB0, T::EA_EB1, T::EA0_EB0, T::EA0_EB1, T::EA1_EB0, T::EA1_EB1})
    EXPECT_EQ(tested[t], 20) << to_string(t);
  RecordProperty("worst_gradient_error", std::to_string(worst_g));
  RecordProperty("worst_hessian_error", std::to_string(worst_h));
}

TEST(Barrier, PairEnergyFiniteDifferencesNearlyParallel) {
  // Inside the mollified band (sin² < ε = 1e-3): exactly parallel, 1e-8 ..
  // 5e-4, overlapping with an offset, aligned, nested, disjoint; distances 0.05
  // to 0.35 with d̂ = 0.4.
  std::mt19937_64 rng(23);
  PairBarrierParams p;
  int tested = 0;
  for (double sin2 : {0.0, 1e-8, 1e-6, 1e-4, 5e-4, 9e-4}) {
    for (double off : {-0.7, -0.3, 0.0, 0.25, 0.9}) {
      for (double hgt : {0.05, 0.2, 0.35}) {
        const Vec3 u = rand_unit(rng), v = orthogonal(u);
        const double lb = off == 0.25 ? 0.5 : 1.0;  // nested short segment
        const X12 x = parallel_pair(u, v, off, hgt, std::asin(std::sqrt(sin2)), lb);
        ASSERT_TRUE(state(x, p).second);
        // steps below the angle scale so the stencil stays in the band and in one case
        double h0 = 1e-5;
        while (h0 > 1e-9 && !stable(x, p, h0)) h0 *= 0.1;
        if (h0 <= 1e-9) continue;
        ++tested;
        const FdErr e = pair_fd(x, p, {h0, 0.1 * h0, 0.01 * h0});
        EXPECT_LT(e.g, 1e-6) << sin2 << " " << off << " " << hgt;  // relative gradient error
        EXPECT_LT(e.h, 1e-4) << sin2 << " " << off << " " << hgt;  // relative Hessian error
      }
    }
  }
  EXPECT_GE(tested, 60);  // of 90; the others have a case change within 1e-9
}

TEST(Barrier, MollifierRemovesTheParallelKink) {
  // Tilt segment b through exactly parallel (angle −δ .. δ): the plain
  // barrier of the segment distance has a gradient jump of order |b'|·length
  // there; the pair energy's gradient is continuous.
  const PairBarrierParams p;
  const Vec3 u(1, 0, 0), v(0, 1, 0);
  for (double off : {-0.4, 0.3}) {
    auto plain_grad = [&](double ang) {
      const auto x = split(parallel_pair(u, v, off, 0.3, ang));
      const T type = edge_edge_distance_type(x[0], x[1], x[2], x[3]);
      const double s = edge_edge_distance_squared(x[0], x[1], x[2], x[3], type);
      const Vec12 gs = edge_edge_distance_squared_gradient(x[0], x[1], x[2], x[3], type);
      const double d = std::sqrt(s);
      return Vec12(barrier_first_derivative(d, p.dhat) / (2 * d) * gs);
    };
    for (double delta : {1e-4, 1e-6, 1e-8}) {
      const Vec12 jump_plain = plain_grad(delta) - plain_grad(-delta);
      const Vec12 jump = pair_gradient(parallel_pair(u, v, off, 0.3, delta), p) -
                         pair_gradient(parallel_pair(u, v, off, 0.3, -delta), p);
      EXPECT_GT(jump_plain.norm(), 0.05) << "the kink being removed exists";
      EXPECT_LT(jump.norm(), 200.0 * delta) << delta;  // O(δ): continuous gradient
    }
  }
}

TEST(Barrier, ContinuousAtTheBandEdge) {
  const PairBarrierParams p;
  const Vec3 u(0, 0, 1), v(1, 0, 0);
  for (double off : {-0.5, 0.2}) {
    const double a_in = std::asin(std::sqrt(p.parallel_threshold * (1 - 1e-9)));
    const double a_out = std::asin(std::sqrt(p.parallel_threshold * (1 + 1e-9)));
    const X12 xi = parallel_pair(u, v, off, 0.25, a_in), xo = parallel_pair(u, v, off, 0.25, a_out);
    EXPECT_NEAR(pair_energy(xi, p), pair_energy(xo, p), 1e-8);
    EXPECT_LT((pair_gradient(xi, p) - pair_gradient(xo, p)).norm(), 1e-6);
  }
}

TEST(Barrier, GrowsWithoutBoundAtContact) {
  const PairBarrierParams p;
  const Vec3 u(1, 0, 0), v(0, 1, 0), w(0, 0, 1);
  struct Config {
    const char* name;
    std::function<X12(double)> at;  // pair at distance d
  };
  const Config configs[] = {
      {"crossing", [&](double d) { return join(-u, u, -v + d * w, v + d * w); }},
      {"small angle crossing", [&](double d) {
         const Vec3 dir = (u + 0.01 * v).normalized();
         return join(-u, u, -dir + d * w, dir + d * w);
       }},
      {"parallel overlap", [&](double d) { return parallel_pair(u, w, 0.4, d, 0.0); }},
      {"parallel aligned", [&](double d) { return parallel_pair(u, w, 0.0, d, 0.0); }},
      {"endpoint to endpoint", [&](double d) { return join(Vec3::Zero(), -u - v, d * w, u + v + d * w); }},
      {"endpoint to interior", [&](double d) { return join(d * v, 2 * v + w, -u, u); }},
  };
  for (const Config& c : configs) {
    double prev = 0, factor = 0;
    for (double d : {0.3, 1e-2, 1e-4, 1e-8, 1e-16}) {
      const auto x = split(c.at(d));
      ASSERT_NEAR(std::sqrt(segment_segment_distance_squared(x[0], x[1], x[2], x[3])), d, 1e-12 + 1e-9 * d) << c.name;
      const double e = pair_energy(c.at(d), p);
      const double m = parallel_mollifier(edge_edge_sin2(x[0], x[1], x[2], x[3]), p.parallel_threshold);
      EXPECT_GT(e, prev) << c.name << " " << d;
      // at least half the barrier of the distance when the closest points
      // include an endpoint (it is one of the d_k), m times it otherwise
      const bool interior = edge_edge_distance_type(x[0], x[1], x[2], x[3]) == T::EA_EB;
      factor = interior ? m : 0.5;
      EXPECT_GE(e, factor * barrier(d, p.dhat) * (1 - 1e-12)) << c.name << " " << d;
      prev = e;
    }
    // unbounded: at d = 1e-16 already factor · 0.16 · ln(4e15)
    EXPECT_GT(prev, factor * 0.9 * 0.16 * std::log(0.4e16)) << c.name;
    EXPECT_GT(factor, 0.1) << c.name;
  }
}

TEST(Barrier, ZeroBeyondDhatAndPsdProjection) {
  const PairBarrierParams p;
  EXPECT_EQ(pair_energy(join({0, 0, 0}, {1, 0, 0}, {0, 0.5, 0}, {1, 0.6, 0}), p), 0.0);
  EXPECT_EQ(pair_gradient(join({0, 0, 0}, {1, 0, 0}, {0, 0.5, 0}, {1, 0.6, 0}), p).norm(), 0.0);
  std::mt19937_64 rng(4);
  int indefinite = 0;
  for (int k = 0; k < 50; ++k) {
    const X12 x = join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
    const auto v = split(x);
    PairBarrierParams q;
    q.dhat = 2.0 * std::sqrt(edge_edge_closest(v[0], v[1], v[2], v[3]).distance_squared);
    Mat12 H = pair_hessian(x, q);
    const double lmin = Eigen::SelfAdjointEigenSolver<Mat12>(H).eigenvalues().minCoeff();
    if (lmin < -1e-9 * H.norm()) ++indefinite;
    const Mat12 H0 = H;
    project_to_psd(H);
    const Eigen::SelfAdjointEigenSolver<Mat12> es(H);
    EXPECT_GE(es.eigenvalues().minCoeff(), -1e-10 * H.norm());
    if (lmin >= 0) {
      EXPECT_LT((H - H0).norm(), 1e-12 * H0.norm());
    }
    // the projection keeps the positive part: H − H0 is PSD
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat12>(H - H0).eigenvalues().minCoeff(), -1e-9 * H0.norm());
  }
  EXPECT_GT(indefinite, 5);  // the barrier Hessian is often indefinite: the projection matters
}

// The pair Hessian annihilates translations, so its projection in the
// 9-dimensional complement equals the full 12 by 12 projection up to
// round-off, for crossing and nearly parallel (mollified) pairs alike.
TEST(Barrier, TranslationInvariantProjectionEqualsTheFullOne) {
  std::mt19937_64 rng(9);
  Eigen::Matrix<double, 12, 3> translations;
  for (int p = 0; p < 4; ++p) translations.block<3, 3>(3 * p, 0).setIdentity();
  int indefinite = 0;
  for (int k = 0; k < 200; ++k) {
    X12 x = join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
    if (k % 4 == 0) {
      const auto v = split(x);
      x = random_nearly_parallel(rng, v[0], v[1]);
    }
    const auto v = split(x);
    PairBarrierParams q;
    q.dhat = 2.0 * std::sqrt(edge_edge_closest(v[0], v[1], v[2], v[3]).distance_squared);
    const Mat12 H = pair_hessian(x, q);
    ASSERT_TRUE(H.allFinite());
    EXPECT_LT((H * translations).norm(), 1e-9 * H.norm()) << k;
    if (Eigen::SelfAdjointEigenSolver<Mat12>(H).eigenvalues().minCoeff() < -1e-9 * H.norm()) ++indefinite;
    Mat12 full = H, reduced = H;
    project_to_psd(full);
    project_translation_invariant_to_psd(reduced);
    EXPECT_LT((reduced - full).norm(), 1e-10 * H.norm()) << k;
    EXPECT_LT((reduced * translations).norm(), 1e-10 * H.norm()) << k;
    EXPECT_LT((reduced - reduced.transpose()).norm(), 1e-12 * H.norm()) << k;
  }
  EXPECT_GT(indefinite, 50);
}

// The projected pair Hessian (computed in the at most 5-dimensional range of
// the structured Hessian, or in the translation complement in the nearly
// parallel band) equals project_to_psd of the exact Hessian up to round-off,
// for every closest-feature type: random pairs (mostly interior–interior),
// pairs whose closest points are endpoints (edge b beyond the end of a,
// sideways), nearly parallel pairs; the gradient and value are unchanged.
TEST(Barrier, ProjectedHessianEqualsTheProjectionOfTheExactOne) {
  std::mt19937_64 rng(21);
  std::array<int, 6> types{};
  for (int k = 0; k < 400; ++k) {
    X12 x = join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
    auto v = split(x);
    if (k % 4 == 1) {  // b starts beyond a's end: vertex–edge or vertex–vertex closest features
      const Vec3 a = v[1] - v[0];
      x = join(v[0], v[1], v[1] + 0.3 * a + 0.2 * rand_vec(rng), v[1] + 1.5 * a + rand_vec(rng));
    } else if (k % 4 == 2) {
      x = random_nearly_parallel(rng, v[0], v[1]);
    }
    v = split(x);
    const EdgeEdgeClosest cl = edge_edge_closest(v[0], v[1], v[2], v[3]);
    ++types[static_cast<size_t>(cl.type) % types.size()];
    PairBarrierParams q;
    q.dhat = 2.0 * std::sqrt(cl.distance_squared);
    Vec12 g0, g1;
    Mat12 H0, H1;
    const double e0 = edge_edge_barrier_derivatives(v[0], v[1], v[2], v[3], q, &g0, &H0, 3.0);
    const double e1 = edge_edge_barrier_derivatives(v[0], v[1], v[2], v[3], q, &g1, &H1, 3.0, true);
    EXPECT_EQ(e0, e1);
    EXPECT_EQ(g0, g1);
    Mat12 P = H0;
    project_to_psd(P);
    EXPECT_LT((H1 - P).norm(), 1e-9 * H0.norm()) << k;
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat12>(H1).eigenvalues().minCoeff(), -1e-10 * H0.norm()) << k;
  }
  int kinds = 0;
  for (int c : types) kinds += c > 0;
  EXPECT_GE(kinds, 3);  // interior–interior and at least two endpoint cases
}

// The Gauss–Newton pair Hessian is w b''(d) ∇d ∇dᵀ with ∇d read from the
// gradient (w b'(d) ∇d): rank one and positive semidefinite, for every
// closest-feature type; in the nearly parallel band it is the projected
// Hessian. Value and gradient are those of the exact call.
TEST(Barrier, GaussNewtonHessianIsTheOuterProductOfTheDistanceGradient) {
  std::mt19937_64 rng(22);
  int band = 0, outside = 0;
  for (int k = 0; k < 400; ++k) {
    X12 x = join(rand_vec(rng), rand_vec(rng), rand_vec(rng), rand_vec(rng));
    auto v = split(x);
    if (k % 4 == 1) {
      const Vec3 a = v[1] - v[0];
      x = join(v[0], v[1], v[1] + 0.3 * a + 0.2 * rand_vec(rng), v[1] + 1.5 * a + rand_vec(rng));
    } else if (k % 4 == 2) {
      x = random_nearly_parallel(rng, v[0], v[1]);
    }
    v = split(x);
    const double d = std::sqrt(edge_edge_closest(v[0], v[1], v[2], v[3]).distance_squared);
    PairBarrierParams q;
    q.dhat = 2.0 * d;
    const double w = 3.0;
    Vec12 g0, g1;
    Mat12 H0, H1, Hp;
    const double e0 = edge_edge_barrier_derivatives(v[0], v[1], v[2], v[3], q, &g0, &H0, w, PairHessian::Exact);
    const double e1 = edge_edge_barrier_derivatives(v[0], v[1], v[2], v[3], q, &g1, &H1, w, PairHessian::GaussNewton);
    edge_edge_barrier_derivatives(v[0], v[1], v[2], v[3], q, nullptr, &Hp, w, PairHessian::Projected);
    EXPECT_EQ(e0, e1);
    EXPECT_EQ(g0, g1);
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat12>(H1).eigenvalues().minCoeff(), -1e-10 * H1.norm()) << k;
    if (edge_edge_sin2(v[0], v[1], v[2], v[3]) < q.parallel_threshold) {
      ++band;
      EXPECT_EQ(H1, Hp) << k;
      continue;
    }
    ++outside;
    const double b1 = barrier_first_derivative(d, q.dhat), b2 = barrier_second_derivative(d, q.dhat);
    ASSERT_GT(b2, 0.0);
    const Mat12 expected = (b2 / (w * b1 * b1)) * g0 * g0.transpose();
    EXPECT_LT((H1 - expected).norm(), 1e-9 * expected.norm()) << k;
  }
  EXPECT_GT(band, 50);
  EXPECT_GT(outside, 250);
}
