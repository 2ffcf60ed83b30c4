// exp_multistability: the distinct equilibria of 4_1 (paper Fig. 2) and 8_1
// (Fig. 8), and the clustering of 7_7 (Fig. 6). Each knot is sampled and
// relaxed, its equilibria clustered by complete linkage on 1 - similarity and
// cut at kClusterCut (the same cut for every knot); a cluster is one
// distinct equilibrium, represented by its lowest-energy member.
//   ci: 80 samples each; default: 150 each; paper: 500 each (one sampling per
//   data set: the per-knot files are merged, and a merge requires it). The ci
//   scale's 80: 4_1 needs them for the six states of Fig. 2. With run seeds
//   1 to 5 and 80 samples the default method found 7 to 8 distinct states
//   and one-level 6 to 8; with 60, one seed of each found 5, and with 40,
//   seeds 1 to 3 found 4 to 6 (docs/reproducing.md).
// Writes multistability.h5 (a data set), clusters_<knot>.csv, members_<knot>.csv,
// mds_7_7.csv and summary.json (docs/results.md).
#include <algorithm>
#include <iostream>

#include "ek/analysis/clustering.hpp"
#include "ek/analysis/mds.hpp"
#include "ek/dataset/run.hpp"
#include "ek/dataset/states.hpp"
#include "experiment.hpp"
#include "multistability_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_multistability", "Distinct equilibria of 4_1, 8_1 and 7_7.", [](const Args& a) {
    const std::vector<std::string> names = {"4_1", "7_7", "8_1"};
    const int samples = by_scale(a, 80, 150, 500);
    announce(a, "exp_multistability", "4_1, 7_7 and 8_1 with " + std::to_string(samples) + " samples each",
             3.0 * samples * kSecondsPerRelaxation / a.jobs);
    const std::string file = a.out + "/multistability.h5";
    for (const auto& name : names) {
      DatasetRunOptions ro;
      ro.explore = base_options(a);
      ro.explore.samples = samples;
      ro.knots = {&KnotTable::global().at(name)};
      ro.output = a.out + "/" + name + ".h5";
      run_dataset(ro);
    }
    merge_datasets({a.out + "/4_1.h5", a.out + "/7_7.h5", a.out + "/8_1.h5"}, file);
    for (const auto& name : names) std::remove((a.out + "/" + name + ".h5").c_str());
    DatasetReader reader(file);
    results::MultistabilitySummary sum;
    sum.scale = a.scale_name;
    sum.cut = kClusterCut;
    sum.planar_threshold = kPlanarThreedim;
    for (const auto& name : names) {
      const KnotEntry e = reader.read(name);
      std::vector<int> rank_of;
      const auto clusters = clusters_at_cut(e, kClusterCut, &rank_of);
      const int tc = e.attribute_column("total_curvature"), td = e.attribute_column("threedim"),
                sp = e.attribute_column("sphericity");
      Csv csv(a.out + "/clusters_" + name + ".csv",
              {"rank", "size", "energy", "representative", "total_curvature", "threedim", "sphericity"});
      const int three_d = count_3d_states(e, clusters, kPlanarThreedim);
      for (size_t c = 0; c < clusters.size(); ++c) {
        const int r = clusters[c].representative;
        csv.row({std::to_string(c), std::to_string(clusters[c].members.size()), Csv::num(clusters[c].energy_min),
                 std::to_string(r), Csv::num(e.attributes(r, tc)), Csv::num(e.attributes(r, td)),
                 Csv::num(e.attributes(r, sp))});
      }
      csv.commit();
      // Members (for figures: every equilibrium's cluster rank) and, for the
      // Fig. 6 knot, the 2D multidimensional scaling and the dendrogram order.
      Csv members(a.out + "/members_" + name + ".csv", {"equilibrium", "cluster_rank", "energy"});
      for (size_t i = 0; i < rank_of.size(); ++i)
        members.row({std::to_string(i), std::to_string(rank_of[i]),
                     Csv::num(e.attributes(static_cast<Eigen::Index>(i), e.attribute_column("energy")))});
      members.commit();
      if (name == "7_7" && e.equilibria.size() > 2) {
        const MdsResult mds = classical_mds_from_similarity(e.similarity);
        const std::vector<int> order = Dendrogram::from_linkage(e.linkage).leaf_order();
        Csv out(a.out + "/mds_" + name + ".csv", {"equilibrium", "x", "y", "cluster_rank", "leaf_position"});
        std::vector<int> position(order.size());
        for (size_t p = 0; p < order.size(); ++p) position[static_cast<size_t>(order[p])] = static_cast<int>(p);
        for (size_t i = 0; i < e.equilibria.size(); ++i)
          out.row({std::to_string(i), Csv::num(mds.coordinates(static_cast<Eigen::Index>(i), 0)),
                   Csv::num(mds.coordinates(static_cast<Eigen::Index>(i), 1)), std::to_string(rank_of[i]),
                   std::to_string(position[i])});
        out.commit();
      }
      results::KnotStates& k = sum.knots[name];
      k.samples = static_cast<long>(e.runs.size());
      k.equilibria = static_cast<long>(e.equilibria.size());
      k.distinct = static_cast<int>(clusters.size());
      k.distinctly_3d = three_d;
      k.distinctly_3d_share = clusters.empty() ? 0.0 : static_cast<double>(three_d) / static_cast<double>(clusters.size());
      std::cout << "exp_multistability: " << name << ": " << e.equilibria.size() << " equilibria, "
                << clusters.size() << " distinct at cut " << kClusterCut << " (" << three_d << " 3D)" << std::endl;
    }
    write_summary(a, sum);
  });
}
