// knots attributes FILE [--radius R] [--young E] [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/attributes.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_attributes(int argc, char** argv) {
  std::string file;
  bool json = false;
  AttributeOptions material;
  ArgParser args("attributes", "FILE [--radius R] [--young E] [--json]");
  args.positional("FILE", &file, "closed curve, .obj (v and l lines) or .txt (x y z per line)");
  args.option("--radius", &material.radius, "wire radius r for the stress (default 0.2)");
  args.option("--young", &material.young_modulus, "Young's modulus E for the stress (default 2000)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  require_input(std::isfinite(material.radius) && material.radius > 0.0, "--radius must be positive");
  require_input(std::isfinite(material.young_modulus) && material.young_modulus > 0.0, "--young must be positive");

  const Points P = read_curve(file);
  const Attributes a = compute_attributes(P, material);
  // The rod-dependent attributes (energy, energy_stretch, energy_bend,
  // energy_twist) and the solver's stiffness are not computed yet: they stay
  // unset (JSON null) until the rod and solver modules exist; then fill
  // a.physical here (e.g. from the rod energy of P with this material, and the
  // smallest positive eigenvalue of the full Hessian) before printing.
  if (json) {
    Json j;
    j["file"] = file;
    j["vertices"] = P.rows();
    for (const std::string& name : attribute_names()) {
      const std::optional<double> v = attribute_value(a, name);
      j[name] = v ? number(*v) : Json(nullptr);
    }
    j["radius"] = number(material.radius);
    j["young_modulus"] = number(material.young_modulus);
    print_json(j);
    return 0;
  }
  std::cout << "vertices:        " << P.rows() << "\n";
  for (const std::string& name : attribute_names()) {
    std::string label = name + ":";
    label.resize(17, ' ');
    const std::optional<double> v = attribute_value(a, name);
    std::cout << label << (v ? fmt(*v) : std::string("n/a (needs the rod and solver modules)")) << "\n";
  }
  std::cout << "material:        r = " << fmt(material.radius) << ", E = " << fmt(material.young_modulus) << "\n";
  return 0;
}

}  // namespace ek::cli
