// exp_planarity: the share of approximately planar equilibria (paper Section
// 8.2: "a significant majority of the observed elastic equilibria are
// approximately planar"). Planar: 3D-ness below kPlanarThreedim (0.1).
// Writes planarity.csv (per knot) and summary.json.
#include <iostream>

#include "ek/dataset/ledger.hpp"
#include "experiment.hpp"
#include "planarity_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_planarity",
                        "Share of planar equilibria (reads ../dataset/dataset.h5, else the ledgers ../ledgers/).",
                        [](const Args& a) {
    std::string in;
    const std::vector<LedgerEntry> entries = read_results_entries(a.results, kClusterCut, &in);
    announce(a, "exp_planarity", "analyse " + in, 5.0);
    Csv csv(a.out + "/planarity.csv", {"knot", "equilibria", "planar", "share"});
    long total = 0, planar = 0;
    nlohmann::ordered_json hist = nlohmann::ordered_json::array();
    std::vector<double> all;
    for (const LedgerEntry& e : entries) {
      const std::string& name = e.name;
      const int td = e.equilibria() == 0 ? -1 : e.attribute_column("threedim");
      long p = 0;
      for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
        all.push_back(e.attributes(i, td));
        if (e.attributes(i, td) < kPlanarThreedim) ++p;
      }
      total += e.attributes.rows();
      planar += p;
      csv.row({name, std::to_string(e.attributes.rows()), std::to_string(p),
               Csv::num(e.attributes.rows() ? static_cast<double>(p) / e.attributes.rows() : 0.0)});
    }
    csv.commit();
    Csv values(a.out + "/threedim.csv", {"threedim"});
    for (double v : all) values.row({Csv::num(v)});
    values.commit();
    results::PlanaritySummary sum;
    sum.scale = a.scale_name;
    sum.threshold = kPlanarThreedim;
    sum.equilibria = total;
    sum.planar = planar;
    sum.planar_share = total ? static_cast<double>(planar) / static_cast<double>(total) : 0.0;
    write_summary(a, sum);
    std::cout << "exp_planarity: " << planar << " of " << total << " equilibria planar (share " << sum.planar_share
              << ")" << std::endl;
  });
}
