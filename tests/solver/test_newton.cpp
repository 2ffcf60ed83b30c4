#include <gtest/gtest.h>

#include <cmath>

#include "ek/solver/newton.hpp"

using namespace ek;

namespace {

/// f(x) = Σ_i [ a (x_{2i}² - 1)² + b x_{2i+1}² ] + coupling c Σ (x_i - x_{i+1})²:
/// minima at x_{2i} = ±1, a saddle at the origin.
class DoubleWell : public Objective {
 public:
  explicit DoubleWell(int pairs, double c = 0.1) : x_(VecX::Zero(2 * pairs)), c_(c) {}
  int num_dofs() const override { return static_cast<int>(x_.size()); }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override {
    double e = 0.0;
    for (int i = 0; i + 1 < x_.size(); i += 2) e += std::pow(x_(i) * x_(i) - 1.0, 2) + 2.0 * x_(i + 1) * x_(i + 1);
    for (int i = 0; i + 1 < x_.size(); ++i) e += c_ * std::pow(x_(i) - x_(i + 1), 2);
    return e;
  }
  VecX gradient() override {
    VecX g = VecX::Zero(x_.size());
    for (int i = 0; i + 1 < x_.size(); i += 2) {
      g(i) += 4.0 * x_(i) * (x_(i) * x_(i) - 1.0);
      g(i + 1) += 4.0 * x_(i + 1);
    }
    for (int i = 0; i + 1 < x_.size(); ++i) {
      g(i) += 2.0 * c_ * (x_(i) - x_(i + 1));
      g(i + 1) -= 2.0 * c_ * (x_(i) - x_(i + 1));
    }
    return g;
  }
  void assemble_hessian(SparseAssembler& A, bool) override {
    A.begin(num_dofs());
    for (int i = 0; i + 1 < x_.size(); i += 2) {
      A.add(i, i, 12.0 * x_(i) * x_(i) - 4.0);
      A.add(i + 1, i + 1, 4.0);
    }
    for (int i = 0; i + 1 < x_.size(); ++i) {
      A.add(i, i, 2.0 * c_);
      A.add(i + 1, i + 1, 2.0 * c_);
      A.add(i, i + 1, -2.0 * c_);
    }
    A.end();
  }
  double max_step(const VecX& x, const VecX& dx) override {
    // a wall at |x_0| = 2: report the largest feasible t, and count calls
    ++ccd_calls;
    if (dx(0) == 0.0) return 1.0;
    const double limit = (dx(0) > 0 ? 1.9 - x(0) : -1.9 - x(0)) / dx(0);
    return std::clamp(limit, 0.0, 1.0);
  }
  void accept() override {
    ++accepted;
    EXPECT_LT(std::fabs(x_(0)), 1.9 + 1e-12);  // never beyond the wall
  }
  int accepted = 0, ccd_calls = 0;

 private:
  VecX x_;
  double c_;
};

}  // namespace

TEST(Newton, ConvergesToAStableMinimum) {
  DoubleWell f(5);
  VecX x0 = VecX::Constant(10, 0.3);
  f.set_dofs(x0);
  NewtonOptions o;
  const NewtonReport r = minimize(f, o);
  EXPECT_EQ(r.status, SolverStatus::ConvergedStable);
  EXPECT_LE(r.gradient_norm, o.gradient_tolerance);
  EXPECT_TRUE(r.hessian_psd);
  const VecX x = f.dofs();
  for (int i = 0; i < 10; i += 2) EXPECT_NEAR(std::fabs(x(i)), 1.0, 0.1);  // near a well (coupling shifts it)
  EXPECT_GT(f.accepted, 0);
  EXPECT_GT(f.ccd_calls, 0);
}

TEST(Newton, LeavesSaddlesUnlessAskedToStop) {
  {
    DoubleWell f(3);
    f.set_dofs(VecX::Zero(6));  // exact saddle: zero gradient, indefinite Hessian
    const NewtonReport r = minimize(f, NewtonOptions{});
    EXPECT_EQ(r.status, SolverStatus::ConvergedStable);
    EXPECT_GE(r.saddle_escapes, 1);
    EXPECT_LT(f.energy(), 3.0);  // the saddle's energy is 3
  }
  {
    DoubleWell f(3);
    f.set_dofs(VecX::Zero(6));
    NewtonOptions o;
    o.stop_at_critical_point = true;
    const NewtonReport r = minimize(f, o);
    EXPECT_EQ(r.status, SolverStatus::ConvergedUnstable);
    EXPECT_FALSE(r.hessian_psd);
  }
}

TEST(Newton, ReportsMaxIterations) {
  DoubleWell f(2);
  f.set_dofs(VecX::Constant(4, 0.3));
  NewtonOptions o;
  o.max_iterations = 1;
  const NewtonReport r = minimize(f, o);
  EXPECT_EQ(r.status, SolverStatus::MaxIterations);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_EQ(to_string(r.status), "max-iterations");
}

TEST(Newton, RejectsBadOptionsAndInfeasibleStart) {
  DoubleWell f(2);
  NewtonOptions o;
  o.lambda_min = 0.0;
  EXPECT_THROW(minimize(f, o), std::invalid_argument);
}
