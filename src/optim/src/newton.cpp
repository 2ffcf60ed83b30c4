#include "ek/optim/newton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/optim/eigen_analysis.hpp"
#include "shift_search.hpp"

namespace ek {
namespace {

// The round-off of an energy E: changes of E smaller than this are noise.
double energy_roundoff(double E) { return 64.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(E)); }

}  // namespace

std::string to_string(SolverStatus status) {
  switch (status) {
    case SolverStatus::ConvergedStable: return "converged-stable";
    case SolverStatus::ConvergedUnstable: return "converged-unstable";
    case SolverStatus::MaxIterations: return "max-iterations";
    case SolverStatus::Stalled: return "stalled";
  }
  return "unknown";
}

std::string to_string(HessianMode mode) {
  switch (mode) {
    case HessianMode::Exact: return "exact";
    case HessianMode::Hybrid: return "hybrid";
  }
  return "unknown";
}

NewtonMethodOptions NewtonMethodOptions::paper() {
  NewtonMethodOptions o;
  o.hessian = HessianMode::Exact;
  o.remove_rigid_motions = false;
  return o;
}

void NewtonOptions::validate() const {
  require(gradient_tolerance > 0.0, "NewtonOptions: gradient_tolerance must be positive");
  require(max_iterations >= 0, "NewtonOptions: max_iterations must be >= 0");
  require(lambda_min > 0.0 && std::isfinite(lambda_min), "NewtonOptions: lambda_min must be positive");
  NewtonMethodOptions::validate();
}

void NewtonMethodOptions::validate() const {
  require(shift_epsilon > 0.0, "NewtonOptions: shift_epsilon must be positive");
  require(shift_growth > 1.0, "NewtonOptions: shift_growth must be > 1");
  require(armijo > 0.0 && armijo < 0.5, "NewtonOptions: armijo must be in (0, 0.5)");
  require(backtrack > 0.0 && backtrack < 1.0, "NewtonOptions: backtrack must be in (0, 1)");
  require(min_step > 0.0 && min_step < 1.0, "NewtonOptions: min_step must be in (0, 1)");
  require(hybrid_switch >= 1.0 && std::isfinite(hybrid_switch), "NewtonOptions: hybrid_switch must be >= 1");
  require(exact_after_full_steps >= 0, "NewtonOptions: exact_after_full_steps must be >= 0");
  require(max_shift_attempts >= 1, "NewtonOptions: max_shift_attempts must be >= 1");
  require(max_expansion >= 1.0 && expansion_ratio > 0.0, "NewtonOptions: max_expansion must be >= 1, expansion_ratio > 0");
  require(short_step_fraction > 0.0 && short_step_fraction <= 1.0, "NewtonOptions: short_step_fraction must be in (0, 1]");
}

std::string to_string(IterationKind kind) {
  switch (kind) {
    case IterationKind::Step: return "step";
    case IterationKind::SaddleEscape: return "saddle-escape";
    case IterationKind::Final: return "final";
  }
  return "unknown";
}

namespace {

/// Hybrid mode (HessianMode::Hybrid): after exact_after_full_steps
/// consecutive full projected steps the iterate is in a region where the
/// quadratic model is good, and the exact Hessian takes over (projected
/// directions converge only linearly when the projection removed real
/// curvature, e.g. of compressed edges); it hands back to the projected
/// Hessian when an exact step must backtrack or the exact Hessian needed a
/// shift above 10⁶·ε·λ_min (indefinite).
class HessianSchedule {
 public:
  explicit HessianSchedule(const NewtonOptions& o) : o_(o) {}
  bool exact(double gnorm) const {
    return o_.hessian == HessianMode::Exact || exact_region_ || gnorm <= o_.hybrid_switch * o_.gradient_tolerance;
  }
  void after_step(bool exact, double t, double shift) {
    if (o_.hessian != HessianMode::Hybrid) return;
    if (!exact) {
      full_projected_steps_ = t >= 1.0 ? full_projected_steps_ + 1 : 0;
      exact_region_ = o_.exact_after_full_steps > 0 && full_projected_steps_ >= o_.exact_after_full_steps;
    } else if (exact_region_ && (t < 1.0 || shift > 1e6 * o_.shift_epsilon * o_.lambda_min)) {
      exact_region_ = false;  // backtracked, or the exact Hessian is indefinite (a large shift: tiny steps)
      full_projected_steps_ = 0;
    }
  }

 private:
  const NewtonOptions& o_;
  bool exact_region_ = false;
  int full_projected_steps_ = 0;
};

}  // namespace

/// Shared by successive minimisations.
struct NewtonSolver::State {
  explicit State(const NewtonOptions& o) : cholesky(o.cholesky) {}
  SparseAssembler assembler;
  CholeskySolver cholesky;
  ShiftSearch shifts;
};

/// One minimisation.
struct NewtonSolver::Run {
  Run(const NewtonOptions& o, const CholeskySolver& c)
      : schedule(o),
        symbolic0(c.symbolic_count()),
        numeric0(c.numeric_count()),
        orderings0(c.ordering_count()),
        symbolic_seconds0(c.symbolic_seconds()) {}
  Stopwatch t_start;
  NewtonReport report;
  HessianSchedule schedule;
  VecX x;
  double E = 0.0;
  double gnorm = 0.0;
  double shift = 0.0;
  bool exact = false;
  IterationRecord rec;
  Stopwatch t_iteration;
  int symbolic0, numeric0, orderings0;
  double symbolic_seconds0;
};

NewtonSolver::NewtonSolver(const NewtonOptions& options) : options_(options), state_(std::make_unique<State>(options)) {
  options_.validate();
}

NewtonSolver::~NewtonSolver() = default;

void NewtonSolver::set_options(const NewtonOptions& options) {
  options.validate();
  options_ = options;
}

NewtonReport NewtonSolver::finish(Run& run, SolverStatus status) {
  const CholeskySolver& c = state_->cholesky;
  NewtonReport& r = run.report;
  r.status = status;
  r.energy = run.E;
  r.symbolic_factorizations = c.symbolic_count() - run.symbolic0;
  r.numeric_factorizations = c.numeric_count() - run.numeric0;
  r.orderings = c.ordering_count() - run.orderings0;
  r.time_symbolic = c.symbolic_seconds() - run.symbolic_seconds0;
  r.seconds = run.t_start.seconds();
  ++phase_;
  return r;
}

void NewtonSolver::record(Run& run) {
  IterationRecord& rec = run.rec;
  rec.seconds = run.t_iteration.seconds();
  if (options_.verbose)
    std::fprintf(stderr, "newton %d:%5d %-13s E %.12g  |g| %.3e  shift %.2e  ccd %.3e  t %.3e  %s%s\n", rec.phase,
                 rec.iteration, to_string(rec.kind).c_str(), rec.energy, rec.gradient_norm, rec.shift, rec.max_step,
                 rec.step, rec.exact ? "exact" : "proj", rec.pattern_changed ? " pattern" : "");
  if (options_.record_trace) trace_.push_back(rec);
}

// Assembles the Hessian of the kind asked for and factorises it with the
// shift search. False when no rung factorises.
bool NewtonSolver::factorize(Objective& f, Run& run, bool exact, bool converged) {
  Stopwatch t0;
  f.assemble_hessian(state_->assembler, exact ? HessianKind::Exact : HessianKind::Projected);
  run.report.time_assembly += t0.seconds();
  t0.restart();
  const SparseAssembler& A = state_->assembler;
  const ShiftSearch::Result s = state_->shifts.factorize(state_->cholesky, A.matrix(), A.pattern_version(), exact,
                                                         converged);
  run.report.time_factorization += t0.seconds();
  run.report.failed_factorizations += s.failed;
  run.report.hessian_psd = s.base_ok;
  run.rec.factorizations = s.attempts;
  run.rec.failed_factorizations = s.failed;
  run.rec.pattern_changed = A.pattern_changed();
  run.rec.exact = exact;
  if (!std::isfinite(s.shift)) return false;
  run.shift = run.rec.shift = run.report.final_shift = s.shift;
  return true;
}

// At ||g|| <= tolerance with H + ε λ_min I not positive definite: leaves the
// saddle along the eigenvector of the most negative eigenvalue. True when a
// step along it lowers E by more than its round-off; false when none does
// (the point is a minimum to working precision, the negative eigenvalue
// noise on a neutral mode: report.marginal) or the eigen-solve finds no
// negative eigenvalue. A decrease within round-off is no escape: taking it
// would repeat the eigen-solve at a point no different in energy.
bool NewtonSolver::stability_test(Objective& f, Run& run, const VecX& g) {
  NewtonReport& report = run.report;
  const double base_shift = options_.shift_epsilon * options_.lambda_min;
  const Stopwatch te;
  EigenOptions eo;
  eo.count = 1;
  eo.exclude_rigid = false;
  const EigenResult eig = smallest_eigenpairs(state_->assembler.matrix(), Eigen::MatrixXd(), base_shift, eo);
  report.time_eigen += te.seconds();
  if (eig.converged) report.smallest_eigenvalue = eig.values(0);
  if (!eig.converged || eig.values(0) >= 0.0) return false;  // failed only by a hair: stable within the shift
  VecX v = eig.vectors.col(0);
  if (g.dot(v) > 0.0) v = -v;
  const Stopwatch tc;
  double t = std::min(1.0, f.max_step(run.x, v));
  report.time_collision += tc.seconds();
  run.rec.max_step = t;
  const Stopwatch tl;
  const double below = run.E - energy_roundoff(run.E);
  for (; t >= options_.min_step; t *= options_.backtrack) {
    const VecX trial = run.x + t * v;
    f.set_dofs(trial);
    ++report.line_search_trials;
    ++run.rec.line_search_trials;
    const double Et = f.energy();
    if (std::isfinite(Et) && Et < below) {
      run.x = trial;
      run.E = Et;
      run.rec.step = t;
      report.time_line_search += tl.seconds();
      return true;
    }
  }
  report.time_line_search += tl.seconds();
  f.set_dofs(run.x);
  report.marginal = true;
  return false;
}

// The Newton direction -(H + shift·I)⁻¹ g without its rigid-motion part.
VecX NewtonSolver::direction(Objective& f, Run& run, const VecX& g) {
  const Stopwatch t0;
  VecX d = -state_->cholesky.solve(g);
  run.report.time_factorization += t0.seconds();
  if (options_.remove_rigid_motions) {
    const Eigen::MatrixXd Q = f.rigid_modes();
    if (Q.cols() > 0) d -= Q * (Q.transpose() * d);
  }
  return d;
}

// Armijo backtracking on the total energy from min(1, collision-free
// bound). Near convergence the decrease c t g·d can fall below the round-off
// of E; then a step that lowers the gradient norm is accepted instead.
bool NewtonSolver::line_search(Objective& f, Run& run, const VecX& d, double gd) {
  const NewtonOptions& o = options_;
  Stopwatch t0;
  const double t_max = f.max_step(run.x, d);
  run.report.time_collision += t0.seconds();
  run.rec.max_step = t_max;
  t0.restart();
  const double roundoff = energy_roundoff(run.E);
  bool accepted = false;
  for (double t = std::min(1.0, t_max); t >= o.min_step && !accepted; t *= o.backtrack) {
    const VecX trial = run.x + t * d;
    f.set_dofs(trial);
    ++run.report.line_search_trials;
    ++run.rec.line_search_trials;
    const double Et = f.energy();
    if (!std::isfinite(Et)) continue;
    accepted = Et <= run.E + o.armijo * t * gd ||
               (std::fabs(t * gd) < roundoff && Et <= run.E + roundoff && f.gradient().norm() < run.gnorm);
    if (accepted) {
      run.x = trial;
      run.E = Et;
      run.rec.step = t;
    }
  }
  run.report.time_line_search += t0.seconds();
  return accepted;
}

// Expansion: the full step met the Armijo condition and lowered E by nearly
// its first-order prediction (the model overestimates the curvature along d,
// as a large shift or a projected Hessian does): try 2, 4, ... times the
// step within the collision-free bound while E keeps decreasing.
void NewtonSolver::expand(Objective& f, Run& run, const VecX& x0, double E0, const VecX& d, double gd) {
  const NewtonOptions& o = options_;
  if (!(run.rec.step == 1.0 && o.max_expansion > 1.0 && E0 - run.E >= -o.expansion_ratio * gd)) return;
  const Stopwatch t0;
  const double T = o.max_expansion;
  const double t_ext = T * f.max_step(x0, T * d);
  run.report.time_collision += t0.seconds();
  const Stopwatch tl;
  double tb = 1.0, Eb = run.E;
  for (double tt = 2.0; tt <= t_ext && tt <= T; tt *= 2.0) {
    f.set_dofs(x0 + tt * d);
    ++run.report.line_search_trials;
    ++run.rec.line_search_trials;
    const double Et = f.energy();
    if (!(Et < Eb)) break;
    tb = tt;
    Eb = Et;
  }
  if (tb > 1.0) {
    run.x = x0 + tb * d;
    run.E = Eb;
    run.rec.step = tb;
    ++run.report.expansions;
  }
  f.set_dofs(run.x);
  run.report.time_line_search += tl.seconds();
}

NewtonReport NewtonSolver::minimize(Objective& f) {
  const NewtonOptions& o = options_;
  Run run(o, state_->cholesky);
  state_->shifts.restart(o);
  run.x = f.dofs();
  run.E = f.energy();
  require(std::isfinite(run.E), "minimize: the starting point is infeasible (energy is not finite)");
  NewtonReport& report = run.report;
  for (;;) {
    run.t_iteration.restart();
    run.rec = IterationRecord{};
    run.rec.phase = phase_;
    run.rec.iteration = report.iterations;
    run.rec.energy = run.E;
    if (o.record_trace || o.verbose) {
      run.rec.parts = f.energy_parts();
      run.rec.active_pairs = f.active_pairs();
    }
    Stopwatch t0;
    const VecX g = f.gradient();
    report.time_assembly += t0.seconds();
    run.gnorm = report.gradient_norm = run.rec.gradient_norm = g.norm();
    require(std::isfinite(run.gnorm), "minimize: the gradient is not finite");
    const bool converged = run.gnorm <= o.gradient_tolerance;
    run.exact = run.schedule.exact(run.gnorm);
    if (!factorize(f, run, run.exact, converged)) {
      record(run);
      return finish(run, SolverStatus::Stalled);
    }
    if (converged) {
      if (report.hessian_psd || o.stop_at_critical_point || report.saddle_escapes >= o.max_saddle_escapes) {
        run.rec.kind = IterationKind::Final;
        record(run);
        if (report.hessian_psd) return finish(run, SolverStatus::ConvergedStable);
        return finish(run, o.stop_at_critical_point ? SolverStatus::ConvergedUnstable : SolverStatus::Stalled);
      }
      run.rec.kind = IterationKind::SaddleEscape;
      if (!stability_test(f, run, g)) {
        run.rec.kind = IterationKind::Final;
        record(run);
        return finish(run, SolverStatus::ConvergedStable);
      }
      f.accept();
      record(run);
      ++report.saddle_escapes;
      if (++report.iterations >= o.max_iterations) return finish(run, SolverStatus::MaxIterations);
      continue;
    }
    if (report.iterations >= o.max_iterations) {
      run.rec.kind = IterationKind::Final;
      record(run);
      return finish(run, SolverStatus::MaxIterations);
    }
    if (run.exact) ++report.exact_iterations;
    VecX d = direction(f, run, g);
    double gd = g.dot(d);
    if (!(gd < 0.0) || !d.allFinite()) {
      d = -g;  // cannot happen for a positive definite shifted H; guard against round-off
      gd = -run.gnorm * run.gnorm;
    }
    const VecX x0 = run.x;
    const double E0 = run.E;
    const bool accepted = line_search(f, run, d, gd);
    if (accepted) expand(f, run, x0, E0, d, gd);
    record(run);
    if (!accepted) {
      f.set_dofs(run.x);
      return finish(run, SolverStatus::Stalled);
    }
    run.schedule.after_step(run.exact, run.rec.step, run.shift);
    if (o.damp_short_steps && !run.exact && run.rec.step < o.short_step_fraction) state_->shifts.damp();
    f.accept();
    ++report.iterations;
  }
}

NewtonReport minimize(Objective& objective, const NewtonOptions& options) {
  NewtonSolver solver(options);
  return solver.minimize(objective);
}

}  // namespace ek
