// knots ledger INPUT... -o OUT.ledger.h5 [--cut C] [--curves K] [--json]
// A ledger (docs/dataset-format.md, "Ledgers") of data sets, or ledgers
// merged: each input is a data set (its states at the cut) or a ledger.
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/ledger.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_ledger(int argc, char** argv) {
  std::string first, out;
  std::vector<std::string> rest;
  std::optional<double> cut;
  int curves = LedgerProvenance{}.curves_per_knot;
  bool json = false;
  ArgParser args("ledger", "INPUT ... -o OUT.ledger.h5 [--cut C] [--curves K] [--json]");
  args.positional("INPUT", &first, "a data set (its states at the cut) or a ledger");
  args.rest("...", &rest, "further data sets or ledgers (same parameters and cut; each knot in one of them)");
  args.option("-o,--output", &out, "the ledger to write (written atomically)");
  args.option("--cut", &cut, "[1] the states' cut in 1 - similarity for data-set inputs (default 0.05, the "
                             "experiments'); a ledger input keeps its own");
  args.option("--curves", &curves,
              "curves kept per knot for data-set inputs: those of its lowest-energy states (default 16)");
  args.flag("--json", &json, "print the written ledger as knots describe --json does");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o OUT.ledger.h5");
  if (cut && !(*cut > 0.0 && *cut < 1.0)) throw InputError("--cut must be in (0, 1)");
  if (curves < 0) throw InputError("--curves must be 0 or more");
  std::vector<std::string> inputs{first};
  inputs.insert(inputs.end(), rest.begin(), rest.end());
  std::vector<Ledger> parts;
  for (const std::string& in : inputs) {
    if (is_ledger_file(in)) {
      parts.push_back(read_ledger(in));
      continue;
    }
    LedgerProvenance p;
    p.cut = cut.value_or(p.cut);
    p.curves_per_knot = curves;
    p.created = now_iso8601();
    p.source = "knots ledger " + in;
    parts.push_back(ledger_of_dataset(in, p));
  }
  Ledger ledger = parts.size() == 1 ? parts.front() : merge_ledgers(parts);
  if (ledger.provenance.created.empty()) ledger.provenance.created = now_iso8601();
  write_ledger(out, ledger);
  if (json) {
    Json j;
    j["file"] = out;
    j.update(ledger_json(ledger));
    print_json(j);
  } else {
    int states = 0;
    for (const LedgerEntry& e : ledger.entries) states += static_cast<int>(e.states.size());
    std::cout << "ledger " << out << ": " << ledger.entries.size() << " knots, " << states << " states at cut "
              << ledger.provenance.cut << "\n";
  }
  return 0;
}

}  // namespace ek::cli
