// knots search DATASET QUERY.obj [--limit K] [--exclude-knot NAME ...] [--knot NAME ...] [--no-filter] [--jobs J] [--json]
//
// Cross-topology search (paper Section 8.2, Fig. 10): the data set's
// equilibria geometrically closest to a query curve, by ICP alignment after a
// pre-filter on 3D-ness and diameter (ek::search_dataset, docs/cli.md).
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_search.hpp"
#include "ek/geometry/curve_io.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_search(int argc, char** argv) {
  std::string file, query_file;
  int limit = 10, jobs = 1;
  std::vector<std::string> exclude, only;
  bool no_filter = false, mirror = false, json = false;
  ArgParser args("search", "DATASET QUERY.obj [--limit K] [--exclude-knot NAME ...] [--knot NAME ...] [--no-filter] "
                           "[--mirror] [--jobs J] [--json]");
  args.positional("DATASET", &file, "data-set file");
  args.positional("QUERY", &query_file, "query curve (.obj or .txt), closed polygon");
  args.option("--limit", &limit, "print the K closest equilibria (default 10; 0: all that pass the pre-filter)");
  args.option("--exclude-knot", &exclude, "do not search this knot type (repeatable), e.g. the query's own");
  args.option("--knot", &only, "search only this knot type (repeatable)");
  args.flag("--no-filter", &no_filter, "align every equilibrium (no pre-filter on 3D-ness and diameter)");
  args.flag("--mirror", &mirror, "also align mirror images");
  args.option("--jobs", &jobs, "alignments in parallel (default 1; the ranking does not depend on it)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  DatasetSearchOptions o;
  o.max_results = limit;
  o.exclude_knots = exclude;
  o.only_knots = only;
  o.jobs = jobs;
  o.alignment.mirror = mirror;
  if (no_filter) o.filter_attributes.clear();
  o.validate();
  const Points query = read_curve(query_file);
  const DatasetReader reader(file);
  const DatasetSearchResult r = search_dataset(reader, query, o);
  if (json) {
    Json j;
    j["dataset"] = file;
    j["query"] = query_file;
    j["searched"] = r.searched;
    j["aligned"] = r.aligned;
    j["hits"] = Json::array();
    for (size_t k = 0; k < r.hits.size(); ++k) {
      const DatasetHit& h = r.hits[k];
      Json hj;
      hj["rank"] = k + 1;
      hj["knot"] = h.knot;
      hj["index"] = h.equilibrium;
      hj["distance"] = number(h.distance);
      hj["reversed"] = h.alignment.reversed;
      hj["mirrored"] = h.alignment.mirrored;
      j["hits"].push_back(hj);
    }
    j["count"] = r.hits.size();
    print_json(j);
    return 0;
  }
  std::cout << "rank knot        index distance\n";
  for (size_t k = 0; k < r.hits.size(); ++k) {
    std::string name = r.hits[k].knot;
    name.resize(std::max<size_t>(name.size(), 11), ' ');
    std::cout << k + 1 << " " << name << " " << r.hits[k].equilibrium << " " << fmt(r.hits[k].distance, 6) << "\n";
  }
  std::cout << r.hits.size() << " of " << r.aligned << " aligned equilibria (" << r.searched << " searched)\n";
  return 0;
}

}  // namespace ek::cli
