// knots attributes FILE [--radius R] [--young E] [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/json.hpp"
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
  material.validate();

  const Points P = read_curve(file);
  const Attributes a = compute_attributes(P, material);
  if (json) {
    Json j;
    j["file"] = file;
    j.update(attributes_json(a, static_cast<int>(P.rows()), material));
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
