// knots describe (DATASET | LEDGER | LEDGER-FOLDER) [--json] [--states | --summary]
#include <filesystem>
#include <iostream>

#include "args.hpp"
#include "ek/core/errors.hpp"
#include "commands.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/ledger.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_describe(int argc, char** argv) {
  std::string file;
  bool json = false, states = false, summary = false;
  ArgParser args("describe", "(DATASET | LEDGER | FOLDER) [--json] [--states | --summary]");
  args.positional("DATASET", &file,
                  "data-set file, a ledger (knots ledger, knots dataset --ledger), or a folder of ledgers (*.ledger.h5, "
                  "read as one)");
  args.flag("--json", &json, "print one JSON object");
  args.flag("--states", &states, "a ledger: one line per state (members, energy and its spread)");
  args.flag("--summary", &summary,
            "a ledger: its totals and sampling cost as one JSON object (knots describe --json's summary)");
  if (!args.parse(argc, argv)) return 0;
  if (is_ledger_source(file)) {
    const Ledger ledger = read_ledger_source(file);
    if (summary) {
      print_json(ledger_summary_json(ledger));
      return 0;
    }
    if (!json) {
      std::cout << ledger_text(ledger, states);
      return 0;
    }
    Json j;
    j["file"] = file;
    j["summary"] = ledger_summary_json(ledger);
    j.update(ledger_json(ledger));
    print_json(j);
    return 0;
  }
  if (states || summary) throw InputError("--states and --summary describe ledgers; '" + file + "' is a data set");
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
