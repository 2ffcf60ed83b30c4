// knots info NAME [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/knots/json.hpp"
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
  if (json) {
    print_json(knot_info_json(k, table));
    return 0;
  }
  const AlexanderPolynomial alex = table_alexander(k);
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
