// knots merge A.h5 B.h5 ... -o ALL.h5 (data sets, or ledgers)
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/run.hpp"

namespace ek::cli {

int cmd_merge(int argc, char** argv) {
  std::string first, out;
  std::vector<std::string> rest;
  ArgParser args("merge", "A.h5 B.h5 ... -o ALL.h5");
  args.positional("A.h5", &first,
                  "data sets to merge (same parameters; each knot in one of them), or ledgers (same cut too)");
  args.rest("B.h5 ...", &rest, "further data sets");
  args.option("-o,--output", &out, "merged data set (written atomically)");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o ALL.h5");
  std::vector<std::string> inputs{first};
  inputs.insert(inputs.end(), rest.begin(), rest.end());
  if (is_ledger_file(first)) {
    std::vector<Ledger> ledgers;
    for (const std::string& in : inputs) {
      if (!is_ledger_file(in)) throw InputError("'" + in + "' is a data set, the other inputs ledgers: merge one kind");
      ledgers.push_back(read_ledger(in));
    }
    write_ledger(out, merge_ledgers(ledgers));
    std::cout << "merged " << inputs.size() << " ledgers into " << out << "\n";
    return 0;
  }
  merge_datasets(inputs, out);
  std::cout << "merged " << inputs.size() << " data sets into " << out << "\n";
  return 0;
}

}  // namespace ek::cli
