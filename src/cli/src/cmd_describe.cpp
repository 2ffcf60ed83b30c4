// knots describe (DATASET | LEDGER) [--json] [--states]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/ledger.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_describe(int argc, char** argv) {
  std::string file;
  bool json = false, states = false;
  ArgParser args("describe", "(DATASET | LEDGER) [--json] [--states]");
  args.positional("DATASET", &file, "data-set file, or a ledger (knots ledger, knots dataset --ledger)");
  args.flag("--json", &json, "print one JSON object");
  args.flag("--states", &states, "a ledger: one line per state (members, energy and its spread)");
  if (!args.parse(argc, argv)) return 0;
  if (is_ledger_file(file)) {
    const Ledger ledger = read_ledger(file);
    if (!json) {
      std::cout << ledger_text(ledger, states);
      return 0;
    }
    Json j;
    j["file"] = file;
    j.update(ledger_json(ledger));
    print_json(j);
    return 0;
  }
  DatasetReader reader(file);
  if (json) {
    Json j;
    j["file"] = file;
    j.update(describe_json(reader));
    print_json(j);
    return 0;
  }
  std::cout << reader.metadata().text() << "knots (" << reader.knot_names().size() << "):";
  for (const auto& name : reader.knot_names()) std::cout << " " << name;
  std::cout << "\n";
  return 0;
}

}  // namespace ek::cli
