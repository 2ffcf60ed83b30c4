#pragma once
/// Newton's method with a Hessian shift, CHOLMOD factorisation with symbolic
/// reuse, a collision-free step bound and Armijo backtracking (paper Section 6,
/// "Numerical Solver"), on an abstract objective.
#include <cstdint>
#include <string>

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
};

/// Outcome of a minimisation.
enum class SolverStatus {
  ConvergedStable,    ///< gradient below tolerance and H positive semidefinite
  ConvergedUnstable,  ///< gradient below tolerance at a saddle (only with stop_at_critical_point)
  MaxIterations,      ///< iteration budget exhausted
  Stalled,            ///< the line search cannot make progress
};
std::string to_string(SolverStatus status);  ///< "converged-stable", "converged-unstable", "max-iterations", "stalled"

struct NewtonOptions {
  double gradient_tolerance = 1e-8;  ///< [energy/length] stop when ||g||₂ <= this (and H is PSD)
  int max_iterations = 1000;         ///< [1] Newton iterations
  /// [energy/length²] λ_min: smallest nonzero eigenvalue of the rod Hessian
  /// in a straight configuration (the caller provides it). The base shift is
  /// shift_epsilon·λ_min.
  double lambda_min = 1.0;
  double shift_epsilon = 1e-4;      ///< [1] ε of the paper
  double shift_growth = 10.0;       ///< [1] factor applied to the shift after a failed factorisation
  int max_shift_attempts = 40;      ///< [1]
  double armijo = 1e-4;             ///< [1] sufficient-decrease constant c: E(x + t d) <= E + c t g·d
  double backtrack = 0.5;           ///< [1] step reduction per backtracking trial
  double min_step = 1e-12;          ///< [1] smallest step fraction tried before declaring a stall
  /// Report converged-unstable at a saddle instead of leaving it along a
  /// direction of negative curvature.
  bool stop_at_critical_point = false;
  int max_saddle_escapes = 50;      ///< [1]
  CholeskyMode cholesky = CholeskyMode::Simplicial;
  /// Print one line per iteration to stderr (iteration, energy, ||g||, shift,
  /// collision-free bound, accepted step, pattern changes).
  bool verbose = false;
  void validate() const;
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
  int numeric_factorizations = 0;
  int line_search_trials = 0;
  double time_assembly = 0.0;           ///< [s] gradient and Hessian
  double time_factorization = 0.0;      ///< [s] symbolic + numeric + solves
  double time_collision = 0.0;          ///< [s] collision-free step bounds
  double time_line_search = 0.0;        ///< [s] energy evaluations of trial points
  double time_eigen = 0.0;              ///< [s] negative-curvature directions
};

/// Minimises the objective from its current dofs; leaves it at the result.
NewtonReport minimize(Objective& objective, const NewtonOptions& options);

}  // namespace ek
