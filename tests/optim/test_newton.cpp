#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "ek/optim/eigen_analysis.hpp"
#include "ek/optim/newton.hpp"

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
  void assemble_hessian(SparseAssembler& A, HessianKind) override {
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

namespace {

/// E(x, y) = 1 + x² − μ y² + y⁴: at the origin g = 0 and H = diag(2, −2μ);
/// the lowest energy along y, at y² = μ/2, lies μ²/4 below E(0).
class ShallowSaddle : public Objective {
 public:
  explicit ShallowSaddle(double mu) : mu_(mu) {}
  int num_dofs() const override { return 2; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override {
    const double y2 = x_(1) * x_(1);
    return 1.0 + x_(0) * x_(0) - mu_ * y2 + y2 * y2;
  }
  VecX gradient() override {
    return (VecX(2) << 2.0 * x_(0), -2.0 * mu_ * x_(1) + 4.0 * x_(1) * x_(1) * x_(1)).finished();
  }
  void assemble_hessian(SparseAssembler& A, HessianKind) override {
    A.begin(2);
    A.add(0, 0, 2.0);
    A.add(1, 1, -2.0 * mu_ + 12.0 * x_(1) * x_(1));
    A.end();
  }

 private:
  VecX x_ = VecX::Zero(2);
  double mu_;
};

}  // namespace

// At a critical point whose direction of negative curvature lowers E by no
// more than E's round-off (64 ε |E| ≈ 1.4e-14 here), no escape is taken: the
// point is reported stable and marginal. A deeper saddle is left.
TEST(Newton, AnEscapeWithinRoundOffIsMarginal) {
  NewtonOptions o;
  o.lambda_min = 1e-10;  // base shift ε λ_min = 1e-14, below 2μ: the saddle test runs
  {
    ShallowSaddle f(1e-7);  // depth μ²/4 = 2.5e-15: within round-off
    const NewtonReport r = minimize(f, o);
    EXPECT_EQ(r.status, SolverStatus::ConvergedStable);
    EXPECT_TRUE(r.marginal);
    EXPECT_EQ(r.saddle_escapes, 0);
    EXPECT_NEAR(r.smallest_eigenvalue, -2e-7, 1e-12);
    EXPECT_EQ(f.dofs(), VecX::Zero(2));  // left where it was
  }
  {
    ShallowSaddle f(1e-5);  // depth 2.5e-11: a real saddle
    const NewtonReport r = minimize(f, o);
    EXPECT_EQ(r.status, SolverStatus::ConvergedStable);
    EXPECT_FALSE(r.marginal);
    EXPECT_GE(r.saddle_escapes, 1);
    EXPECT_LT(f.energy(), 1.0 - 1e-11);
  }
}

namespace {

/// E = ½ Σ a_i x_i² whose projected Hessian is 5% of the exact one: a
/// projected Newton step goes 20 times too far and the line search cuts it.
class SoftModel : public Objective {
 public:
  SoftModel() { x_ = VecX::Constant(6, 1.0); }
  int num_dofs() const override { return 6; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override { return 0.5 * (a() * x_.array().square()).sum(); }
  VecX gradient() override { return (a() * x_.array()).matrix(); }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override {
    A.begin(6);
    for (int i = 0; i < 6; ++i) A.add(i, i, (kind == HessianKind::Exact ? 1.0 : 0.05) * a()(i));
    A.end();
  }

 private:
  static Eigen::ArrayXd a() { return (Eigen::ArrayXd(6) << 1.0, 2.0, 4.0, 8.0, 16.0, 32.0).finished(); }
  VecX x_;
};

}  // namespace

// damp_short_steps: after a projected step cut below short_step_fraction,
// the next search starts one rung (×shift_growth) above the last shift;
// without it the projected iterations stay at the base shift.
TEST(Newton, ShortProjectedStepsRaiseTheShift) {
  for (bool damp : {false, true}) {
    SoftModel f;
    NewtonOptions o;
    o.record_trace = true;
    o.exact_after_full_steps = 0;
    o.hybrid_switch = 1e6;  // projected while ||g|| > 1e-2
    o.damp_short_steps = damp;
    NewtonSolver solver(o);
    const NewtonReport r = solver.minimize(f);
    EXPECT_EQ(r.status, SolverStatus::ConvergedStable) << damp;
    const auto& t = solver.trace();
    ASSERT_GE(t.size(), 2u);
    const double base = o.shift_epsilon * o.lambda_min;
    int raised = 0;
    for (size_t k = 0; k + 1 < t.size(); ++k) {
      if (t[k].exact || t[k + 1].exact || t[k].kind != IterationKind::Step) continue;
      if (damp && t[k].step < o.short_step_fraction) {
        EXPECT_GE(t[k + 1].shift, o.shift_growth * t[k].shift * (1 - 1e-12)) << k;
        ++raised;
      }
      if (!damp) {
        EXPECT_EQ(t[k + 1].shift, base) << k;
      }
    }
    if (damp) {
      EXPECT_GT(raised, 0);
    }
  }
  NewtonOptions bad;
  bad.short_step_fraction = 0.0;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
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

// The report counts the failed rungs of the shift ladder: at x = (0.1, 0)
// without coupling, H = diag(12·0.01 − 4, 4) = diag(−3.88, 4), and with
// ε·λ_min = 1e-4 the shifts 1e-4, 1e-3, 1e-2, 0.1 and 1 fail; 10 succeeds.
// With shift_skip_proven the first failure proves that every shift below
// 1e-4 + 3.88 fails (the pivot −3.8799 of an uncoupled dof: the bound is
// exact), so 1e-3 … 1 are skipped: one failure, then 10.
TEST(Newton, CountsFailedFactorisations) {
  for (bool skip : {false, true}) {
    DoubleWell f(1, 0.0);
    f.set_dofs((VecX(2) << 0.1, 0.0).finished());
    NewtonOptions o;
    o.lambda_min = 1.0;
    o.max_iterations = 0;  // one factorisation search, no step
    o.shift_skip_proven = skip;
    const NewtonReport r = minimize(f, o);
    EXPECT_EQ(r.status, SolverStatus::MaxIterations);
    EXPECT_EQ(r.failed_factorizations, skip ? 1 : 5);
    EXPECT_EQ(r.numeric_factorizations, skip ? 2 : 6);
    EXPECT_NEAR(r.final_shift, 10.0, 1e-9);
  }
}

namespace {

/// The double wells from x = 0.1, where every well starts indefinite
/// (H_ii = 12·0.01 − 4 + coupling) and needs shifts of ~1..10, minimised
/// with the base shift 1e-7 and no warm start (long climbs from the first
/// rung), the shift search as given; the minimiser in `x`.
NewtonReport wells_with_shift_search(bool hint, bool skip, VecX* x) {
  DoubleWell f(4);
  f.set_dofs(VecX::Constant(8, 0.1));
  NewtonOptions o;
  o.lambda_min = 1e-3;
  o.shift_warm_start = false;
  o.shift_hint = hint;
  o.shift_skip_proven = skip;
  const NewtonReport r = minimize(f, o);
  *x = f.dofs();
  return r;
}

/// Two searches of the same ladder: the same iterates, fewer failures by `a`.
void expect_same_iterates_fewer_failures(const NewtonReport& a, const VecX& xa, const NewtonReport& b,
                                         const VecX& xb, const char* what) {
  EXPECT_EQ(a.status, SolverStatus::ConvergedStable);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(xa, xb);
  EXPECT_EQ(a.energy, b.energy);
  EXPECT_EQ(a.final_shift, b.final_shift);
  EXPECT_LT(a.failed_factorizations, b.failed_factorizations);
  std::printf("[ measured ] %d iterations; factorisations %d (%d failed) %s, %d (%d failed) climbing\n",
              a.iterations, a.numeric_factorizations, a.failed_factorizations, what, b.numeric_factorizations,
              b.failed_factorizations);
}

}  // namespace

// With shift_hint the ladder is searched around the last shift (stepping
// down when that rung factorises, up when the one below it fails); the shift
// found is the lowest rung that factorises, as the climb from the first rung
// finds it, so the iterates are identical (the hint alone, no skips).
TEST(Newton, ShiftHintGivesTheSameIterates) {
  VecX xa, xb;
  const NewtonReport a = wells_with_shift_search(true, false, &xa), b = wells_with_shift_search(false, false, &xb);
  expect_same_iterates_fewer_failures(a, xa, b, xb, "with the hint");
}

// shift_skip_proven skips the rungs that a failed factorisation proves to
// fail (CholeskySolver::shift_deficit()); the lowest rung that factorises is
// found as by the climb, so the iterates are identical, with fewer failed
// factorisations.
TEST(Newton, ShiftSkipGivesTheSameIterates) {
  VecX xa, xb;
  const NewtonReport a = wells_with_shift_search(false, true, &xa), b = wells_with_shift_search(false, false, &xb);
  expect_same_iterates_fewer_failures(a, xa, b, xb, "skipping");
}

TEST(Newton, RejectsBadOptionsAndInfeasibleStart) {
  DoubleWell f(2);
  NewtonOptions o;
  o.lambda_min = 0.0;
  EXPECT_THROW(minimize(f, o), std::invalid_argument);
}

namespace {

/// f(x) = Σ_i (x_i² − 1)² + c Σ_i (x_i − x_{i+1})²: separated wells at ±1
/// (the coupling shifts them), indefinite for |x_i| < 1/√3. With exact =
/// false the Hessian's well curvature 12x² − 4 is clamped at 0 (a per-element
/// PSD projection, as RodObjective does for compressed edges).
class ProjectableWells : public Objective {
 public:
  explicit ProjectableWells(int n, double c = 0.2) : x_(VecX::Zero(n)), c_(c) {}
  int num_dofs() const override { return static_cast<int>(x_.size()); }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override {
    double e = 0.0;
    for (Eigen::Index i = 0; i < x_.size(); ++i) e += std::pow(x_(i) * x_(i) - 1.0, 2);
    for (Eigen::Index i = 0; i + 1 < x_.size(); ++i) e += c_ * std::pow(x_(i) - x_(i + 1), 2);
    return e;
  }
  VecX gradient() override {
    VecX g(x_.size());
    for (Eigen::Index i = 0; i < x_.size(); ++i) g(i) = 4.0 * x_(i) * (x_(i) * x_(i) - 1.0);
    for (Eigen::Index i = 0; i + 1 < x_.size(); ++i) {
      g(i) += 2.0 * c_ * (x_(i) - x_(i + 1));
      g(i + 1) -= 2.0 * c_ * (x_(i) - x_(i + 1));
    }
    return g;
  }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override {
    const bool exact = kind == HessianKind::Exact;
    ++(exact ? exact_hessians : projected_hessians);
    A.begin(num_dofs());
    A.segment(0, 1);
    for (int i = 0; i < num_dofs(); ++i) {
      const double w = 12.0 * x_(i) * x_(i) - 4.0;
      A.add(i, i, exact ? w : std::max(w, 0.0));
    }
    for (int i = 0; i + 1 < num_dofs(); ++i) {
      A.add(i, i, 2.0 * c_);
      A.add(i + 1, i + 1, 2.0 * c_);
      A.add(i, i + 1, -2.0 * c_);
    }
    A.end();
  }
  int exact_hessians = 0, projected_hessians = 0;

 private:
  VecX x_;
  double c_;
};

/// m points in space joined pairwise by springs of rest lengths r_ij (those
/// of a reference shape): E = Σ_{i<j} ½ (|p_i − p_j| − r_ij)². Invariant
/// under rigid motions (6 zero modes at the minimum E = 0, the reference shape
/// up to a rigid motion or reflection). exact = false clamps the transverse
/// curvature (1 − r/l) of compressed springs at 0, like the rod's stretching.
class SpringFrame : public Objective {
 public:
  SpringFrame(const Points& reference, bool with_rigid_modes)
      : m_(static_cast<int>(reference.rows())), rest_(m_, m_), x_(as_vector(reference)), rigid_(with_rigid_modes) {
    for (int i = 0; i < m_; ++i)
      for (int j = 0; j < m_; ++j) rest_(i, j) = (reference.row(i) - reference.row(j)).norm();
  }
  int num_dofs() const override { return 3 * m_; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  Vec3 p(int i) const { return x_.segment<3>(3 * i); }
  double energy() override {
    double e = 0.0;
    for (int i = 0; i < m_; ++i)
      for (int j = i + 1; j < m_; ++j) e += 0.5 * std::pow((p(i) - p(j)).norm() - rest_(i, j), 2);
    return e;
  }
  VecX gradient() override {
    VecX g = VecX::Zero(3 * m_);
    for (int i = 0; i < m_; ++i)
      for (int j = i + 1; j < m_; ++j) {
        const Vec3 u = p(i) - p(j);
        const double l = u.norm();
        const Vec3 f = (l - rest_(i, j)) * u / l;
        g.segment<3>(3 * i) += f;
        g.segment<3>(3 * j) -= f;
      }
    return g;
  }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override {
    const bool exact = kind == HessianKind::Exact;
    ++(exact ? exact_hessians : projected_hessians);
    A.begin(num_dofs());
    A.segment(0, 1);
    for (int i = 0; i < m_; ++i)
      for (int j = i + 1; j < m_; ++j) {
        const Vec3 u = p(i) - p(j);
        const double l = u.norm();
        const Vec3 t = u / l;
        double across = 1.0 - rest_(i, j) / l;
        if (!exact) across = std::max(across, 0.0);
        const Mat3 K = t * t.transpose() + across * (Mat3::Identity() - t * t.transpose());
        Eigen::Matrix<double, 6, 6> L;
        L << K, -K, -K, K;
        const std::array<int, 6> idx = {3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2};
        A.add_local(idx, L);
      }
    A.end();
  }
  Eigen::MatrixXd rigid_modes() override {
    if (!rigid_) return {};
    ++rigid_calls;
    return ek::rigid_modes(as_points(x_), num_dofs());
  }
  /// Records every accepted step Δ from the previous iterate x_k: the largest
  /// (‖QᵀΔ‖ − 1e-14 ‖x_k‖)/‖Δ‖ over the steps, Q the rigid modes at x_k.
  void accept() override {
    const VecX step = x_ - previous_;
    if (step.norm() > 0.0) {
      const Eigen::MatrixXd Q = ek::rigid_modes(as_points(previous_), num_dofs());
      // (a step of size ~ε|x| carries the round-off of x_{k+1} − x_k)
      const double roundoff = 1e-14 * previous_.norm();
      rigid_fraction = std::max(rigid_fraction, std::max(0.0, (Q.transpose() * step).norm() - roundoff) / step.norm());
    }
    previous_ = x_;
  }
  void start_tracking() { previous_ = x_; }
  double rigid_fraction = 0.0;
  /// Largest |r_ij − |p_i − p_j|| (0 at a minimum).
  double shape_error() const {
    double e = 0.0;
    for (int i = 0; i < m_; ++i)
      for (int j = i + 1; j < m_; ++j) e = std::max(e, std::fabs((p(i) - p(j)).norm() - rest_(i, j)));
    return e;
  }
  Vec3 centroid() const { return as_points(x_).colwise().mean().transpose(); }
  int exact_hessians = 0, projected_hessians = 0, rigid_calls = 0;

 private:
  int m_;
  Eigen::MatrixXd rest_;
  VecX x_;
  bool rigid_;
  VecX previous_;
};

Points spring_reference() {
  // an irregular rigid cluster of 7 points
  Points P(7, 3);
  P << 0, 0, 0, 1.2, 0.1, -0.2, 0.3, 1.1, 0.4, -0.4, 0.5, 1.3, 1.0, 1.2, 0.9, -0.9, -0.6, 0.2, 0.5, -0.8, 1.0;
  return P;
}

/// The reference moved rigidly and perturbed (N(0, sigma) per coordinate).
Points spring_start(double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, sigma);
  const double a = 0.7;
  Mat3 R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  Points P = (spring_reference() * R.transpose()).rowwise() + Vec3(2.0, -1.0, 0.5).transpose();
  for (Eigen::Index i = 0; i < P.size(); ++i) P.data()[i] += N(rng);
  return P;
}

}  // namespace

TEST(Newton, HybridAndExactHessiansReachTheSameMinimum) {
  VecX x0(12);
  for (int i = 0; i < 12; ++i) x0(i) = 0.45 + 0.03 * i * (i % 2 ? 1 : -1);  // in the indefinite band
  NewtonOptions exact;
  exact.hessian = HessianMode::Exact;
  NewtonOptions hybrid;  // the default
  ASSERT_EQ(hybrid.hessian, HessianMode::Hybrid);
  ProjectableWells fe(12), fh(12);
  fe.set_dofs(x0);
  fh.set_dofs(x0);
  const NewtonReport re = minimize(fe, exact), rh = minimize(fh, hybrid);
  for (const NewtonReport* r : {&re, &rh}) {
    EXPECT_EQ(r->status, SolverStatus::ConvergedStable);
    EXPECT_LE(r->gradient_norm, 1e-8);
    EXPECT_TRUE(r->hessian_psd);
  }
  // the minimum is non-degenerate (H ≥ 8 − 8c there): |x − x*| <= |g| / λ_min
  EXPECT_LT((fe.dofs() - fh.dofs()).lpNorm<Eigen::Infinity>(), 1e-8);
  EXPECT_NEAR(re.energy, rh.energy, 1e-14);
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(fe.dofs()(i), 1.0, 0.05);
  // Exact: every Hessian exact; Hybrid: projected far from the minimum, exact near it
  EXPECT_EQ(fe.projected_hessians, 0);
  EXPECT_EQ(re.exact_iterations, re.iterations - re.saddle_escapes);
  EXPECT_GT(fh.projected_hessians, 0);
  EXPECT_GT(fh.exact_hessians, 0);  // the stability test at the end is exact
  EXPECT_LT(rh.exact_iterations, rh.iterations);
  EXPECT_EQ(to_string(HessianMode::Exact), "exact");
  EXPECT_EQ(to_string(HessianMode::Hybrid), "hybrid");
}

TEST(Newton, HybridAndExactHessiansRecoverTheSpringShape) {
  // Compressed and stretched springs: the exact Hessian is indefinite at the start.
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Points start = spring_start(0.2, seed);
    double E_start = 0.0;
    for (HessianMode mode : {HessianMode::Exact, HessianMode::Hybrid}) {
      SpringFrame f(spring_reference(), true);
      f.set_dofs(as_vector(start));
      E_start = f.energy();
      NewtonOptions o;
      o.hessian = mode;
      const NewtonReport r = minimize(f, o);
      EXPECT_EQ(r.status, SolverStatus::ConvergedStable) << to_string(mode) << " seed " << seed;
      EXPECT_LE(r.gradient_norm, o.gradient_tolerance);
      EXPECT_LT(f.shape_error(), 1e-8) << to_string(mode) << " seed " << seed;  // E = 0: the reference shape
      EXPECT_LT(r.energy, 1e-16);
      if (mode == HessianMode::Hybrid) {
        EXPECT_GT(f.projected_hessians, 0);
      } else {
        EXPECT_EQ(f.projected_hessians, 0);
      }
    }
    ASSERT_GT(E_start, 1e-2);
  }
}

TEST(Newton, RigidMotionRemovalMakesStepsOrthogonalToRigidModes) {
  for (std::uint64_t seed : {4u, 5u, 6u}) {
    const Points start = spring_start(0.15, seed);
    SpringFrame f(spring_reference(), true);
    f.set_dofs(as_vector(start));
    f.start_tracking();
    const Vec3 c0 = f.centroid();
    NewtonOptions o;
    ASSERT_TRUE(o.remove_rigid_motions);  // the default
    const NewtonReport r = minimize(f, o);
    EXPECT_EQ(r.status, SolverStatus::ConvergedStable) << seed;
    EXPECT_LT(f.shape_error(), 1e-8) << seed;
    EXPECT_GT(f.rigid_calls, 0);
    EXPECT_EQ(r.saddle_escapes, 0);
    // every accepted step is orthogonal to the rigid modes where it started
    EXPECT_LT(f.rigid_fraction, 1e-10) << seed;
    EXPECT_LT((f.centroid() - c0).norm(), 1e-12) << seed;
    // without the removal: the same shape, but steps with rigid components
    // (the shifted Newton step turns, since rotations are not null modes of H
    // away from the minimum)
    SpringFrame g(spring_reference(), true);
    g.set_dofs(as_vector(start));
    g.start_tracking();
    NewtonOptions keep = o;
    keep.remove_rigid_motions = false;
    const NewtonReport rk = minimize(g, keep);
    EXPECT_EQ(rk.status, SolverStatus::ConvergedStable) << seed;
    EXPECT_LT(g.shape_error(), 1e-8) << seed;
    EXPECT_EQ(g.rigid_calls, 0);
    EXPECT_GT(g.rigid_fraction, 1e-6) << seed;
  }
}

TEST(Newton, NewOptionsAreValidated) {
  ProjectableWells f(3);
  for (auto mutate : std::vector<std::function<void(NewtonOptions&)>>{
           [](NewtonOptions& o) { o.hybrid_switch = 0.5; },
           [](NewtonOptions& o) { o.max_expansion = 0.5; }, [](NewtonOptions& o) { o.expansion_ratio = 0.0; },
           [](NewtonOptions& o) { o.max_shift_attempts = 0; }}) {
    NewtonOptions o;
    mutate(o);
    EXPECT_THROW(minimize(f, o), std::invalid_argument);
  }
  const NewtonOptions paper = NewtonOptions::paper();
  EXPECT_EQ(paper.hessian, HessianMode::Exact);
  EXPECT_FALSE(paper.remove_rigid_motions);
  EXPECT_NO_THROW(paper.validate());
}
