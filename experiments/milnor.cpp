// exp_milnor: Milnor's bound (paper Section 8.2, Fig. 9). For each knot type
// of the data set, the equilibrium of smallest total curvature divided by
// 2π·bridge index. Writes milnor.csv (one row per knot) and summary.json with
// the measured quantities behind the paper's claims:
//  - every equilibrium has total curvature above 2π·bridge index (Milnor 1950);
//  - BB knots (bridge index = braid index) reach the bound (ratio within 3%)
//    with a multi-covered circle (3D-ness below the planarity threshold);
//  - the knots farthest from the bound are 2-bridge knots.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "ek/dataset/dataset_file.hpp"
#include "experiment.hpp"
#include "milnor_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_milnor", "Milnor-bound ratios of the data set (reads ../dataset/dataset.h5).", [](const Args& a) {
    const std::string in = a.results + "/dataset/dataset.h5";
    announce(a, "exp_milnor", "analyse " + in, 5.0);
    DatasetReader reader(in);
    Csv csv(a.out + "/milnor.csv", {"knot", "crossing_number", "bridge_index", "braid_index", "bb", "two_bridge",
                                    "equilibria", "min_total_curvature", "ratio", "threedim_at_min", "violations"});
    struct Row {
      std::string name;
      int bridge, braid;
      double ratio, threedim;
    };
    std::vector<Row> rows;
    int violations = 0, equilibria = 0;
    for (const auto& name : reader.knot_names()) {
      const KnotEntry e = reader.read(name);
      if (e.equilibria.empty() || e.bridge_index < 1) continue;
      const int tc = e.attribute_column("total_curvature"), td = e.attribute_column("threedim");
      Eigen::Index best = 0;
      e.attributes.col(tc).minCoeff(&best);
      const double bound = 2.0 * M_PI * e.bridge_index;
      int v = 0;
      for (Eigen::Index i = 0; i < e.attributes.rows(); ++i)
        if (!(e.attributes(i, tc) > bound)) ++v;
      violations += v;
      equilibria += static_cast<int>(e.attributes.rows());
      const double ratio = e.attributes(best, tc) / bound;
      rows.push_back({name, e.bridge_index, e.braid_index, ratio, e.attributes(best, td)});
      csv.row({name, std::to_string(e.crossing_number), std::to_string(e.bridge_index), std::to_string(e.braid_index),
               Csv::flag(e.bridge_index == e.braid_index), Csv::flag(e.bridge_index == 2),
               std::to_string(e.attributes.rows()), Csv::num(e.attributes(best, tc)), Csv::num(ratio),
               Csv::num(e.attributes(best, td)), std::to_string(v)});
    }
    csv.commit();
    // BB knots and the top decile by ratio.
    results::MilnorSummary sum;
    sum.scale = a.scale_name;
    for (const auto& r : rows)
      if (r.bridge == r.braid) {
        sum.bb_knots.push_back({r.name, r.ratio, r.threedim});
        sum.bb_max_ratio_deviation = std::max(sum.bb_max_ratio_deviation, std::fabs(r.ratio - 1.0));
        sum.bb_max_threedim = std::max(sum.bb_max_threedim, r.threedim);
      }
    std::vector<Row> sorted = rows;
    std::sort(sorted.begin(), sorted.end(), [](const Row& x, const Row& y) { return x.ratio > y.ratio; });
    const size_t decile = std::max<size_t>(1, sorted.size() / 10);
    int two_bridge = 0;
    for (size_t k = 0; k < decile && k < sorted.size(); ++k) two_bridge += sorted[k].bridge == 2;
    sum.knots = static_cast<long>(rows.size());
    sum.equilibria = equilibria;
    sum.milnor_violations = violations;
    sum.planar_threshold = kPlanarThreedim;
    sum.top_decile_size = static_cast<long>(decile);
    sum.top_decile_two_bridge_share = sorted.empty() ? 0.0 : static_cast<double>(two_bridge) / static_cast<double>(decile);
    write_summary(a, sum);
    std::cout << "exp_milnor: " << rows.size() << " knots, " << violations << " violations, BB max |ratio-1| "
              << sum.bb_max_ratio_deviation << ", top-decile 2-bridge share " << sum.top_decile_two_bridge_share
              << std::endl;
  });
}
