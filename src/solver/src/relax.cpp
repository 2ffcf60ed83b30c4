#include "ek/solver/relax.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/solver/eigen_analysis.hpp"

namespace ek {
namespace {

/// E_rod + ω E_contact (+ E_slab) over the rod's dofs (positions first).
class KnotObjective : public Objective {
 public:
  KnotObjective(ElasticRod& rod, ContactPotential& contact, const PlanaritySlab* slab, double max_rotation)
      : rod_(rod), contact_(contact), slab_(slab), max_rotation_(max_rotation) {
    contact_.update(rod_.positions());
  }
  void set_slab(const PlanaritySlab* slab) { slab_ = slab; }

  int num_dofs() const override { return rod_.num_dofs(); }
  VecX dofs() const override { return rod_.dofs(); }
  void set_dofs(const VecX& x) override {
    rod_.set_dofs(x);
    contact_.update(rod_.positions());
  }
  double energy() override { return parts().total; }
  EnergyParts parts() const {
    EnergyParts p;
    const Points& x = rod_.positions();
    p.stretch = rod_.energy(EnergyTerm::Stretch);
    p.bend = rod_.energy(EnergyTerm::Bend);
    p.twist = rod_.model() == TwistModel::TwistFree ? 0.0 : rod_.energy(EnergyTerm::Twist);
    p.contact = contact_.energy(x);
    p.slab = slab_ ? slab_->energy(x) : 0.0;
    p.total = p.stretch + p.bend + p.twist + p.contact + p.slab;
    return p;
  }
  VecX gradient() override {
    VecX g = rod_.gradient();
    const Points& x = rod_.positions();
    contact_.add_gradient(x, g.head(x.size()));
    if (slab_) g.head(x.size()) += slab_->gradient(x);
    return g;
  }
  /// exact = false: the contact pairs' barrier Hessians and the stretching
  /// Hessians of compressed edges projected to positive semidefinite
  /// (bending and twisting stay exact; see NewtonOptions::hessian).
  void assemble_hessian(SparseAssembler& A, bool exact) override {
    const Points& x = rod_.positions();
    A.begin(num_dofs());
    A.segment(0, rod_.hessian_structure());
    rod_.add_hessian(A, EnergyTerm::All, !exact);
    A.segment(1, contact_.hessian_structure());
    contact_.add_hessian(x, A, !exact);
    A.segment(2, slab_ ? 1 : 0);
    if (slab_) slab_->add_hessian(x, A);
    A.end();
  }
  Eigen::MatrixXd rigid_modes() override {
    return ek::rigid_modes(rod_.positions(), rod_.num_dofs(),
                           rod_.model() == TwistModel::TwistFree ? -1 : 3 * rod_.num_vertices(), slab_ != nullptr);
  }
  double max_step(const VecX& x, const VecX& dx) override {
    const Eigen::Index m = rod_.positions().size();
    const Points X = as_points(x.head(m)), D = as_points(dx.head(m));
    double t = contact_.max_step(X, D);
    if (slab_) t = std::min(t, slab_->max_step(X, D));
    if (rod_.model() != TwistModel::TwistFree) {
      // keep every tangent within max_rotation of its source: |s·de| <= sin(α)|e|
      const double s = std::sin(max_rotation_);
      const auto n = X.rows();
      for (Eigen::Index j = 0; j < n; ++j) {
        const Vec3 e = (X.row((j + 1) % n) - X.row(j)).transpose();
        const Vec3 de = (D.row((j + 1) % n) - D.row(j)).transpose();
        const double len = de.norm();
        if (len > 0.0) t = std::min(t, s * e.norm() / len);
      }
    }
    return t;
  }
  void accept() override { rod_.update_reference_frames(); }

 private:
  ElasticRod& rod_;
  ContactPotential& contact_;
  const PlanaritySlab* slab_;
  double max_rotation_;
};

std::string model_name(TwistModel m) {
  switch (m) {
    case TwistModel::TwistFree: return "twist-free";
    case TwistModel::FreeTheta: return "free-theta";
    case TwistModel::FixedLink: return "fixed-link";
  }
  return "?";
}

}  // namespace

void RelaxOptions::validate() const {
  material.validate();
  require_input(std::isfinite(dhat) && std::isfinite(contact_stiffness) && std::isfinite(tolerance),
                "relax: options must be finite");
  require_input(max_iterations >= 0, "relax: max_iterations must be >= 0");
  require_input(!link || std::isfinite(*link), "relax: link must be finite");
  require_input(max_tangent_rotation > 0.0 && max_tangent_rotation < 1.5, "relax: max_tangent_rotation in (0, 1.5)");
  require_input(!release_slab || slab, "relax: release_slab needs a slab");
  for (const double f : contact_continuation)
    require_input(f > 0.0 && f < 1.0, "relax: contact_continuation factors must be in (0, 1)");
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
  r.dhat = options.dhat > 0.0 ? options.dhat : 2.0 * mat.radius;
  r.contact_stiffness = options.contact_stiffness > 0.0 ? options.contact_stiffness : default_contact_stiffness(mat);
  r.tolerance = options.tolerance > 0.0
                    ? options.tolerance
                    : 1e-8 * (mat.bending_stiffness() / kReferenceBendingStiffness) / (mean_edge_length * mean_edge_length);
  if (options.link) r.model = TwistModel::FixedLink;
  else if (options.full_model) r.model = TwistModel::FreeTheta;
  return r;
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
  for (const NewtonReport& r : continuation_reports) add(r);
  if (slab_report) add(*slab_report);
  return sum;
}

bool RelaxResult::converged() const {
  return report.status == SolverStatus::ConvergedStable || report.status == SolverStatus::ConvergedUnstable;
}
bool RelaxResult::stable() const { return report.status == SolverStatus::ConvergedStable; }
std::string RelaxResult::status() const { return alexander_preserved ? to_string(report.status) : "topology-changed"; }

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

RelaxResult relax(const Points& curve, const RelaxOptions& options) {
  options.validate();
  const int n = static_cast<int>(curve.rows());
  require_input(n >= 4, "relax: a closed curve needs at least 4 vertices");
  require_input(curve.allFinite(), "relax: the curve has non-finite coordinates");
  require_input(edge_lengths(curve).minCoeff() > 0.0, "relax: the curve has a zero-length edge");
  const VecX rest = options.rest_lengths ? *options.rest_lengths : edge_lengths(curve);
  require_input(rest.size() == n && rest.minCoeff() > 0.0 && rest.allFinite(),
                "relax: rest lengths must be n positive numbers");
  RelaxResult result;
  if (options.check_topology) {
    try {
      result.alexander = alexander(curve);
    } catch (const InputError& e) {
      throw InputError(std::string("relax: the input curve is not simple: ") + e.what());
    }
  }
  const RodMaterial& mat = options.material;
  const double edge = rest.mean();
  const ResolvedModel resolved = resolve_model(options, edge);
  ContactOptions co;
  co.dhat = resolved.dhat;
  co.stiffness = resolved.contact_stiffness;
  const double tol = resolved.tolerance;
  const TwistModel model = resolved.model;
  result.model = model_name(model);

  ElasticRod rod(curve, rest, mat, model);
  if (options.link) {
    rod.set_link(*options.link);
    rod.relax_twist();
  }
  ContactPotential contact(CurveTopology::single(n), co);
  contact.update(curve);
  if (contact.min_distance() <= 0.0) throw InputError("relax: the input curve touches itself");
  std::optional<PlanaritySlab> slab;
  if (options.slab) {
    slab.emplace(*options.slab);
    if (!slab->inside(curve))
      throw InputError("relax: the input curve is not strictly inside the planarity slab |z| < " +
                       std::to_string(options.slab->half_thickness));
  }
  KnotObjective objective(rod, contact, slab ? &*slab : nullptr, options.max_tangent_rotation);

  NewtonOptions no = options.newton;
  no.gradient_tolerance = tol;
  no.max_iterations = options.max_iterations;
  no.stop_at_critical_point = options.stop_at_critical_point;
  result.lambda_min = cached_lambda_min(n, edge, mat, model);
  no.lambda_min = result.lambda_min;

  // Contact-stiffness continuation (RelaxOptions::contact_continuation): the
  // same rod, slab and tolerance with a softer barrier; every accepted step
  // is still collision-free (the barrier is singular at d = 0 for any ω).
  for (const double f : options.contact_continuation) {
    ContactOptions soft = co;
    soft.stiffness = f * co.stiffness;
    ContactPotential soft_contact(CurveTopology::single(n), soft);
    KnotObjective soft_objective(rod, soft_contact, slab ? &*slab : nullptr, options.max_tangent_rotation);
    result.continuation_reports.push_back(minimize(soft_objective, no));
  }
  if (!options.contact_continuation.empty()) objective.set_dofs(rod.dofs());
  result.report = minimize(objective, no);
  if (slab && options.release_slab) {
    result.slab_report = result.report;
    result.slab_energy = objective.parts();
    objective.set_slab(nullptr);
    result.report = minimize(objective, no);
  }
  result.positions = rod.positions();
  result.theta = rod.thetas();
  result.Theta = model == TwistModel::TwistFree ? 0.0 : rod.theta_total();
  result.energy = objective.parts();
  contact.update(result.positions);
  result.contacts = static_cast<int>(contact.num_active());
  result.min_distance = clearance(result.positions).distance;
  result.twist = rod.twist();
  result.writhe = rod.writhe();
  result.link = result.twist + result.writhe;
  if (options.check_topology) {
    try {
      result.result_alexander = alexander(result.positions);
    } catch (const InputError&) {
      result.result_alexander = AlexanderPolynomial{{0}};
    }
    result.alexander_preserved = (result.result_alexander == result.alexander);
  }
  if (options.smallest_eigenvalue) {
    SparseAssembler A;
    objective.assemble_hessian(A, true);
    const int theta_begin = model == TwistModel::TwistFree ? -1 : 3 * n;
    // All six rigid motions are excluded even under a kept slab: where no
    // vertex is within the slab's activation distance of a plane, the z
    // translation and the tilts are (near-)zero modes of H too, and the
    // stiffness is meant to describe the shape.
    const Eigen::MatrixXd Q = rigid_modes(result.positions, rod.num_dofs(), theta_begin);
    EigenOptions eo;
    eo.count = 1;
    const EigenResult eig = smallest_eigenpairs(A.matrix(), Q, no.shift_epsilon * no.lambda_min, eo);
    if (eig.converged) result.smallest_eigenvalue = eig.values(0);
  }
  return result;
}

}  // namespace ek
