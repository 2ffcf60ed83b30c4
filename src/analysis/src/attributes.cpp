#include "ek/analysis/attributes.hpp"

#include <cmath>
#include <limits>

#include "ek/analysis/bounding_box.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/writhe.hpp"

namespace ek {

void AttributeOptions::validate() const {
  require_input(std::isfinite(radius) && radius > 0.0, "--radius must be positive");
  require_input(std::isfinite(young_modulus) && young_modulus > 0.0, "--young must be positive");
}

Points curvature_binormals(const Points& P) {
  require_closed_polygon(P, "curvature_binormals");
  const Points E = edge_vectors(P);
  const auto n = P.rows();
  Points KB(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 a = E.row((i + n - 1) % n).transpose(), b = E.row(i).transpose();
    require(a.norm() > 0.0 && b.norm() > 0.0, "curvature_binormals: zero-length edge");
    const double den = a.norm() * b.norm() + a.dot(b);
    // den = 0 only for a fold-back (φ = π): |κb| = 2 tan(π/2) is infinite
    const Vec3 kb = den > 0.0 ? Vec3(2.0 * a.cross(b) / den) : Vec3::Constant(std::numeric_limits<double>::infinity());
    KB.row(i) = kb.transpose();
  }
  return KB;
}

double max_bending_stress(const Points& P, double radius, double young_modulus) {
  AttributeOptions{radius, young_modulus}.validate();
  return radius * young_modulus * curvature_binormals(P).rowwise().norm().maxCoeff();
}

double threedim(const Points& P) {
  require_closed_polygon(P, "threedim");
  const OrientedBox box = min_volume_bounding_box(P);
  return box.extents(0) > 0.0 ? box.extents(2) / box.extents(0) : 0.0;
}

double sphericity(const Points& P) {
  require_closed_polygon(P, "sphericity");
  const Vec3 c = centroid(P);
  const VecX d = (P.rowwise() - c.transpose()).rowwise().norm();
  const double mean = d.mean();
  if (!(mean > 0.0)) return 0.0;
  const double var = (d.array() - mean).square().mean();
  return std::sqrt(var) / mean;
}

Diameter diameter(const Points& P) {
  require_closed_polygon(P, "diameter");
  const auto n = P.rows();
  Diameter best;
  double best_d2 = -1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double xi = P(i, 0), yi = P(i, 1), zi = P(i, 2);
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const double dx = P(j, 0) - xi, dy = P(j, 1) - yi, dz = P(j, 2) - zi;
      const double d2 = dx * dx + dy * dy + dz * dz;
      if (d2 > best_d2) {
        best_d2 = d2;
        best.i = static_cast<int>(i);
        best.j = static_cast<int>(j);
      }
    }
  }
  best.distance = std::sqrt(best_d2);
  return best;
}

GeometricAttributes geometric_attributes(const Points& P) {
  require_closed_polygon(P, "geometric_attributes");
  require(edge_lengths(P).minCoeff() > 0.0, "geometric_attributes: zero-length edge");
  GeometricAttributes g;
  g.total_curvature = total_curvature(P);
  g.threedim = threedim(P);
  g.sphericity = sphericity(P);
  g.diameter = diameter(P).distance;
  g.writhe = writhe(P);
  return g;
}

Attributes compute_attributes(const Points& P, const AttributeOptions& options) {
  options.validate();
  Attributes a;
  a.geometric = geometric_attributes(P);
  a.physical.max_stress = max_bending_stress(P, options.radius, options.young_modulus);
  return a;
}

const std::vector<std::string>& attribute_names() {
  static const std::vector<std::string> names = {"total_curvature", "threedim",       "sphericity",  "diameter",
                                                 "writhe",          "max_stress",     "energy",      "energy_stretch",
                                                 "energy_bend",     "energy_twist",   "stiffness"};
  return names;
}

std::optional<double> attribute_value(const Attributes& a, const std::string& name) {
  if (name == "total_curvature") return a.geometric.total_curvature;
  if (name == "threedim") return a.geometric.threedim;
  if (name == "sphericity") return a.geometric.sphericity;
  if (name == "diameter") return a.geometric.diameter;
  if (name == "writhe") return a.geometric.writhe;
  if (name == "max_stress") return a.physical.max_stress;
  if (name == "energy") return a.physical.energy;
  if (name == "energy_stretch") return a.physical.energy_stretch;
  if (name == "energy_bend") return a.physical.energy_bend;
  if (name == "energy_twist") return a.physical.energy_twist;
  if (name == "stiffness") return a.physical.stiffness;
  std::string list;
  for (const auto& n : attribute_names()) list += (list.empty() ? "" : ", ") + n;
  throw InputError("unknown attribute '" + name + "' (known: " + list + ")");
}

}  // namespace ek
