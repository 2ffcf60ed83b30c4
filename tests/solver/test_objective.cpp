#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "ek/contact/contact_potential.hpp"
#include "ek/optim/newton.hpp"
#include "ek/optim/objective.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/rod_terms.hpp"
#include "ek/solver/trace.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// E = a/2 |x - c|², a quadratic well on all dofs (Hessian a·I), with a wall
/// at x_0 = wall below it: max_step keeps 10% of the distance to the wall.
class Well : public Potential {
 public:
  Well(double a, VecX c, double wall, const char* name) : a_(a), c_(std::move(c)), wall_(wall), name_(name) {}
  void set_dofs(const VecX& x) override { x_ = x; }
  double energy() const override { return 0.5 * a_ * (x_ - c_).squaredNorm(); }
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({name_, energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override { g += a_ * (x_ - c_); }
  std::uint64_t hessian_structure() const override { return 7; }
  void add_hessian(SparseAssembler& A, HessianKind) const override {
    for (int i = 0; i < x_.size(); ++i) A.add(i, i, a_);
  }
  double max_step(const VecX& x, const VecX& dx) const override {
    if (dx(0) >= 0.0) return 1.0;
    return std::clamp(0.9 * (x(0) - wall_) / -dx(0), 0.0, 1.0);
  }
  void accept() override { ++accepted; }
  int accepted = 0;

 private:
  double a_;
  VecX c_, x_;
  double wall_;
  const char* name_;
};

struct TwoWells {
  VecX x = VecX::Zero(3);
  Well a{2.0, (VecX(3) << 1.0, 2.0, 3.0).finished(), -10.0, "a"};
  Well b{6.0, (VecX(3) << -1.0, 0.0, 1.0).finished(), -0.52, "b"};
  CompositeObjective f{{[] { return 3; }, [this] { return x; }, {}}, {&a, &b}};
  TwoWells() { f.set_dofs(x); }
};

}  // namespace

// The composite is the sum of its terms: energy, parts, gradient and Hessian
// add up; the step bound is the smallest term's; accept() reaches every term.
TEST(Objective, CompositeSumsItsTerms) {
  TwoWells w;
  const VecX x = (VecX(3) << 0.1, -0.2, 0.3).finished();
  w.x = x;
  w.f.set_dofs(x);
  const double Ea = 0.5 * 2.0 * (x - VecX((VecX(3) << 1.0, 2.0, 3.0).finished())).squaredNorm();
  const double Eb = 0.5 * 6.0 * (x - VecX((VecX(3) << -1.0, 0.0, 1.0).finished())).squaredNorm();
  EXPECT_DOUBLE_EQ(w.f.energy(), Ea + Eb);
  const auto parts = w.f.energy_parts();
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].name, "a");
  EXPECT_DOUBLE_EQ(parts[1].value, Eb);
  const VecX g = w.f.gradient();
  const VecX fd = fixtures::fd_gradient(
      [&](const VecX& y) {
        w.f.set_dofs(y);
        return w.f.energy();
      },
      x, 1e-6);
  w.f.set_dofs(x);
  EXPECT_LT((g - fd).norm(), 1e-6 * g.norm());
  EXPECT_GT(g.norm(), 1.0);
  SparseAssembler A;
  w.f.assemble_hessian(A, HessianKind::Exact);
  EXPECT_DOUBLE_EQ(Eigen::MatrixXd(A.matrix())(1, 1), 8.0);
  const VecX dx = VecX::Constant(3, -1.0);
  EXPECT_DOUBLE_EQ(w.f.max_step(x, dx), 0.9 * 0.62);  // the wall of b at -0.52
  w.f.accept();
  EXPECT_EQ(w.a.accepted + w.b.accepted, 2);
}

// One solver minimising two objectives in turn (the phases of a relaxation)
// reaches what two fresh solvers reach; its reports count each call alone.
TEST(Newton, SolverSharedAcrossPhasesMatchesFreshSolvers) {
  auto run_phases = [](bool shared) {
    TwoWells w1, w2;
    NewtonOptions o;
    o.gradient_tolerance = 1e-10;
    NewtonSolver one(o);
    NewtonSolver a(o), b(o);
    const NewtonReport r1 = (shared ? one : a).minimize(w1.f);
    w2.x = w1.x = w1.f.dofs();
    w2.f.set_dofs(w2.x);
    const NewtonReport r2 = (shared ? one : b).minimize(w2.f);
    return std::make_pair(r1, r2);
  };
  const auto [s1, s2] = run_phases(true);
  const auto [f1, f2] = run_phases(false);
  EXPECT_EQ(s1.status, SolverStatus::ConvergedStable);
  EXPECT_EQ(s2.status, SolverStatus::ConvergedStable);
  EXPECT_EQ(s1.iterations, f1.iterations);
  EXPECT_EQ(s2.iterations, f2.iterations);
  EXPECT_NEAR(s2.energy, f2.energy, 1e-12);
  EXPECT_EQ(s2.numeric_factorizations, f2.numeric_factorizations);
  EXPECT_EQ(s2.symbolic_factorizations, 0);  // the pattern was analysed in the first phase
  EXPECT_EQ(f2.symbolic_factorizations, 1);
}

// The trace has one record per iteration plus the final convergence test, in
// order, with the energy decreasing along accepted steps, the wall's bound
// recorded, and the phases numbered.
TEST(Newton, TraceRecordsEveryIterationOfEveryPhase) {
  TwoWells w;
  NewtonOptions o;
  o.record_trace = true;
  NewtonSolver solver(o);
  const NewtonReport r = solver.minimize(w.f);
  ASSERT_EQ(r.status, SolverStatus::ConvergedStable);
  const std::vector<IterationRecord> trace = solver.trace();
  ASSERT_EQ(trace.size(), static_cast<size_t>(r.iterations + 1));
  EXPECT_EQ(trace.back().kind, IterationKind::Final);
  EXPECT_LE(trace.back().gradient_norm, o.gradient_tolerance);
  EXPECT_DOUBLE_EQ(trace.back().energy, r.energy);
  // the minimum is at x_0 = -0.5, the wall of b at -0.52: it limits the first step
  EXPECT_NEAR(trace.front().max_step, 0.9 * 0.52 / 0.5, 1e-4);  // (the shift 1e-4 shortens the step)
  for (size_t k = 0; k + 1 < trace.size(); ++k) {
    EXPECT_EQ(trace[k].iteration, static_cast<int>(k));
    EXPECT_EQ(trace[k].kind, IterationKind::Step);
    EXPECT_GT(trace[k].step, 0.0);
    EXPECT_LE(trace[k + 1].energy, trace[k].energy);
    ASSERT_EQ(trace[k].parts.size(), 2u);
    EXPECT_NEAR(trace[k].parts[0].value + trace[k].parts[1].value, trace[k].energy, 1e-12);
  }
  solver.minimize(w.f);  // a second phase, already converged: one final record
  ASSERT_EQ(solver.trace().size(), trace.size() + 1);
  EXPECT_EQ(solver.trace().back().phase, 1);
  std::ostringstream csv;
  write_trace_csv(csv, solver.trace(), {"first", "second"});
  const std::string text = csv.str();
  EXPECT_EQ(text.rfind("phase,phase_name,iteration,kind,energy,energy_a,energy_b,gradient_norm", 0), 0u);
  EXPECT_NE(text.find("\n1,second,0,final,"), std::string::npos);
  EXPECT_EQ(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')), solver.trace().size() + 1);
}

// The knot objective's gradient is the derivative of its energy with rod,
// contact and slab all active (two close, nearly parallel strands of a
// flattened coil inside the slab), and its parts sum to the energy.
TEST(Objective, RodObjectiveGradientMatchesFiniteDifferences) {
  const int n = 60;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {  // a doubly covered circle, the covers 0.3 apart radially
    const double t = 4.0 * M_PI * i / n;
    const double R = 3.0 + 0.15 * std::cos(t / 2.0);
    P.row(i) << R * std::cos(t), R * std::sin(t), 0.15 * std::sin(t / 2.0);
  }
  ElasticRod rod(P, RodMaterial{}, TwistModel::FreeTheta);
  ContactPotential contact(CurveTopology::single(n), ContactOptions{});
  SlabOptions so;
  so.half_thickness = 0.2;
  const PlanaritySlab slab(so);
  RodObjective f(rod, contact, &slab, 0.5);
  const VecX x = f.dofs();
  ASSERT_GT(f.active_pairs(), 0);
  double sum = 0.0;
  for (const EnergyPart& p : f.energy_parts()) sum += p.value;
  EXPECT_NEAR(sum, f.energy(), 1e-12 * std::fabs(sum));
  for (const EnergyPart& p : f.energy_parts())
    if (p.name == "contact" || p.name == "slab" || p.name == "bend") {
      EXPECT_GT(p.value, 0.0) << p.name;
    }
  const VecX g = f.gradient();
  const VecX fd = fixtures::fd_gradient(
      [&](const VecX& y) {
        f.set_dofs(y);
        return f.energy();
      },
      x, 1e-7);
  f.set_dofs(x);
  EXPECT_LT((g - fd).norm(), 1e-5 * g.norm());
}

// The summary counts what the records say: bands of excess energy over the
// phase's end, step lengths, factorisations and time.
TEST(Newton, TraceSummaryCountsTheRecords) {
  auto rec = [](int phase, IterationKind kind, double E, double step, double max_step, bool exact) {
    IterationRecord r;
    r.phase = phase;
    r.kind = kind;
    r.energy = E;
    r.step = step;
    r.max_step = max_step;
    r.exact = exact;
    r.factorizations = 2;
    r.failed_factorizations = 1;
    r.seconds = 0.5;
    return r;
  };
  const std::vector<IterationRecord> trace = {
      rec(0, IterationKind::Step, 10.5, 1.0, 1.0, false),    // excess 0.5 over phase 0's end
      rec(0, IterationKind::Step, 10.05, 0.001, 0.3, false),  // 0.05
      rec(0, IterationKind::Final, 10.0, 0.0, 1.0, true),
      rec(1, IterationKind::Step, 3.00005, 1.0, 1.0, true),   // 5e-5 over phase 1's end
      rec(1, IterationKind::Final, 3.0, 0.0, 1.0, true)};
  const TraceSummary s = summarize_trace(trace);
  EXPECT_EQ(s.iterations, 3);
  EXPECT_EQ(s.by_excess, (std::array<int, 5>{1, 1, 0, 0, 1}));
  EXPECT_EQ(s.full_steps, 2);
  EXPECT_EQ(s.short_steps, 1);
  EXPECT_EQ(s.collision_limited, 1);
  EXPECT_EQ(s.exact_iterations, 1);
  EXPECT_EQ(s.factorizations, 10);
  EXPECT_EQ(s.failed_factorizations, 5);
  EXPECT_DOUBLE_EQ(s.seconds, 2.5);
  EXPECT_DOUBLE_EQ(s.seconds_exact, 1.5);
}
