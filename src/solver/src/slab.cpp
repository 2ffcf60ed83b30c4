#include "ek/solver/slab.hpp"

#include <cmath>
#include <limits>

#include "ek/contact/barrier.hpp"
#include "ek/core/errors.hpp"

namespace ek {

void SlabOptions::validate() const {
  require(half_thickness > 0.0 && std::isfinite(half_thickness), "SlabOptions: half_thickness must be positive");
  require(activation > 0.0 && activation <= 1.0, "SlabOptions: activation must be in (0, 1]");
  require(stiffness > 0.0, "SlabOptions: stiffness must be positive");
  require(separation > 0.0 && separation < 1.0, "SlabOptions: separation must be in (0, 1)");
}

PlanaritySlab::PlanaritySlab(SlabOptions options) : o_(options) { o_.validate(); }

bool PlanaritySlab::inside(const Points& x) const { return x.col(2).cwiseAbs().maxCoeff() < o_.half_thickness; }

double PlanaritySlab::energy(const Points& x) const {
  const double h = o_.half_thickness, dhat = o_.activation * h;
  double e = 0.0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double z = x(i, 2);
    e += barrier(h - z, dhat) + barrier(h + z, dhat);
  }
  return o_.stiffness * e;
}

VecX PlanaritySlab::gradient(const Points& x) const {
  const double h = o_.half_thickness, dhat = o_.activation * h;
  VecX g = VecX::Zero(x.size());
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double z = x(i, 2);
    g(3 * i + 2) = o_.stiffness * (-barrier_first_derivative(h - z, dhat) + barrier_first_derivative(h + z, dhat));
  }
  return g;
}

void PlanaritySlab::add_hessian(const Points& x, SparseAssembler& A) const {
  const double h = o_.half_thickness, dhat = o_.activation * h;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double z = x(i, 2);
    const int k = static_cast<int>(3 * i + 2);
    A.add(k, k, o_.stiffness * (barrier_second_derivative(h - z, dhat) + barrier_second_derivative(h + z, dhat)));
  }
}

double PlanaritySlab::max_step(const Points& x, const Points& dx) const {
  const double h = o_.half_thickness;
  double t = 1.0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const double z = x(i, 2), dz = dx(i, 2);
    if (dz > 0.0) t = std::min(t, (1.0 - o_.separation) * (h - z) / dz);
    if (dz < 0.0) t = std::min(t, (1.0 - o_.separation) * (h + z) / -dz);
  }
  return std::max(t, 0.0);
}

}  // namespace ek
