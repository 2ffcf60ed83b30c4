#pragma once
/// Newton's method with a Hessian shift, CHOLMOD factorisation with symbolic
/// reuse, a collision-free step bound and Armijo backtracking (paper Section 6,
/// "Numerical Solver"), on an abstract objective.
#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <vector>

#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/types.hpp"
#include "ek/solver/cholesky.hpp"

namespace ek {

/// A smooth objective E(x) with exact gradient and sparse Hessian.
///
/// set_dofs() may be called with trial points (line search) and must make
/// energy()/gradient()/assemble_hessian() describe that point; accept() is
/// called once a point is accepted as the new iterate (for example to
/// parallel-transport reference frames or refresh contact sets).
class Objective {
 public:
  virtual ~Objective() = default;
  virtual int num_dofs() const = 0;
  virtual VecX dofs() const = 0;
  virtual void set_dofs(const VecX& x) = 0;
  /// E at the current dofs; +infinity when the point is infeasible.
  virtual double energy() = 0;
  virtual VecX gradient() = 0;
  /// Fills A with the Hessian's upper triangle (A.begin() ... A.end()).
  /// With exact = false an objective may return a modified Hessian that is
  /// closer to positive semidefinite (for example with per-element
  /// projections) to get better Newton directions; the stability test at
  /// convergence always asks for the exact Hessian.
  virtual void assemble_hessian(SparseAssembler& A, bool exact) = 0;
  /// Largest t in (0, 1] such that x + s·dx is feasible for all s <= t
  /// (continuous collision detection). Default: unconstrained.
  virtual double max_step(const VecX& x, const VecX& dx) {
    (void)x;
    (void)dx;
    return 1.0;
  }
  virtual void accept() {}
  /// Orthonormal basis (num_dofs by k, k >= 0) of the motions that leave E
  /// invariant at the current dofs to first order (rigid motions). With
  /// NewtonOptions::remove_rigid_motions their components are removed from
  /// each Newton step. Default: none.
  virtual Eigen::MatrixXd rigid_modes() { return {}; }
};

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

struct NewtonOptions {
  double gradient_tolerance = 1e-8;  ///< [energy/length] stop when ||g||₂ <= this (and H is PSD)
  int max_iterations = 1000;         ///< [1] Newton iterations
  /// [energy/length²] λ_min: smallest nonzero eigenvalue of the rod Hessian
  /// in a straight configuration (the caller provides it). The base shift is
  /// shift_epsilon·λ_min.
  double lambda_min = 1.0;
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
  bool shift_hint = true;
  HessianMode hessian = HessianMode::Hybrid;  ///< see HessianMode
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
  /// Report converged-unstable at a saddle instead of leaving it along a
  /// direction of negative curvature.
  bool stop_at_critical_point = false;
  int max_saddle_escapes = 50;      ///< [1]
  CholeskyOptions cholesky;         ///< factorisation mode and ordering reuse (cholesky.hpp)
  /// Print one line per iteration to stderr (iteration, energy, ||g||, shift,
  /// collision-free bound, accepted step, pattern changes).
  bool verbose = false;
  void validate() const;

  /// The paper's method as issue 6 describes it: exact Hessian in every
  /// iteration, no rigid-motion removal (the shift alone suppresses rigid
  /// motions), warm-started shift search.
  static NewtonOptions paper();
};

/// Timings and counters of a minimisation.
struct NewtonReport {
  SolverStatus status = SolverStatus::MaxIterations;
  int iterations = 0;
  double seconds = 0.0;                 ///< [s] wall time
  double energy = 0.0;
  double gradient_norm = 0.0;           ///< ||g||₂ at the result
  double final_shift = 0.0;             ///< shift used in the last factorisation
  bool hessian_psd = false;             ///< H + ε λ_min I factorised at the end
  int saddle_escapes = 0;
  /// Converged where H + ε λ_min I is not positive definite but no step along
  /// the direction of negative curvature lowers the energy beyond round-off
  /// (a neutral mode): reported as converged-stable with this flag.
  bool marginal = false;
  /// [energy/length²] most negative eigenvalue found at the last saddle test (0 if none).
  double smallest_eigenvalue = 0.0;
  int symbolic_factorizations = 0;
  int orderings = 0;                    ///< fill-reducing orderings (AMD), <= symbolic_factorizations
  int numeric_factorizations = 0;
  /// Numeric factorisations that failed (H + shift·I not positive definite:
  /// a rung of the shift ladder; part of numeric_factorizations).
  int failed_factorizations = 0;
  int line_search_trials = 0;
  double time_assembly = 0.0;           ///< [s] gradient and Hessian
  double time_factorization = 0.0;      ///< [s] symbolic + numeric + solves
  double time_collision = 0.0;          ///< [s] collision-free step bounds
  double time_line_search = 0.0;        ///< [s] energy evaluations of trial points
  double time_eigen = 0.0;              ///< [s] negative-curvature directions
  double time_symbolic = 0.0;           ///< [s] symbolic analyses (part of time_factorization)
  int expansions = 0;                   ///< steps lengthened by the line-search expansion
  int exact_iterations = 0;             ///< iterations whose direction used the exact Hessian
};

/// Minimises the objective from its current dofs; leaves it at the result.
NewtonReport minimize(Objective& objective, const NewtonOptions& options);

}  // namespace ek
