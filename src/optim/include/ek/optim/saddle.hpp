#pragma once
/// \file
/// Index-1 saddle points and minimum energy paths between stable states
/// (paper Section 8.5, "transitions between stable states": the paper names
/// minimum energy paths as the next step; this is ours).
///
/// Search (search_saddle): single-ended min-mode following on the exact
/// Hessian, from a stable equilibrium x₀ along one of its soft modes. Each
/// iteration at x, with g = ∇E(x), H = ∇²E(x) and P the projection out of
/// the rigid modes Q (Objective::rigid_modes()):
///  1. the `count` lowest eigenpairs (λ_i, v_i) of P H P (Spectra's Lanczos
///     on P (H − τI)⁻¹ P, τ below the lowest eigenvalue, a Cholesky factor);
///     the followed mode v is the one with the largest overlap |v_i·v_prev|;
///  2. along v, the partitioned rational-function step that maximises:
///        Δ_v = g_v / (√(λ²/4 + g_v²) − λ/2),   g_v = g·v, λ = λ_v
///     (Newton's −g_v/λ near a saddle where λ < 0; uphill, of trust-region
///     length, where λ > 0);
///  3. in the complement, the minimiser of ½dᵀ(H + σI)d + gᵀd over d ⊥ [v, Q]
///     from a sparse LDLᵀ factor of M = H + σI and the bordered system
///        d = −M⁻¹(g + Cη),   (CᵀM⁻¹C) η = −CᵀM⁻¹g,   C = [v Q],
///     with σ = σ₀·10^j the smallest rung for which M is positive definite on
///     C^⊥, read from the inertia: neg(ZᵀMZ) = neg(M) + pos(CᵀM⁻¹C) − cols(C);
///  4. d_⊥ is taken with a backtracking line search on the energy (Armijo,
///     1e-4; at most max_trust_radius long): it is a descent direction, and
///     the quadratic model of a rod holds only over short steps (a linear
///     step stretches the edges at second order), so a trust region on d_⊥
///     would keep it a small fraction of Newton's step;
///  5. then, with g_v at the new point, the step Δ_v v is scaled to the trust
///     radius (largest |d_i|); it is accepted when the energy change agrees
///     with the quadratic model g·d + ½dᵀHd within half the model's scale
///     |g·d| + ½|dᵀHd| (the radius then grows ×2 after a good agreement),
///     else the radius shrinks ×1/4.
///  Every trial is cut to the collision-free fraction (Objective::max_step:
///  the CCD, so no step lets two edges touch and the knot type cannot change).
/// Near a non-degenerate index-1 saddle the step is Newton's (quadratic
/// convergence). The search ends converged when ||g||₂ <= the tolerance with
/// λ_v < 0 and v the lowest mode; otherwise with a status (never a false
/// saddle: the result is then checked by hessian_index()).
///
/// Verification helpers: hessian_index() (the lowest eigenvalues of P H P),
/// descend() (Newton's method from a point, recording every accepted iterate:
/// the images of a minimum energy path).
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <string>
#include <vector>

#include "ek/core/types.hpp"
#include "ek/optim/newton.hpp"
#include "ek/optim/objective.hpp"

namespace ek {

/// How a saddle search ended.
enum class SaddleStatus {
  Converged,      ///< ||g|| <= tolerance, the followed mode the lowest and negative
  MaxIterations,  ///< iteration budget exhausted
  Stalled,        ///< the trust radius fell below its minimum (no step agrees with the model)
  LeftBasin,      ///< the energy rose more than max_energy_rise above the start without a saddle
  Degenerate,     ///< no usable eigenpair or complement factorisation (singular Hessian)
};
std::string to_string(SaddleStatus status);  ///< "converged", "max-iterations", "stalled", "left-basin", "degenerate"

/// The tolerance, trust region, eigen-solves and trace of search_saddle().
struct SaddleSearchOptions {
  double gradient_tolerance = 1e-8;  ///< [energy/length] converged when ||g||₂ <= this
  int max_iterations = 400;          ///< [1] iterations (each one eigen-solve and one LDLᵀ)
  double trust_radius = 0.05;        ///< [length] initial largest dof change of a step
  double max_trust_radius = 0.5;     ///< [length]
  double min_trust_radius = 1e-9;    ///< [length] below it the search has stalled
  /// [energy] the search has left the basin when E − E₀ exceeds this (E₀
  /// the start's energy) before converging.
  double max_energy_rise = 1.0;
  /// [energy/length²] σ₀ of the complement factorisation M = H + σI (the
  /// Newton solver's ε·λ_min).
  double base_shift = 1e-4;
  int eigen_count = 3;               ///< [1] eigenpairs per iteration (>= the followed mode's rank + 2)
  double eigen_tolerance = 1e-10;    ///< [1] relative tolerance of the Ritz values
  bool record_trace = false;         ///< keep one SaddleIteration per iteration
  bool verbose = false;              ///< print each iteration on stderr
  void validate() const;             ///< std::invalid_argument for impossible values
};

/// One iteration of search_saddle() (SaddleSearchOptions::record_trace).
struct SaddleIteration {
  double energy = 0.0;         ///< [energy]
  double gradient_norm = 0.0;  ///< [energy/length]
  double eigenvalue = 0.0;     ///< [energy/length²] λ of the followed mode
  int mode_rank = 0;           ///< [1] its rank among the lowest eigenpairs (0: the lowest)
  double overlap = 0.0;        ///< [1] |v·v_prev|
  double trust_radius = 0.0;   ///< [length]
  double shift = 0.0;          ///< [energy/length²] σ of the complement factorisation
  bool accepted = false;       ///< the step was taken
};

/// What search_saddle() returns: the last iterate, its energy, gradient and
/// followed mode, and how the search ended.
struct SaddleSearchResult {
  SaddleStatus status = SaddleStatus::MaxIterations;  ///< How the search ended.
  VecX x;                      ///< the last iterate (the saddle when converged)
  double energy = 0.0;         ///< [energy] at x
  double gradient_norm = 0.0;  ///< [energy/length] ||g||₂ at x
  double eigenvalue = 0.0;     ///< [energy/length²] λ of the followed mode at x
  VecX mode;                   ///< the followed mode at x (unit; dofs)
  int iterations = 0;          ///< [1] iterations taken
  int rejected = 0;            ///< steps rejected by the trust-region test
  double seconds = 0.0;        ///< [s]
  std::vector<SaddleIteration> trace;  ///< One record per iteration (SaddleSearchOptions::record_trace).
};

/// Searches an index-1 saddle from the objective's current dofs x₀ (a stable
/// equilibrium) by following the mode closest to `direction` (dofs; unit or
/// not, its sign chooses the way): the first step is x₀ + t·direction with
/// the largest |t·direction_i| equal to the trust radius. Leaves the
/// objective at the result's x. Throws std::invalid_argument for a direction
/// of the wrong size or zero.
SaddleSearchResult search_saddle(Objective& objective, const VecX& direction, const SaddleSearchOptions& options);

/// The lowest eigenvalues of P H P at the objective's current dofs (H exact,
/// P: the rigid modes projected out).
struct HessianIndex {
  bool converged = false;      ///< the eigen-solve converged
  VecX values;                 ///< [energy/length²] ascending, `count` or more
  Eigen::MatrixXd vectors;     ///< dofs by values.size(), unit columns
  /// [1] eigenvalues below −threshold; when every computed one is negative
  /// (the index may be larger) it is values.size().
  int negative = 0;
  /// [1] eigenvalues within ±threshold (a degenerate, neutral direction).
  int near_zero = 0;
};
/// `count` >= 2 lowest eigenpairs; `threshold` [energy/length²] > 0. When all
/// `count` are negative, more are computed (up to 8) to count the index.
HessianIndex hessian_index(Objective& objective, int count, double threshold, double eigen_tolerance = 1e-10);

/// Up to this many dofs the eigenpairs are computed densely (unit tests,
/// small models); above, with Spectra.
inline constexpr int kDenseModes = 64;
/// The most eigenpairs lowest_modes() computes for `dofs` and `rigid` modes.
int max_modes(int dofs, int rigid);

/// The lowest eigenpairs of P H P that lowest_modes() computes.
struct LowestModes {
  bool converged = false;      ///< the pairs were computed (else values and vectors are empty)
  VecX values;                 ///< [energy/length²] ascending, `count` of them
  Eigen::MatrixXd vectors;     ///< dofs by count, unit columns
  double tau = 0.0;            ///< the shift τ used
};
/// The `count` lowest eigenpairs of P H P for the upper triangle `upper` and
/// rigid modes Q (dofs by k, orthonormal; may be empty), with a shift-invert
/// around τ <= `guess` (lowered by `scale`, 4·scale, ... until H − τI
/// factorises; `scale` > 0). Ascending. Up to kDenseModes dofs computed
/// densely. std::invalid_argument unless 1 <= count <= max_modes() and
/// scale > 0.
LowestModes lowest_modes(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper, const Eigen::MatrixXd& Q,
                         int count, double guess, double scale, double tolerance = 1e-10);

/// The images of a descent path, as descend() records them.
struct Descent {
  NewtonReport report;           ///< of the Newton solve
  std::vector<VecX> images;      ///< the start, then every accepted iterate (the last: the result)
  std::vector<double> energies;  ///< [energy] of each image
};
/// Newton's method from the objective's current dofs with every accepted
/// iterate recorded (the images of a descent path). Leaves the objective at
/// the result.
Descent descend(Objective& objective, const NewtonOptions& options);

}  // namespace ek
