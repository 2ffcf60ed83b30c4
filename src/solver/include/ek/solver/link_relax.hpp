#pragma once
/// \file
/// Relaxation of a link (paper Section 8.5: "We can easily extend our
/// simulation algorithm to handle links, i.e.\ intertwined combinations of
/// several knots").
///
/// Model: one twist-free elastic rod per component (elastic_rod.hpp, eq. 1 of
/// Section 6 summed over the components; rest lengths: each component's own
/// edge lengths), and the contact barrier with its certified collision
/// detection between every pair of edges of the link that do not share a
/// vertex, across components too (contact_potential.hpp, CurveTopology):
/// ~~~{.unparsed}
///   E(x) = Σ_c E_rod(x_c) + ω Σ_{pairs} b(d_ij).
/// ~~~
/// The dofs are the components' positions back to back, [x_0 (3n_0) | x_1
/// (3n_1) | ...]. Since no accepted step lets two edges touch, no component
/// changes its knot type and no two components pass through each other: the
/// link type is kept. Both are checked again on the result: every
/// component's Alexander polynomial and every linking number.
///
/// Solve: the direct method of relax() (relax.hpp): the contact-stiffness
/// continuation of RelaxOptions, then Newton at ω with the options'
/// tolerance, iteration cap and Newton settings; λ_min (the shift's scale) of
/// the straight rod with the link's total vertex count.
#include <memory>
#include <string>
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/knots/conway.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/solver/newton.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// What relax_link() returns: the equilibrium of the link, the solver's
/// reports and the link type checked on the result.
struct LinkRelaxResult {
  Link positions;                               ///< the equilibrium, one n_c by 3 array per component
  NewtonReport report;                          ///< of the solve at ω
  std::vector<NewtonReport> continuation_reports;  ///< of the continuation solves, in order
  double energy = 0.0;                          ///< [energy] E at the result
  std::vector<EnergyPart> parts;                ///< E's parts at the result: "stretch", "bend", "contact"
  /// [length] smallest distance of edges sharing no vertex, components included
  double min_distance = 0.0;
  std::vector<AlexanderPolynomial> alexander;   ///< of the input's components
  Eigen::MatrixXi linking_numbers;              ///< [1] of the input (m by m)
  bool alexander_preserved = true;              ///< every component's polynomial equal on the result
  bool linking_preserved = true;                ///< every linking number equal on the result
  ConwayPolynomial conway;                      ///< the input link's ∇ (conway.hpp)
  bool conway_preserved = true;                 ///< ∇ equal on the result (tells the Borromean rings from the unlink)

  bool converged() const;  ///< Whether the solve at ω converged (stable or, with stop_at_critical_point, unstable).
  /// Every component's Alexander polynomial, every linking number and ∇ kept.
  bool topology_preserved() const { return alexander_preserved && linking_preserved && conway_preserved; }
  /// The solver's status, or TopologyChanged when a component's
  /// Alexander polynomial, a linking number or the link's Conway polynomial
  /// differs (an error, never a silent result).
  RelaxStatus status() const;
};

/// The link's model at a configuration: its rods (rest lengths: the edges
/// of the link given) and the contact between all its edges, as one
/// Objective over [x_0 | x_1 | ...] whose rigid modes are the link's rigid
/// motions. ω, d̂ and the tolerance are resolved from the options
/// (resolve_model()) with ℓ the mean edge of the first component.
class LinkModel {
 public:
  /// Throws InputError as relax_link() does.
  LinkModel(const Link& link, const RelaxOptions& options);
  ~LinkModel();                                     ///< Releases the rods, the contact and the objective.
  LinkModel(const LinkModel&) = delete;             ///< Not copyable.
  LinkModel& operator=(const LinkModel&) = delete;  ///< Not copyable.
  /// The objective with contact stiffness factor·ω (factor > 0; 1: the
  /// model's), at the current positions. A call with another factor
  /// invalidates the previous reference.
  Objective& objective(double factor = 1.0);
  Link components() const;  ///< the current positions, one array per component
  double min_distance();    ///< [length] smallest distance of edges sharing no vertex
  const ResolvedModel& model() const;  ///< d̂, ω and the tolerance resolved from the options.
  /// The Newton options of the relaxation (newton_options() of relax.hpp),
  /// λ_min that of the straight rod with the link's total vertex count.
  NewtonOptions newton_options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Relaxes `link` (at least 2 components, each a simple closed polygon, no
/// two touching: validate_link) with the material, d̂, ω, tolerance,
/// iteration cap, contact continuation and Newton settings of `options`.
/// Throws InputError for a link of one component (use relax()), for options
/// the link model does not have (a prescribed link Lk, the full model with
/// material frames, a slab, given rest lengths) and for impossible options.
LinkRelaxResult relax_link(const Link& link, const RelaxOptions& options = {});

}  // namespace ek
