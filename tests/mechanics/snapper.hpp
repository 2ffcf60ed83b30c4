#pragma once
// The snapping system of the load tests: E(x, y; μ) = x⁴/4 − x²/2 − μx + y²/2,
// with equilibria μ = x³ − x, y = 0, stable branches x < −1/√3 and x > 1/√3
// and folds (limit loads) at x = ±1/√3, μ = ∓2/(3√3). It starts at
// x = (−1.2, 0.1), μ = −0.6, on the left branch's side.
#include <cmath>

#include <Eigen/Core>

#include "ek/core/sparse_assembler.hpp"
#include "ek/mechanics/continuation.hpp"

namespace ek::fixtures {

class Snapper : public ParameterizedObjective {
 public:
  int num_dofs() const override { return 2; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override { return std::pow(x_(0), 4) / 4 - x_(0) * x_(0) / 2 - mu_ * x_(0) + x_(1) * x_(1) / 2; }
  VecX gradient() override { return Eigen::Vector2d(x_(0) * x_(0) * x_(0) - x_(0) - mu_, x_(1)); }
  void assemble_hessian(SparseAssembler& A, HessianKind) override {
    A.begin(2);
    A.segment(0, 1);
    A.add(0, 0, 3 * x_(0) * x_(0) - 1);
    A.add(1, 1, 1.0);
    A.end();
  }
  double parameter() const override { return mu_; }
  void set_parameter(double mu) override { mu_ = mu; }
  VecX parameter_gradient() override { return Eigen::Vector2d(-1.0, 0.0); }
  double parameter_derivative() override { return -x_(0); }

 private:
  VecX x_ = Eigen::Vector2d(-1.2, 0.1);
  double mu_ = -0.6;
};

}  // namespace ek::fixtures
