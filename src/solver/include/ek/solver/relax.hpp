#pragma once
/// \file
/// Relaxing a closed curve to a stable equilibrium of the elastic rod with
/// self-contact (paper Section 6, eq.\ 1):
///
/// ~~~{.unparsed}
///   min_{x, θ} E_rod(x, θ) + ω E_contact(x) [+ E_slab(x)]
/// ~~~
///
/// by Newton's method (newton.hpp) with the Hessian shift ε·λ_min, λ_min the
/// smallest nonzero eigenvalue of the straight rod's Hessian (computed once per
/// n, edge length, material and model, and cached), CHOLMOD with symbolic
/// reuse while the contact set is unchanged, and a line search capped by the
/// continuous collision detection, so that no accepted step ever produces a
/// crossing. The result's Alexander polynomial is compared with the input's.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "ek/contact/contact_potential.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/optim/newton.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/slab.hpp"

namespace ek {

/// Reference values of the paper's data set (Section 7.4): E = 2000, r = 0.2,
/// unit edges. Tolerances and contact stiffness scale from them.
inline constexpr double kReferenceBendingStiffness = 2000.0 * 3.14159265358979323846 * 0.0016 / 4.0;  // E π r⁴ / 4

/// How relax() reaches an equilibrium (docs/models.md, "Solver").
enum class RelaxMethod {
  /// Coarse-to-fine: the curve is relaxed first with n/2^L vertices
  /// (coarsen() in multilevel.hpp, certified collision-free), with the
  /// contact-stiffness continuation `coarse_continuation`, then refined
  /// (the same polygon) and relaxed at each finer level up to n. Used for
  /// the twist-free model without a slab; other models relax as Direct.
  Multilevel,
  /// Newton from the input at n vertices (with contact_continuation when given).
  Direct,
};
std::string to_string(RelaxMethod method);  ///< "multilevel", "direct"

/// Defaults of the multilevel method: two coarse levels, n/4 and n/2
/// (RelaxOptions::coarse_levels; the named method one-level has one).
inline constexpr int kDefaultCoarseLevels = 2;
inline constexpr double kDefaultCoarseContinuation = 1e-3;  ///< [1] contact-stiffness factor of the coarsest level
/// Fewest vertices of a coarse level.
inline constexpr int kMinCoarseVertices = 24;

/// How the multilevel method finds its coarse levels (multilevel.hpp,
/// docs/models.md, "Solver"). The default: either parity, rechecks of 30
/// soft iterations at most 6 times, levels below n/2 of at least 100
/// vertices. Measured (exp_bench_solver, docs/performance.md): on the lattice
/// samples at n = 400 the collapse of the odd vertices of the n/2 level to
/// n/4 is certified for 30 of 80 samples, of either parity for 41, and with
/// the rechecks for all 80.
struct CoarseningOptions {
  /// [bool] Where the collapse of the odd vertices is not certified, collapse
  /// the even ones instead if that is (certified_coarsening()).
  bool either_parity = true;
  /// [1] A level below n (not the input) whose coarsening is not certified
  /// runs its soft phase (contact stiffness coarse_continuation[0]·ω) for
  /// this many Newton iterations at a time and tries again, at most
  /// `rechecks` times, while that phase has not converged; the curve is
  /// then coarser and smoother. When no try is certified the level goes on
  /// from where the soft iterations left it. 0: no rechecks.
  int recheck_iterations = 30;
  int rechecks = 6;  ///< [1] see recheck_iterations
  /// [1] Fewest vertices of a coarse level below the first one (n/4, n/8,
  /// ...; the first, n/2, needs kMinCoarseVertices); at least
  /// kMinCoarseVertices. Measured (docs/performance.md): a coarsest level of
  /// 52, 68 or 90 vertices made the peer curves of 208, 272 and 360 vertices
  /// slower than one coarse level, while 100 of 400 made the lattice samples
  /// faster.
  int min_vertices = 100;
  /// The default: either parity, rechecks of 30 soft iterations at most 6
  /// times, levels below n/2 of at least 100 vertices.
  static CoarseningOptions rechecked() { return {}; }
  /// The odd vertices collapsed, tried once, levels of kMinCoarseVertices
  /// (the named methods one-level and eigen-projected: the rule before two levels).
  static CoarseningOptions even_only() { return {false, 0, 0, kMinCoarseVertices}; }
  void validate() const;  ///< InputError for negative counts or min_vertices below kMinCoarseVertices
};
/// "even" or "either-parity", then ",recheck-IxR" when R > 0 rechecks of I
/// iterations each, then ",min-V" when min_vertices V is not
/// kMinCoarseVertices (the data-set metadata's `coarsening`, e.g.
/// "either-parity,recheck-30x6,min-100").
std::string to_string(const CoarseningOptions& coarsening);

/// The model and the method of relax(): the material, the contact, the
/// tolerance and iteration cap, the twist model (link, full model), the
/// planarity slab, and the Newton settings. Unset optional fields are resolved
/// by resolve_model().
struct RelaxOptions {
  RodMaterial material;             ///< E, ν, r (paper defaults)
  /// [length] rest edge lengths (n); default: the input curve's edge lengths.
  std::optional<VecX> rest_lengths;
  /// [length] contact distance d̂; unset: 2r (the wire diameter).
  std::optional<double> dhat;
  /// [energy/length²] ω; unset: 1e3 · (E/2000) · (r/0.2)³ (same relative
  /// penetration for the same shape; contact_potential.hpp).
  std::optional<double> contact_stiffness;
  /// [energy/length] gradient tolerance; unset: 1e-8 · (EI / EI_ref) / ℓ²
  /// with EI_ref = 2000·π·0.2⁴/4 and ℓ the mean rest edge length: the paper's
  /// 1e-8 for its material and unit edges, scaled like the gradient.
  std::optional<double> tolerance;
  /// [1] Newton iterations (per phase). 5,000: at 2,000 later samples of a
  /// walk were cut off in slow descents that converge in 2,000–2,400
  /// (docs/models.md, "Solver").
  int max_iterations = 5000;
  /// Prescribed link Lk: the full model with Θ fixed (FixedLink). Without it
  /// Θ is free and the twist relaxes to zero, so the centerline-only fast path
  /// is used unless full_model is set.
  std::optional<double> link;
  bool full_model = false;          ///< use the 4n+1-dof model even when Θ is free
  /// [1] Contact-stiffness continuation, off when empty: before the solve at
  /// ω, one Newton solve per factor f (in order, each in (0, 1)) with the
  /// contact stiffness f·ω, each starting where the previous one ended and
  /// run to the same tolerance and iteration cap (its status is not used: it
  /// only provides the next start). The result is an equilibrium of the
  /// model at ω like any other, reached along another path, so it may lie in
  /// another basin. Why: at ω the contact lines form one edge pair per
  /// Newton iteration (a pair that the Hessian does not yet see stops the
  /// step); with a soft barrier the knot tightens in far fewer iterations
  /// and the final solve only pushes the contacts apart by their extra
  /// penetration. Measured (exp_bench_solver --continuation,
  /// docs/performance.md): {1e-3} cuts the median time per equilibrium by
  /// about 2×.
  std::vector<double> contact_continuation;
  RelaxMethod method = RelaxMethod::Multilevel;  ///< see RelaxMethod
  /// [length] ContactOptions::hessian_margin: the contact Hessian's pattern
  /// holds the pairs within d̂ + margin and changes only when an active pair
  /// falls outside it (0: the active pairs; the same values either way, the
  /// iterates the same up to the round-off of another elimination order).
  /// Unset: 0.05·d̂ where the multilevel method relaxes (multilevel_applies();
  /// measured: a third fewer symbolic analyses and 0.94 times the time per
  /// equilibrium, docs/performance.md), 0 for the direct method (no gain
  /// measured there).
  std::optional<double> contact_hessian_margin;
  /// [bool] ContactOptions::gauss_newton_projection: in the projected
  /// iterations each contact pair's Hessian is its Gauss–Newton term
  /// b''∇d∇dᵀ instead of its eigen-projection, and the Newton iteration
  /// damps short steps (NewtonMethodOptions::damp_short_steps, which this
  /// model needs). Unset: on where the multilevel method relaxes
  /// (multilevel_applies(), one component), off for the direct method
  /// (ResolvedModel::contact_gauss_newton). Measured (docs/performance.md):
  /// about 20% less time per equilibrium of the multilevel method and other
  /// equilibria for some samples; about twice the time of the direct
  /// relaxations at prescribed links and under the slab.
  std::optional<bool> contact_gauss_newton;
  /// [1] Multilevel: levels below n, each with half the vertices of the next;
  /// a level is used while the count is even, the coarse curve has at least
  /// kMinCoarseVertices vertices (below n/2: CoarseningOptions::min_vertices)
  /// and its coarsening is certified.
  int coarse_levels = kDefaultCoarseLevels;
  /// [1] Multilevel: contact-stiffness continuation factors (as
  /// contact_continuation) of the first, coarsest level solved; when that
  /// level is n itself, contact_continuation replaces them if given.
  std::vector<double> coarse_continuation = {kDefaultCoarseContinuation};
  CoarseningOptions coarsening;  ///< Multilevel: how the coarse levels are found
  /// Planarity slab |z| < h (slab.hpp). With release_slab the slab is dropped
  /// after the first phase and the solve continues from the flat state.
  std::optional<SlabOptions> slab;
  bool release_slab = false;          ///< drop the slab after the first phase and continue from the flat state
  /// Tangent rotation allowed per Newton step when material frames are
  /// transported (full model), so that time-parallel transport stays well defined.
  double max_tangent_rotation = 0.5;  ///< [rad]
  bool stop_at_critical_point = false;  ///< report converged-unstable instead of leaving saddles
  /// Compare the input's knot type (its Alexander polynomial) or link type
  /// (every component's polynomial, the linking numbers, ∇) with the result's.
  bool check_topology = true;
  bool smallest_eigenvalue = false;   ///< also compute the smallest non-rigid eigenvalue of H (stiffness)
  /// How Newton's method steps (shift ε, Hessian, Armijo constant, ...);
  /// relax() adds the goal: the tolerance, iteration cap and
  /// stop_at_critical_point above, and λ_min of the straight rod.
  NewtonMethodOptions newton;
  /// Throws InputError for impossible values (non-positive radius, ...).
  void validate() const;
};

/// Whether relax() uses the multilevel method for these options: the
/// method is Multilevel and the model twist-free (no link, no full model)
/// without a slab; other options relax by the direct method.
bool multilevel_applies(const RelaxOptions& options);

/// The model's parameters with every unset field of
/// RelaxOptions resolved. The only place where these defaults are computed:
/// relax(), the data-set metadata and `knots energy` call it.
struct ResolvedModel {
  double dhat = 0.0;               ///< [length] d̂ = 2r unless given
  double contact_stiffness = 0.0;  ///< [energy/length²] ω = 1e3 · (E/2000) · (r/0.2)³ unless given
  /// [energy/length] 1e-8 · (EI/EI_ref) / ℓ² unless given (ℓ: mean rest edge length)
  double tolerance = 0.0;
  TwistModel model = TwistModel::TwistFree;  ///< FixedLink with a link, FreeTheta with full_model
  /// RelaxOptions::contact_gauss_newton, or where unset whether the
  /// multilevel method applies (multilevel_applies()).
  bool contact_gauss_newton = false;
  /// NewtonMethodOptions::damp_short_steps, or the Gauss–Newton pair
  /// Hessians above (which need it).
  bool damp_short_steps = false;
  /// [length] RelaxOptions::contact_hessian_margin, or where unset 0.05·d̂
  /// when the multilevel method applies, else 0.
  double contact_hessian_margin = 0.0;
};
/// Resolves the defaults of `options` for rest edges of mean length
/// `mean_edge_length` [length] (> 0).
ResolvedModel resolve_model(const RelaxOptions& options, double mean_edge_length);
/// The contact options of the resolved model (d̂, ω, the pair Hessians, the
/// Hessian pattern's margin), as RodModel uses them.
ContactOptions contact_options(const ResolvedModel& model);
/// The Newton options of a relaxation: options.newton with the goal of
/// `options` (the resolved tolerance, the iteration cap, stop at a critical
/// point, damp_short_steps with the Gauss–Newton pair Hessians) and the
/// straight rod's λ_min (the shift's scale).
NewtonOptions newton_options(const RelaxOptions& options, const ResolvedModel& model, double lambda_min);
/// The rod of a relaxation: `x` (n by 3) with rest edges `rest` (n), the
/// material of `options` and the resolved twist model; with options.link,
/// its twist set to carry that link (the fixed-link model) and relaxed.
/// relax(), saddles, dynamics and `knots energy` build their rod here.
ElasticRod model_rod(const Points& x, const VecX& rest, const RelaxOptions& options, const ResolvedModel& model);
/// The Alexander polynomial of a curve given as input, the reference of the
/// topology check; InputError "<what> is not a simple curve: ..." when it
/// meets itself (`what` names it, e.g. "relax: the input curve").
AlexanderPolynomial input_alexander(const Points& curve, const std::string& what);
/// ω that keeps the paper's relative penetration for another material:
/// 1e3 · (E/2000) · (r/0.2)³ (contact_potential.hpp, "Stiffness scaling").
double default_contact_stiffness(const RodMaterial& material);

/// Energy breakdown at a configuration.
struct EnergyParts {
  ///@{
  /// [energy] The total and its parts: stretching, bending, twisting (0 in the
  /// twist-free model), ω times the contact barrier, the planarity slab (0
  /// without one); total = stretch + bend + twist + contact + slab.
  double total = 0.0, stretch = 0.0, bend = 0.0, twist = 0.0, contact = 0.0, slab = 0.0;
  ///@}
};

/// A relaxation's outcome: the solver's status of its last phase, or
/// TopologyChanged when the result's knot or link type differs from the
/// input's (an error, never a silent result). Text only at the boundary
/// (files, JSON, CSV, Python, the command line): to_string / parse_relax_status.
enum class RelaxStatus {
  ConvergedStable,    ///< "converged-stable"
  ConvergedUnstable,  ///< "converged-unstable" (only with stop_at_critical_point)
  MaxIterations,      ///< "max-iterations"
  Stalled,            ///< "stalled"
  TopologyChanged,    ///< "topology-changed"
};
std::string to_string(RelaxStatus status);  ///< the texts above ("converged-stable", ...)
/// The status of a text written by to_string; InputError for any other text.
RelaxStatus parse_relax_status(const std::string& text);
/// The solver's status, or TopologyChanged when the topology was not kept.
RelaxStatus relax_status(SolverStatus solver, bool topology_preserved);
/// Prints to_string(status) (messages, test failures).
std::ostream& operator<<(std::ostream& out, RelaxStatus status);

/// What relax() returns: the equilibrium, the solver's reports of every
/// phase, the energy's parts, the contacts, twist, writhe and link, and the
/// check of the knot type.
struct RelaxResult {
  Points positions;                 ///< n by 3 equilibrium
  VecX theta;                       ///< material angles (n; zeros for the fast path)
  double Theta = 0.0;               ///< injected twist Θ
  NewtonReport report;              ///< of the last phase (after release when released)
  /// Every phase's name in order: the coarse levels' phases prefixed with
  /// "coarse M: " (M vertices), "continuation F" per factor, then "slab"
  /// (under the slab) or "final", and "final" after a release.
  std::vector<std::string> phases;
  /// Every Newton iteration of every phase (NewtonOptions::record_trace;
  /// IterationRecord::phase indexes `phases`).
  std::vector<IterationRecord> trace;
  std::optional<NewtonReport> slab_report;  ///< of the phase under the slab, when released
  /// Of the continuation solves at n vertices, in order.
  std::vector<NewtonReport> continuation_reports;
  /// Multilevel: the coarse levels solved, coarsest first: their vertex
  /// counts and each level's phases summed (RelaxResult::all_phases()).
  std::vector<int> coarse_vertices;
  std::vector<NewtonReport> coarse_reports;  ///< Multilevel: each coarse level's phases summed, coarsest first
  EnergyParts energy;               ///< at the result
  std::optional<EnergyParts> slab_energy;   ///< at the end of the slab phase
  int contacts = 0;                 ///< active contact pairs at the result
  double min_distance = 0.0;        ///< [length] smallest non-adjacent edge distance at the result
  ///@{
  /// [1] Lk, Tw and Wr of the result (Lk = Tw + Wr; Tw = 0 in the twist-free
  /// model).
  double link = 0.0, twist = 0.0, writhe = 0.0;
  ///@}
  /// [1] The vertices of each component, in order (one entry for a knot);
  /// `positions` holds the components back to back.
  std::vector<int> component_sizes;
  ///@{
  /// The check of the knot or link type (RelaxOptions::check_topology):
  /// every component's Alexander polynomial and, with several components,
  /// every linking number and the link's Conway polynomial ∇ (which tells
  /// the Borromean rings from the unlink), each equal on the result.
  bool alexander_preserved = true, linking_preserved = true, conway_preserved = true;
  ///@}
  AlexanderPolynomial alexander;          ///< of the input (one component)
  AlexanderPolynomial result_alexander;   ///< of the result (one component)
  /// Of the input with several components (computed with or without
  /// check_topology): each component's Alexander polynomial, the linking
  /// numbers and ∇ (invariants.hpp).
  std::optional<LinkType> link_type;
  std::optional<double> smallest_eigenvalue;  ///< of H without rigid modes, when asked
  double lambda_min = 0.0;          ///< straight-rod λ_min used for the shift
  TwistModel model = TwistModel::TwistFree;  ///< the unknowns the rod was relaxed with

  /// The report of all phases (coarse levels, continuation, slab, final) together:
  /// iterations, factorisations, line-search trials, saddle escapes and the
  /// times summed; status, energy, gradient norm and the other values of the
  /// final phase (`report`).
  NewtonReport all_phases() const;

  bool converged() const;  ///< The last phase converged, stable or (stop_at_critical_point) unstable.
  bool stable() const;     ///< The last phase converged to a stable equilibrium.
  /// Every component's Alexander polynomial, every linking number and ∇ kept.
  bool topology_preserved() const { return alexander_preserved && linking_preserved && conway_preserved; }
  Link components() const;  ///< `positions` split by component_sizes
  /// The solver status of the last phase, or TopologyChanged when the
  /// knot or link type differs (an error, never a silent result).
  RelaxStatus status() const;
};

/// The named methods of `knots relax --method` (and of explore, dataset and
/// the experiments) applied to `options`: "default" (RelaxMethod::Multilevel
/// with the hybrid Hessian; RelaxOptions::contact_gauss_newton as given,
/// unset: Gauss–Newton contact pair Hessians and damped short steps where
/// the multilevel method applies: `options` as they are; two coarse levels,
/// n/4 and n/2, found by CoarseningOptions::rechecked(), and the contact
/// pattern's margin 0.05·d̂), "gauss-newton" and "two-level" (aliases of
/// "default"), "one-level" (the default with one coarse level, no
/// contact-pattern margin and the coarsening CoarseningOptions::even_only():
/// the default before two levels, about 1.4 times the time per equilibrium,
/// docs/performance.md), "eigen-projected" (one-level with each contact
/// pair's Hessian eigen-projected and no damping: the method of the
/// committed ledgers under docs/results), "hybrid" (Direct: the default
/// before the multilevel relaxation), "exact" (Direct with the exact Hessian
/// every iteration) or "paper" (Direct with NewtonOptions::paper()). The
/// three direct methods use eigen-projected pair Hessians without damping.
/// The trace and verbosity settings are kept. Throws InputError for another
/// name.
RelaxOptions with_method(RelaxOptions options, const std::string& name);

/// The names with_method() accepts, in the order above.
const std::vector<std::string>& method_names();

/// Relaxes `curve` (n by 3, a simple closed polygon; rest lengths are its edge
/// lengths unless options.rest_lengths gives them). Throws InputError for a curve that is not simple or has a
/// non-positive edge, and for impossible options.
RelaxResult relax(const Points& curve, const RelaxOptions& options = {});

/// Relaxes a knot or a link (paper Section 8.5: "We can easily extend our
/// simulation algorithm to handle links, i.e.\ intertwined combinations of
/// several knots"). One component: relax(link[0], options). Several: the
/// model of RodModel (rod_model.hpp: one twist-free rod per component with
/// its own edge lengths as rest lengths, the contact between every two
/// edges that share no vertex, across components too, E = Σ_c E_rod(x_c) +
/// ω Σ b(d_ij)) relaxed by the direct method: the contact continuation of
/// the options, then Newton at ω with their tolerance, iteration cap and
/// Newton settings. Since no accepted step lets two edges touch, no
/// component changes its knot type and no two components pass through each
/// other; the link type is checked again on the result (link_type(), with
/// check_topology, the default).
/// link, twist and writhe are 0 for several components (their linking
/// numbers are link_type's). Throws InputError for components that touch
/// or are not simple polygons, for options a link of several components
/// does not have (a prescribed link Lk, the full model, a slab, given rest
/// lengths, the smallest eigenvalue) and for impossible options.
RelaxResult relax(const Link& link, const RelaxOptions& options = {});

/// λ_min of the straight rod (cached; thread-safe).
double cached_lambda_min(int n, double edge_length, const RodMaterial& material, TwistModel model);

}  // namespace ek
