#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "ek/solver/slab.hpp"
#include "testing.hpp"

using namespace ek;

TEST(Slab, GradientAndHessianOfWholeCurve) {
  SlabOptions o;
  o.half_thickness = 0.5;
  o.stiffness = 3.0;
  PlanaritySlab slab(o);
  Points P = fixtures::random_fourier_curve(30, 3, 4);
  P.col(2) *= 0.45 / P.col(2).cwiseAbs().maxCoeff();  // inside, several vertices near the planes
  const VecX x0 = as_vector(P);
  auto f = [&](const VecX& x) { return slab.energy(as_points(x)); };
  const VecX g = slab.gradient(P);
  const VecX gfd = fixtures::fd_gradient(f, x0, 1e-7);
  EXPECT_LT((g - gfd).norm(), 1e-6 * std::max(1.0, g.norm()));
  SparseAssembler A;
  A.begin(static_cast<int>(x0.size()));
  slab.add_hessian(P, A);
  A.end();
  const Eigen::MatrixXd H = Eigen::MatrixXd(A.matrix()).selfadjointView<Eigen::Upper>();
  for (int k = 2; k < x0.size(); k += 3) {
    auto gk = [&](const VecX& x) { return slab.gradient(as_points(x))(k); };
    const VecX row = fixtures::fd_gradient(gk, x0, 1e-7);
    EXPECT_LT((H.row(k).transpose() - row).norm(), 1e-5 * std::max(1.0, row.norm())) << k;
  }
}

TEST(Slab, MaxStepKeepsVerticesInside) {
  SlabOptions o;
  PlanaritySlab slab(o);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int trial = 0; trial < 1000; ++trial) {
    Points x(5, 3), dx(5, 3);
    for (int i = 0; i < 5; ++i) {
      x.row(i) << U(rng), U(rng), 0.49 * U(rng);
      dx.row(i) << U(rng), U(rng), 3 * U(rng);
    }
    const double t = slab.max_step(x, dx);
    ASSERT_GT(t, 0.0);
    for (double s : {0.25 * t, 0.5 * t, t}) EXPECT_TRUE(slab.inside(x + s * dx));
    EXPECT_TRUE(std::isfinite(slab.energy(x + t * dx)));
  }
}
