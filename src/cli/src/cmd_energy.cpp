// knots energy FILE [--radius R] [--young E] [--poisson NU] [--link LK] [--rest-length L] [--json]
//
// Elastic energy of a curve as a closed discrete elastic rod (paper Section 6):
// its parts, the gradient norm, twist, writhe and link. Without --link the
// rod is twist-free (Θ free: Tw = 0, Lk = Wr, the centerline-only model);
// with --link the full model with Θ fixed so that Lk = Tw + Wr, the material
// frame spread to uniform twist density (the minimiser of the twisting energy
// for this centerline).
//
// Energy terms are collected in `terms` (key, label, value) and gradients
// summed in `gradient`; the contact barrier adds energy_contact and the count
// of active pairs, "contacts".
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "commands.hpp"
#include "ek/contact/contact_potential.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/relax.hpp"
#include "output.hpp"

namespace ek::cli {

namespace {

struct EnergyTermValue {
  std::string key;    ///< JSON key
  std::string label;  ///< human-readable name
  double value = 0.0;
};

}  // namespace

int cmd_energy(int argc, char** argv) {
  std::string file;
  RodMaterial material;
  std::optional<double> link, rest_length;
  bool json = false;
  ArgParser args("energy", "FILE [--radius R] [--young E] [--poisson NU] [--link LK] [--rest-length L] [--json]");
  args.positional("FILE", &file, "closed curve, .obj (v and l lines) or .txt (x y z per line)");
  args.option("--radius", &material.radius, "wire radius r (default 0.2)");
  args.option("--young", &material.young, "Young's modulus E (default 2000)");
  args.option("--poisson", &material.poisson, "Poisson ratio nu in (-1, 0.5] (default 0.3)");
  args.option("--link", &link,
              "prescribed link Lk: full model with Theta fixed and uniform twist density "
              "(default: twist-free, Tw = 0 and Lk = Wr)");
  args.option("--rest-length", &rest_length,
              "rest length of every edge (default: the curve's own edge lengths, so no stretching)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  material.validate();
  if (rest_length) require_input(*rest_length > 0.0, "--rest-length must be positive");

  const Points P = read_curve(file);
  const int n = static_cast<int>(P.rows());
  const TwistModel model = link ? TwistModel::FixedLink : TwistModel::TwistFree;
  const ElasticRod rod = [&] {
    ElasticRod r = rest_length ? ElasticRod(P, VecX::Constant(n, *rest_length), material, model)
                               : ElasticRod(P, material, model);
    if (link) {
      r.set_link(*link);
      r.relax_twist();
    }
    return r;
  }();

  std::vector<EnergyTermValue> terms = {
      {"energy_stretch", "stretching", rod.energy(EnergyTerm::Stretch)},
      {"energy_bend", "bending", rod.energy(EnergyTerm::Bend)},
      {"energy_twist", "twisting", rod.energy(EnergyTerm::Twist)},
  };
  // Self-contact (paper eq. 1): ω E_contact with d̂ = 2r and ω scaled with E and r
  // exactly as `knots relax` does (1e3 at the paper's material).
  ContactOptions co;
  co.dhat = 2.0 * material.radius;
  co.stiffness = default_contact_stiffness(material);
  ContactPotential contact(CurveTopology::single(n), co);
  contact.update(P);
  terms.push_back({"energy_contact", "contact", contact.energy(P)});
  VecX gradient = rod.gradient();
  contact.add_gradient(P, gradient.head(3 * n));
  double total = 0.0;
  for (const auto& t : terms) total += t.value;
  const double wr = rod.writhe();
  const double tw = rod.twist();

  if (json) {
    Json j;
    j["file"] = file;
    j["vertices"] = n;
    j["model"] = link ? "fixed-link" : "twist-free";
    j["energy"] = number(total);
    for (const auto& t : terms) j[t.key] = number(t.value);
    j["gradient_norm"] = number(gradient.norm());
    j["contacts"] = contact.num_active();
    j["twist"] = number(tw);
    j["writhe"] = number(wr);
    j["link"] = number(tw + wr);
    print_json(j);
    return 0;
  }
  std::cout << "vertices:      " << n << "\n"
            << "model:         " << (link ? "fixed link (Theta fixed, uniform twist)" : "twist-free (Theta free)")
            << "\n"
            << "energy:        " << fmt(total) << "\n";
  for (const auto& t : terms) {
    std::string label = "  " + t.label + ":";
    label.resize(15, ' ');
    std::cout << label << fmt(t.value) << "\n";
  }
  std::cout << "contacts:      " << contact.num_active() << " pairs within " << fmt(co.dhat) << "\n"
            << "gradient norm: " << fmt(gradient.norm()) << "\n"
            << "twist:         " << fmt(tw) << "\n"
            << "writhe:        " << fmt(wr) << "\n"
            << "link:          " << fmt(tw + wr) << "\n";
  return 0;
}

}  // namespace ek::cli
