#pragma once
/// \file
/// The terms of the relaxation of a knot or a link (paper Section 6, eq.\ 1)
/// as Potentials (objective.hpp) over the rods' dofs (RodTerm):
///
/// ~~~{.unparsed}
///   RodTerm      E_stretch + E_bend + E_twist        (elastic_rod.hpp)
///   ContactTerm  ω Σ b(d_ij) over close edge pairs   (contact_potential.hpp)
///   SlabTerm     κ Σ b(h ∓ z_i), the planarity slab  (slab.hpp)
/// ~~~
///
/// Each wraps an object it does not own; the contact and slab terms act on
/// the position dofs only. RodObjective sums them.
#include <memory>
#include <optional>
#include <vector>

#include "ek/contact/contact_potential.hpp"
#include "ek/optim/objective.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/slab.hpp"

namespace ek {

/// The elastic rods of a curve or a link (paper Section 6, eq.\ 1 summed over
/// the components). Parts "stretch", "bend", "twist" (each summed over the
/// rods; twist 0 in TwistFree). The rods' dofs lie back to back, rod c's
/// block starting after the dofs of rods 0..c−1: one rod [x (3n) | θ | Θ];
/// several rods (twist-free only) [x_0 (3n_0) | x_1 (3n_1) | ...], so the
/// positions of all rods are the head of the dofs either way.
/// max_step keeps every tangent within `max_rotation` [rad] of its source
/// when the model has material frames (time-parallel transport stays well
/// defined); accept() transports the reference frames in those models. In
/// TwistFree the frames enter no energy and are not transported (the rod's
/// reference twists then describe its starting frames).
class RodTerm : public Potential {
 public:
  /// The term of `rod` (not owned); `max_rotation` [rad] bounds the tangents' rotation per step.
  RodTerm(ElasticRod& rod, double max_rotation) : RodTerm(std::vector<ElasticRod*>{&rod}, max_rotation) {}
  /// The term of `rods` (not owned, at least one; several only twist-free,
  /// else InputError), back to back.
  RodTerm(std::vector<ElasticRod*> rods, double max_rotation);
  int num_dofs() const;     ///< the rods' dofs together
  VecX dofs() const;        ///< [rod 0 | rod 1 | ...]
  Points positions() const; ///< every rod's vertices, rod 0's first (N by 3)
  /// The first material-angle dof (3n) of one rod with frames; −1 when twist-free.
  int theta_begin() const;
  void set_dofs(const VecX& x) override;
  double energy() const override;
  void add_energy_parts(std::vector<EnergyPart>& parts) const override;
  void add_gradient(Eigen::Ref<VecX> g) const override;
  std::uint64_t hessian_structure() const override;
  /// HessianKind::Projected: the stretching Hessians of compressed edges projected.
  void add_hessian(SparseAssembler& A, HessianKind kind) const override;
  double max_step(const VecX& x, const VecX& dx) const override;
  void accept() override;

 private:
  std::vector<ElasticRod*> rods_;
  std::vector<Eigen::Index> offsets_;  ///< first dof of each rod
  double max_rotation_;
};

/// Self-contact. Part "contact". HessianKind::Projected: each pair's barrier
/// Hessian projected to positive semidefinite. max_step: the certified collision
/// detection, so no accepted step lets two edges touch.
class ContactTerm : public Potential {
 public:
  /// `x` (n by 3): the positions to start from (the active set is built there).
  ContactTerm(ContactPotential& contact, const Points& x);
  void set_dofs(const VecX& x) override;
  double energy() const override { return contact_.energy(x_); }
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"contact", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override { contact_.add_gradient(x_, g.head(x_.size())); }
  std::uint64_t hessian_structure() const override { return contact_.hessian_structure(); }
  void add_hessian(SparseAssembler& A, HessianKind kind) const override { contact_.add_hessian(x_, A, kind); }
  double max_step(const VecX& x, const VecX& dx) const override;
  int active_pairs() const override { return static_cast<int>(contact_.num_active()); }

 private:
  ContactPotential& contact_;
  Points x_;
};

/// The planarity slab |z| < h. Part "slab".
class SlabTerm : public Potential {
 public:
  /// The term of `slab` (not owned), starting at the positions `x` (n by 3).
  SlabTerm(const PlanaritySlab& slab, const Points& x) : slab_(slab), x_(x) {}
  void set_dofs(const VecX& x) override { x_ = as_points(x.head(x_.size())); }
  double energy() const override { return slab_.energy(x_); }
  void add_energy_parts(std::vector<EnergyPart>& parts) const override { parts.push_back({"slab", energy()}); }
  void add_gradient(Eigen::Ref<VecX> g) const override { g.head(x_.size()) += slab_.gradient(x_); }
  std::uint64_t hessian_structure() const override { return 1; }
  void add_hessian(SparseAssembler& A, HessianKind) const override { slab_.add_hessian(x_, A); }
  double max_step(const VecX& x, const VecX& dx) const override;

 private:
  const PlanaritySlab& slab_;
  Points x_;
};

/// E_rod + ω E_contact [+ E_slab] over the rods' dofs (RodTerm), with the
/// rigid motions of the curve or link (only the slab's own symmetries when
/// the slab is present; see rigid_modes() in eigen_analysis.hpp). Owns its
/// terms; the rods, contact and slab must outlive it.
class RodObjective : public CompositeObjective {
 public:
  /// The objective of `rods` and `contact` (not owned; the contact's
  /// topology the rods' components), with the slab when `slab` is not null;
  /// `max_rotation` [rad] as for RodTerm. Starts at the rods' current positions.
  RodObjective(std::vector<ElasticRod*> rods, ContactPotential& contact, const PlanaritySlab* slab,
               double max_rotation);
  /// The objective of one rod.
  RodObjective(ElasticRod& rod, ContactPotential& contact, const PlanaritySlab* slab, double max_rotation)
      : RodObjective(std::vector<ElasticRod*>{&rod}, contact, slab, max_rotation) {}

 private:
  RodObjective(std::unique_ptr<RodTerm> r, ContactPotential& contact, const PlanaritySlab* slab);
  RodObjective(std::unique_ptr<RodTerm>&& r, ContactPotential& contact, const PlanaritySlab* slab, const Points& x);
  RodObjective(std::unique_ptr<RodTerm>&& r, std::unique_ptr<ContactTerm> c, std::unique_ptr<SlabTerm> s);
  std::unique_ptr<RodTerm> rod_term_;
  std::unique_ptr<ContactTerm> contact_term_;
  std::unique_ptr<SlabTerm> slab_term_;
};

}  // namespace ek
