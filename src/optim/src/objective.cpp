#include "ek/optim/objective.hpp"

#include <algorithm>

#include "ek/core/errors.hpp"

namespace ek {

CompositeObjective::CompositeObjective(Dofs dofs, std::vector<Potential*> terms)
    : dofs_(std::move(dofs)), terms_(std::move(terms)) {
  require(dofs_.count && dofs_.get, "CompositeObjective: the dof callbacks must be set");
  for (const Potential* t : terms_) require(t != nullptr, "CompositeObjective: a term is null");
}

void CompositeObjective::set_dofs(const VecX& x) {
  require(x.size() == num_dofs(), "CompositeObjective::set_dofs: wrong number of dofs");
  for (Potential* t : terms_) t->set_dofs(x);
}

double CompositeObjective::energy() {
  double e = 0.0;
  for (const Potential* t : terms_) e += t->energy();
  return e;
}

VecX CompositeObjective::gradient() {
  VecX g = VecX::Zero(num_dofs());
  for (const Potential* t : terms_) t->add_gradient(g);
  return g;
}

void CompositeObjective::assemble_hessian(SparseAssembler& A, HessianKind kind) {
  A.begin(num_dofs());
  for (size_t k = 0; k < terms_.size(); ++k) {
    A.segment(static_cast<int>(k), terms_[k]->hessian_structure());
    terms_[k]->add_hessian(A, kind);
  }
  A.end();
}

double CompositeObjective::max_step(const VecX& x, const VecX& dx) {
  double t = 1.0;
  for (const Potential* term : terms_) t = std::min(t, term->max_step(x, dx));
  return t;
}

void CompositeObjective::accept() {
  for (Potential* t : terms_) t->accept();
}

Eigen::MatrixXd CompositeObjective::rigid_modes() {
  return dofs_.rigid_modes ? dofs_.rigid_modes() : Eigen::MatrixXd();
}

std::vector<EnergyPart> CompositeObjective::energy_parts() {
  std::vector<EnergyPart> parts;
  for (const Potential* t : terms_) t->add_energy_parts(parts);
  return parts;
}

int CompositeObjective::active_pairs() const {
  int n = 0;
  for (const Potential* t : terms_) n += t->active_pairs();
  return n;
}

}  // namespace ek
