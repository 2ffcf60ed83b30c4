#pragma once
/// \file
/// Newton restricted to the curves with a p-fold rotational symmetry (paper
/// Section 8.4, Fig.\ 16: the periodic braids' states "with p-fold symmetry").
///
/// A closed curve of n = p·m vertices is cyclically symmetric when a rotation
/// R by `angle` about an axis through c carries every vertex m places along
/// the curve:
///
/// ~~~{.unparsed}
///   x_{i+m} = c + R (x_i − c)   (indices mod n),   angle = 2πk/p, gcd(k, p) = 1.
/// ~~~
///
/// The symmetric curves form a linear subspace, parameterised by the
/// fundamental vertices y = (x_0 … x_{m−1}) (3m dofs):
///
/// ~~~{.unparsed}
///   x = S y + b,   x_{i+tm} = R^t y_i + (I − R^t) c   (t = 0 … p−1).
/// ~~~
///
/// E is invariant under the symmetry, so by the principle of symmetric
/// criticality (Palais 1979) a critical point of E(S y + b) over y is a
/// critical point of E over all curves: at a symmetric x the gradient is
/// equivariant, so ∇E(x) = 0 exactly when Sᵀ∇E(x) = 0. Its stability in the
/// full space is a separate question (hessian_index() in saddle.hpp).
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/types.hpp"
#include "ek/optim/newton.hpp"
#include "ek/optim/objective.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// The symmetry x_{i+m} = c + R(angle)(x_i − c), m = n/order.
struct CyclicSymmetry {
  int order = 2;               ///< [1] p >= 2
  Vec3 center = Vec3::Zero();  ///< [length] a point of the axis
  Vec3 axis = Vec3::UnitZ();   ///< unit direction
  double angle = M_PI;         ///< [rad] the rotation carrying vertex i to vertex i + n/p
  /// R^t, the rotation by t·angle about the axis.
  Mat3 rotation(int t) const;
};

/// The cyclic symmetry of P (n divisible by p) about the given axis whose
/// angle 2πk/p (k = 1 … p−1, gcd(k, p) = 1) best fits P: the smallest
/// cyclic_symmetry_residual(). Throws std::invalid_argument when n is not
/// divisible by p or p < 2.
CyclicSymmetry fit_cyclic_symmetry(const Points& P, int p, const Vec3& center, const Vec3& axis);

/// [length] sqrt((1/n) Σ_i |x_{i+m} − c − R(x_i − c)|²): 0 for a symmetric curve.
double cyclic_symmetry_residual(const Points& P, const CyclicSymmetry& symmetry);

/// The nearest symmetric curve (the orthogonal projection onto the subspace):
/// y_i = c + (1/p) Σ_t R^{−t}(x_{i+tm} − c), then x = S y + b.
Points project_symmetric(const Points& P, const CyclicSymmetry& symmetry);

/// How the components of a vector field on the vertices (v: 3n) split into the
/// Fourier classes of the symmetry: v = Σ_k v_k with T v_k = e^{2πik/p} v_k,
/// (T v)_{i+m} = R v_i. Entry k (k = 0 … ⌊p/2⌋) is |v_k|² + |v_{p−k}|² over
/// |v|² (k and p − k are complex conjugates for a real v, so they come
/// together). Class 0 is the symmetric part; a mode with no weight in class 0
/// breaks the p-fold symmetry, and its class is the wavenumber of the break.
std::vector<double> symmetry_classes(const VecX& v, const CyclicSymmetry& symmetry);

/// E(S y + b) over the fundamental vertices y, on an objective whose dofs are
/// the 3n vertex positions (the twist-free model). The rigid motions that
/// keep the symmetry (translation along the axis, rotation about it) are its
/// rigid modes; the collision-free bound is the full objective's along S·dy.
/// The full objective is not owned and is kept at S y + b.
class SymmetricObjective : public Objective {
 public:
  /// Projects the full objective's current dofs onto the subspace
  /// (project_symmetric()) and sets it there. Throws std::invalid_argument
  /// when its dofs are not 3n positions with n divisible by the order.
  SymmetricObjective(Objective& full, const CyclicSymmetry& symmetry);

  int num_dofs() const override { return 3 * m_; }
  VecX dofs() const override { return y_; }
  void set_dofs(const VecX& y) override;
  double energy() override { return full_.energy(); }
  /// Sᵀ ∇E(S y + b).
  VecX gradient() override { return S_.transpose() * full_.gradient(); }
  /// Sᵀ H S (its upper triangle), H the full objective's (exact or projected) Hessian.
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override;
  double max_step(const VecX& y, const VecX& dy) override;
  void accept() override { full_.accept(); }
  Eigen::MatrixXd rigid_modes() override;
  std::vector<EnergyPart> energy_parts() override { return full_.energy_parts(); }
  int active_pairs() const override { return full_.active_pairs(); }

  /// The full dofs S y + b of reduced dofs y.
  VecX full_dofs(const VecX& y) const { return S_ * y + b_; }
  const CyclicSymmetry& symmetry() const { return symmetry_; }  ///< The symmetry of the subspace.

 private:
  Objective& full_;
  CyclicSymmetry symmetry_;
  int n_ = 0, m_ = 0;
  Eigen::SparseMatrix<double> S_;  ///< 3n by 3m
  VecX b_;                         ///< 3n
  VecX y_;
  SparseAssembler inner_;
};


// ---- Critical points of any index -----------------------------------------

/// Newton–Raphson on ∇E = 0: each step solves (H + Q Qᵀ·κ) d = −g with the
/// exact Hessian H (indefinite in general; a sparse LU with pivoting), Q the
/// rigid modes (κ = the mean |H_ii|, so the rigid directions are not
/// singular) and d projected out of them, then backtracks from the largest
/// collision-free fraction of d until the merit ||g||² decreases (Armijo,
/// 1e-4). It converges to the nearest critical point of whatever index,
/// quadratically where that point is non-degenerate; from far away the merit
/// can stall at a minimum of ||g||² that is not critical (status Stalled).
struct CriticalPointOptions {
  double gradient_tolerance = 1e-8;  ///< [energy/length] converged when ||g||₂ <= this
  int max_iterations = 200;          ///< [1]
  double min_step = 1e-10;           ///< [1] smallest step fraction before declaring a stall
  void validate() const;             ///< std::invalid_argument for impossible values
};

/// How a Newton–Raphson solve ended: ConvergedUnstable stands for
/// "converged" whatever the index (solve_critical_point() does not test it),
/// MaxIterations or Stalled.
struct CriticalPointReport {
  SolverStatus status = SolverStatus::MaxIterations;  ///< ConvergedUnstable (converged), MaxIterations or Stalled
  int iterations = 0;          ///< [1] Newton–Raphson iterations taken
  double energy = 0.0;         ///< [energy]
  double gradient_norm = 0.0;  ///< [energy/length] ||g||₂ of the objective's dofs
  double seconds = 0.0;        ///< [s]
};
/// From the objective's current dofs; leaves it at the result.
CriticalPointReport solve_critical_point(Objective& objective, const CriticalPointOptions& options);

// ---- The p-fold symmetric critical point of the knot model ----------------

/// How find_symmetric_critical_point() solves within the symmetric subspace.
enum class SymmetricSolve {
  /// Newton's descent (the relaxation's solver): a minimum within the subspace.
  Minimize,
  /// Newton–Raphson (solve_critical_point()): the nearest critical point
  /// within the subspace, of any index there.
  Root,
};
std::string to_string(SymmetricSolve solve);          ///< "minimize", "root"

/// The model and the solve of find_symmetric_critical_point() and
/// descend_symmetric().
struct SymmetricSearchOptions {
  /// The model (twist-free only: no link, no full model, no slab): material,
  /// d̂, ω, tolerance, iteration cap and Newton options as for relax().
  RelaxOptions relax;
  SymmetricSolve solve = SymmetricSolve::Minimize;  ///< see SymmetricSolve
  /// [1] iteration cap of SymmetricSolve::Root (Newton–Raphson converges
  /// quadratically near a non-degenerate critical point, in a few dozen
  /// iterations; a start that needs more is far from one)
  int max_root_iterations = 100;
  /// [1] most eigenpairs of the full Hessian computed for the Morse index
  /// (the index is complete when one computed eigenvalue is non-negative).
  int max_modes = 24;
  /// [energy/length²] eigenvalues below −threshold count in the index, those
  /// within ±threshold are reported as near zero; unset: 1e3·ε·λ_min of the
  /// model (the Newton solver's shift scale).
  std::optional<double> index_threshold;
  void validate() const;  ///< InputError for impossible values
};

/// One eigenpair of the full Hessian at a symmetric critical point.
struct SymmetricMode {
  double eigenvalue = 0.0;      ///< [energy/length²] of P H P (rigid modes projected out)
  /// symmetry_classes() of the eigenvector: entry k is its weight in
  /// wavenumber k (0: symmetric, k >= 1: breaks the p-fold symmetry)
  std::vector<double> classes;
  int dominant_class = 0;       ///< [1] the class of largest weight
  VecX vector;                  ///< 3n, unit
};

/// A p-fold symmetric critical point: Newton restricted to the symmetric
/// subspace (SymmetricObjective), from a symmetric start, then checked in
/// the full space (gradient, Morse index).
struct SymmetricCriticalPoint {
  Points positions;                   ///< n by 3
  CyclicSymmetry symmetry;            ///< the symmetry kept
  SymmetricSolve solve = SymmetricSolve::Minimize;  ///< how it was found
  SolverStatus status = SolverStatus::MaxIterations;  ///< of the restricted solve
  int iterations = 0;                 ///< [1] of the restricted solve
  double energy = 0.0;                ///< [energy]
  double gradient_norm = 0.0;         ///< [energy/length] ||∇E||₂ in the full space
  double tolerance = 0.0;             ///< [energy/length] the model's gradient tolerance
  bool converged = false;             ///< restricted Newton converged and gradient_norm <= tolerance
  bool alexander_preserved = true;    ///< same Alexander polynomial as the start
  double residual = 0.0;              ///< [length] cyclic_symmetry_residual() of the result
  int contacts = 0;                   ///< active contact pairs
  /// Morse index: eigenvalues of the full exact Hessian below −threshold,
  /// rigid modes projected out. Complete when `index_complete`; otherwise a
  /// lower bound (every computed eigenvalue was negative).
  int index = 0;
  bool index_complete = false;        ///< some computed eigenvalue was non-negative: `index` is the whole index
  int near_zero = 0;                  ///< [1] eigenvalues within ±threshold
  double threshold = 0.0;             ///< [energy/length²]
  /// The lowest eigenpairs, ascending: every negative one and the lowest
  /// non-negative ones computed with them.
  std::vector<SymmetricMode> modes;
  /// The index within the subspace: the negative eigenvalues of the
  /// restricted Hessian Sᵀ H S (symmetric rigid modes projected out), below
  /// −p·threshold. 0: the point is a minimum within the subspace, so every
  /// unstable direction breaks the symmetry.
  int subspace_index = 0;
  double seconds = 0.0;               ///< [s] wall time
};

/// Newton in the subspace of the curves with `symmetry` from `start` (n by
/// 3, n divisible by p, approximately symmetric: it is projected first;
/// simple), rest lengths `rest` (n, invariant under the shift by n/p to a
/// relative 1e-6; each orbit's mean is used), then
/// the full gradient and the lowest eigenpairs of the full Hessian and of the
/// restricted one. SymmetricSolve::Minimize leaves the subspace's saddles, so
/// its result is a minimum of E on the subspace (it may still be a saddle of
/// E); SymmetricSolve::Root converges to the nearest critical point. Every step is cut by the continuous collision detection of the full
/// curve. InputError for a start that touches itself, rest lengths that are
/// not periodic, or options outside the twist-free model.
SymmetricCriticalPoint find_symmetric_critical_point(const Points& start, const VecX& rest,
                                                     const CyclicSymmetry& symmetry,
                                                     const SymmetricSearchOptions& options = {});

/// Newton's descent within the subspace (SymmetricSolve::Minimize) with every
/// accepted iterate recorded: where the restricted flow goes from `start`
/// and how fast. A critical point of E that the path passes near shows as a
/// dip of the gradient norm towards 0; a bottleneck without one (a "ghost"
/// of critical points that have merged) as a dip that stays well above the
/// tolerance.
struct SymmetricDescent {
  NewtonReport report;                 ///< of the restricted solve
  std::vector<Points> images;          ///< n by 3: the projected start, then every accepted iterate
  std::vector<double> energies;        ///< [energy] of each image
  std::vector<double> gradient_norms;  ///< [energy/length] ||∇E||₂ of each image in the full space
};
/// Arguments as find_symmetric_critical_point() (options.solve is not used).
SymmetricDescent descend_symmetric(const Points& start, const VecX& rest, const CyclicSymmetry& symmetry,
                                   const SymmetricSearchOptions& options = {});

}  // namespace ek
