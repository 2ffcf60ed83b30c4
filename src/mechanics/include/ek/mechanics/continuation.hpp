#pragma once
/// \file
/// Equilibria of a knot along a load path, by pseudo-arclength continuation
/// (Keller 1977), so that the path passes limit points (folds) where the
/// load parameter turns back, with the stability of every point.
///
/// The family: E(x; μ) = E_knot(x) + E_load(x; μ) (loads.hpp), equilibria
/// G(x, μ) = ∇ₓE = 0. From a point (x_k, μ_k) with unit tangent
/// t = (t_x, t_μ) (weighted norm w²|t_x|² + t_μ² = 1, w² = 1/dofs), the
/// predictor (x_p, μ_p) = (x_k, μ_k) + Δs·t, and the corrector, Newton on
///   G(x, μ) = 0,   w² t_xᵀ(x − x_p) + t_μ(μ − μ_p) = 0,
/// by two solves with the exact Hessian H (indefinite in general; a sparse
/// LU of H + κ QQᵀ, Q the rigid modes that keep the load):
/// ~~~{.unparsed}
///   H a = −G,  H b = −∂G/∂μ,  Δμ = −(N + w² t_xᵀa) / (w² t_xᵀb + t_μ),  Δx = a + Δμ b.
/// ~~~
/// Every corrector step is cut to the collision-free fraction (the CCD of the
/// contact term, the plates' barrier), so the knot type is kept, and halved
/// until ||G|| decreases; a corrector that does not converge in
/// `corrector_iterations` halves Δs.
/// The new tangent solves H b = −∂G/∂μ: t ∝ (b, 1), oriented along the
/// previous one; Δs grows ×1.5 after an easy corrector (<= 3 iterations).
/// At each point: the energy, the load's reaction and displacement, and the
/// lowest eigenvalues of H without the rigid modes (its index: negative
/// eigenvalues below −threshold). A limit point is where t_μ changes sign
/// (the parameter turns back: under that control the knot snaps there); a
/// bifurcation where the index changes without a turn.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"
#include "ek/mechanics/loads.hpp"
#include "ek/optim/newton.hpp"
#include "ek/optim/objective.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// E(x; μ): an objective with one parameter, and the derivatives in μ that
/// continuation needs.
class ParameterizedObjective : public Objective {
 public:
  virtual double parameter() const = 0;       ///< μ, the load parameter.
  virtual void set_parameter(double mu) = 0;  ///< Sets μ (the dofs are unchanged).
  /// ∂(∇ₓE)/∂μ at the current dofs (num_dofs()).
  virtual VecX parameter_gradient() = 0;
  /// ∂E/∂μ at the current dofs.
  virtual double parameter_derivative() = 0;
  /// What a device measures and applies (loads.hpp); by default μ and ∂E/∂μ.
  /// This one: the displacement the device measures (μ by default).
  virtual double displacement() { return parameter(); }
  virtual double reaction() { return parameter_derivative(); }  ///< The force the device applies; ∂E/∂μ by default.
  virtual double load_energy() { return 0.0; }                  ///< [energy] E_load at the current dofs; 0 by default.
  /// Vertices whose positions lead the dofs (x0 y0 z0 x1 ...): the stable
  /// path measures a minimiser's jump after the best rigid motion of them
  /// (a knot pushed or turned whole by a load has not snapped); 0: the
  /// plain RMS of all dofs.
  virtual Eigen::Index rigid_vertices() const { return 0; }
};

/// The end, steps, corrector and stability settings of follow_path().
struct ContinuationOptions {
  double target = 0.0;               ///< [parameter] the path ends where μ reaches it
  /// [parameter] first arclength step; unset: |target − μ₀| / 40
  std::optional<double> step;
  double min_step_factor = 1e-4;     ///< [1] the smallest step, as a share of the first: below it the path stalls
  double max_step_factor = 4.0;      ///< [1] the largest step, as a multiple of the first
  int max_points = 1000;             ///< [1] points of the path at most
  int corrector_iterations = 20;     ///< [1] Newton iterations of a corrector before Δs is halved
  double gradient_tolerance = 1e-8;  ///< [energy/length] a corrector has converged when ||G|| <= this
  int eigen_count = 4;               ///< [1] lowest eigenpairs computed at each point (0: no stability)
  double index_threshold = 1e-9;     ///< [energy/length²] eigenvalues below −this count as negative
  /// The stable path instead of the arclength corrector: when set, the
  /// step is taken in μ (Δs towards the target; a stable branch is a graph
  /// over μ), the predictor is x + Δμ·dx/dμ with dx/dμ = −H⁻¹ ∂G/∂μ, and each
  /// point minimises E(·; μ_p) from the predictor (NewtonSolver with these
  /// options: line search, shifts of indefinite Hessians, the CCD), so the
  /// path follows stable equilibria only. A landing farther than `max_jump`
  /// from the predictor, or above the energy of the branch's last state at
  /// the new control, is not taken as the branch's next point: the minimiser
  /// starts again from that last state; if it too lands farther than
  /// `max_jump`, Δs is halved, and at the smallest Δs the landing is a snap
  /// (PathEvent::Snap: the stable state it fell to, past a fold or a
  /// subcritical bifurcation, with less energy at the same control, and
  /// which, minimised back at the previous control, does not return to the
  /// branch: two stable states there), the branch's next point (it does
  /// return: the branch only moved fast along a soft mode) or, if it
  /// released no energy, a branch jump (PathEvent::BranchJump).
  std::optional<NewtonOptions> minimizer;
  /// [length] the RMS vertex distance from the predictor after the best rigid motion (rigid_vertices(); minimizer only)
  double max_jump = 1.0;
  void validate() const;             ///< InputError for impossible values
};

/// Where a path point sits.
enum class PathEvent {
  Regular,       ///< an ordinary point of the path
  LimitPoint,    ///< the parameter turned back between the previous point and this one
  Bifurcation,   ///< the index changed without a turn (an eigenvalue crossed zero)
  /// (stable path) the branch ended at the smallest step: its last state,
  /// minimised at the new control, fell to another stable state of lower
  /// energy (energy_drop > 0)
  Snap,
  /// (stable path) at the smallest step the minimiser landed on another
  /// equilibrium that is not the branch's continuation and released no
  /// energy at the same control (or the branch's last state is outside what
  /// the load admits there): the path goes on from it, but it is no snap
  BranchJump,
};
/// "regular", "limit-point", "bifurcation", "snap", "branch-jump"
std::string to_string(PathEvent event);

/// One equilibrium of a load path: the load, the energy, the stability and
/// what happened there.
struct PathPoint {
  double parameter = 0.0;      ///< [parameter] μ
  double displacement = 0.0;   ///< [length] what the device measures
  double reaction = 0.0;       ///< [force] what the device applies
  double parameter_derivative = 0.0;  ///< [energy/parameter] ∂E/∂μ
  double energy = 0.0;         ///< [energy] E_knot + E_load
  double load_energy = 0.0;    ///< [energy]
  double gradient_norm = 0.0;  ///< [energy/length] ||∇ₓE||
  double tangent_parameter = 0.0;  ///< [1] t_μ of the unit tangent
  int index = -1;              ///< [1] negative eigenvalues of H (rigid modes removed); -1: not computed
  double lowest_eigenvalue = 0.0;  ///< [energy/length²]
  VecX lowest_mode;            ///< its unit eigenvector (num_dofs); empty when not computed
  bool stable = false;         ///< index == 0
  PathEvent event = PathEvent::Regular;  ///< where the point sits (a limit point, a snap, ...)
  int corrector_iterations = 0;  ///< [1] Newton iterations of the corrector (or minimiser) that reached it
  /// [energy] Snap: E(x_{k−1}; μ_k) − E(x_k; μ_k), the energy the branch's
  /// last state releases falling into this one at the same control; else 0
  double energy_drop = 0.0;
  VecX dofs;                   ///< the equilibrium
};

/// How a path ended.
enum class PathStatus {
  Reached,     ///< μ reached the target
  MaxPoints,   ///< the point budget ran out
  Stalled,     ///< Δs fell below its minimum (no corrector converged)
  Stopped,     ///< the caller stopped it (on_point returned false)
};
std::string to_string(PathStatus status);  ///< "reached", "max-points", "stalled", "stopped"

/// What follow_path() returns: the points of the path and how it ended.
struct LoadPath {
  PathStatus status = PathStatus::MaxPoints;  ///< how the path ended
  std::vector<PathPoint> points;  ///< the start (relaxed at μ₀) first
  double seconds = 0.0;           ///< [s]
};

/// Follows the equilibria of `f` from its current dofs and parameter μ₀ (an
/// equilibrium: it is first brought to ||G|| <= tolerance at μ₀ by the same
/// Newton solve with μ fixed) towards options.target. Leaves `f` at the last
/// point. `on_point` (optional) sees every accepted point; returning false
/// ends the path there (PathStatus::Stopped).
LoadPath follow_path(ParameterizedObjective& f, const ContinuationOptions& options,
                     const std::function<bool(const PathPoint&)>& on_point = {});

/// The knot model (RodModel: rod and contact, twist-free) plus a load: the
/// sum of the knot's potentials and the load (a CompositeObjective: each term
/// one Hessian segment), a ParameterizedObjective whose parameter is the
/// load's. Its rigid modes are those the load keeps. The system and the load
/// must outlive it.
class LoadedKnot : public ParameterizedObjective {
 public:
  LoadedKnot(CompositeObjective& knot, ControlledLoad& load);  ///< At the knot's current dofs (the load is moved there).
  int num_dofs() const override { return sum_.num_dofs(); }
  VecX dofs() const override { return sum_.dofs(); }
  void set_dofs(const VecX& x) override;
  double energy() override { return sum_.energy(); }
  VecX gradient() override { return sum_.gradient(); }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override { sum_.assemble_hessian(A, kind); }
  double max_step(const VecX& x, const VecX& dx) override { return sum_.max_step(x, dx); }
  void accept() override { sum_.accept(); }
  Eigen::MatrixXd rigid_modes() override;
  std::vector<EnergyPart> energy_parts() override { return sum_.energy_parts(); }
  int active_pairs() const override { return sum_.active_pairs(); }
  double parameter() const override { return load_.parameter(); }
  void set_parameter(double mu) override;
  VecX parameter_gradient() override { return load_.parameter_gradient(num_dofs()); }
  double parameter_derivative() override { return load_.parameter_derivative(); }
  double displacement() override { return load_.displacement(); }
  double reaction() override { return load_.reaction(); }
  double load_energy() override { return load_.energy(); }
  Eigen::Index rigid_vertices() const override { return num_dofs() / 3; }  // twist-free: the dofs are positions
  ControlledLoad& load() { return load_; }  ///< The load (not owned).

 private:
  CompositeObjective& knot_;
  ControlledLoad& load_;
  CompositeObjective sum_;  ///< the knot's terms, then the load
  VecX x_;
};

}  // namespace ek
