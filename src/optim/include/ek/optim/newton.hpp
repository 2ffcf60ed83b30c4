#pragma once
/// \file
/// Newton's method with a Hessian shift, CHOLMOD factorisation with symbolic
/// reuse, a collision-free step bound and Armijo backtracking (paper Section 6,
/// "Numerical Solver"), on an abstract objective (objective.hpp).
///
/// One iteration of NewtonSolver::minimize():
///  1. gradient g; the Hessian kind (exact or projected, HessianSchedule);
///  2. assemble H and factorise H + shift·I, the shift from the ladder
///     ε·λ_min·growth^j searched by ShiftSearch;
///  3. at ||g|| <= tolerance: stable when H + ε·λ_min·I factorised, else
///     leave the saddle along the most negative eigenvector;
///  4. direction d = -(H + shift·I)⁻¹ g without its rigid-motion part;
///  5. line search: t <= the collision-free bound, Armijo backtracking
///     (and the optional expansion);
///  6. accept, update the Hessian schedule, record the iteration.
#include <Eigen/Dense>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ek/core/sparse_assembler.hpp"
#include "ek/core/types.hpp"
#include "ek/optim/cholesky.hpp"
#include "ek/optim/objective.hpp"

namespace ek {

/// Outcome of a minimisation.
enum class SolverStatus {
  ConvergedStable,    ///< gradient below tolerance and H positive semidefinite
  ConvergedUnstable,  ///< gradient below tolerance at a saddle (only with stop_at_critical_point)
  MaxIterations,      ///< iteration budget exhausted
  Stalled,            ///< the line search cannot make progress
};
std::string to_string(SolverStatus status);  ///< "converged-stable", "converged-unstable", "max-iterations", "stalled"

/// Which Hessian the Newton directions use (the stability test at
/// convergence always uses the exact one).
enum class HessianMode {
  /// The exact Hessian in every iteration (paper Section 6).
  Exact,
  /// The objective's projected Hessian (Objective::assemble_hessian with
  /// exact = false: per-element positive semidefinite projections of the
  /// terms that are strongly indefinite far from equilibrium) while
  /// ||g|| > hybrid_switch · gradient_tolerance, the exact Hessian below,
  /// and also after two consecutive full (t = 1) projected steps until an
  /// exact step must backtrack or is indefinite (projected directions
  /// converge only linearly where the projection removed real curvature).
  /// Quadratic convergence near the equilibrium is that of exact Newton.
  Hybrid,
};
std::string to_string(HessianMode mode);  ///< "exact", "hybrid"

/// How Newton's method steps: every setting but the solve's goal (its
/// tolerance, iteration cap, λ_min and whether to stop at a saddle, which
/// NewtonOptions adds). RelaxOptions holds these; relax() adds the goal.
struct NewtonMethodOptions {
  double shift_epsilon = 1e-4;      ///< [1] ε of the paper
  double shift_growth = 10.0;       ///< [1] factor applied to the shift after a failed factorisation
  /// Start each iteration's shift search one factor shift_growth below the
  /// previous iteration's shift instead of at ε·λ_min (same shift up to that
  /// factor, far fewer failed factorisations). The search always starts at
  /// ε·λ_min when the gradient is below tolerance (stability test).
  bool shift_warm_start = true;
  int max_shift_attempts = 40;      ///< [1] rungs of the shift ladder above the first one tried
  /// Search the shift ladder from the rung below the shift that the same
  /// kind of Hessian (projected or exact) needed last time, stepping up or
  /// down from there, instead of climbing from the first rung: the same
  /// shift (the lowest rung that factorises), fewer failed factorisations.
  /// Used only where failures cannot be skipped (shift_skip_proven off, or
  /// a CHOLMOD mode): with the skips, climbing from the warm start costs
  /// fewer factorisations than the hint's steps down (docs/performance.md).
  bool shift_hint = true;
  /// After a failed attempt at shift s, skip the rungs that the failure
  /// proves to fail: those below s + δ/2, with δ the least extra shift the
  /// failing pivot implies (CholeskySolver::shift_deficit(); the half is a
  /// margin against round-off). The same rung is found, with fewer failed
  /// factorisations (block factorisation only; the CHOLMOD modes report no δ).
  bool shift_skip_proven = true;
  HessianMode hessian = HessianMode::Hybrid;  ///< see HessianMode
  /// After a projected step that the line search cut below
  /// short_step_fraction, start the next shift search one rung above the
  /// last shift (Levenberg–Marquardt-like damping of a model that lets the
  /// curve move too far); the warm start lowers it again by one rung per
  /// search. Off by default.
  bool damp_short_steps = false;
  double short_step_fraction = 0.25;  ///< [1] see damp_short_steps
  double hybrid_switch = 1e3;       ///< [1] Hybrid: exact Hessian once ||g|| <= hybrid_switch · gradient_tolerance
  /// [1] Hybrid: exact Hessian after this many consecutive full (t = 1)
  /// projected steps, until an exact step backtracks or needs a shift above
  /// 10⁶·ε·λ_min (indefinite); 0 disables.
  int exact_after_full_steps = 2;
  /// Remove the components along Objective::rigid_modes() from each Newton
  /// step. A rigid rotation leaves E invariant, but its linearisation
  /// x + ω×x stretches every edge to second order; with the tiny shift
  /// ε·λ_min the Newton step can carry a large such component near an
  /// equilibrium (where rotations are near-null modes of H), whose
  /// second-order stretch then dominates the gradient and stalls convergence.
  bool remove_rigid_motions = true;
  double armijo = 1e-4;             ///< [1] sufficient-decrease constant c: E(x + t d) <= E + c t g·d
  double backtrack = 0.5;           ///< [1] step reduction per backtracking trial
  double min_step = 1e-12;          ///< [1] smallest step fraction tried before declaring a stall
  /// [1] Line-search expansion: when the full step lowers E by at least
  /// expansion_ratio·|g·d| (a quadratic model predicts |g·d|/2), steps of
  /// 2, 4, ... up to max_expansion times d are tried (within the
  /// collision-free bound) while E keeps decreasing. 1 disables it.
  /// Default 1: expanded steps cut the run time per equilibrium but carry
  /// samples across basins, so fewer distinct equilibria are found (measured
  /// on 8_1, 40 lattice samples: 2 clusters with 16, 4 without).
  double max_expansion = 1.0;
  double expansion_ratio = 0.75;    ///< [1] see max_expansion
  int max_saddle_escapes = 50;      ///< [1]
  CholeskyOptions cholesky;         ///< factorisation mode and ordering reuse (cholesky.hpp)
  /// Keep an IterationRecord per iteration (NewtonSolver::trace()).
  bool record_trace = false;
  /// Print each iteration's record to stderr (iteration, energy, ||g||,
  /// shift, collision-free bound, accepted step, pattern changes).
  bool verbose = false;
  void validate() const;  ///< std::invalid_argument for impossible values

  /// The paper's method: exact Hessian in every iteration, no rigid-motion
  /// removal (the shift alone suppresses rigid motions), warm-started shift
  /// search.
  static NewtonMethodOptions paper();
};

/// One Newton solve: the method and its goal.
struct NewtonOptions : NewtonMethodOptions {
  double gradient_tolerance = 1e-8;  ///< [energy/length] stop when ||g||₂ <= this (and H is PSD)
  int max_iterations = 1000;         ///< [1] Newton iterations
  /// [energy/length²] λ_min: smallest nonzero eigenvalue of the rod Hessian
  /// in a straight configuration (the caller provides it). The base shift is
  /// shift_epsilon·λ_min.
  double lambda_min = 1.0;
  /// Report converged-unstable at a saddle instead of leaving it along a
  /// direction of negative curvature.
  bool stop_at_critical_point = false;
  NewtonOptions() = default;  ///< The default method and goal.
  /// `method` with the default goal.
  explicit NewtonOptions(const NewtonMethodOptions& method) : NewtonMethodOptions(method) {}
  void validate() const;  ///< std::invalid_argument for impossible values
  /// The paper's method with the default goal.
  static NewtonOptions paper() { return NewtonOptions(NewtonMethodOptions::paper()); }
};

/// Timings and counters of a minimisation.
struct NewtonReport {
  SolverStatus status = SolverStatus::MaxIterations;  ///< How the minimisation ended.
  int iterations = 0;                   ///< [1] Newton steps and saddle escapes taken.
  double seconds = 0.0;                 ///< [s] wall time
  double energy = 0.0;                  ///< [energy] E at the result
  double gradient_norm = 0.0;           ///< ||g||₂ at the result
  double final_shift = 0.0;             ///< shift used in the last factorisation
  bool hessian_psd = false;             ///< H + ε λ_min I factorised at the end
  int saddle_escapes = 0;               ///< [1] steps along a direction of negative curvature at a saddle
  /// Converged where H + ε λ_min I is not positive definite but no step along
  /// the direction of negative curvature lowers the energy beyond round-off
  /// (a neutral mode): reported as converged-stable with this flag.
  bool marginal = false;
  /// [energy/length²] most negative eigenvalue found at the last saddle test (0 if none).
  double smallest_eigenvalue = 0.0;
  int symbolic_factorizations = 0;      ///< [1] symbolic analyses (pattern changes)
  int orderings = 0;                    ///< fill-reducing orderings (AMD), <= symbolic_factorizations
  int numeric_factorizations = 0;       ///< [1] numeric factorisations, failed ones included
  /// Numeric factorisations that failed (H + shift·I not positive definite:
  /// a rung of the shift ladder; part of numeric_factorizations).
  int failed_factorizations = 0;
  int line_search_trials = 0;           ///< [1] energy evaluations of trial points (line search and expansion)
  double time_assembly = 0.0;           ///< [s] gradient and Hessian
  double time_factorization = 0.0;      ///< [s] symbolic + numeric + solves
  double time_collision = 0.0;          ///< [s] collision-free step bounds
  double time_line_search = 0.0;        ///< [s] energy evaluations of trial points
  double time_eigen = 0.0;              ///< [s] negative-curvature directions
  double time_symbolic = 0.0;           ///< [s] symbolic analyses (part of time_factorization)
  int expansions = 0;                   ///< steps lengthened by the line-search expansion
  int exact_iterations = 0;             ///< iterations whose direction used the exact Hessian
};

/// What an iteration did.
enum class IterationKind {
  Step,          ///< a Newton step (accepted, or the line search stalled: step = 0)
  SaddleEscape,  ///< a step along the most negative eigenvector at a saddle
  Final,         ///< the convergence test at the result (no step)
};
std::string to_string(IterationKind kind);  ///< "step", "saddle-escape", "final"

/// One iteration of NewtonSolver::minimize() (NewtonOptions::record_trace).
/// Values describe the iterate before the step unless they say otherwise.
struct IterationRecord {
  int phase = 0;                  ///< which minimize() call of the solver (0, 1, ...)
  int iteration = 0;              ///< iterations taken before this one, in the phase
  IterationKind kind = IterationKind::Step;  ///< a step, a saddle escape or the final test
  double energy = 0.0;            ///< [energy] E
  std::vector<EnergyPart> parts;  ///< Objective::energy_parts()
  double gradient_norm = 0.0;     ///< [energy/length] ||g||₂
  bool exact = false;             ///< the exact Hessian (else the projected one)
  double shift = 0.0;             ///< [energy/length²] shift of the factorisation used
  int factorizations = 0;         ///< numeric factorisations in this iteration (failed included)
  int failed_factorizations = 0;  ///< rungs of the shift ladder that failed
  bool pattern_changed = false;   ///< the Hessian's sparsity pattern changed
  double max_step = 1.0;          ///< [1] collision-free bound of the step
  double step = 0.0;              ///< [1] accepted step fraction t (0: none; > 1 expanded)
  int line_search_trials = 0;     ///< [1] energy evaluations of trial points in this iteration
  int active_pairs = 0;           ///< Objective::active_pairs() at the iterate
  double seconds = 0.0;           ///< [s] wall time of the iteration
};

/// Newton's method (see the file comment). One solver serves successive
/// minimisations (the phases of a relaxation): they share the assembler's
/// sparsity pattern, CHOLMOD's ordering and symbolic analysis and the shift
/// search's hints; the warm start of the shift and the Hessian schedule
/// start afresh each time, so a phase's iterates are those of a new solver
/// up to the round-off of another elimination order.
class NewtonSolver {
 public:
  /// A solver with these options; std::invalid_argument for impossible ones.
  explicit NewtonSolver(const NewtonOptions& options = {});
  ~NewtonSolver();                                        ///< Releases the assembler and the factorisation.
  NewtonSolver(const NewtonSolver&) = delete;             ///< Not copyable.
  NewtonSolver& operator=(const NewtonSolver&) = delete;  ///< Not copyable.

  const NewtonOptions& options() const { return options_; }  ///< The options of the next minimize().
  /// Validates and sets the options of the following minimisations.
  void set_options(const NewtonOptions& options);
  /// Minimises from the objective's current dofs; leaves it at the result.
  /// The report counts this call only.
  NewtonReport minimize(Objective& objective);
  /// Every iteration of every minimize() call so far (record_trace).
  const std::vector<IterationRecord>& trace() const { return trace_; }

 private:
  struct Run;
  bool factorize(Objective& f, Run& run, bool exact, bool converged);
  bool stability_test(Objective& f, Run& run, const VecX& g);
  VecX direction(Objective& f, Run& run, const VecX& g);
  bool line_search(Objective& f, Run& run, const VecX& d, double gd);
  void expand(Objective& f, Run& run, const VecX& x0, double E0, const VecX& d, double gd);
  NewtonReport finish(Run& run, SolverStatus status);
  void record(Run& run);

  struct State;
  NewtonOptions options_;
  std::unique_ptr<State> state_;
  std::vector<IterationRecord> trace_;
  int phase_ = 0;
};

/// One-shot: NewtonSolver(options).minimize(objective).
NewtonReport minimize(Objective& objective, const NewtonOptions& options);

}  // namespace ek
