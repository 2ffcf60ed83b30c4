// knots query (DATASET | LEDGER | FOLDER) [--knot NAME] [--sort ATTR[:asc|desc]] [--where 'ATTR<VALUE' ...] [--limit K] [--json]
#include <algorithm>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/query.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_query(int argc, char** argv) {
  std::string file;
  QueryOptions q;
  bool json = false;
  ArgParser args("query", "(DATASET | LEDGER | FOLDER) [--knot NAME] [--sort ATTR[:asc|desc]] [--where 'ATTR<VALUE' ...] [--limit K] [--json]");
  args.positional("DATASET", &file, "data-set file, a ledger, or a folder of ledgers (*.ledger.h5, read as one)");
  args.option("--knot", &q.knot, "only this knot type");
  args.option("--sort", &q.sort, "sort by an attribute, ascending (default) or :desc");
  args.option("--where", &q.where, "keep equilibria with ATTR<VALUE (also <=, >, >=, =, !=); repeatable");
  args.option("--limit", &q.limit, "print at most K rows");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  const QueryResult result =
      is_ledger_source(file) ? query_ledger(read_ledger_source(file), q) : query_dataset(DatasetReader(file), q);
  if (json) {
    print_json(query_json(result));
    return 0;
  }
  std::cout << "knot        index";
  for (const auto& c : result.columns) std::cout << " " << c;
  std::cout << "\n";
  for (const auto& r : result.rows) {
    std::string k = r.knot;
    k.resize(std::max<size_t>(k.size(), 11), ' ');
    std::cout << k << " " << r.index;
    for (double v : r.values) std::cout << " " << fmt(v, 6);
    std::cout << "\n";
  }
  std::cout << result.rows.size() << " equilibria\n";
  return 0;
}

}  // namespace ek::cli
