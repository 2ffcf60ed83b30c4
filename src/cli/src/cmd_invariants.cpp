// knots invariants FILE [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/json.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_invariants(int argc, char** argv) {
  std::string file;
  bool json = false;
  ArgParser args("invariants", "FILE [--json]");
  args.positional("FILE", &file, "closed curve, .obj (v and l lines) or .txt (x y z per line)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;

  const Points P = read_curve(file);
  const CurveInvariants c = curve_invariants(P);
  if (json) {
    Json j;
    j["file"] = file;
    j.update(invariants_json(c));
    print_json(j);
    return 0;
  }
  const AlexanderPolynomial& alex = c.alexander;
  const double wr = c.writhe, tc = c.total_curvature, len = c.length;
  const Clearance& cl = c.clearance;
  std::cout << "vertices:        " << P.rows() << "\n"
            << "length:          " << fmt(len) << "\n"
            << "Alexander:       " << alex.to_string() << "\n"
            << "determinant:     " << alex.determinant() << "\n"
            << "writhe:          " << fmt(wr) << "\n"
            << "total curvature: " << fmt(tc) << " (" << fmt(tc / (2 * M_PI), 6) << " x 2pi)\n"
            << "clearance:       " << fmt(cl.distance) << " (edges " << cl.edge_a << " and " << cl.edge_b << ")\n";
  return 0;
}

}  // namespace ek::cli
