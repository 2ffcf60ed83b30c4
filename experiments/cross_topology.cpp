// exp_cross_topology: cross-topology analysis (paper Section 8.2, Fig. 10).
// Query states: the most 3D distinct state (cluster representative of largest
// 3D-ness at kClusterCut) of 4_1, 7_7 and 8_1 from the multistability
// experiment. For each, the equilibria of the other knot types in the data
// set closest in shape: pre-filter on 3D-ness and diameter, ICP alignment,
// ranked by distance (ek::search_dataset, the search of `knots search`).
// Reads ../multistability/multistability.h5 and ../dataset/dataset.h5.
//   every scale: the data sets of that scale, 6 hits per query.
// Writes hits.csv, curves/query_<knot>.obj (the stored query curve),
// curves/<knot>_hit<rank>.obj (each hit aligned onto its query) and
// summary.json (docs/results.md).
#include <filesystem>
#include <iostream>

#include "cross_topology_summary.hpp"
#include "ek/dataset/dataset_search.hpp"
#include "ek/dataset/states.hpp"
#include "ek/geometry/curve_io.hpp"
#include "experiment.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_cross_topology", "Cross-topology search (Fig. 10).", [](const Args& a) {
    const std::vector<std::string> query_knots = {"4_1", "7_7", "8_1"};
    const DatasetReader states(a.results + "/multistability/multistability.h5");
    const DatasetReader data(a.results + "/dataset/dataset.h5");
    long total = 0;
    for (const auto& name : data.knot_names()) total += static_cast<long>(data.read(name).equilibria.size());
    announce(a, "exp_cross_topology", std::to_string(query_knots.size()) + " queries against " +
                                          std::to_string(total) + " equilibria (pre-filtered)",
             query_knots.size() * total * 0.01 / a.jobs);  // ~10 ms per alignment, at most all of them
    DatasetSearchOptions o;
    o.max_results = 6;
    o.jobs = a.jobs;
    results::CrossTopologySummary sum;
    sum.scale = a.scale_name;
    sum.dataset = "dataset/dataset.h5";
    sum.limit = o.max_results;
    sum.filter_attributes = o.filter_attributes;
    sum.filter_relative_width = o.filter_relative_width;
    sum.filter_absolute_width = o.filter_absolute_width;
    std::filesystem::create_directories(a.out + "/curves");
    Csv csv(a.out + "/hits.csv", {"query", "rank", "knot", "index", "distance", "energy", "threedim", "curve"});
    for (const std::string& knot : query_knots) {
      const KnotEntry e = states.read(knot);
      const int td = e.attribute_column("threedim"), ec = e.attribute_column("energy");
      int best = -1;
      for (const StateCluster& c : clusters_at_cut(e, kClusterCut))
        if (best < 0 || e.attributes(c.representative, td) > e.attributes(best, td)) best = c.representative;
      if (best < 0) continue;
      results::CrossTopologyQuery q;
      q.knot = knot;
      q.equilibrium = best;
      q.energy = e.attributes(best, ec);
      q.threedim = e.attributes(best, td);
      q.curve = "curves/query_" + knot + ".obj";
      const Points& query = e.equilibria[static_cast<size_t>(best)];
      write_curve(a.out + "/" + q.curve, query);
      o.exclude_knots = {knot};
      const DatasetSearchResult r = search_dataset(data, query, o);
      q.searched = r.searched;
      q.aligned = r.aligned;
      for (size_t k = 0; k < r.hits.size(); ++k) {
        const DatasetHit& h = r.hits[k];
        const KnotEntry he = data.read(h.knot);
        results::CrossTopologyHit x;
        x.rank = static_cast<int>(k) + 1;
        x.knot = h.knot;
        x.index = h.equilibrium;
        x.distance = h.distance;
        x.energy = he.attributes(h.equilibrium, he.attribute_column("energy"));
        x.threedim = he.attributes(h.equilibrium, he.attribute_column("threedim"));
        x.curve = "curves/" + knot + "_hit" + std::to_string(x.rank) + ".obj";
        write_curve(a.out + "/" + x.curve, aligned_candidate(he.equilibria[static_cast<size_t>(h.equilibrium)], h.alignment));
        csv.row({knot, std::to_string(x.rank), x.knot, std::to_string(x.index), Csv::num(x.distance),
                 Csv::num(x.energy), Csv::num(x.threedim), x.curve});
        q.hits.push_back(x);
      }
      std::cout << "exp_cross_topology: " << knot << " #" << best << " (3D-ness " << q.threedim << "): " << q.aligned
                << " of " << q.searched << " aligned; closest "
                << (q.hits.empty() ? std::string("none") : q.hits[0].knot + " at " + std::to_string(q.hits[0].distance))
                << std::endl;
      sum.queries.push_back(q);
    }
    csv.commit();
    write_summary(a, sum);
  });
}
