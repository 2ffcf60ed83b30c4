#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/solver/saddle.hpp"

namespace ek {

struct KnotSystem::Impl {
  ElasticRod rod;
  ContactPotential contact;
  std::unique_ptr<KnotObjective> objective;
};

KnotSystem::KnotSystem(const Points& x, const VecX& rest, const RelaxOptions& options) {
  options.validate();
  require_input(!options.slab, "KnotSystem: the planarity slab is not supported");
  const int n = static_cast<int>(x.rows());
  require_input(n >= 4 && x.allFinite(), "a closed curve needs at least 4 finite vertices");
  require_input(rest.size() == n && rest.allFinite() && rest.minCoeff() > 0.0, "rest lengths must be n positive numbers");
  const ResolvedModel model = resolve_model(options, rest.mean());
  impl_ = std::unique_ptr<Impl>(new Impl{model_rod(x, rest, options, model),
                                         ContactPotential(CurveTopology::single(n), contact_options(model, options)),
                                         nullptr});
  impl_->contact.update(x);
  require_input(impl_->contact.min_distance() > 0.0, "the curve touches itself");
  impl_->objective = std::make_unique<KnotObjective>(impl_->rod, impl_->contact, nullptr, options.max_tangent_rotation);
  newton_ = newton_options(options, model, cached_lambda_min(n, rest.mean(), options.material, model.model));
}

KnotSystem::~KnotSystem() = default;

CompositeObjective& KnotSystem::objective() { return *impl_->objective; }
ElasticRod& KnotSystem::rod() { return impl_->rod; }

Points KnotSystem::positions(const VecX& dofs) const {
  const int n = impl_->rod.num_vertices();
  require(dofs.size() >= 3 * n, "KnotSystem::positions: too few dofs");
  return as_points(dofs.head(3 * n));
}

std::string KnotSystem::model_name() const { return to_string(impl_->rod.model()); }

}  // namespace ek
