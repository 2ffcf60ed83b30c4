// The rod's known instability: a closed ring twisted past Michell's critical
// twist Tw_c = √3·EI/GJ = √3(1 + ν) (Michell 1889; Goriely 2006) loses
// stability; hessian_index() must see the circle stable below it and with a
// negative eigenvalue (the pair of m = 2 modes) above it.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/optim/saddle.hpp"
#include "ek/solver/rod_model.hpp"

using namespace ek;

namespace {

Points circle(int n) {
  const double R = n / (2.0 * M_PI);
  Points P(n, 3);
  for (int i = 0; i < n; ++i) P.row(i) << R * std::cos(2 * M_PI * i / n), R * std::sin(2 * M_PI * i / n), 0.0;
  return P;
}

HessianIndex ring_index(double link, int n) {
  const Points P = circle(n);
  RelaxOptions o;
  o.link = link;
  o.stop_at_critical_point = true;  // the circle stays a circle (it expands slightly under bending)
  RodModel sys(P, VecX::Constant(n, (P.row(1) - P.row(0)).norm()), o);
  const double threshold = sys.newton().shift_epsilon * sys.lambda_min();
  const Descent d = descend(sys.objective(), sys.newton());
  EXPECT_NE(d.report.status, SolverStatus::MaxIterations);
  EXPECT_LE(sys.objective().gradient().norm(), sys.tolerance()) << "the twisted circle is an equilibrium";
  return hessian_index(sys.objective(), 4, threshold);
}

}  // namespace

TEST(Michell, TwistedRingIsStableBelowTheCriticalTwistAndUnstableAbove) {
  const double critical = std::sqrt(3.0) * (1.0 + RodMaterial{}.poisson);  // EI/GJ = 1 + ν
  const int n = 60;
  const HessianIndex below = ring_index(0.9 * critical, n);
  ASSERT_TRUE(below.converged);
  EXPECT_EQ(below.negative, 0) << below.values.transpose();
  EXPECT_GT(below.values(0), 0.0);
  const HessianIndex above = ring_index(1.1 * critical, n);
  ASSERT_TRUE(above.converged);
  EXPECT_EQ(above.negative, 2) << above.values.transpose();  // the two phases of the m = 2 mode
  EXPECT_NEAR(above.values(0), above.values(1), 1e-6 * std::abs(above.values(0)));
}
