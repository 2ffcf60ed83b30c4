#pragma once
/// \file
/// Loads on a knot as potential terms of the position dofs (beside the rod,
/// contact and slab terms of rod_terms.hpp), each controlled by one scalar
/// parameter μ: a pull between two material points under displacement
/// control, two parallel plates at a prescribed gap, or a pair of opposite
/// point forces of prescribed magnitude (paper Section 8.5: "a quantitative
/// analysis of the deformation of elastic knots under load").
///
/// Every load gives, besides its energy, gradient and Hessian in x, what
/// path following needs (continuation.hpp): ∂(∇ₓE)/∂μ and ∂E/∂μ, and the
/// reaction and displacement the device measures. Along a path of
/// equilibria x*(μ), dE*/dμ = ∂E/∂μ (the x-gradient vanishes), so the work
/// ∫ (∂E/∂μ) dμ equals the change of the total energy E* = E_knot + E_load.
///
/// Positions are n by 3 (vertex i at dofs 3i .. 3i+2); the loads act on the
/// positions only (the twist-free model).
#include <Eigen/Dense>
#include <string>

#include "ek/geometry/types.hpp"
#include "ek/optim/objective.hpp"

namespace ek {

/// A load controlled by one parameter μ (a Potential over the positions).
class ControlledLoad : public Potential {
 public:
  virtual double parameter() const = 0;            ///< μ
  virtual void set_parameter(double mu) = 0;       ///< moves the device
  /// ∂(∇ₓE_load)/∂μ at the current point (3n; zero beyond the positions).
  virtual VecX parameter_gradient(int dofs) const = 0;
  /// ∂E_load/∂μ at the current point.
  virtual double parameter_derivative() const = 0;
  /// The force the device applies: the pull's tension (> 0 pulling the
  /// points apart, = ∂E/∂D), the plates' compressive force (> 0 pressing,
  /// = −∂E/∂g), the prescribed force of ForceLoad.
  virtual double reaction() const = 0;
  /// The displacement the device measures: the distance of the pulled
  /// points, the plates' gap, or the loaded points' distance.
  virtual double displacement() const = 0;
  /// What the parameter is: "distance", "gap" or "force".
  virtual std::string parameter_name() const = 0;
  /// Whether the load is a pair of plates. The rigid motions of the curve
  /// that leave a load unchanged are all six for a pull or forces between
  /// two points, and for plates only the translations in their plane and the
  /// rotation about their normal (LoadedKnot::rigid_modes()).
  virtual bool plates() const { return false; }
  /// The plates' unit normal a (plates()); +z for the other loads.
  virtual Vec3 normal() const { return Vec3::UnitZ(); }
};

/// Pull between vertices i and j under displacement control, by a stiff
/// spring of rest length D (the parameter):
/// ~~~{.unparsed}
///   E = (k/2)(δ − D)²,  δ = |x_i − x_j|,  F = ∂E/∂D·(−1) = k(D − δ)
/// ~~~
/// (F > 0: the device pulls the points apart; F = ∂E/∂D). With k much stiffer than
/// the knot along the pull, δ follows D (a hard device in the limit).
class PullLoad : public ControlledLoad {
 public:
  /// `k` [energy/length²] > 0; i != j.
  PullLoad(int i, int j, double distance, double stiffness);
  void set_dofs(const VecX& x) override;
  double energy() const override;
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"load", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override;
  std::uint64_t hessian_structure() const override { return 0x9011u; }
  void add_hessian(SparseAssembler& A, HessianKind kind) const override;
  double parameter() const override { return D_; }
  void set_parameter(double mu) override { D_ = mu; }
  VecX parameter_gradient(int dofs) const override;
  double parameter_derivative() const override { return k_ * (D_ - distance()); }
  double reaction() const override { return k_ * (D_ - distance()); }
  double displacement() const override { return distance(); }
  std::string parameter_name() const override { return "distance"; }

 private:
  double distance() const { return (xi_ - xj_).norm(); }
  int i_, j_;
  double D_, k_;
  Vec3 xi_ = Vec3::Zero(), xj_ = Vec3::UnitX();
};

/// Opposite point forces of magnitude F (the parameter) on vertices i and j
/// along the line joining them (F > 0 pulls them apart):
/// ~~~{.unparsed}
///   E = −F δ,  δ = |x_i − x_j|.
/// ~~~
class ForceLoad : public ControlledLoad {
 public:
  /// Forces of magnitude `force` [force] on vertices i != j (>= 0); InputError
  /// otherwise or for a non-finite force.
  ForceLoad(int i, int j, double force);
  void set_dofs(const VecX& x) override;
  double energy() const override { return -F_ * distance(); }
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"load", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override;
  std::uint64_t hessian_structure() const override { return 0xF0ACu; }
  void add_hessian(SparseAssembler& A, HessianKind kind) const override;
  double parameter() const override { return F_; }
  void set_parameter(double mu) override { F_ = mu; }
  VecX parameter_gradient(int dofs) const override;
  double parameter_derivative() const override { return -distance(); }
  double reaction() const override { return F_; }
  double displacement() const override { return distance(); }
  std::string parameter_name() const override { return "force"; }

 private:
  double distance() const { return (xi_ - xj_).norm(); }
  int i_, j_;
  double F_;
  Vec3 xi_ = Vec3::Zero(), xj_ = Vec3::UnitX();
};

/// Two parallel plates with unit normal a, through the planes
/// a·(x − c) = ±g/2 (the gap g is the parameter), as a barrier on every
/// vertex's distance to each plate, as the planarity slab (slab.hpp):
/// ~~~{.unparsed}
///   E = κ Σ_i [ b(g/2 − s_i) + b(g/2 + s_i) ],  s_i = a·(x_i − c),
/// ~~~
/// b the IPC barrier with activation distance `reach` (the wire radius: the
/// plates touch the wire's surface). F = −∂E/∂g is the force the plates
/// press with (> 0). max_step keeps every vertex strictly between them.
class PlatesLoad : public ControlledLoad {
 public:
  /// Plates through `center` [length] with normal `normal` (nonzero, normalised
  /// here), gap g = `gap` [length] > 0, barrier reach [length] > 0 and stiffness
  /// κ [energy/length²] > 0; InputError otherwise.
  PlatesLoad(const Vec3& center, const Vec3& normal, double gap, double reach, double stiffness);
  void set_dofs(const VecX& x) override;
  double energy() const override;
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"load", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override;
  std::uint64_t hessian_structure() const override { return 0x91A7u; }
  void add_hessian(SparseAssembler& A, HessianKind kind) const override;
  double max_step(const VecX& x, const VecX& dx) const override;
  double parameter() const override { return g_; }
  void set_parameter(double mu) override { g_ = mu; }
  VecX parameter_gradient(int dofs) const override;
  double parameter_derivative() const override;
  double reaction() const override { return 0.0 - parameter_derivative(); }
  double displacement() const override { return g_; }
  std::string parameter_name() const override { return "gap"; }
  bool plates() const override { return true; }
  Vec3 normal() const override { return a_; }
  /// Whether every vertex lies strictly between the plates at gap g.
  bool inside(double g) const;

 private:
  Vec3 c_, a_;
  double g_, reach_, kappa_;
  VecX s_;  ///< a·(x_i − c) per vertex
};

}  // namespace ek
