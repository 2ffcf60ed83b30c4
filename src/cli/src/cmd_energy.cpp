// knots energy FILE [--radius R] [--young E] [--poisson NU] [--link LK] [--rest-length L] [--json]
//
// Elastic and contact energy of a curve as a closed discrete elastic rod
// (paper Section 6; ek::curve_energy, solver/energy.hpp): its parts, the
// gradient norm, twist, writhe and link.
#include <iostream>
#include <optional>
#include <string>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/solver/energy.hpp"
#include "ek/solver/json.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_energy(int argc, char** argv) {
  std::string file;
  CurveEnergyOptions opt;
  bool json = false;
  ArgParser args("energy", "FILE [--radius R] [--young E] [--poisson NU] [--link LK] [--rest-length L] [--json]");
  args.positional("FILE", &file, "closed curve, .obj (v and l lines) or .txt (x y z per line)");
  args.option("--radius", &opt.material.radius, "wire radius r (default 0.2)");
  args.option("--young", &opt.material.young, "Young's modulus E (default 2000)");
  args.option("--poisson", &opt.material.poisson, "Poisson ratio nu in (-1, 0.5] (default 0.3)");
  args.option("--link", &opt.link,
              "prescribed link Lk: full model with Theta fixed and uniform twist density "
              "(default: twist-free, Tw = 0 and Lk = Wr)");
  args.option("--rest-length", &opt.rest_length,
              "rest length of every edge (default: the curve's own edge lengths, so no stretching)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  opt.validate();

  const CurveEnergy e = curve_energy(read_curve(file), opt);
  if (json) {
    Json j;
    j["file"] = file;
    j.update(curve_energy_json(e));
    print_json(j);
    return 0;
  }
  std::cout << "vertices:      " << e.vertices << "\n"
            << "model:         " << (opt.link ? "fixed link (Theta fixed, uniform twist)" : "twist-free (Theta free)")
            << "\n"
            << "energy:        " << fmt(e.energy.total) << "\n"
            << "  stretching:  " << fmt(e.energy.stretch) << "\n"
            << "  bending:     " << fmt(e.energy.bend) << "\n"
            << "  twisting:    " << fmt(e.energy.twist) << "\n"
            << "  contact:     " << fmt(e.energy.contact) << "\n"
            << "contacts:      " << e.contacts << " pairs within " << fmt(2.0 * opt.material.radius) << "\n"
            << "gradient norm: " << fmt(e.gradient_norm) << "\n"
            << "twist:         " << fmt(e.twist) << "\n"
            << "writhe:        " << fmt(e.writhe) << "\n"
            << "link:          " << fmt(e.link) << "\n";
  return 0;
}

}  // namespace ek::cli
