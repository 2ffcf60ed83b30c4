#include "ek/solver/link_relax.hpp"

#include <numeric>
#include <optional>

#include "ek/contact/contact_potential.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/eigen_analysis.hpp"
#include "ek/solver/knot_terms.hpp"

namespace ek {
namespace {

/// The components' twist-free rods as one term over [x_0 | x_1 | ...]:
/// each rod reads and writes its own block of the dofs.
class LinkRodsTerm : public Potential {
 public:
  explicit LinkRodsTerm(const Link& link, const RodMaterial& material) {
    int offset = 0;
    for (const Points& P : link) {
      rods_.emplace_back(P, edge_lengths(P), material, TwistModel::TwistFree);
      offsets_.push_back(offset);
      offset += static_cast<int>(P.rows());
    }
  }
  int num_dofs() const { return 3 * (offsets_.back() + rods_.back().num_vertices()); }
  VecX dofs() const {
    VecX x(num_dofs());
    for (size_t c = 0; c < rods_.size(); ++c) x.segment(block(c), rods_[c].num_dofs()) = rods_[c].dofs();
    return x;
  }
  Points positions() const { return as_points(dofs()); }
  Link components() const {
    Link out;
    for (const ElasticRod& r : rods_) out.push_back(r.positions());
    return out;
  }
  void set_dofs(const VecX& x) override {
    for (size_t c = 0; c < rods_.size(); ++c) rods_[c].set_dofs(x.segment(block(c), rods_[c].num_dofs()));
  }
  double energy() const override {
    double e = 0.0;
    for (const ElasticRod& r : rods_) e += r.energy(EnergyTerm::Stretch) + r.energy(EnergyTerm::Bend);
    return e;
  }
  void add_energy_parts(std::vector<EnergyPart>& parts) const override {
    double stretch = 0.0, bend = 0.0;
    for (const ElasticRod& r : rods_) {
      stretch += r.energy(EnergyTerm::Stretch);
      bend += r.energy(EnergyTerm::Bend);
    }
    parts.push_back({"stretch", stretch});
    parts.push_back({"bend", bend});
  }
  void add_gradient(Eigen::Ref<VecX> g) const override {
    for (size_t c = 0; c < rods_.size(); ++c) g.segment(block(c), rods_[c].num_dofs()) += rods_[c].gradient();
  }
  std::uint64_t hessian_structure() const override {
    std::uint64_t h = rods_.size();
    for (const ElasticRod& r : rods_) h = splitmix64(h ^ r.hessian_structure());
    return h;
  }
  void add_hessian(SparseAssembler& A, HessianKind kind) const override {
    for (size_t c = 0; c < rods_.size(); ++c) {
      A.set_offset(static_cast<SparseAssembler::Index>(block(c)));
      rods_[c].add_hessian(A, EnergyTerm::All, kind);
    }
    A.set_offset(0);
  }

 private:
  Eigen::Index block(size_t c) const { return 3 * static_cast<Eigen::Index>(offsets_[c]); }
  std::vector<ElasticRod> rods_;
  std::vector<int> offsets_;  ///< first vertex of each component
};

/// The link's objective: its rods and the contact between all its edges.
class LinkObjective : public CompositeObjective {
 public:
  LinkObjective(LinkRodsTerm& rods, ContactPotential& contact)
      : LinkObjective(rods, std::make_unique<ContactTerm>(contact, rods.positions())) {}

 private:
  LinkObjective(LinkRodsTerm& rods, std::unique_ptr<ContactTerm> c)
      : CompositeObjective(Dofs{[&rods] { return rods.num_dofs(); }, [&rods] { return rods.dofs(); },
                                [&rods] { return ek::rigid_modes(rods.positions(), rods.num_dofs()); }},
                           {&rods, c.get()}),
        contact_(std::move(c)) {}
  std::unique_ptr<ContactTerm> contact_;
};

void check_options(const Link& link, const RelaxOptions& o) {
  o.validate();
  require_input(link.size() >= 2, "relax: a link needs at least 2 components (relax a knot with relax())");
  require_input(!o.link, "relax: a prescribed link Lk applies to a knot, not to a link of several components");
  require_input(!o.full_model, "relax: links are relaxed in the twist-free model");
  require_input(!o.slab, "relax: the planarity slab applies to knots only");
  require_input(!o.rest_lengths, "relax: a link's rest lengths are its components' edge lengths");
  validate_link(link, "relax");
}

CurveTopology topology_of(const Link& link) {
  std::vector<int> sizes;
  for (const Points& P : link) sizes.push_back(static_cast<int>(P.rows()));
  return CurveTopology::from_sizes(sizes);
}


}  // namespace

struct LinkModel::Impl {
  RelaxOptions options;
  double mean_edge;  ///< [length] of the first component: the model's ℓ
  ResolvedModel model;
  CurveTopology topology;
  LinkRodsTerm rods;
  std::optional<ContactPotential> contact;
  std::unique_ptr<LinkObjective> objective;
  double factor = 0.0;

  Impl(const Link& link, const RelaxOptions& o)
      : options(o),
        mean_edge(curve_length(link[0]) / static_cast<double>(link[0].rows())),
        model(resolve_model(o, mean_edge)),
        topology(topology_of(link)),
        rods(link, o.material) {}
};

LinkModel::LinkModel(const Link& link, const RelaxOptions& options) {
  check_options(link, options);
  impl_ = std::make_unique<Impl>(link, options);
}

LinkModel::~LinkModel() = default;

Objective& LinkModel::objective(double factor) {
  require(factor > 0.0, "LinkModel::objective: the contact stiffness factor must be positive");
  if (!impl_->objective || factor != impl_->factor) {
    impl_->objective.reset();
    ContactOptions co = contact_options(impl_->model, impl_->options);
    co.stiffness *= factor;
    impl_->contact.emplace(impl_->topology, co);
    impl_->objective = std::make_unique<LinkObjective>(impl_->rods, *impl_->contact);
    impl_->factor = factor;
  }
  return *impl_->objective;
}

Link LinkModel::components() const { return impl_->rods.components(); }

double LinkModel::min_distance() {
  if (!impl_->contact) objective();
  impl_->contact->update(impl_->rods.positions());
  return impl_->contact->min_distance();
}

const ResolvedModel& LinkModel::model() const { return impl_->model; }

NewtonOptions LinkModel::newton_options() const {
  const int n = impl_->rods.num_dofs() / 3;
  return ek::newton_options(impl_->options, impl_->model,
                            cached_lambda_min(n, impl_->mean_edge, impl_->options.material, TwistModel::TwistFree));
}

bool LinkRelaxResult::converged() const {
  return report.status == SolverStatus::ConvergedStable || report.status == SolverStatus::ConvergedUnstable;
}

RelaxStatus LinkRelaxResult::status() const { return relax_status(report.status, topology_preserved()); }

LinkRelaxResult relax_link(const Link& link, const RelaxOptions& options) {
  LinkModel m(link, options);
  LinkRelaxResult out;
  const LinkType before = link_type(link);
  out.alexander = before.alexander;
  out.linking_numbers = before.linking_numbers;
  out.conway = before.conway;
  NewtonSolver solver(m.newton_options());
  for (const double f : options.contact_continuation) out.continuation_reports.push_back(solver.minimize(m.objective(f)));
  Objective& objective = m.objective(1.0);
  out.report = solver.minimize(objective);
  out.energy = objective.energy();
  out.parts = objective.energy_parts();
  out.min_distance = m.min_distance();
  out.positions = m.components();
  const LinkType after = link_type(out.positions);
  out.alexander_preserved = after.alexander == before.alexander;
  out.linking_preserved = after.linking_numbers == before.linking_numbers;
  out.conway_preserved = after.conway == before.conway;
  return out;
}

}  // namespace ek
