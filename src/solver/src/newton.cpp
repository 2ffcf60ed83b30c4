#include "ek/solver/newton.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/solver/eigen_analysis.hpp"

namespace ek {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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

void NewtonOptions::validate() const {
  require(gradient_tolerance > 0.0, "NewtonOptions: gradient_tolerance must be positive");
  require(max_iterations >= 0, "NewtonOptions: max_iterations must be >= 0");
  require(lambda_min > 0.0 && std::isfinite(lambda_min), "NewtonOptions: lambda_min must be positive");
  require(shift_epsilon > 0.0, "NewtonOptions: shift_epsilon must be positive");
  require(shift_growth > 1.0, "NewtonOptions: shift_growth must be > 1");
  require(armijo > 0.0 && armijo < 0.5, "NewtonOptions: armijo must be in (0, 0.5)");
  require(backtrack > 0.0 && backtrack < 1.0, "NewtonOptions: backtrack must be in (0, 1)");
  require(min_step > 0.0 && min_step < 1.0, "NewtonOptions: min_step must be in (0, 1)");
}

NewtonReport minimize(Objective& f, const NewtonOptions& o) {
  o.validate();
  const auto t_start = Clock::now();
  NewtonReport report;
  SparseAssembler assembler;
  CholeskySolver cholesky(o.cholesky);
  const double base_shift = o.shift_epsilon * o.lambda_min;

  VecX x = f.dofs();
  double E = f.energy();
  require(std::isfinite(E), "minimize: the starting point is infeasible (energy is not finite)");

  auto finish = [&](SolverStatus status) {
    report.status = status;
    report.energy = E;
    report.symbolic_factorizations = cholesky.symbolic_count();
    report.numeric_factorizations = cholesky.numeric_count();
    report.seconds = since(t_start);
    return report;
  };

  // Factorises H + shift·I, escalating the shift ×growth until it succeeds.
  // The paper starts every attempt at ε·λ_min; starting one step below the
  // last successful shift gives the same shift up to a factor `growth` and
  // saves most failed factorisations far from equilibrium. Returns the shift
  // used (infinity if every attempt failed); `base_ok` tells whether the
  // factorisation at exactly ε·λ_min succeeded (H + ε λ_min I positive
  // definite), which is decided here only when that shift was tried.
  double start_shift = base_shift;
  auto factorize = [&](double first, bool& base_ok, bool& base_tried) {
    const auto t0 = Clock::now();
    double shift = first;
    base_ok = false;
    base_tried = (first <= base_shift);
    for (int attempt = 0; attempt < o.max_shift_attempts; ++attempt) {
      if (cholesky.factorize(assembler.matrix(), shift, assembler.pattern_version())) {
        base_ok = base_tried && attempt == 0;
        report.time_factorization += since(t0);
        report.final_shift = shift;
        return shift;
      }
      shift *= o.shift_growth;
    }
    report.time_factorization += since(t0);
    return std::numeric_limits<double>::infinity();
  };

  for (;;) {
    auto t0 = Clock::now();
    VecX g = f.gradient();
    const bool near = g.norm() <= o.gradient_tolerance;
    f.assemble_hessian(assembler, near);
    report.time_assembly += since(t0);
    const double gnorm = g.norm();
    report.gradient_norm = gnorm;
    require(std::isfinite(gnorm), "minimize: the gradient is not finite");

    bool psd = false, base_tried = false;
    double shift = factorize(gnorm <= o.gradient_tolerance ? base_shift : start_shift, psd, base_tried);
    if (!std::isfinite(shift)) return finish(SolverStatus::Stalled);
    start_shift = std::max(base_shift, shift / o.shift_growth);
    report.hessian_psd = psd;

    if (gnorm <= o.gradient_tolerance) {
      if (psd) return finish(SolverStatus::ConvergedStable);
      if (o.stop_at_critical_point) return finish(SolverStatus::ConvergedUnstable);
      if (report.saddle_escapes >= o.max_saddle_escapes) return finish(SolverStatus::Stalled);
      // Leave the saddle along the eigenvector of the most negative eigenvalue.
      const auto te = Clock::now();
      EigenOptions eo;
      eo.count = 1;
      eo.exclude_rigid = false;
      const EigenResult eig = smallest_eigenpairs(assembler.matrix(), Eigen::MatrixXd(), base_shift, eo);
      report.time_eigen += since(te);
      if (eig.converged) report.smallest_eigenvalue = eig.values(0);
      if (!eig.converged || eig.values(0) >= 0.0) {
        // The factorisation failed only by a hair: treat as stable within the shift.
        return finish(o.stop_at_critical_point ? SolverStatus::ConvergedUnstable : SolverStatus::ConvergedStable);
      }
      VecX v = eig.vectors.col(0);
      if (g.dot(v) > 0.0) v = -v;
      const auto tc = Clock::now();
      double t = std::min(1.0, f.max_step(x, v));
      report.time_collision += since(tc);
      bool moved = false;
      const auto tl = Clock::now();
      for (; t >= o.min_step; t *= o.backtrack) {
        const VecX trial = x + t * v;
        f.set_dofs(trial);
        ++report.line_search_trials;
        const double Et = f.energy();
        if (std::isfinite(Et) && Et < E) {
          x = trial;
          E = Et;
          moved = true;
          break;
        }
      }
      report.time_line_search += since(tl);
      if (!moved) {
        // No step along the direction of negative curvature lowers the
        // energy by more than its round-off: the negative eigenvalue is
        // numerical noise on a flat (neutral) mode, and the point is a
        // minimum to working precision.
        f.set_dofs(x);
        report.marginal = true;
        return finish(SolverStatus::ConvergedStable);
      }
      f.accept();
      ++report.saddle_escapes;
      ++report.iterations;
      if (report.iterations >= o.max_iterations) return finish(SolverStatus::MaxIterations);
      continue;
    }
    if (report.iterations >= o.max_iterations) return finish(SolverStatus::MaxIterations);

    t0 = Clock::now();
    VecX d = -cholesky.solve(g);
    report.time_factorization += since(t0);
    double gd = g.dot(d);
    if (!(gd < 0.0) || !d.allFinite()) {
      d = -g;  // cannot happen for a positive definite shifted H; guard against round-off
      gd = -gnorm * gnorm;
    }
    t0 = Clock::now();
    const double t_max = f.max_step(x, d);
    double t = std::min(1.0, t_max);
    report.time_collision += since(t0);

    // Armijo backtracking on the total energy. Near convergence the decrease
    // c t g·d can fall below the round-off of E; then a step that lowers the
    // gradient norm is accepted instead.
    t0 = Clock::now();
    bool accepted = false;
    const double roundoff = 64.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(E));
    for (; t >= o.min_step; t *= o.backtrack) {
      const VecX trial = x + t * d;
      f.set_dofs(trial);
      ++report.line_search_trials;
      const double Et = f.energy();
      if (!std::isfinite(Et)) continue;
      if (Et <= E + o.armijo * t * gd) {
        x = trial;
        E = Et;
        accepted = true;
        break;
      }
      if (std::fabs(t * gd) < roundoff && Et <= E + roundoff) {
        const double gt = f.gradient().norm();
        if (gt < gnorm) {
          x = trial;
          E = Et;
          accepted = true;
          break;
        }
      }
    }
    report.time_line_search += since(t0);
    if (o.verbose)
      std::fprintf(stderr, "newton %5d  E %.12g  |g| %.3e  shift %.2e  |d|inf %.2e  ccd %.3e  t %.3e  %s\n",
                   report.iterations, E, gnorm, shift, d.lpNorm<Eigen::Infinity>(), t_max, accepted ? t : 0.0,
                   assembler.pattern_changed() ? "pattern" : "");
    if (!accepted) {
      f.set_dofs(x);
      return finish(SolverStatus::Stalled);
    }
    f.accept();
    ++report.iterations;
  }
}

}  // namespace ek
