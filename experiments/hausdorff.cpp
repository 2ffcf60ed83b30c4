// exp_hausdorff: why the similarity measure and not the Hausdorff distance
// (paper Section 7.1, Fig. 5). 6_1 is sampled and relaxed as in
// exp_multistability; for every pair of its equilibria, the Hausdorff
// distance between the polygons after the rigid alignment of the
// cross-topology search (ek::align_curves) and the similarity distance
// 1 - similarity. Pairs in different clusters (distinct states at
// kClusterCut) whose Hausdorff distance is below the median of the
// same-cluster pairs are states that the similarity separates and the
// Hausdorff distance does not (ek::hausdorff_separation); counted also for
// the stricter "distinct" pairs (different clusters and themselves farther
// apart than the cut in similarity), from which the figure's pairs come.
// Both counts are taken over all equilibria and over the unique ones (an
// equilibrium reached by several samples counted once).
//   ci: 40 samples; default: 150; paper: 500.
// Writes hausdorff.h5 (a data set holding 6_1), pairs.csv, curves/ (the shown
// pairs, the second state aligned onto the first) and summary.json
// (docs/results.md).
#include <cmath>
#include <filesystem>
#include <iostream>

#include "ek/dataset/run.hpp"
#include "ek/dataset/states.hpp"
#include "ek/geometry/curve_io.hpp"
#include "experiment.hpp"
#include "hausdorff_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_hausdorff", "Hausdorff distance against similarity on 6_1.", [](const Args& a) {
    const std::string knot = "6_1";
    const int samples = by_scale(a, 40, 150, 500);
    const double pairs_estimate = 0.5 * samples * samples * 0.04;  // [s] ~40 ms per pair (docs/reproducing.md)
    announce(a, "exp_hausdorff", knot + " with " + std::to_string(samples) + " samples, every pair aligned",
             (samples * kSecondsPerRelaxation + pairs_estimate) / a.jobs);
    DatasetRunOptions ro;
    ro.explore = base_options(a);
    ro.explore.samples = samples;
    ro.knots = {&KnotTable::global().at(knot)};
    ro.output = a.out + "/hausdorff.h5";
    run_dataset(ro);
    const KnotEntry e = DatasetReader(ro.output).read(knot);
    const std::vector<StatePair> pairs = pairwise_shape_distances(e, kClusterCut, {}, a.jobs);
    const int ec = e.attribute_column("energy");
    Csv csv(a.out + "/pairs.csv", {"a", "b", "cluster_a", "cluster_b", "same_cluster", "hausdorff",
                                   "similarity_distance", "icp_distance"});
    for (const StatePair& p : pairs)
      csv.row({std::to_string(p.a), std::to_string(p.b), std::to_string(p.cluster_a), std::to_string(p.cluster_b),
               Csv::flag(p.same_cluster()), Csv::num(p.hausdorff), Csv::num(p.similarity_distance),
               Csv::num(p.icp_distance)});
    csv.commit();
    const HausdorffSeparation sep = hausdorff_separation(pairs, kClusterCut);
    results::HausdorffSummary sum;
    sum.scale = a.scale_name;
    sum.knot = knot;
    sum.cut = kClusterCut;
    sum.samples = static_cast<long>(e.runs.size());
    sum.equilibria = static_cast<long>(e.equilibria.size());
    sum.clusters = static_cast<int>(clusters_at_cut(e, kClusterCut).size());
    sum.pairs = static_cast<long>(pairs.size());
    sum.same_cluster_pairs = sep.same_cluster_pairs;
    if (sep.same_cluster_pairs > 0) sum.median_same_cluster_hausdorff = sep.median_same_cluster_hausdorff;
    sum.different_cluster_pairs = sep.different_cluster_pairs;
    sum.below_median_pairs = sep.below_median_pairs;
    sum.distinct_pairs = sep.distinct_pairs;
    sum.separated_pairs = sep.separated_pairs;
    sum.identical_hausdorff = kIdenticalHausdorff;
    sum.identical_pairs = sep.identical_pairs;
    sum.unique_equilibria = sep.unique_equilibria;
    sum.unique_same_cluster_pairs = sep.unique_same_cluster_pairs;
    if (sep.unique_same_cluster_pairs > 0)
      sum.median_unique_same_cluster_hausdorff = sep.median_unique_same_cluster_hausdorff;
    sum.unique_different_cluster_pairs = sep.unique_different_cluster_pairs;
    sum.below_unique_median_pairs = sep.below_unique_median_pairs;
    sum.separated_below_unique_median = sep.separated_below_unique_median;
    std::filesystem::create_directories(a.out + "/curves");
    for (const StatePair& p : closest_distinct_pairs(pairs, kClusterCut, 3)) {
      const Points& A = e.equilibria[static_cast<size_t>(p.a)];
      const Points& B = e.equilibria[static_cast<size_t>(p.b)];
      results::HausdorffPair h{p.a, p.b, p.cluster_a, p.cluster_b, p.hausdorff, p.similarity_distance,
                               p.icp_distance, e.attributes(p.a, ec), e.attributes(p.b, ec),
                               "curves/" + knot + "_" + std::to_string(p.a) + ".obj",
                               "curves/" + knot + "_" + std::to_string(p.b) + "_on_" + std::to_string(p.a) + ".obj"};
      write_curve(a.out + "/" + h.curve_a, A);
      write_curve(a.out + "/" + h.curve_b, aligned_candidate(B, align_curves(A, B)));
      sum.shown.push_back(h);
    }
    write_summary(a, sum);
    std::cout << "exp_hausdorff: " << knot << ": " << e.equilibria.size() << " equilibria, " << sum.clusters
              << " clusters, " << pairs.size() << " pairs; median same-cluster Hausdorff "
              << sep.median_same_cluster_hausdorff << "; below it: " << sep.below_median_pairs << " of "
              << sep.different_cluster_pairs << " pairs of different clusters, " << sep.separated_pairs << " of "
              << sep.distinct_pairs << " also farther apart than the cut in similarity; " << sep.unique_equilibria
              << " unique equilibria (" << sep.identical_pairs << " identical pairs), median same-cluster Hausdorff "
              << sep.median_unique_same_cluster_hausdorff << ", below it: " << sep.below_unique_median_pairs << " of "
              << sep.unique_different_cluster_pairs << " pairs of different clusters, "
              << sep.separated_below_unique_median << " also farther apart than the cut" << std::endl;
  });
}
