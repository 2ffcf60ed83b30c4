// knots cluster DATASET NAME --cut C [--json]
#include <algorithm>
#include <iostream>
#include <map>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/pipeline.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_cluster(int argc, char** argv) {
  std::string file, name;
  std::optional<double> cut;
  bool json = false;
  ArgParser args("cluster", "DATASET NAME --cut C [--json]");
  args.positional("DATASET", &file, "data-set file");
  args.positional("NAME", &name, "knot name");
  args.option("--cut", &cut, "distance threshold in 1 - similarity, in [0, 1] (merges at or below it are joined)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  if (!cut) throw InputError("missing --cut C");
  if (*cut < 0.0 || *cut > 1.0) throw InputError("--cut must be in [0, 1]");
  DatasetReader reader(file);
  const KnotEntry e = reader.read(name);
  const int m = static_cast<int>(e.equilibria.size());
  const std::vector<StateCluster> clusters = clusters_at_cut(e, *cut);
  const int k = static_cast<int>(clusters.size());
  if (json) {
    print_json(entry_clusters_json(e, *cut));
    return 0;
  }
  std::cout << name << ": " << m << " equilibria in " << k << " clusters at cut " << *cut << " (sorted by energy)\n"
            << "  " << entry_unseen_text(e, *cut) << "\n";
  for (size_t c = 0; c < clusters.size(); ++c)
    std::cout << "  cluster " << c << ": " << clusters[c].members.size() << " members, energy "
              << fmt(clusters[c].energy_min, 6) << " .. " << fmt(clusters[c].energy_max, 6) << ", representative "
              << clusters[c].representative << "\n";
  return 0;
}

}  // namespace ek::cli
