#include "ek/solver/energy.hpp"

#include <cmath>

#include "ek/contact/contact_potential.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

void CurveEnergyOptions::validate() const {
  material.validate();
  if (link) require_input(std::isfinite(*link), "the link must be finite");
  if (rest_length) require_input(std::isfinite(*rest_length) && *rest_length > 0.0, "--rest-length must be positive");
}

CurveEnergy curve_energy(const Points& P, const CurveEnergyOptions& options) {
  options.validate();
  const int n = static_cast<int>(P.rows());
  RelaxOptions model_options;  // the model as relax() resolves it
  model_options.material = options.material;
  model_options.link = options.link;
  const VecX rest = options.rest_length ? VecX(VecX::Constant(n, *options.rest_length)) : edge_lengths(P);
  const ResolvedModel resolved = resolve_model(model_options, rest.mean());
  ElasticRod rod = model_rod(P, rest, model_options, resolved);
  CurveEnergy e;
  e.vertices = n;
  e.model = resolved.model;
  e.energy.stretch = rod.energy(EnergyTerm::Stretch);
  e.energy.bend = rod.energy(EnergyTerm::Bend);
  e.energy.twist = rod.energy(EnergyTerm::Twist);
  // Self-contact (paper eq. 1): ω E_contact with d̂ and ω as relax() resolves them.
  ContactPotential contact(CurveTopology::single(n), contact_options(resolved));
  contact.update(P);
  e.energy.contact = contact.energy(P);
  e.energy.total = e.energy.stretch + e.energy.bend + e.energy.twist + e.energy.contact;
  VecX gradient = rod.gradient();
  contact.add_gradient(P, gradient.head(3 * n));
  e.gradient_norm = gradient.norm();
  e.contacts = static_cast<int>(contact.num_active());
  e.writhe = rod.writhe();
  e.twist = rod.twist();
  e.link = e.twist + e.writhe;
  return e;
}

}  // namespace ek
