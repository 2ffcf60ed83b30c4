#include "ek/contact/motion.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"

namespace ek {

void MotionCheckOptions::validate() const {
  require_input(radius > 0.0 && std::isfinite(radius), "--radius must be positive");
  require_input(separation > 0.0 && separation < 1.0, "--separation must be in (0, 1)");
  require_input(samples >= 1, "motion check: at least 1 clearance sample");
}

MotionCheck check_linear_motion(const Points& x, const Points& y, const MotionCheckOptions& options) {
  options.validate();
  require_input(x.rows() == y.rows(), "the end has " + std::to_string(y.rows()) + " vertices, the start has " +
                                          std::to_string(x.rows()));
  ContactOptions co;
  co.ccd_separation = options.separation;
  co.dhat = 2.0 * options.radius;
  const Points dx = y - x;
  const int n = static_cast<int>(x.rows());
  ContactPotential contact(CurveTopology::single(n), co);
  MotionCheck m;
  m.vertices = n;
  m.step = contact.max_step_report(x, dx);
  m.separation = co.ccd_separation;
  m.dhat = co.dhat;
  m.clearance_start = clearance(x).distance;
  m.clearance_at_t = clearance(x + m.step.t * dx).distance;
  m.clearance_end = clearance(y).distance;
  m.min_clearance_sampled = m.clearance_start;
  for (int k = 1; k <= options.samples; ++k)
    m.min_clearance_sampled =
        std::min(m.min_clearance_sampled, clearance(x + (m.step.t * k / options.samples) * dx).distance);
  return m;
}

}  // namespace ek
