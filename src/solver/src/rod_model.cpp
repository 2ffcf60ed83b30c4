#include "ek/solver/rod_model.hpp"

#include <string>
#include <utility>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/solver/rod_terms.hpp"

namespace ek {

VecX checked_rest_lengths(const Points& curve, const RelaxOptions& options) {
  const auto n = curve.rows();
  require_input(n >= 4, "relax: a closed curve needs at least 4 vertices");
  require_input(curve.allFinite(), "relax: the curve has non-finite coordinates");
  require_input(edge_lengths(curve).minCoeff() > 0.0, "relax: the curve has a zero-length edge");
  const VecX rest = options.rest_lengths ? *options.rest_lengths : edge_lengths(curve);
  require_input(rest.size() == n && rest.minCoeff() > 0.0 && rest.allFinite(),
                "relax: rest lengths must be n positive numbers");
  return rest;
}

namespace {

/// The rest lengths of every component: a knot's checked (options.rest_lengths
/// or its edges), a link's its edges after checking the link and the
/// options it does not have.
std::vector<VecX> rest_lengths_of(const Link& link, const RelaxOptions& o) {
  require_input(!link.empty(), "relax: no curve");
  if (link.size() == 1) return {checked_rest_lengths(link[0], o)};
  require_input(!o.link, "relax: a prescribed link Lk applies to a knot, not to a link of several components");
  require_input(!o.full_model, "relax: links are relaxed in the twist-free model");
  require_input(!o.slab, "relax: the planarity slab applies to knots only");
  require_input(!o.rest_lengths, "relax: a link's rest lengths are its components' edge lengths");
  validate_link(link, "relax");
  std::vector<VecX> rest;
  for (const Points& P : link) rest.push_back(edge_lengths(P));
  return rest;
}

CurveTopology topology_of(const Link& link) {
  std::vector<int> sizes;
  for (const Points& P : link) sizes.push_back(static_cast<int>(P.rows()));
  return CurveTopology::from_sizes(sizes);
}

}  // namespace

struct RodModel::Impl {
  RelaxOptions options;
  ResolvedModel resolved;
  std::vector<ElasticRod> rods;     ///< never resized: the objectives point at them
  ContactOptions contact_options;   ///< at ω
  ContactPotential contact;         ///< at ω
  std::optional<PlanaritySlab> slab;
  NewtonOptions newton;
  std::optional<ContactPotential> soft_contact;  ///< of the current objective when its factor is not 1
  std::unique_ptr<RodObjective> objective;
  double factor = 0.0;
  bool with_slab = false;

  Impl(const Link& link, const std::vector<VecX>& rest, const RelaxOptions& o)
      : options(o),
        resolved(resolve_model(o, rest[0].mean())),
        contact_options(ek::contact_options(resolved)),
        contact(topology_of(link), contact_options) {
    int vertices = 0;
    for (size_t c = 0; c < link.size(); ++c) {
      rods.push_back(model_rod(link[c], rest[c], o, resolved));
      vertices += static_cast<int>(link[c].rows());
    }
    const double lambda = cached_lambda_min(vertices, rest[0].mean(), o.material, resolved.model);
    newton = newton_options(o, resolved, lambda);
  }

  std::vector<ElasticRod*> rod_pointers() {
    std::vector<ElasticRod*> p;
    for (ElasticRod& r : rods) p.push_back(&r);
    return p;
  }
};

RodModel::RodModel(const Link& link, const RelaxOptions& options) {
  options.validate();
  impl_ = std::make_unique<Impl>(link, rest_lengths_of(link, options), options);
  const Points x = positions();
  impl_->contact.update(x);
  require_input(impl_->contact.min_distance() > 0.0, "relax: the input curve touches itself");
  if (options.slab) {
    impl_->slab.emplace(*options.slab);
    if (!impl_->slab->inside(x))
      throw InputError("relax: the input curve is not strictly inside the planarity slab |z| < " +
                       std::to_string(options.slab->half_thickness));
  }
}

namespace {

RelaxOptions with_rest(RelaxOptions options, const VecX& rest) {
  options.rest_lengths = rest;
  return options;
}

}  // namespace

RodModel::RodModel(const Points& curve, const VecX& rest, const RelaxOptions& options)
    : RodModel(Link{curve}, with_rest(options, rest)) {}

RodModel::~RodModel() = default;

const RelaxOptions& RodModel::options() const { return impl_->options; }
const ResolvedModel& RodModel::resolved() const { return impl_->resolved; }
int RodModel::num_components() const { return static_cast<int>(impl_->rods.size()); }

int RodModel::num_vertices() const {
  int n = 0;
  for (const ElasticRod& r : impl_->rods) n += r.num_vertices();
  return n;
}

ElasticRod& RodModel::rod(int component) { return impl_->rods.at(static_cast<size_t>(component)); }
const ElasticRod& RodModel::rod(int component) const { return impl_->rods.at(static_cast<size_t>(component)); }

CompositeObjective& RodModel::objective(double contact_factor, bool with_slab) {
  require(contact_factor > 0.0, "RodModel::objective: the contact stiffness factor must be positive");
  Impl& m = *impl_;
  if (m.objective && contact_factor == m.factor && with_slab == m.with_slab) return *m.objective;
  m.objective.reset();
  ContactPotential* contact = &m.contact;
  if (contact_factor != 1.0) {
    ContactOptions soft = m.contact_options;
    soft.stiffness = contact_factor * m.contact_options.stiffness;
    contact = &m.soft_contact.emplace(m.contact.topology(), soft);
  }
  const PlanaritySlab* slab = with_slab && m.slab ? &*m.slab : nullptr;
  m.objective = std::make_unique<RodObjective>(m.rod_pointers(), *contact, slab, m.options.max_tangent_rotation);
  m.factor = contact_factor;
  m.with_slab = with_slab;
  return *m.objective;
}

ContactPotential& RodModel::contact() { return impl_->contact; }
const PlanaritySlab* RodModel::slab() const { return impl_->slab ? &*impl_->slab : nullptr; }
const NewtonOptions& RodModel::newton() const { return impl_->newton; }
double RodModel::tolerance() const { return impl_->newton.gradient_tolerance; }
double RodModel::lambda_min() const { return impl_->newton.lambda_min; }

Points RodModel::positions() const {
  if (impl_->rods.size() == 1) return impl_->rods[0].positions();
  return all_vertices(components());
}

Points RodModel::positions(const VecX& dofs) const {
  const int n = num_vertices();
  require(dofs.size() >= 3 * n, "RodModel::positions: too few dofs");
  return as_points(dofs.head(3 * n));
}

Link RodModel::components() const {
  Link out;
  for (const ElasticRod& r : impl_->rods) out.push_back(r.positions());
  return out;
}

double RodModel::min_distance() {
  impl_->contact.update(positions());
  return impl_->contact.min_distance();
}

}  // namespace ek
