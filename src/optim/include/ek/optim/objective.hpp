#pragma once
/// \file
/// What the Newton solver minimises (paper Section 6, eq.\ 1):
///
/// ~~~{.unparsed}
///   E(x) = Σ_k E_k(x)
/// ~~~
///
/// over one vector of degrees of freedom x, as a sum of potentials E_k (the
/// elastic rod, ω times the contact barrier, the planarity slab, ...). The
/// solver sees only the Objective interface; CompositeObjective builds one
/// from Potential terms, so a new term (an external force, a soft
/// constraint, a second rod) is a new Potential class, not a change of the
/// solver or of relax().
#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ek/core/hessian_kind.hpp"
#include "ek/core/sparse_assembler.hpp"
#include "ek/core/types.hpp"

namespace ek {

/// One named part of an energy (for breakdowns and the iteration trace).
struct EnergyPart {
  std::string name;    ///< e.g. "stretch", "bend", "twist", "contact", "slab"
  double value = 0.0;  ///< [energy]
};

/// A smooth objective E(x) with exact gradient and sparse Hessian.
///
/// set_dofs() may be called with trial points (line search) and must make
/// energy()/gradient()/assemble_hessian() describe that point; accept() is
/// called once a point is accepted as the new iterate (for example to
/// parallel-transport reference frames or refresh contact sets).
class Objective {
 public:
  virtual ~Objective() = default;            ///< Objectives are used through references to this interface.
  virtual int num_dofs() const = 0;          ///< Length of the dof vector x.
  virtual VecX dofs() const = 0;             ///< The current dofs x (num_dofs()).
  virtual void set_dofs(const VecX& x) = 0;  ///< Moves to x (num_dofs()): a trial point or the next iterate.
  /// E at the current dofs; +infinity when the point is infeasible.
  virtual double energy() = 0;
  virtual VecX gradient() = 0;  ///< ∇E at the current dofs (num_dofs()).
  /// Fills A with the Hessian's upper triangle (A.begin() ... A.end()).
  /// HessianKind::Projected lets an objective return a modified Hessian that
  /// is closer to positive semidefinite (for example with per-element
  /// projections) to get better Newton directions; the stability test at
  /// convergence always asks for the exact one.
  virtual void assemble_hessian(SparseAssembler& A, HessianKind kind) = 0;
  /// Largest t in (0, 1] such that x + s·dx is feasible for all s <= t
  /// (continuous collision detection). Default: unconstrained.
  virtual double max_step(const VecX& x, const VecX& dx) {
    (void)x;
    (void)dx;
    return 1.0;
  }
  /// Called once the current dofs are accepted as the new iterate (for example
  /// to parallel-transport reference frames). Default: nothing.
  virtual void accept() {}
  /// Orthonormal basis (num_dofs by k, k >= 0) of the motions that leave E
  /// invariant at the current dofs to first order (rigid motions). With
  /// NewtonOptions::remove_rigid_motions their components are removed from
  /// each Newton step. Default: none.
  virtual Eigen::MatrixXd rigid_modes() { return {}; }
  /// The parts of E at the current dofs, summing to energy() (iteration
  /// trace, energy breakdowns). Default: none.
  virtual std::vector<EnergyPart> energy_parts() { return {}; }
  /// Contact pairs active at the current dofs (iteration trace). Default 0.
  virtual int active_pairs() const { return 0; }
};

/// One term E_k of a CompositeObjective. It is evaluated at the point given
/// to its last set_dofs() call (the objective's whole dof vector; a term
/// over positions reads its first 3n entries).
class Potential {
 public:
  virtual ~Potential() = default;  ///< Terms are used through pointers to this interface.
  /// Moves the term to x (the objective's dofs, every trial point).
  virtual void set_dofs(const VecX& x) = 0;
  /// E_k at the current point [energy]; +infinity when infeasible.
  virtual double energy() const = 0;
  /// The parts of E_k (one part named after the term by default).
  virtual void add_energy_parts(std::vector<EnergyPart>& parts) const = 0;
  /// Adds ∇E_k to g (length: the objective's dofs).
  virtual void add_gradient(Eigen::Ref<VecX> g) const = 0;
  /// Identifies the sequence of positions add_hessian() writes (for
  /// SparseAssembler::segment): equal ids replay the same pattern.
  virtual std::uint64_t hessian_structure() const = 0;
  /// Adds the Hessian's upper triangle to A; HessianKind::Projected: a
  /// positive semidefinite modification of the strongly indefinite parts
  /// (the same sequence of positions either way).
  virtual void add_hessian(SparseAssembler& A, HessianKind kind) const = 0;
  /// Largest certified t in (0, 1] such that x + s·dx, s <= t, keeps the term
  /// finite (collision detection). Default 1.
  virtual double max_step(const VecX& x, const VecX& dx) const {
    (void)x;
    (void)dx;
    return 1.0;
  }
  /// Called once a point is accepted as the new iterate.
  virtual void accept() {}
  /// Active contact pairs (terms without contact: 0).
  virtual int active_pairs() const { return 0; }
};

/// E = Σ_k E_k over dofs owned by a state object (the rod): dofs() and
/// num_dofs() come from the callbacks given at construction; set_dofs()
/// moves every term. Each term's Hessian is one SparseAssembler segment,
/// numbered in the order of the terms, so a term whose structure is
/// unchanged replays its pattern. The terms are not owned.
class CompositeObjective : public Objective {
 public:
  /// Where the dofs live: callbacks into the state object that owns them.
  struct Dofs {
    std::function<int()> count;                      ///< number of dofs
    std::function<VecX()> get;                       ///< current dofs
    std::function<Eigen::MatrixXd()> rigid_modes;    ///< may be empty: none
  };
  /// The sum of `terms` (not owned, none null) over the dofs of `dofs` (count and
  /// get set); std::invalid_argument otherwise.
  CompositeObjective(Dofs dofs, std::vector<Potential*> terms);

  int num_dofs() const override { return dofs_.count(); }
  VecX dofs() const override { return dofs_.get(); }
  void set_dofs(const VecX& x) override;  ///< Moves every term to x (num_dofs()).
  /// The sum in the order of the terms.
  double energy() override;
  VecX gradient() override;                                              ///< The sum of the terms' gradients.
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override;  ///< One assembler segment per term, in order.
  /// The smallest of the terms' bounds.
  double max_step(const VecX& x, const VecX& dx) override;
  void accept() override;                                          ///< Every term's accept(), in order.
  Eigen::MatrixXd rigid_modes() override;                          ///< Dofs::rigid_modes(), or none when it is empty.
  std::vector<EnergyPart> energy_parts() override;                 ///< Every term's parts, in the order of the terms.
  int active_pairs() const override;                               ///< The sum over the terms.
  const std::vector<Potential*>& terms() const { return terms_; }  ///< The terms, in order (not owned).

 private:
  Dofs dofs_;
  std::vector<Potential*> terms_;
};

}  // namespace ek
