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

std::string to_string(HessianMode mode) {
  switch (mode) {
    case HessianMode::Exact: return "exact";
    case HessianMode::Hybrid: return "hybrid";
  }
  return "unknown";
}

NewtonOptions NewtonOptions::paper() {
  NewtonOptions o;
  o.hessian = HessianMode::Exact;
  o.remove_rigid_motions = false;
  return o;
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
  require(hybrid_switch >= 1.0 && std::isfinite(hybrid_switch), "NewtonOptions: hybrid_switch must be >= 1");
  require(exact_after_full_steps >= 0, "NewtonOptions: exact_after_full_steps must be >= 0");
  require(max_shift_attempts >= 1, "NewtonOptions: max_shift_attempts must be >= 1");
  require(max_expansion >= 1.0 && expansion_ratio > 0.0, "NewtonOptions: max_expansion must be >= 1, expansion_ratio > 0");
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
    report.orderings = cholesky.ordering_count();
    report.time_symbolic = cholesky.symbolic_seconds();
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
  //
  // The result is the lowest rung first·growth^j (j >= 0) that factorises.
  // With NewtonOptions::shift_hint the search does not climb from `first`
  // but probes the rung below `hint` (the shift the same kind of Hessian
  // needed last time) first: if it fails, every lower rung fails too (H +
  // s·I is positive definite for every s above its smallest eigenvalue's
  // negative) and the climb goes on from there; if it succeeds, the search
  // steps down while the rung below factorises and, when one fails, takes
  // the last good rung's factor back (CholeskySolver::recall). The rung
  // found is the same.
  double start_shift = base_shift, last_shift = base_shift;
  int backoff = 0, wait = 0;
  auto rung = [&](double first, int j) {
    double s = first;  // by repeated multiplication, as the climb makes it
    for (int k = 0; k < j; ++k) s *= o.shift_growth;
    return s;
  };
  auto factorize = [&](double first, bool& base_ok, double hint) {
    const auto t0 = Clock::now();
    auto attempt = [&](int j) {
      const bool ok = cholesky.factorize(assembler.matrix(), rung(first, j), assembler.pattern_version());
      if (!ok) ++report.failed_factorizations;
      return ok;
    };
    const int attempts = o.max_shift_attempts;
    int probe = 0;  // the hint's rung minus one
    if (o.shift_hint && hint > first) {
      int j = 0;
      for (double s = first; s < hint * (1.0 - 1e-12) && j < attempts; s *= o.shift_growth) ++j;
      probe = j - 1;
    }
    int found = -1;
    if (probe > 0 && attempt(probe)) {
      found = probe;
      while (found > 0 && attempt(found - 1)) --found;
      if (found > 0 && !cholesky.recall(rung(first, found))) found = -1;  // (cannot fail: same analysis, same H)
    } else {
      for (int j = probe > 0 ? probe + 1 : 0; j < attempts && found < 0; ++j)
        if (attempt(j)) found = j;
    }
    report.time_factorization += since(t0);
    base_ok = found == 0 && first <= base_shift;
    if (found < 0) return std::numeric_limits<double>::infinity();
    report.final_shift = rung(first, found);
    return report.final_shift;
  };
  double hint[2] = {0.0, 0.0};  // last shift of the projected [0] and the exact [1] Hessian

  // Hybrid mode: after exact_after_full_steps consecutive full projected steps the iterate is
  // in a region where the quadratic model is good, and the exact Hessian
  // takes over (projected directions converge only linearly when the
  // projection removed real curvature, e.g. of compressed edges); it hands
  // back to the projected Hessian when an exact step must backtrack or the
  // exact Hessian needed a shift above 10⁶·ε·λ_min (indefinite).
  bool exact_region = false;
  int full_projected_steps = 0;
  double shift = base_shift;
  for (;;) {
    auto t0 = Clock::now();
    const VecX g = f.gradient();
    report.time_assembly += since(t0);
    const double gnorm = g.norm();
    report.gradient_norm = gnorm;
    require(std::isfinite(gnorm), "minimize: the gradient is not finite");
    const bool converged = gnorm <= o.gradient_tolerance;
    const bool exact =
        o.hessian == HessianMode::Exact || exact_region || gnorm <= o.hybrid_switch * o.gradient_tolerance;

    {
      t0 = Clock::now();
      f.assemble_hessian(assembler, exact);
      report.time_assembly += since(t0);
      bool psd = false;
      const double first = converged || !o.shift_warm_start ? base_shift : start_shift;
      shift = factorize(first, psd, hint[exact ? 1 : 0]);
      if (std::isfinite(shift)) hint[exact ? 1 : 0] = shift;
      if (!std::isfinite(shift)) return finish(SolverStatus::Stalled);
      // Warm start: next time try one factor lower, unless that level has
      // just failed; then wait 1, 2, 4, ... factorisations before retrying
      // it (a shift that stays needed costs no failed attempts).
      if (shift > first) {
        backoff = std::min(2 * backoff + 1, 64);
        wait = backoff;
      } else if (shift < last_shift) {
        backoff = 0;
      }
      last_shift = shift;
      if (wait > 0) {
        --wait;
        start_shift = shift;
      } else {
        start_shift = std::max(base_shift, shift / o.shift_growth);
      }
      report.hessian_psd = psd;

      if (converged) {
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
    }
    if (report.iterations >= o.max_iterations) return finish(SolverStatus::MaxIterations);

    t0 = Clock::now();
    VecX d = -cholesky.solve(g);
    report.time_factorization += since(t0);
    if (exact) ++report.exact_iterations;
    if (o.remove_rigid_motions) {
      const Eigen::MatrixXd Q = f.rigid_modes();
      if (Q.cols() > 0) d -= Q * (Q.transpose() * d);
    }
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
    const VecX x0 = x;
    const double E0 = E;
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
    // Expansion: the full step met the Armijo condition and lowered E by
    // nearly its first-order prediction (the model overestimates the
    // curvature along d, as a large shift or a projected Hessian does):
    // try 2, 4, ... times the step within the collision-free bound while E
    // keeps decreasing.
    if (accepted && t == 1.0 && o.max_expansion > 1.0 && E0 - E >= -o.expansion_ratio * gd) {
      const auto tc = Clock::now();
      const double T = o.max_expansion;
      const double t_ext = T * f.max_step(x0, T * d);
      report.time_collision += since(tc);
      double tb = 1.0, Eb = E;
      for (double tt = 2.0; tt <= t_ext && tt <= T; tt *= 2.0) {
        f.set_dofs(x0 + tt * d);
        ++report.line_search_trials;
        const double Et = f.energy();
        if (!(Et < Eb)) break;
        tb = tt;
        Eb = Et;
      }
      if (tb > 1.0) {
        x = x0 + tb * d;
        E = Eb;
        t = tb;
        ++report.expansions;
      }
      f.set_dofs(x);
    }
    report.time_line_search += since(t0);
    if (o.verbose)
      std::fprintf(stderr, "newton %5d  E %.12g  |g| %.3e  shift %.2e  |d|inf %.2e  ccd %.3e  t %.3e  %s %s\n",
                   report.iterations, E, gnorm, shift, d.lpNorm<Eigen::Infinity>(), t_max, accepted ? t : 0.0,
                   exact ? "exact" : "proj", assembler.pattern_changed() ? "pattern" : "");
    if (!accepted) {
      f.set_dofs(x);
      return finish(SolverStatus::Stalled);
    }
    if (o.hessian == HessianMode::Hybrid) {
      if (!exact) {
        full_projected_steps = t >= 1.0 ? full_projected_steps + 1 : 0;
        exact_region = o.exact_after_full_steps > 0 && full_projected_steps >= o.exact_after_full_steps;
      } else if (exact_region && (t < 1.0 || shift > 1e6 * base_shift)) {
        // backtracked, or the exact Hessian is indefinite (a large shift: tiny steps)
        exact_region = false;
        full_projected_steps = 0;
      }
    }
    f.accept();
    ++report.iterations;
  }
}

}  // namespace ek
