// knots info NAME [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/table.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_info(int argc, char** argv) {
  std::string name;
  bool json = false;
  ArgParser args("info", "NAME [--json]");
  args.positional("NAME", &name, "knot name as in the table: 3_1, 10_123, 12a_1019, 12n_838, 0_1 (unknot)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;

  const auto& table = KnotTable::global();
  const KnotRecord& k = table.at(name);
  AlexanderPolynomial alex;
  if (k.pd) alex = alexander(*k.pd);
  if (k.braid && alexander(*k.braid) != alex)
    throw std::runtime_error("the table's braid word and PD code of " + k.name +
                             " give different Alexander polynomials");
  auto opt = [](const std::optional<int>& v) { return v ? Json(*v) : Json(nullptr); };
  if (json) {
    Json j;
    j["name"] = k.name;
    j["crossing_number"] = k.crossing_number;
    j["bridge_index"] = opt(k.bridge_index);
    j["braid_index"] = opt(k.braid_index);
    j["unknotting_number"] = opt(k.unknotting_number);
    j["alternating"] = k.alternating ? Json(*k.alternating) : Json(nullptr);
    j["symmetry_type"] = k.symmetry_type;
    j["dt"] = k.dt ? Json(to_string(*k.dt)) : Json(nullptr);
    j["pd"] = k.pd ? Json(to_string(*k.pd)) : Json(nullptr);
    j["braid"] = k.braid ? Json(to_string(*k.braid)) : Json(nullptr);
    j["braid_strands"] = k.braid ? Json(k.braid->strands) : Json(nullptr);
    j["alexander"] = alex.coefficients;
    j["determinant"] = alex.determinant();
    j["table"] = table.path();
    print_json(j);
    return 0;
  }
  auto show = [](const std::optional<int>& v) { return v ? std::to_string(*v) : std::string("?"); };
  std::cout << "name:              " << k.name << "\n"
            << "crossing number:   " << k.crossing_number << "\n"
            << "bridge index:      " << show(k.bridge_index) << "\n"
            << "braid index:       " << show(k.braid_index) << "\n"
            << "unknotting number: " << show(k.unknotting_number) << "\n"
            << "symmetry type:     " << (k.symmetry_type.empty() ? "?" : k.symmetry_type) << "\n"
            << "DT code:           " << (k.dt ? to_string(*k.dt) : "?") << "\n"
            << "PD code:           " << (k.pd ? to_string(*k.pd) : "?") << "\n"
            << "braid word:        " << (k.braid ? to_string(*k.braid) : "?") << "\n"
            << "Alexander:         " << alex.to_string() << "\n"
            << "determinant:       " << alex.determinant() << "\n";
  return 0;
}

}  // namespace ek::cli
