#include "ek/solver/knot_terms.hpp"

#include <cmath>

#include "ek/solver/eigen_analysis.hpp"

namespace ek {

double RodTerm::energy() const {
  const double twist = rod_.model() == TwistModel::TwistFree ? 0.0 : rod_.energy(EnergyTerm::Twist);
  return rod_.energy(EnergyTerm::Stretch) + rod_.energy(EnergyTerm::Bend) + twist;
}

void RodTerm::add_energy_parts(std::vector<EnergyPart>& parts) const {
  parts.push_back({"stretch", rod_.energy(EnergyTerm::Stretch)});
  parts.push_back({"bend", rod_.energy(EnergyTerm::Bend)});
  parts.push_back({"twist", rod_.model() == TwistModel::TwistFree ? 0.0 : rod_.energy(EnergyTerm::Twist)});
}

double RodTerm::max_step(const VecX& x, const VecX& dx) const {
  if (rod_.model() == TwistModel::TwistFree) return 1.0;
  // keep every tangent within max_rotation of its source: |s·de| <= sin(α)|e|
  const int n = rod_.num_vertices();
  const Points X = as_points(x.head(3 * n)), D = as_points(dx.head(3 * n));
  const double s = std::sin(max_rotation_);
  double t = 1.0;
  for (int j = 0; j < n; ++j) {
    const Vec3 e = (X.row((j + 1) % n) - X.row(j)).transpose();
    const Vec3 de = (D.row((j + 1) % n) - D.row(j)).transpose();
    const double len = de.norm();
    if (len > 0.0) t = std::min(t, s * e.norm() / len);
  }
  return t;
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

KnotObjective::KnotObjective(ElasticRod& rod, ContactPotential& contact, const PlanaritySlab* slab,
                             double max_rotation)
    : KnotObjective(rod, std::make_unique<RodTerm>(rod, max_rotation),
                    std::make_unique<ContactTerm>(contact, rod.positions()),
                    slab ? std::make_unique<SlabTerm>(*slab, rod.positions()) : nullptr) {}

KnotObjective::KnotObjective(ElasticRod& rod, std::unique_ptr<RodTerm> r, std::unique_ptr<ContactTerm> c,
                             std::unique_ptr<SlabTerm> s)
    : CompositeObjective(
          Dofs{[&rod] { return rod.num_dofs(); }, [&rod] { return rod.dofs(); },
               [&rod, planar = s != nullptr] {
                 const int theta_begin = rod.model() == TwistModel::TwistFree ? -1 : 3 * rod.num_vertices();
                 return ek::rigid_modes(rod.positions(), rod.num_dofs(), theta_begin, planar);
               }},
          s ? std::vector<Potential*>{r.get(), c.get(), s.get()} : std::vector<Potential*>{r.get(), c.get()}),
      rod_term_(std::move(r)),
      contact_term_(std::move(c)),
      slab_term_(std::move(s)) {}

}  // namespace ek
