#pragma once
/// \file
/// The model of a relaxation (paper Section 6, eq.\ 1; links: Section 8.5),
/// built once from a curve or a link and the RelaxOptions, and shared by
/// relax(), the saddle and critical-point searches, the loads and the links:
///
/// ~~~{.unparsed}
///   E(x, θ) = Σ_c E_rod(x_c, θ_c) + ω Σ_{pairs} b(d_ij) [+ E_slab(x)]
/// ~~~
///
/// A knot is a link of one component. The model resolves the options' unset
/// fields once (resolve_model(): d̂, ω, the tolerance and the twist model,
/// with ℓ the mean rest edge of the first component), owns one elastic rod
/// per component (model_rod()), the contact between every pair of edges
/// that share no vertex (across components too, contact_potential.hpp) and
/// the planarity slab when the options give one, and gives the objective
/// (RodObjective, rod_terms.hpp) and the Newton options of relax().
///
/// Dofs: one component [x (3n) | θ | Θ] (elastic_rod.hpp); several
/// components [x_0 (3n_0) | x_1 (3n_1) | ...] (twist-free only).
/// λ_min (the shift's scale, newton.hpp) is that of the straight rod with
/// the link's total vertex count and edge ℓ.
#include <memory>
#include <optional>
#include <string>

#include "ek/contact/contact_potential.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"
#include "ek/optim/newton.hpp"
#include "ek/optim/objective.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/relax.hpp"
#include "ek/solver/slab.hpp"

namespace ek {

/// The rods, contact and slab of one relaxation, with its resolved model
/// and Newton options. Not copyable; the objectives it gives refer to it.
class RodModel {
 public:
  /// The model of `link` (one component: a knot with rest lengths
  /// options.rest_lengths or its edge lengths; several: the components'
  /// edge lengths, twist-free, without a slab). Throws InputError (messages
  /// beginning "relax: ") for a curve with fewer than 4 vertices, non-finite
  /// coordinates or a zero-length edge, rest lengths that are not n
  /// positive numbers, curves that touch (themselves or each other), a
  /// start outside the slab, options a link of several components does not
  /// have (a prescribed link Lk, the full model, a slab, given rest
  /// lengths), and impossible options.
  RodModel(const Link& link, const RelaxOptions& options);
  /// The model of one closed curve `curve` (n by 3) with rest lengths `rest` (n).
  RodModel(const Points& curve, const VecX& rest, const RelaxOptions& options);
  ~RodModel();                                    ///< Releases the rods, contact, slab and objective.
  RodModel(const RodModel&) = delete;             ///< Not copyable.
  RodModel& operator=(const RodModel&) = delete;  ///< Not copyable.

  /// As given (with rest_lengths set to `rest` by the constructor of one curve).
  const RelaxOptions& options() const;
  const ResolvedModel& resolved() const;  ///< d̂, ω, the tolerance and the twist model.
  int num_components() const;            ///< [1] the link's components (1: a knot)
  int num_vertices() const;              ///< [1] of all components
  ElasticRod& rod(int component = 0);    ///< A component's rod (owned); its dofs are the objective's block.
  const ElasticRod& rod(int component = 0) const;  ///< A component's rod (owned).

  /// The objective E_rod + f·ω E_contact [+ E_slab] at the rods' current
  /// dofs: `contact_factor` f > 0 (1: the model's contact, whose state the
  /// model keeps from its construction on: with a Hessian margin
  /// (RelaxOptions::contact_hessian_margin) its pattern carries over from
  /// one objective to the next; otherwise a fresh contact potential with
  /// stiffness f·ω),
  /// `with_slab` whether the slab (when the model has one) is a term. The
  /// same object while the arguments are those of the previous call; a call
  /// with others builds a new one and invalidates the previous reference.
  CompositeObjective& objective(double contact_factor = 1.0, bool with_slab = true);
  /// The contact potential at ω (owned); its active set where it was last updated.
  ContactPotential& contact();
  const PlanaritySlab* slab() const;  ///< The slab, or null.

  /// The Newton options of relax() for this model (newton_options(): the
  /// resolved tolerance, the iteration cap, λ_min).
  const NewtonOptions& newton() const;
  double tolerance() const;   ///< [energy/length] the resolved gradient tolerance
  double lambda_min() const;  ///< [energy/length²] of the straight rod (the shift's scale)

  Points positions() const;                 ///< [length] every vertex, components back to back (N by 3)
  Points positions(const VecX& dofs) const;  ///< [length] the vertices of dofs (N by 3)
  Link components() const;                  ///< [length] the current positions, one array per component
  /// [length] the smallest distance of two edges that share no vertex
  /// (components included), at the current positions.
  double min_distance();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The rest lengths of a knot's model: options.rest_lengths or the edge
/// lengths of `curve` (n by 3), after checking both as RodModel does (InputError).
VecX checked_rest_lengths(const Points& curve, const RelaxOptions& options);

}  // namespace ek
