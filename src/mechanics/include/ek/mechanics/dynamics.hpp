#pragma once
/// \file
/// Knots in time: the same model as relax() (elastic rod, self-contact
/// barrier, certified collision detection) with inertia, damping, gravity
/// and friction, integrated by implicit (backward) Euler. Beyond the paper,
/// whose relaxations are static ("our simulation neither accounts for
/// dynamics nor friction", Section 8, jumping knots).
///
/// One step from (x^t, v^t) with time step h minimises the incremental
/// potential (Li et al. 2020, "Incremental Potential Contact", Sec. 3)
///
///   Φ(x) = Σ_i m_i [ |x_i − x̂_i|² / (2h²) + γ |x_i − x_i^t|² / (2h) ]
///          + E_rod(x) + ω E_contact(x) [+ E_envelope(x)] + D(x),
///   x̂ = x^t + h v^t + h² g,
///
/// over the model's dofs (positions, and the material angles of the full
/// model, which carry no inertia: the twist follows the centerline
/// quasi-statically, as in discrete viscous threads), by the project's
/// Newton solver with the same collision-free step bound, so no step ever
/// lets the wire pass through itself; then v^{t+h} = (x − x^t)/h. The
/// stationarity of Φ is M (x − x̂)/h² + γ M (x − x^t)/h = −∇E − ∇D: mass
/// times acceleration equals the elastic, contact, gravity, viscous
/// (−γ M v) and friction forces. Backward Euler dissipates energy at first
/// order in h (oscillations of angular frequency ϖ decay as
/// (1 + ϖ²h²)^(−t/2h)); a uniform motion is integrated exactly.
///
/// Masses: the wire's lumped mass m_i = ρ π r² l̄_i^V (density ρ, radius r,
/// rest Voronoi length of vertex i).
///
/// Friction (Coulomb, smoothed and lagged as in IPC, Sec. 5): each contact
/// k at the step's start x^t, with normal force λ_k, unit normal n_k and
/// closest-point weights w_kj on its vertices, contributes
///
///   D_k(x) = μ λ_k f₀(|u_k|),  u_k = (I − n_k n_kᵀ) Σ_j w_kj (x_j − x_j^t),
///
/// the relative tangential displacement over the step, with
/// f₀'(y) = f₁(y) = 2y/(ε_v h) − y²/(ε_v h)² for y < ε_v h, 1 above: a
/// sliding contact (relative speed above ε_v) feels the force μ λ_k opposing
/// its tangential motion, a slower one a viscous force that vanishes with
/// its speed. λ_k, n_k and the weights are fixed during the step (lagged).
/// Contacts: every self-contact pair within d̂ (λ = ω |b'(d)| of its segment
/// distance; closest points (1 − s) a0 + s a1 and (1 − t) b0 + t b1, weights
/// (1 − s, s, −(1 − t), −t)), and every vertex within the envelope's reach
/// of one of its plates (λ = κ |b'|, weight 1; the plates do not move along
/// their plane). D is convex in x for fixed λ: its Hessian is positive
/// semidefinite.
///
/// Units: consistent but arbitrary as for the rod (material.hpp), with
/// [pressure] = [mass]/([length]·[time]²): lengths in metres, E in pascals
/// and ρ in kg/m³ give times in seconds.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "ek/contact/contact_potential.hpp"
#include "ek/geometry/types.hpp"
#include "ek/optim/objective.hpp"
#include "ek/solver/relax.hpp"
#include "ek/solver/slab.hpp"

namespace ek {

/// m_i = ρ π r² (l̄_{i−1} + l̄_i)/2 [mass] for the rest edge lengths
/// `rest` (n, edge i from vertex i to i + 1, closed).
VecX lumped_masses(const VecX& rest, double density, double radius);

/// Inertia, viscous damping and gravity of one backward Euler step, a
/// Potential over the positions (the first 3n dofs):
///   E = Σ_i m_i [ |x_i − x̂_i|²/(2h²) + γ |x_i − x_i^t|²/(2h) ],
///   x̂ = x^t + h v^t + h² g.
/// Part "inertia". Its Hessian is diagonal: m_i (1/h² + γ/h) per coordinate.
class InertiaTerm : public Potential {
 public:
  /// `masses` n (> 0); h > 0; γ >= 0.
  InertiaTerm(VecX masses, double time_step, double damping, const Vec3& gravity);
  /// The step's start x^t and v^t (n by 3 each).
  void start_step(const Points& x, const Points& v);
  void set_dofs(const VecX& x) override;
  double energy() const override;
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"inertia", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override;
  std::uint64_t hessian_structure() const override { return 0x1E27u; }
  void add_hessian(SparseAssembler& A, HessianKind kind) const override;

 private:
  VecX m_;
  double h_, gamma_;
  Vec3 g_;
  VecX x_, start_, target_;  ///< 3n: current, x^t, x̂
};

/// One frictional contact of the step (lagged: fixed during the step).
struct FrictionContact {
  std::array<int, 4> vertices{-1, -1, -1, -1};  ///< the vertices it moves (-1: unused)
  std::array<double, 4> weights{0, 0, 0, 0};    ///< [1] relative displacement Σ_j w_j Δx_j
  Vec3 normal = Vec3::UnitZ();                  ///< unit normal of the contact
  double normal_force = 0.0;                    ///< [force] λ >= 0
};

/// The self-contact pairs within d̂ of `contact` at x (update(x) called):
/// closest points, normal and λ = ω |b'(d)|.
std::vector<FrictionContact> self_friction_contacts(const ContactPotential& contact, const Points& x);
/// The vertices within reach of a plate of `slab` at x: normal ±z, λ = κ |b'|.
std::vector<FrictionContact> envelope_friction_contacts(const PlanaritySlab& slab, const Points& x);

/// f₀ of the smoothed friction (see the file comment), for y >= 0 and
/// eps = ε_v h > 0 [length]: y²/eps − y³/(3 eps²) + eps/3 below eps, y above.
double friction_f0(double y, double eps);
/// f₁ = f₀': 2y/eps − y²/eps² below eps, 1 above.
double friction_f1(double y, double eps);

/// Lagged smoothed Coulomb friction D = Σ_k μ λ_k f₀(|u_k|) over the
/// contacts of the step's start (a Potential over the positions). Part
/// "friction".
class FrictionTerm : public Potential {
 public:
  /// μ >= 0; `eps` = ε_v h > 0 [length]; `start` the step's x^t (n by 3).
  FrictionTerm(double mu, double eps, const Points& start, std::vector<FrictionContact> contacts);
  void set_dofs(const VecX& x) override;
  double energy() const override;
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"friction", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override;
  std::uint64_t hessian_structure() const override;
  void add_hessian(SparseAssembler& A, HessianKind kind) const override;
  /// The step's frictional contacts.
  const std::vector<FrictionContact>& contacts() const { return contacts_; }

 private:
  Vec3 tangential(const FrictionContact& c) const;  ///< u_k at the current point
  double mu_, eps_;
  VecX start_, x_;
  std::vector<FrictionContact> contacts_;
};

/// How simulate() integrates: the model, the wire's density, the step, the
/// forces, the envelope, the frames and when the run counts as at rest.
struct DynamicsOptions {
  /// The model as for relax(): material, d̂, ω, the Newton tolerance and
  /// iteration cap of each step, the link (full model with Θ fixed); its
  /// slab is not used (the envelope below is).
  RelaxOptions model;
  double density = 1.0;              ///< [mass/length³] ρ of the wire
  double time_step = 1.0;            ///< [time] h
  double duration = 100.0;           ///< [time] the run ends here unless it comes to rest first
  Vec3 gravity = Vec3::Zero();       ///< [length/time²] g
  double damping = 0.0;              ///< [1/time] γ: the viscous force −γ m_i v_i on every vertex
  double friction = 0.0;             ///< [1] μ, between touching wires and against the envelope
  double friction_velocity = 1e-3;   ///< [length/time] ε_v: slower contacts feel viscous, not Coulomb, friction
  /// The envelope: two plates |z| < h with the slab's barrier (slab.hpp),
  /// none: no plates (a flat state released at t = 0).
  std::optional<SlabOptions> envelope;
  /// [length/time] each plate moves away from z = 0 at this speed (0:
  /// fixed); its barrier keeps the reach it had at t = 0
  double envelope_speed = 0.0;
  int frame_every = 10;              ///< [steps] a frame every this many steps (and the first and last)
  /// [length/time] at rest once every vertex is slower than this for
  /// `rest_steps` consecutive steps (after at least one step); 0: never.
  double rest_speed = 0.0;
  int rest_steps = 10;               ///< [steps]
  void validate() const;             ///< InputError for impossible values
};

/// The state at one time.
struct DynamicsFrame {
  double time = 0.0;                 ///< [time]
  Points positions;                  ///< n by 3
  double kinetic = 0.0;              ///< [energy] ½ Σ m_i |v_i|²
  double elastic = 0.0;              ///< [energy] E_rod + ω E_contact (+ the envelope's barrier)
  double gravity = 0.0;              ///< [energy] −Σ m_i g·x_i
  double max_speed = 0.0;            ///< [length/time] max_i |v_i|
  int contacts = 0;                  ///< [1] self-contact pairs within d̂
  int newton_iterations = 0;         ///< [1] of the step that ended here (0 at t = 0)
};

/// How simulate() ended.
enum class DynamicsStatus {
  Rest,             ///< "rest": came to rest
  Duration,         ///< "duration": the time ran out
  /// "step-failed": a step's Newton solve did not converge (the run ends at
  /// the last step that did)
  StepFailed,
  /// "topology-changed": the Alexander polynomial differs from the start's
  /// (an error, never a silent result)
  TopologyChanged,
};
std::string to_string(DynamicsStatus status);  ///< the texts above
std::ostream& operator<<(std::ostream& out, DynamicsStatus status);  ///< prints to_string(status)

/// What simulate() did: its status, frames and end state.
struct DynamicsResult {
  DynamicsStatus status = DynamicsStatus::Duration;  ///< how it ended
  std::vector<DynamicsFrame> frames; ///< every frame_every steps, the first and the last
  Points positions;                  ///< n by 3 at the end
  Points velocities;                 ///< n by 3 at the end
  VecX theta;                        ///< material angles at the end (zeros twist-free)
  double link = 0.0;                 ///< [turns] Tw + Wr at the end (full model; 0 twist-free)
  double time = 0.0;                 ///< [time] at the end
  std::optional<double> rest_time;   ///< [time] when it came to rest
  double max_speed = 0.0;            ///< [length/time] over the run
  double max_kinetic = 0.0;          ///< [energy] over the run
  int steps = 0;                     ///< [1]
  int newton_iterations = 0;         ///< [1] over all steps
  std::optional<SolverStatus> failed_status;  ///< the solver status of a failed step
  bool alexander_preserved = true;   ///< the end's Alexander polynomial is the start's
  TwistModel model = TwistModel::TwistFree;  ///< the unknowns of the rod
};

/// Integrates from `start` (n by 3, simple, not touching itself; inside the
/// envelope when there is one) with velocities `velocity` (n by 3; empty:
/// at rest) and rest edge lengths `rest` (n). InputError for bad options
/// or a start the model refuses.
DynamicsResult simulate(const Points& start, const VecX& rest, const DynamicsOptions& options,
                        const Points& velocity = Points());

}  // namespace ek
