// Saddle search (saddle.hpp) on objectives with known saddles: the
// Müller–Brown potential, a double well, and the twisted elastic ring
// (Michell's instability, the rod model's known answer).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/optim/saddle.hpp"
#include "ek/solver/symmetric.hpp"

using namespace ek;

namespace {

/// Müller & Brown (1979): V = Σ_k A_k exp(a_k dx² + b_k dx dy + c_k dy²),
/// dx = x − x0_k, dy = y − y0_k. Minima A (−0.558, 1.442), B (0.623, 0.028),
/// C (−0.050, 0.467); saddles S1 (−0.822, 0.624) between A and C, S2
/// (0.212, 0.293) between B and C.
class MullerBrown : public Objective {
 public:
  explicit MullerBrown(Eigen::Vector2d x) : x_(x) {}
  int num_dofs() const override { return 2; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override {
    double e = 0.0;
    for (int k = 0; k < 4; ++k) e += term(k);
    return e;
  }
  VecX gradient() override {
    VecX g = VecX::Zero(2);
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d q = exponent_gradient(k);
      g += term(k) * q;
    }
    return g;
  }
  void assemble_hessian(SparseAssembler& A, HessianKind) override {
    Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d q = exponent_gradient(k);
      Eigen::Matrix2d Q;
      Q << 2 * a_[k], b_[k], b_[k], 2 * c_[k];
      H += term(k) * (q * q.transpose() + Q);
    }
    A.begin(2);
    A.segment(0, 1);
    A.add(0, 0, H(0, 0));
    A.add(0, 1, H(0, 1));
    A.add(1, 1, H(1, 1));
    A.end();
  }

 private:
  double term(int k) const {
    const double dx = x_(0) - x0_[k], dy = x_(1) - y0_[k];
    return A_[k] * std::exp(a_[k] * dx * dx + b_[k] * dx * dy + c_[k] * dy * dy);
  }
  Eigen::Vector2d exponent_gradient(int k) const {
    const double dx = x_(0) - x0_[k], dy = x_(1) - y0_[k];
    return {2 * a_[k] * dx + b_[k] * dy, b_[k] * dx + 2 * c_[k] * dy};
  }
  VecX x_;
  std::array<double, 4> A_{-200, -100, -170, 15}, a_{-1, -1, -6.5, 0.7}, b_{0, 0, 11, 0.6}, c_{-10, -10, -6.5, 0.7},
      x0_{1, 0, -0.5, -1}, y0_{0, 0.5, 1.5, 1};
};

/// E = (x² − 1)² + 2y²: minima (±1, 0), one saddle at the origin (E = 1,
/// Hessian diag(−4, 4)); along y the energy rises without a saddle.
class DoubleWell2 : public Objective {
 public:
  explicit DoubleWell2(Eigen::Vector2d x) : x_(x) {}
  int num_dofs() const override { return 2; }
  VecX dofs() const override { return x_; }
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() override { return std::pow(x_(0) * x_(0) - 1, 2) + 2 * x_(1) * x_(1); }
  VecX gradient() override { return Eigen::Vector2d(4 * x_(0) * (x_(0) * x_(0) - 1), 4 * x_(1)); }
  void assemble_hessian(SparseAssembler& A, HessianKind) override {
    A.begin(2);
    A.segment(0, 1);
    A.add(0, 0, 12 * x_(0) * x_(0) - 4);
    A.add(1, 1, 4);
    A.end();
  }

 private:
  VecX x_;
};

NewtonOptions tight() {
  NewtonOptions o;
  o.gradient_tolerance = 1e-10;
  o.lambda_min = 1.0;
  return o;
}

SaddleSearchOptions search_options(double rise) {
  SaddleSearchOptions o;
  o.gradient_tolerance = 1e-9;
  o.max_energy_rise = rise;
  o.trust_radius = 0.02;
  o.max_trust_radius = 0.1;
  o.base_shift = 1e-4;
  o.eigen_count = 2;
  o.record_trace = true;
  return o;
}

}  // namespace

TEST(MullerBrown, HessianMatchesFiniteDifferencesOfTheGradient) {
  MullerBrown f(Eigen::Vector2d(-0.3, 0.8));
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);
  const Eigen::Matrix2d H = Eigen::MatrixXd(Eigen::SparseMatrix<double>(A.matrix().selfadjointView<Eigen::Upper>()));
  const double h = 1e-6;
  for (int i = 0; i < 2; ++i) {
    VecX xp = f.dofs(), xm = f.dofs();
    xp(i) += h;
    xm(i) -= h;
    f.set_dofs(xp);
    const VecX gp = f.gradient();
    f.set_dofs(xm);
    const VecX gm = f.gradient();
    const double ep = [&] { f.set_dofs(xp); return f.energy(); }(), em = [&] { f.set_dofs(xm); return f.energy(); }();
    f.set_dofs(Eigen::Vector2d(-0.3, 0.8));
    EXPECT_NEAR((ep - em) / (2 * h), f.gradient()(i), 1e-5 * std::abs(f.gradient()(i)) + 1e-6);
    for (int j = 0; j < 2; ++j) EXPECT_NEAR((gp(j) - gm(j)) / (2 * h), H(j, i), 1e-5 * H.norm());
  }
  EXPECT_GT(H.norm(), 10.0);  // not trivially zero
}

TEST(SaddleSearch, MullerBrownFindsTheKnownSaddlesFromEachMinimum) {
  // from B (0.623, 0.028) the saddle S2 toward C; from A the saddle S1
  struct Case {
    Eigen::Vector2d start, saddle;
    double energy;
  };
  const std::array<Case, 2> cases{{{{0.623, 0.028}, {0.21249, 0.29299}, -72.2489},
                                   {{-0.558, 1.442}, {-0.82200, 0.62431}, -40.6648}}};
  for (const Case& c : cases) {
    MullerBrown f(c.start);
    ASSERT_EQ(minimize(f, tight()).status, SolverStatus::ConvergedStable);
    const VecX minimum = f.dofs();
    int found = 0;
    for (int mode = 0; mode < 2; ++mode) {
      for (const double sign : {1.0, -1.0}) {
        f.set_dofs(minimum);
        SparseAssembler A;
        f.assemble_hessian(A, HessianKind::Exact);
        const LowestModes m = lowest_modes(A.matrix(), {}, 2, -1.0, 1.0);
        ASSERT_TRUE(m.converged);
        const SaddleSearchResult r = search_saddle(f, sign * m.vectors.col(mode), search_options(200.0));
        if (r.status != SaddleStatus::Converged) continue;
        EXPECT_LE(r.gradient_norm, 1e-9);
        EXPECT_LT(r.eigenvalue, 0.0);
        const HessianIndex idx = hessian_index(f, 2, 1e-6);
        EXPECT_EQ(idx.negative, 1);
        if ((r.x - c.saddle).norm() < 1e-3) {
          ++found;
          EXPECT_NEAR(r.energy, c.energy, 1e-3);
        }
      }
    }
    EXPECT_GE(found, 1) << "no search from (" << c.start.transpose() << ") reached the known saddle";
  }
}

TEST(CriticalPoint, NewtonRaphsonConvergesToTheNearestCriticalPointOfAnyIndex) {
  // Newton–Raphson on ∇V = 0 (solve_critical_point()) from 0.05 away from
  // each known critical point of the Müller–Brown potential reaches that
  // point: the saddles S1, S2 (index 1) as well as the minimum C, to 1e-6.
  const std::array<Eigen::Vector2d, 3> points{
      {{0.21249, 0.29299}, {-0.82200, 0.62431}, {-0.05001, 0.46669}}};
  for (const Eigen::Vector2d& x : points) {
    MullerBrown f(x + Eigen::Vector2d(0.03, -0.04));
    CriticalPointOptions o;
    o.gradient_tolerance = 1e-9;
    const CriticalPointReport r = solve_critical_point(f, o);
    ASSERT_EQ(r.status, SolverStatus::ConvergedUnstable) << "from near (" << x.transpose() << ")";
    EXPECT_LE(r.gradient_norm, 1e-9);
    EXPECT_LT((f.dofs() - x).norm(), 1e-4) << f.dofs().transpose();
    EXPECT_LE(r.iterations, 10);  // quadratic convergence
  }
  // A start far from any critical point either converges to one or ends
  // with a status, never silently elsewhere.
  MullerBrown far(Eigen::Vector2d(1.5, 2.0));
  const CriticalPointReport r = solve_critical_point(far, {});
  if (r.status == SolverStatus::ConvergedUnstable) {
    EXPECT_LE(r.gradient_norm, 1e-8);
  } else {
    EXPECT_GT(r.gradient_norm, 1e-8);
  }
}

TEST(SaddleSearch, DoubleWellSaddleAndAStatusWhereThereIsNone) {
  DoubleWell2 f(Eigen::Vector2d(1.0, 0.0));
  SaddleSearchResult r = search_saddle(f, Eigen::Vector2d(-1.0, 0.0), search_options(5.0));
  ASSERT_EQ(r.status, SaddleStatus::Converged) << to_string(r.status);
  EXPECT_NEAR(r.x(0), 0.0, 1e-9);
  EXPECT_NEAR(r.x(1), 0.0, 1e-9);
  EXPECT_NEAR(r.energy, 1.0, 1e-12);
  EXPECT_NEAR(r.eigenvalue, -4.0, 1e-6);
  // the far side: +x rises without a saddle, so does y: never a false saddle
  for (const Eigen::Vector2d& d : {Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 1.0)}) {
    f.set_dofs(Eigen::Vector2d(1.0, 0.0));
    r = search_saddle(f, d, search_options(5.0));
    EXPECT_EQ(r.status, SaddleStatus::LeftBasin) << to_string(r.status);
  }
  // an iteration cap that is too small ends with its status
  f.set_dofs(Eigen::Vector2d(1.0, 0.0));
  SaddleSearchOptions o = search_options(5.0);
  o.max_iterations = 2;
  EXPECT_EQ(search_saddle(f, Eigen::Vector2d(-1.0, 0.0), o).status, SaddleStatus::MaxIterations);
}

TEST(SaddleSearch, DescentRecordsImagesDownToTheMinimum) {
  DoubleWell2 f(Eigen::Vector2d(-0.01, 0.3));
  const Descent d = descend(f, tight());
  EXPECT_EQ(d.report.status, SolverStatus::ConvergedStable);
  ASSERT_GE(d.images.size(), 3u);
  EXPECT_NEAR(d.images.back()(0), -1.0, 1e-9);
  for (size_t k = 1; k < d.energies.size(); ++k) EXPECT_LE(d.energies[k], d.energies[k - 1] + 1e-14);
  EXPECT_EQ(d.images.size(), d.energies.size());
}

TEST(SaddleSearch, RejectsABadDirection) {
  DoubleWell2 f(Eigen::Vector2d(1.0, 0.0));
  EXPECT_THROW(search_saddle(f, VecX::Zero(2), search_options(1.0)), std::invalid_argument);
  EXPECT_THROW(search_saddle(f, VecX::Ones(3), search_options(1.0)), std::invalid_argument);
  SaddleSearchOptions o = search_options(1.0);
  o.eigen_count = 1;
  EXPECT_THROW(search_saddle(f, VecX::Ones(2), o), std::invalid_argument);
}
