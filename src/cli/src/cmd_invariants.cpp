// knots invariants FILE [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/json.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

/// A link's invariants: each component's, the linking numbers, the Conway
/// polynomial and |μ̄(123)|, the clearance between components.
int print_link(const std::string& file, const LinkInvariants& l, bool json) {
  if (json) {
    Json j;
    j["file"] = file;
    j.update(link_invariants_json(l));
    print_json(j);
    return 0;
  }
  std::cout << "components:      " << l.components.size() << "\n";
  for (size_t k = 0; k < l.components.size(); ++k) {
    const CurveInvariants& c = l.components[k];
    std::cout << "component " << k + 1 << ":     " << c.vertices << " vertices, length " << fmt(c.length)
              << ", Alexander " << c.alexander.to_string() << ", writhe " << fmt(c.writhe) << "\n";
  }
  std::cout << "linking numbers: " << matrix_rows(l.linking_numbers, std::string(17, ' '))
            << " (largest distance of the Gauss sums to integers " << fmt(l.linking_error, 2) << ")\n"
            << "Conway:          " << l.conway.to_string() << " (coefficients of z^0, z^1, ...; [] for a split link)\n";
  if (l.milnor_triple) std::cout << "Milnor |mu(123)|: " << *l.milnor_triple << "\n";
  std::cout << "clearance between components: " << fmt(l.component_clearance) << "\n";
  return 0;
}

}  // namespace

int cmd_invariants(int argc, char** argv) {
  std::string file;
  bool json = false;
  ArgParser args("invariants", "FILE [--json]");
  args.positional("FILE", &file,
                  "closed curve or link, .obj (v and l lines, one l loop per component) or .txt (x y z per line, "
                  "a blank line between components)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;

  const Link link = read_link(file);
  if (link.size() > 1) return print_link(file, link_invariants(link), json);
  const Points& P = link[0];
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
