// knots cluster DATASET NAME --cut C [--json]
#include <algorithm>
#include <iostream>
#include <map>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
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
  std::vector<int> labels(static_cast<size_t>(m), 0);
  if (m > 1) {
    Dendrogram d;
    d.leaves = m;
    for (Eigen::Index k = 0; k < e.linkage.rows(); ++k)
      d.merges.push_back({static_cast<int>(e.linkage(k, 0)), static_cast<int>(e.linkage(k, 1)), e.linkage(k, 2),
                          static_cast<int>(e.linkage(k, 3))});
    labels = cut_dendrogram(d, *cut);
  }
  const int energy_col = e.attribute_column("energy");
  const int k = m == 0 ? 0 : 1 + *std::max_element(labels.begin(), labels.end());
  struct Cluster {
    std::vector<int> members;
    int representative = -1;
    double emin = 0, emax = 0;
  };
  std::vector<Cluster> clusters(static_cast<size_t>(k));
  for (int i = 0; i < m; ++i) {
    Cluster& c = clusters[static_cast<size_t>(labels[static_cast<size_t>(i)])];
    const double E = e.attributes(i, energy_col);
    if (c.members.empty() || E < c.emin) {
      c.emin = E;
      c.representative = i;
    }
    if (c.members.empty() || E > c.emax) c.emax = E;
    c.members.push_back(i);
  }
  std::sort(clusters.begin(), clusters.end(), [](const Cluster& a, const Cluster& b) { return a.emin < b.emin; });
  if (json) {
    Json j;
    j["name"] = name;
    j["cut"] = *cut;
    j["equilibria"] = m;
    j["clusters"] = Json::array();
    for (const auto& c : clusters) {
      Json cj;
      cj["size"] = c.members.size();
      cj["representative"] = c.representative;
      cj["energy_min"] = number(c.emin);
      cj["energy_max"] = number(c.emax);
      cj["members"] = c.members;
      j["clusters"].push_back(cj);
    }
    print_json(j);
    return 0;
  }
  std::cout << name << ": " << m << " equilibria in " << k << " clusters at cut " << *cut << " (sorted by energy)\n";
  for (size_t c = 0; c < clusters.size(); ++c)
    std::cout << "  cluster " << c << ": " << clusters[c].members.size() << " members, energy "
              << fmt(clusters[c].emin, 6) << " .. " << fmt(clusters[c].emax, 6) << ", representative "
              << clusters[c].representative << "\n";
  return 0;
}

}  // namespace ek::cli
