// knots info NAME [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/knots/json.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/table.hpp"
#include "output.hpp"

namespace ek::cli {

namespace {

/// A link of the link table.
int print_link(const LinkRecord& l, bool json) {
  if (json) {
    print_json(link_info_json(l));
    return 0;
  }
  std::string aliases, types;
  for (const std::string& a : l.aliases) aliases += (aliases.empty() ? "" : ", ") + a;
  for (const std::string& t : l.component_types) types += (types.empty() ? "" : ", ") + t;
  std::cout << "name:              " << l.name << (aliases.empty() ? "" : " (" + aliases + ")") << "\n"
            << "link:              " << l.description << "\n"
            << "components:        " << l.components() << " (" << types << ")\n"
            << "crossing number:   " << l.crossing_number << "\n"
            << "braid word:        " << to_string(l.braid) << "\n"
            << "PD code:           " << to_string(l.pd().code) << " (of the braid's closure)\n"
            << "linking numbers:   " << matrix_rows(l.linking_matrix(), std::string(19, ' ')) << "\n"
            << "Conway:            " << l.conway.to_string() << " (coefficients of z^0, z^1, ...)\n";
  if (const auto mu = l.milnor_triple()) std::cout << "Milnor |mu(123)|:  " << *mu << "\n";
  return 0;
}

}  // namespace

int cmd_info(int argc, char** argv) {
  std::string name;
  bool json = false;
  ArgParser args("info", "NAME [--json]");
  std::string links;
  for (const LinkRecord& l : link_table()) links += (links.empty() ? "" : ", ") + l.name;
  args.positional("NAME", &name,
                  "knot name as in the table: 3_1, 10_123, 12a_1019, 12n_838, 0_1 (unknot); or a link of the "
                  "built-in link table: " + links + " (or an alias: L2a1, ...)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;

  if (const LinkRecord* link = find_link(name)) return print_link(*link, json);
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
