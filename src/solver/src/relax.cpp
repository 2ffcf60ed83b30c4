#include "ek/solver/relax.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <ostream>
#include <tuple>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/optim/eigen_analysis.hpp"
#include "ek/solver/multilevel.hpp"
#include "ek/solver/rod_model.hpp"

namespace ek {
namespace {

EnergyParts parts_of(Objective& objective) {
  EnergyParts p;
  for (const EnergyPart& part : objective.energy_parts()) {
    if (part.name == "stretch") p.stretch = part.value;
    else if (part.name == "bend") p.bend = part.value;
    else if (part.name == "twist") p.twist = part.value;
    else if (part.name == "contact") p.contact = part.value;
    else if (part.name == "slab") p.slab = part.value;
  }
  p.total = p.stretch + p.bend + p.twist + p.contact + p.slab;
  return p;
}

}  // namespace

ElasticRod model_rod(const Points& x, const VecX& rest, const RelaxOptions& options, const ResolvedModel& model) {
  ElasticRod rod(x, rest, options.material, model.model);
  if (options.link) {
    rod.set_link(*options.link);
    rod.relax_twist();
  }
  return rod;
}

AlexanderPolynomial input_alexander(const Points& curve, const std::string& what) {
  try {
    return alexander(curve);
  } catch (const InputError& e) {
    throw InputError(what + " is not a simple curve: " + e.what());
  }
}

ContactOptions contact_options(const ResolvedModel& model) {
  ContactOptions co;
  co.dhat = model.dhat;
  co.stiffness = model.contact_stiffness;
  co.hessian_margin = model.contact_hessian_margin;
  co.gauss_newton_projection = model.contact_gauss_newton;
  return co;
}

NewtonOptions newton_options(const RelaxOptions& options, const ResolvedModel& model, double lambda_min) {
  NewtonOptions no(options.newton);
  no.gradient_tolerance = model.tolerance;
  no.max_iterations = options.max_iterations;
  no.stop_at_critical_point = options.stop_at_critical_point;
  no.lambda_min = lambda_min;
  no.damp_short_steps = model.damp_short_steps;
  return no;
}

namespace {

/// The name of the phase of contact-stiffness continuation factor f.
std::string continuation_phase(double f) { return "continuation " + std::to_string(f); }

/// `trace` appended to `out` with its phases numbered after `offset` earlier ones.
void append_trace(const std::vector<IterationRecord>& trace, int offset, std::vector<IterationRecord>& out) {
  for (IterationRecord rec : trace) {
    rec.phase += offset;
    out.push_back(rec);
  }
}

/// The phases: contact-stiffness continuation (each factor with a softer
/// barrier; every accepted step is still collision-free, the barrier being
/// singular at d = 0 for any ω), the solve at ω (under the slab when there
/// is one), and after release the solve without the slab.
void run_phases(RodModel& m, NewtonSolver& solver, RelaxResult& result) {
  const int offset = static_cast<int>(result.phases.size());  // phases of coarse levels before these
  for (const double f : m.options().contact_continuation) {
    result.continuation_reports.push_back(solver.minimize(m.objective(f)));
    result.phases.push_back(continuation_phase(f));
  }
  CompositeObjective& objective = m.objective();
  result.report = solver.minimize(objective);
  result.phases.push_back(m.slab() ? "slab" : "final");
  result.energy = parts_of(objective);
  if (m.slab() && m.options().release_slab) {
    result.slab_report = result.report;
    result.slab_energy = result.energy;
    CompositeObjective& released = m.objective(1.0, false);
    result.report = solver.minimize(released);
    result.phases.push_back("final");
    result.energy = parts_of(released);
  }
  append_trace(solver.trace(), offset, result.trace);
}

/// The smallest eigenvalue of H with every rigid motion excluded: all six
/// even under a kept slab (where no vertex is within the slab's activation
/// distance of a plane, the z translation and the tilts are (near-)zero
/// modes of H too, and the stiffness is meant to describe the shape).
std::optional<double> stiffness(RodModel& m) {
  Objective& objective = m.objective(1.0, !m.options().release_slab);
  SparseAssembler A;
  objective.assemble_hessian(A, HessianKind::Exact);
  const ElasticRod& rod = m.rod();
  const int theta_begin = rod.model() == TwistModel::TwistFree ? -1 : 3 * rod.num_vertices();
  const Eigen::MatrixXd Q = rigid_modes(rod.positions(), rod.num_dofs(), theta_begin);
  EigenOptions eo;
  eo.count = 1;
  const EigenResult eig = smallest_eigenpairs(A.matrix(), Q, m.newton().shift_epsilon * m.lambda_min(), eo);
  if (!eig.converged) return std::nullopt;
  return eig.values(0);
}

/// Positions, angles, contacts, twist, writhe and link of the result (a
/// coarse level's only positions and angles: it is a start for the next).
void describe_result(RodModel& m, RelaxResult& result, bool coarse) {
  const ElasticRod& rod = m.rod();
  result.positions = rod.positions();
  result.theta = rod.thetas();
  result.Theta = rod.model() == TwistModel::TwistFree ? 0.0 : rod.theta_total();
  if (coarse) return;
  m.contact().update(result.positions);
  result.contacts = static_cast<int>(m.contact().num_active());
  result.min_distance = clearance(result.positions).distance;
  result.twist = rod.twist();
  result.writhe = rod.writhe();
  result.link = result.twist + result.writhe;
}

}  // namespace

void CoarseningOptions::validate() const {
  require_input(recheck_iterations >= 0 && rechecks >= 0, "relax: the coarsening's rechecks must be >= 0");
  require_input(min_vertices >= kMinCoarseVertices,
                "relax: a coarse level needs at least " + std::to_string(kMinCoarseVertices) + " vertices");
}

std::string to_string(const CoarseningOptions& c) {
  std::string s = c.either_parity ? "either-parity" : "even";
  if (c.rechecks > 0 && c.recheck_iterations > 0)
    s += ",recheck-" + std::to_string(c.recheck_iterations) + "x" + std::to_string(c.rechecks);
  if (c.min_vertices != kMinCoarseVertices) s += ",min-" + std::to_string(c.min_vertices);
  return s;
}

void RelaxOptions::validate() const {
  material.validate();
  for (const auto& [value, name] : {std::pair{dhat, "dhat"}, std::pair{contact_stiffness, "contact_stiffness"},
                                    std::pair{tolerance, "tolerance"}})
    require_input(!value || (*value > 0.0 && std::isfinite(*value)),
                  std::string("relax: ") + name + " must be positive and finite when given");
  require_input(max_iterations >= 0, "relax: max_iterations must be >= 0");
  require_input(!link || std::isfinite(*link), "relax: link must be finite");
  require_input(max_tangent_rotation > 0.0 && max_tangent_rotation < 1.5, "relax: max_tangent_rotation in (0, 1.5)");
  require_input(!release_slab || slab, "relax: release_slab needs a slab");
  for (const double f : contact_continuation)
    require_input(f > 0.0 && f < 1.0, "relax: contact_continuation factors must be in (0, 1)");
  for (const double f : coarse_continuation)
    require_input(f > 0.0 && f < 1.0, "relax: coarse_continuation factors must be in (0, 1)");
  require_input(coarse_levels >= 0 && coarse_levels <= 8, "relax: coarse_levels must be in [0, 8]");
  require_input(!contact_hessian_margin || (*contact_hessian_margin >= 0.0 && std::isfinite(*contact_hessian_margin)),
                "relax: contact_hessian_margin must be >= 0");
  coarsening.validate();
  if (slab) {
    require_input(slab->half_thickness > 0.0 && std::isfinite(slab->half_thickness),
                  "relax: slab half-thickness must be positive");
  }
}

double default_contact_stiffness(const RodMaterial& m) {
  const double r_scale = m.radius / 0.2;
  return kDefaultContactStiffness * (m.young / 2000.0) * r_scale * r_scale * r_scale;
}

ResolvedModel resolve_model(const RelaxOptions& options, double mean_edge_length) {
  require(mean_edge_length > 0.0 && std::isfinite(mean_edge_length), "resolve_model: edge length must be positive");
  const RodMaterial& mat = options.material;
  ResolvedModel r;
  r.dhat = options.dhat.value_or(2.0 * mat.radius);
  r.contact_stiffness = options.contact_stiffness.value_or(default_contact_stiffness(mat));
  r.tolerance = options.tolerance.value_or(1e-8 * (mat.bending_stiffness() / kReferenceBendingStiffness) /
                                           (mean_edge_length * mean_edge_length));
  r.contact_gauss_newton = options.contact_gauss_newton.value_or(multilevel_applies(options));
  r.damp_short_steps = options.newton.damp_short_steps || r.contact_gauss_newton;
  r.contact_hessian_margin = options.contact_hessian_margin.value_or(multilevel_applies(options) ? 0.05 * r.dhat : 0.0);
  if (options.link) r.model = TwistModel::FixedLink;
  else if (options.full_model) r.model = TwistModel::FreeTheta;
  return r;
}

const std::vector<std::string>& method_names() {
  static const std::vector<std::string> names = {"default", "gauss-newton", "two-level", "one-level",
                                                  "eigen-projected", "hybrid", "exact", "paper"};
  return names;
}

RelaxOptions with_method(RelaxOptions o, const std::string& name) {
  const std::vector<std::string>& names = method_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;  // "a, b, ... or z"
    for (size_t k = 0; k < names.size(); ++k) list += (k == 0 ? "" : k + 1 < names.size() ? ", " : " or ") + names[k];
    throw InputError("the method must be " + list + ", not '" + name + "'");
  }
  if (name == "default" || name == "gauss-newton" || name == "two-level") return o;
  if (name == "one-level" || name == "eigen-projected") {  // the multilevel method as it was before two levels
    o.coarse_levels = 1;
    o.contact_hessian_margin = 0.0;
    o.coarsening = CoarseningOptions::even_only();
  }
  if (name == "one-level") return o;
  o.contact_gauss_newton = false;
  o.newton.damp_short_steps = false;
  if (name == "eigen-projected") return o;
  o.method = RelaxMethod::Direct;
  if (name == "exact") o.newton.hessian = HessianMode::Exact;
  if (name == "paper") {
    const bool verbose = o.newton.verbose, trace = o.newton.record_trace;
    o.newton = NewtonMethodOptions::paper();
    o.newton.verbose = verbose;
    o.newton.record_trace = trace;
  }
  return o;
}

bool multilevel_applies(const RelaxOptions& o) {
  return o.method == RelaxMethod::Multilevel && !o.link && !o.full_model && !o.slab;
}

std::string to_string(RelaxMethod method) {
  return method == RelaxMethod::Multilevel ? "multilevel" : "direct";
}

NewtonReport RelaxResult::all_phases() const {
  NewtonReport sum = report;
  auto add = [&sum](const NewtonReport& r) {
    sum.iterations += r.iterations;
    sum.seconds += r.seconds;
    sum.symbolic_factorizations += r.symbolic_factorizations;
    sum.orderings += r.orderings;
    sum.numeric_factorizations += r.numeric_factorizations;
    sum.failed_factorizations += r.failed_factorizations;
    sum.line_search_trials += r.line_search_trials;
    sum.saddle_escapes += r.saddle_escapes;
    sum.exact_iterations += r.exact_iterations;
    sum.expansions += r.expansions;
    sum.time_assembly += r.time_assembly;
    sum.time_factorization += r.time_factorization;
    sum.time_collision += r.time_collision;
    sum.time_line_search += r.time_line_search;
    sum.time_eigen += r.time_eigen;
    sum.time_symbolic += r.time_symbolic;
  };
  for (const NewtonReport& r : coarse_reports) add(r);
  for (const NewtonReport& r : continuation_reports) add(r);
  if (slab_report) add(*slab_report);
  return sum;
}

bool RelaxResult::converged() const {
  return report.status == SolverStatus::ConvergedStable || report.status == SolverStatus::ConvergedUnstable;
}
bool RelaxResult::stable() const { return report.status == SolverStatus::ConvergedStable; }
RelaxStatus RelaxResult::status() const { return relax_status(report.status, topology_preserved()); }

Link RelaxResult::components() const {
  Link out;
  Eigen::Index row = 0;
  for (const int n : component_sizes) {
    out.push_back(positions.middleRows(row, n));
    row += n;
  }
  return out;
}

namespace {

const std::pair<RelaxStatus, const char*> kRelaxStatusNames[] = {
    {RelaxStatus::ConvergedStable, "converged-stable"}, {RelaxStatus::ConvergedUnstable, "converged-unstable"},
    {RelaxStatus::MaxIterations, "max-iterations"},     {RelaxStatus::Stalled, "stalled"},
    {RelaxStatus::TopologyChanged, "topology-changed"},
};

}  // namespace

std::string to_string(RelaxStatus status) {
  for (const auto& [s, name] : kRelaxStatusNames)
    if (s == status) return name;
  return "unknown";
}

RelaxStatus parse_relax_status(const std::string& text) {
  for (const auto& [s, name] : kRelaxStatusNames)
    if (text == name) return s;
  throw InputError("unknown relaxation status '" + text + "'");
}

RelaxStatus relax_status(SolverStatus solver, bool topology_preserved) {
  if (!topology_preserved) return RelaxStatus::TopologyChanged;
  switch (solver) {
    case SolverStatus::ConvergedStable: return RelaxStatus::ConvergedStable;
    case SolverStatus::ConvergedUnstable: return RelaxStatus::ConvergedUnstable;
    case SolverStatus::MaxIterations: return RelaxStatus::MaxIterations;
    case SolverStatus::Stalled: return RelaxStatus::Stalled;
  }
  return RelaxStatus::Stalled;
}

std::ostream& operator<<(std::ostream& out, RelaxStatus status) { return out << to_string(status); }

double cached_lambda_min(int n, double edge_length, const RodMaterial& m, TwistModel model) {
  static std::mutex mutex;
  static std::map<std::tuple<int, double, double, double, double, int>, double> cache;
  const auto key = std::make_tuple(n, edge_length, m.young, m.poisson, m.radius, static_cast<int>(model));
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  const double value = straight_rod_min_eigenvalue(n, edge_length, m, model);
  std::lock_guard<std::mutex> lock(mutex);
  cache[key] = value;
  return value;
}

namespace {

/// One level: Newton from `curve` with rest lengths `rest` (the phases of
/// run_phases), and the description of the result. The input's Alexander
/// polynomial is compared when result.alexander is set (check_topology).
void relax_level(const Points& curve, const VecX& rest, const RelaxOptions& options, bool coarse,
                 RelaxResult& result) {
  RodModel m(curve, rest, options);
  result.model = m.resolved().model;
  result.lambda_min = m.lambda_min();
  NewtonSolver solver(m.newton());
  run_phases(m, solver, result);
  describe_result(m, result, coarse);
  if (options.smallest_eigenvalue) result.smallest_eigenvalue = stiffness(m);
}

/// The coarse level's result with its own coarse levels and phases folded
/// into `result` (coarsest first; its trace's phases renumbered after the
/// phases already in `result`, its own phases named "coarse M: ...").
void add_coarse_level(const RelaxResult& coarse, RelaxResult& result) {
  RelaxResult own = coarse;
  own.coarse_reports.clear();
  result.coarse_vertices = coarse.coarse_vertices;
  result.coarse_reports = coarse.coarse_reports;
  result.coarse_vertices.push_back(static_cast<int>(coarse.positions.rows()));
  result.coarse_reports.push_back(own.all_phases());
  const int offset = static_cast<int>(result.phases.size());
  const std::string prefix = "coarse " + std::to_string(coarse.positions.rows()) + ": ";
  for (const std::string& p : coarse.phases) result.phases.push_back(p.rfind("coarse ", 0) == 0 ? p : prefix + p);
  append_trace(coarse.trace, offset, result.trace);
}

/// At most `iterations` Newton iterations of the coarsest level's soft phase
/// (contact stiffness coarse_continuation[0]·ω, or ω without one) from
/// `curve`, which becomes their result; the phase's report, name and trace
/// go to `result` (phase "continuation F before coarsening").
SolverStatus soft_iterations(Points& curve, const VecX& rest, const RelaxOptions& options, int iterations,
                             RelaxResult& result) {
  RelaxOptions soft = options;
  soft.rest_lengths = rest;
  const double f = options.coarse_continuation.empty() ? 1.0 : options.coarse_continuation.front();
  soft.contact_stiffness = f * resolve_model(options, rest.mean()).contact_stiffness;
  soft.contact_continuation.clear();
  soft.max_iterations = iterations;
  soft.smallest_eigenvalue = false;
  RelaxResult r;
  relax_level(curve, rest, soft, true, r);
  curve = r.positions;
  const int offset = static_cast<int>(result.phases.size());
  result.continuation_reports.push_back(r.report);
  result.phases.push_back(continuation_phase(f) + " before coarsening");
  append_trace(r.trace, offset, result.trace);
  return r.report.status;
}

/// Multilevel or direct relaxation of `curve` (rest lengths `rest`) with up
/// to `levels` coarse levels below it; `top`: the level of the input. The
/// first (coarsest) level solved gets the multilevel continuation, the top
/// level contact_continuation, the levels between none.
RelaxResult relax_levels(const Points& curve, const VecX& rest, const RelaxOptions& options, int levels, bool top) {
  RelaxResult result;
  Points start = curve;
  const int n = static_cast<int>(curve.rows());
  const bool multilevel = multilevel_applies(options);
  const CoarseningOptions& rule = options.coarsening;
  const int fewest = top ? kMinCoarseVertices : rule.min_vertices;  // the first coarse level: the general minimum
  if (multilevel && levels > 0 && n % 2 == 0 && n / 2 >= fewest) {
    const ContactOptions contact = contact_options(resolve_model(options, rest.mean()));
    std::optional<ShiftedCoarsening> c = certified_coarsening(curve, rest, contact, rule.either_parity);
    const int rechecks = top || rule.recheck_iterations == 0 ? 0 : rule.rechecks;
    for (int k = 0; k < rechecks && !c; ++k) {
      const SolverStatus status = soft_iterations(start, rest, options, rule.recheck_iterations, result);
      c = certified_coarsening(start, rest, contact, rule.either_parity);
      if (status != SolverStatus::MaxIterations) break;  // the soft phase has converged
    }
    if (c) {
      const RelaxResult rc = relax_levels(c->curve.coarse, c->curve.coarse_rest, options, levels - 1, false);
      add_coarse_level(rc, result);
      start = refine(rc.positions, rest, c->offset);
    }
  }
  RelaxOptions level = options;
  level.rest_lengths = rest;
  level.smallest_eigenvalue = options.smallest_eigenvalue && top;
  const bool coarsest = result.coarse_reports.empty();
  if (multilevel && coarsest && !(top && !options.contact_continuation.empty()))
    level.contact_continuation = options.coarse_continuation;
  else if (!top)
    level.contact_continuation.clear();
  relax_level(start, rest, level, !top, result);
  return result;
}

}  // namespace

RelaxResult relax(const Points& curve, const RelaxOptions& options) {
  options.validate();
  const VecX rest = checked_rest_lengths(curve, options);
  AlexanderPolynomial input;
  if (options.check_topology) input = input_alexander(curve, "relax: the input curve");
  RelaxOptions unchecked = options;
  unchecked.check_topology = false;  // checked once below, on the result
  RelaxResult result = relax_levels(curve, rest, unchecked, options.coarse_levels, true);
  result.component_sizes = {static_cast<int>(curve.rows())};
  if (options.check_topology) {
    result.alexander = input;
    try {
      result.result_alexander = alexander(result.positions);
    } catch (const InputError&) {
      result.result_alexander = AlexanderPolynomial{{0}};
    }
    result.alexander_preserved = (result.result_alexander == result.alexander);
  }
  return result;
}

namespace {

/// The link of several components relaxed by the direct method (relax(const Link&)).
RelaxResult relax_components(const Link& link, const RelaxOptions& options) {
  require_input(!options.smallest_eigenvalue, "relax: the smallest eigenvalue is computed for a knot only");
  RodModel m(link, options);
  RelaxResult result;
  result.link_type = link_type(link);  // the input's, always: results and their JSON report it
  result.model = m.resolved().model;
  result.lambda_min = m.lambda_min();
  NewtonSolver solver(m.newton());
  run_phases(m, solver, result);
  result.min_distance = m.min_distance();
  result.contacts = static_cast<int>(m.contact().num_active());
  result.positions = m.positions();
  for (const Points& P : link) result.component_sizes.push_back(static_cast<int>(P.rows()));
  if (options.check_topology) {
    const LinkType after = link_type(m.components());
    result.alexander_preserved = after.alexander == result.link_type->alexander;
    result.linking_preserved = after.linking_numbers == result.link_type->linking_numbers;
    result.conway_preserved = after.conway == result.link_type->conway;
  }
  return result;
}

}  // namespace

RelaxResult relax(const Link& link, const RelaxOptions& options) {
  require_input(!link.empty(), "relax: no curve");
  if (link.size() == 1) return relax(link[0], options);
  options.validate();
  RelaxOptions direct = options;  // several components relax by the direct method
  direct.method = RelaxMethod::Direct;
  return relax_components(link, direct);
}

}  // namespace ek
