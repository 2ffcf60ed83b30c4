#include "ek/solver/rod_terms.hpp"

#include <cmath>
#include <utility>

#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/optim/eigen_analysis.hpp"

namespace ek {

RodTerm::RodTerm(std::vector<ElasticRod*> rods, double max_rotation)
    : rods_(std::move(rods)), max_rotation_(max_rotation) {
  require(!rods_.empty(), "RodTerm: no rod");
  Eigen::Index offset = 0;
  for (const ElasticRod* r : rods_) {
    require(r != nullptr, "RodTerm: a null rod");
    require_input(rods_.size() == 1 || r->model() == TwistModel::TwistFree,
                  "the rods of several components must be twist-free");
    offsets_.push_back(offset);
    offset += r->num_dofs();
  }
}

int RodTerm::num_dofs() const { return static_cast<int>(offsets_.back()) + rods_.back()->num_dofs(); }

VecX RodTerm::dofs() const {
  if (rods_.size() == 1) return rods_[0]->dofs();
  VecX x(num_dofs());
  for (size_t c = 0; c < rods_.size(); ++c) x.segment(offsets_[c], rods_[c]->num_dofs()) = rods_[c]->dofs();
  return x;
}

Points RodTerm::positions() const {
  if (rods_.size() == 1) return rods_[0]->positions();
  Eigen::Index rows = 0;
  for (const ElasticRod* r : rods_) rows += r->num_vertices();
  Points P(rows, 3);
  Eigen::Index row = 0;
  for (const ElasticRod* r : rods_) {
    P.middleRows(row, r->num_vertices()) = r->positions();
    row += r->num_vertices();
  }
  return P;
}

int RodTerm::theta_begin() const {
  return rods_[0]->model() == TwistModel::TwistFree ? -1 : 3 * rods_[0]->num_vertices();
}

void RodTerm::set_dofs(const VecX& x) {
  for (size_t c = 0; c < rods_.size(); ++c) rods_[c]->set_dofs(x.segment(offsets_[c], rods_[c]->num_dofs()));
}

namespace {

double twist_energy(const ElasticRod& rod) {
  return rod.model() == TwistModel::TwistFree ? 0.0 : rod.energy(EnergyTerm::Twist);
}

}  // namespace

double RodTerm::energy() const {
  double e = 0.0;
  for (const ElasticRod* r : rods_)
    e += r->energy(EnergyTerm::Stretch) + r->energy(EnergyTerm::Bend) + twist_energy(*r);
  return e;
}

void RodTerm::add_energy_parts(std::vector<EnergyPart>& parts) const {
  double stretch = 0.0, bend = 0.0, twist = 0.0;
  for (const ElasticRod* r : rods_) {
    stretch += r->energy(EnergyTerm::Stretch);
    bend += r->energy(EnergyTerm::Bend);
    twist += twist_energy(*r);
  }
  parts.push_back({"stretch", stretch});
  parts.push_back({"bend", bend});
  parts.push_back({"twist", twist});
}

void RodTerm::add_gradient(Eigen::Ref<VecX> g) const {
  for (size_t c = 0; c < rods_.size(); ++c) g.segment(offsets_[c], rods_[c]->num_dofs()) += rods_[c]->gradient();
}

std::uint64_t RodTerm::hessian_structure() const {
  if (rods_.size() == 1) return rods_[0]->hessian_structure();
  std::uint64_t h = rods_.size();
  for (const ElasticRod* r : rods_) h = splitmix64(h ^ r->hessian_structure());
  return h;
}

void RodTerm::add_hessian(SparseAssembler& A, HessianKind kind) const {
  for (size_t c = 0; c < rods_.size(); ++c) {
    A.set_offset(static_cast<SparseAssembler::Index>(offsets_[c]));
    rods_[c]->add_hessian(A, EnergyTerm::All, kind);
  }
  A.set_offset(0);
}

double RodTerm::max_step(const VecX& x, const VecX& dx) const {
  // keep every tangent within max_rotation of its source: |s·de| <= sin(α)|e|
  const double s = std::sin(max_rotation_);
  double t = 1.0;
  for (size_t c = 0; c < rods_.size(); ++c) {
    if (rods_[c]->model() == TwistModel::TwistFree) continue;
    const int n = rods_[c]->num_vertices();
    const Points X = as_points(x.segment(offsets_[c], 3 * n)), D = as_points(dx.segment(offsets_[c], 3 * n));
    for (int j = 0; j < n; ++j) {
      const Vec3 e = (X.row((j + 1) % n) - X.row(j)).transpose();
      const Vec3 de = (D.row((j + 1) % n) - D.row(j)).transpose();
      const double len = de.norm();
      if (len > 0.0) t = std::min(t, s * e.norm() / len);
    }
  }
  return t;
}

void RodTerm::accept() {
  for (ElasticRod* r : rods_)
    if (r->model() != TwistModel::TwistFree) r->update_reference_frames();
}

ContactTerm::ContactTerm(ContactPotential& contact, const Points& x) : contact_(contact), x_(x) {
  contact_.update(x_);
}

void ContactTerm::set_dofs(const VecX& x) {
  x_ = as_points(x.head(x_.size()));
  contact_.update(x_);
}

double ContactTerm::max_step(const VecX& x, const VecX& dx) const {
  const Eigen::Index m = x_.size();
  return contact_.max_step(as_points(x.head(m)), as_points(dx.head(m)));
}

double SlabTerm::max_step(const VecX& x, const VecX& dx) const {
  const Eigen::Index m = x_.size();
  return slab_.max_step(as_points(x.head(m)), as_points(dx.head(m)));
}

RodObjective::RodObjective(std::vector<ElasticRod*> rods, ContactPotential& contact, const PlanaritySlab* slab,
                           double max_rotation)
    : RodObjective(std::make_unique<RodTerm>(std::move(rods), max_rotation), contact, slab) {}

RodObjective::RodObjective(std::unique_ptr<RodTerm> r, ContactPotential& contact, const PlanaritySlab* slab)
    : RodObjective(std::move(r), contact, slab, r->positions()) {}

RodObjective::RodObjective(std::unique_ptr<RodTerm>&& r, ContactPotential& contact, const PlanaritySlab* slab,
                           const Points& x)
    : RodObjective(std::move(r), std::make_unique<ContactTerm>(contact, x),
                   slab ? std::make_unique<SlabTerm>(*slab, x) : nullptr) {}

RodObjective::RodObjective(std::unique_ptr<RodTerm>&& r, std::unique_ptr<ContactTerm> c, std::unique_ptr<SlabTerm> s)
    : CompositeObjective(
          Dofs{[t = r.get()] { return t->num_dofs(); }, [t = r.get()] { return t->dofs(); },
               [t = r.get(), planar = s != nullptr] {
                 return ek::rigid_modes(t->positions(), t->num_dofs(), t->theta_begin(), planar);
               }},
          s ? std::vector<Potential*>{r.get(), c.get(), s.get()} : std::vector<Potential*>{r.get(), c.get()}),
      rod_term_(std::move(r)),
      contact_term_(std::move(c)),
      slab_term_(std::move(s)) {}

}  // namespace ek
